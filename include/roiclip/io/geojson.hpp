// roiclip::io: reading and writing path sets and open polylines as GeoJSON or plain JSON.
//
// Coordinates are taken as they are (no projection): x = first number, y = second number, in the
// same y-down pixel convention as the rest of roiclip (see roiclip/geometry.hpp).
#pragma once

#include <map>
#include <string>
#include <vector>

#include <roiclip/roiclip.hpp>

namespace roiclip::io {

/// How strictly rings are checked while reading.
struct ReadOptions {
  /// When false (the default), a ring with fewer than 3 distinct points is an InvalidInputError,
  /// and so is a polyline with fewer than 2 points (parseLines()). When true, such rings and lines
  /// are kept as they are (the core ignores them); conformance data from other projects contains
  /// them on purpose.
  bool allowDegenerateRings = false;
};

/// Read a path set from text holding either
///  - GeoJSON: a Polygon, MultiPolygon, Feature or FeatureCollection; every ring (outer or inner)
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

/// A GeoJSON feature with its structure kept: a list of polygons, each a list of rings (ring 0
/// the outer ring, then the inner rings), rings without the repeated closing point.
struct Feature {
  std::vector<Paths> polygons;
  /// The feature's properties whose values are strings (others are not kept).
  std::map<std::string, std::string> properties;
};

/// Read GeoJSON keeping its structure. A FeatureCollection gives one Feature per feature; a lone
/// Feature, Polygon or MultiPolygon gives one Feature. Plain {"paths": ...} JSON is rejected.
/// Errors as parsePaths().
std::vector<Feature> parseFeatures(const std::string& text, const std::string& source = "<string>",
                                   const ReadOptions& options = {});
/// parseFeatures() on the contents of a file.
std::vector<Feature> readFeatures(const std::string& file, const ReadOptions& options = {});

/// A PolygonSet as GeoJSON text: a FeatureCollection with one Feature whose geometry is a
/// MultiPolygon (each polygon: outer ring, then its holes; every ring closed by repeating its first
/// point, as GeoJSON requires; ring orientation as in the PolygonSet, i.e. outer rings with a
/// negative shoelace sum) and properties "area" (PolygonSet::area()) and "rings" (ringCount()).
/// @param indent spaces per indentation level, or -1 for a single line.
std::string toGeoJson(const PolygonSet& set, int indent = -1);

/// Write toGeoJson(set) to `file` atomically: the text goes to a temporary file in the same folder
/// which is then renamed, so a failure never leaves a partial `file`.
/// @throws Error when the file cannot be written.
void writeGeoJson(const PolygonSet& set, const std::string& file, int indent = -1);

/// Polylines (e.g. clipLines() output) as GeoJSON text: a FeatureCollection with one Feature
/// whose geometry is a MultiLineString (one line string per polyline, points as they are) and
/// properties "length" (the total Euclidean length, in coordinate units, i.e. px) and "lines" (the
/// number of polylines).
/// @param indent spaces per indentation level, or -1 for a single line.
std::string linesToGeoJson(const Paths& lines, int indent = -1);

/// Write linesToGeoJson(lines) to `file` atomically, as writeGeoJson().
/// @throws Error when the file cannot be written.
void writeLinesGeoJson(const Paths& lines, const std::string& file, int indent = -1);

}  // namespace roiclip::io
