// SPDX-License-Identifier: MIT
// roiclip::io: reading and writing path sets and open polylines as GeoJSON or plain JSON.
//
// Coordinates are taken as they are (no projection): x = first number, y = second number, in the
// same y-down pixel convention as the rest of roiclip (see roiclip/geometry.hpp). A third (z)
// coordinate is dropped (a Warning in ReadOptions::warnings). Files named "-" are standard input.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <roiclip/io/feature.hpp>
#include <roiclip/roiclip.hpp>

namespace roiclip::io {

/// Read a path set from text holding either
///  - GeoJSON: a Polygon, MultiPolygon, GeometryCollection of them (collections may nest), Feature
///    or FeatureCollection; every ring (outer or inner)
///    becomes one closed path taken as-is, so the fill rule alone decides what is inside; a
///    repeated closing point is dropped; or
///  - plain JSON: {"paths": [[[x, y], ...], ...]}; the last point need not repeat the first (if
///    it does, the repeat is dropped).
/// Features with a null geometry contribute nothing.
/// @param text   the JSON text.
/// @param source name of the input used in error messages (a file name, or "<string>").
/// @throws InvalidInputError (message starts with `source`) on unparsable JSON, a wrong
///         structure, a coordinate that is not a finite number, or a ring with fewer than 3
///         distinct points (unless options allow it); the message names the ring.
Paths parsePaths(const std::string& text, const std::string& source = "<string>",
                 const ReadOptions& options = {});

/// parsePaths() on the contents of a file. @throws InvalidInputError also when the file cannot
/// be read; the message names the file.
Paths readPaths(const std::string& file, const ReadOptions& options = {});

/// Read open polylines (for clipLines()) from text holding either
///  - GeoJSON: a LineString or MultiLineString, or a Feature, FeatureCollection or
///    GeometryCollection of them (collections may nest); every line string is one polyline; or
///  - plain JSON: {"paths": [[[x, y], ...], ...]}.
/// Points are taken as they are: a last point that repeats the first is kept, since the core reads
/// such a polyline as a loop. Features with a null geometry contribute nothing.
/// A line needs 2 points (as GeoJSON requires of a LineString); one of 2 or more points that are
/// all equal is valid and simply gives nothing when clipped, like any polyline that the core finds
/// shorter than one grid step.
/// @param text   the JSON text.
/// @param source name of the input used in error messages (a file name, or "<string>").
/// @throws InvalidInputError (message starts with `source`) on unparsable JSON, a wrong
///         structure (including polygons: a region is not a line), a coordinate that is not a
///         finite number, or a line with fewer than 2 points (unless options allow it); the
///         message names the line ("path i" in plain JSON; in GeoJSON e.g. "feature 2, line 0
///         (path 5)", with the flat index the core's messages use).
Paths parseLines(const std::string& text, const std::string& source = "<string>",
                 const ReadOptions& options = {});

/// parseLines() on the contents of a file. @throws InvalidInputError also when the file cannot
/// be read; the message names the file.
Paths readLines(const std::string& file, const ReadOptions& options = {});

/// Read GeoJSON keeping its structure. A FeatureCollection gives one Feature per feature (with its
/// "id" and "properties" as JSON text); a lone Feature, Polygon, MultiPolygon or
/// GeometryCollection gives one Feature (a bare geometry: without properties). Plain
/// {"paths": ...} JSON is rejected (parseAnyFeatures() takes it). Errors as parsePaths().
std::vector<Feature> parseFeatures(const std::string& text, const std::string& source = "<string>",
                                   const ReadOptions& options = {});
/// parseFeatures() on the contents of a file.
std::vector<Feature> readFeatures(const std::string& file, const ReadOptions& options = {});

/// Features as GeoJSON text: a FeatureCollection with one Feature per feature, in order, each with
/// its "id" (when it has one), its "properties" as they were read (null when it has none) and a
/// MultiPolygon geometry (each polygon: outer ring, then its holes; every ring closed by
/// repeating its first point, as GeoJSON requires; ring order as options.orientation asks,
/// RFC 7946 by default).
std::string featuresToGeoJson(const std::vector<Feature>& features,
                              const WriteOptions& options = {});

/// A PolygonSet as GeoJSON text: featuresToGeoJson({toFeature(set)}), i.e. a FeatureCollection
/// with one Feature whose geometry is a MultiPolygon and whose properties are "area"
/// (PolygonSet::area()) and "rings" (ringCount()). Rings in RFC 7946 order unless `orientation`
/// says otherwise (RingOrientation::OpenCv: as in the PolygonSet).
/// @param indent spaces per indentation level, or -1 for a single line.
std::string toGeoJson(const PolygonSet& set, int indent = -1,
                      RingOrientation orientation = RingOrientation::Rfc7946);

/// Write toGeoJson(set) to `file` atomically: the text goes to a temporary file in the same folder
/// which is then renamed, so a failure never leaves a partial `file`.
/// @throws Error naming `file` when it cannot be written (a missing folder, a directory).
void writeGeoJson(const PolygonSet& set, const std::string& file, int indent = -1,
                  RingOrientation orientation = RingOrientation::Rfc7946);

/// Polylines (e.g. clipLines() output) as GeoJSON text: a FeatureCollection with one Feature
/// whose geometry is a MultiLineString (one line string per polyline, points as they are) and
/// properties "length" (the total Euclidean length, in coordinate units, i.e. px) and "lines" (the
/// number of polylines), then "ignoredClipRings" when `ignoredClipRings` is non-zero (how many
/// rings of the region clipLines() took contributed nothing: checkDegenerateRings()).
/// @param indent spaces per indentation level, or -1 for a single line.
std::string linesToGeoJson(const Paths& lines, int indent = -1, std::size_t ignoredClipRings = 0);

/// Write linesToGeoJson(lines) to `file` atomically, as writeGeoJson().
/// @throws Error when the file cannot be written.
void writeLinesGeoJson(const Paths& lines, const std::string& file, int indent = -1);

}  // namespace roiclip::io
