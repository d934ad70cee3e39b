// SPDX-License-Identifier: MIT
// roiclip::io features: what every reader gives (GeoJSON, plain paths JSON, WKT) and every writer
// takes, and the core's operations applied feature by feature so that each feature keeps its
// `id` and `properties` (as GIS tools expect).
//
// Ring orientation: the core returns roiclip's native order (outer rings with a negative shoelace
// sum of the raw (x, y) numbers, holes positive, as cv::findContours). GeoJSON (RFC 7946) and
// most GIS software want the opposite: exterior rings counter-clockwise in x-right/y-up axes,
// i.e. a positive shoelace sum, holes negative. On a y-down image an RFC 7946 exterior ring runs
// clockwise on screen. The writers take the order as an option (RingOrientation).
#pragma once

#include <cstddef>
#include <initializer_list>
#include <map>
#include <string>
#include <vector>

#include <roiclip/roiclip.hpp>

namespace roiclip::io {

/// Something a reader or a check noticed that is not an error (the input is processed anyway).
struct Warning {
  std::string source;   ///< the input's name (a file name, "<stdin>", "<string>")
  std::string message;  ///< what happened, without the source
  /// "SOURCE: MESSAGE".
  [[nodiscard]] std::string what() const { return source + ": " + message; }
};

/// How strictly rings are checked while reading, and where warnings go.
struct ReadOptions {
  /// When true (the default), a ring with fewer than 3 distinct points, or a polyline with fewer
  /// than 2 points, is kept as it is: the core ignores it (it contributes nothing), and the
  /// feature-wise operations count it (Feature::ignoredRings). When false (the CLI's --strict),
  /// such a ring or line is an InvalidInputError naming it. A ring of 3 or more distinct points
  /// all on one line (no area) is a degenerate ring too, but whether its points lie on one line
  /// is decided on the grid of the call that uses it: DegenerateRings::Refuse refuses those.
  bool allowDegenerateRings = true;
  /// When set, non-fatal findings are appended here: a third (z) coordinate, which every reader
  /// drops (roiclip is 2-D), gives one Warning per input. When null they are dropped silently.
  std::vector<Warning>* warnings = nullptr;
};

/// Text formats of the readers and writers.
enum class Format {
  Auto,     ///< readers only: WKT when the text starts with a letter, JSON otherwise
  GeoJson,  ///< GeoJSON, or (reading) plain {"paths": ...} JSON
  Wkt,      ///< OGC Well-Known Text (through Boost.Geometry)
};
/// "auto", "geojson", "wkt" (any case) as a Format. @throws InvalidInputError on other names.
Format parseFormat(const char* name);

/// The order of the points of the rings the writers write.
enum class RingOrientation {
  Rfc7946,  ///< exterior rings: positive shoelace sum (counter-clockwise in y-up axes); holes
            ///< negative. The GeoJSON standard, shapely's orient(p, 1.0), GDAL's default.
  OpenCv,   ///< roiclip's native order: exterior rings negative, holes positive, like
            ///< cv::findContours (cv::contourArea(c, true) < 0 for outer contours).
};
/// "rfc7946", "opencv" (any case) as a RingOrientation. @throws InvalidInputError otherwise.
RingOrientation parseRingOrientation(const char* name);

/// A feature with its structure kept: a list of polygons, each a list of rings (ring 0 the outer
/// ring, then the inner rings), rings without the repeated closing point.
struct Feature {
  std::vector<Paths> polygons;  ///< each polygon: its outer ring, then its inner rings
  /// The feature's properties whose values are strings (others are in propertiesJson only).
  std::map<std::string, std::string> properties;
  /// The GeoJSON "id" member as JSON text (`"a1"`, `7`), or empty when the feature has none.
  std::string id;
  /// The whole GeoJSON "properties" member as JSON text, every value and the key order kept
  /// (`{"name":"roi","n":3}`, or `null`). Empty when the input had no Feature at all (a bare
  /// geometry, plain paths JSON, WKT): the operations below then fill in "area" and "rings".
  std::string propertiesJson;
  /// In results of simplifyFeatures() and clipFeatures(): how many of the input feature's rings
  /// contributed nothing (countDegeneratePaths()). Written as the property "ignoredRings" when
  /// non-zero and the feature has roiclip's summary properties ("area", "rings").
  std::size_t ignoredRings = 0;
  /// In results of clipFeatures(): how many rings of the clip operand (all the clip features)
  /// contributed nothing, the same in every result of one call (the whole clip operand is
  /// applied to each subject feature). Written as the property "ignoredClipRings" as
  /// ignoredRings is.
  std::size_t ignoredClipRings = 0;
};

/// What the feature-wise operations do with a degenerate ring: one that contributes nothing
/// because, snapped to the call's grid, all its points lie on one line (fewer than 3 distinct
/// points, or 3 or more on one line: no area; countDegeneratePaths()).
enum class DegenerateRings {
  Count,   ///< ignore it and count it (Feature::ignoredRings, Feature::ignoredClipRings)
  Refuse,  ///< an InvalidInputError naming it (the CLI's --strict): "path P: ring has ..."
};

/// The rings of `rings` that countDegeneratePaths() counts on `grid` (the call's grid, resolved:
/// resolveGrid()): how many with DegenerateRings::Count; with DegenerateRings::Refuse, 0, or an
/// InvalidInputError at the first of them (location: `operand` and its index in `rings`; the
/// problem "ring has fewer than 3 distinct points" or "ring has no area (all its points on one
/// line)"; name its file with nameSource()).
/// @throws InvalidInputError also as countDegeneratePaths().
std::size_t checkDegenerateRings(const Paths& rings, const Grid& grid, Operand operand,
                                 DegenerateRings mode = DegenerateRings::Count);

/// How many rings of `features` are degenerate when each feature is one call on
/// `options.grid`, as simplifyFeatures() and the clip operand of clipFeatures() take them: the
/// sum of simplifyFeatures()' ignoredRings, and the ignoredClipRings of every result of
/// clipFeatures() with `features` as the clip operand (also when there is no subject feature,
/// hence no result to carry it).
std::size_t countDegenerateRings(const std::vector<Feature>& features, const Options& options);

/// Every ring of every polygon of `features` as one path set, in order (the core's input).
Paths allRings(const std::vector<Feature>& features);

/// One feature holding every polygon of `features` and no properties (--dissolve).
Feature dissolve(const std::vector<Feature>& features);

/// A PolygonSet as a feature: each polygon its outer ring, then its holes; properties
/// {"area": set.area(), "rings": set.ringCount()}, plus "ignoredRings" and "ignoredClipRings"
/// when `ignoredRings` and `ignoredClipRings` are non-zero (the fields are set to them too); no
/// id.
Feature toFeature(const PolygonSet& set, std::size_t ignoredRings = 0,
                  std::size_t ignoredClipRings = 0);

/// The name of the input (a file) an operand of the core was read from.
struct Source {
  Operand operand;   ///< the operand read from it
  std::string name;  ///< its name in messages (sourceName())
};

/// `e` naming the source of the operand it concerns (e.location().operand, a field: the message
/// is never read), or all of `sources` when it names no operand; an error that already names its
/// source (e.g. one from a reader) is returned as it is. A path index in `e` is shifted by
/// `pathOffset` (the index of the operand's first path in its file: the flat index the readers'
/// messages give).
InvalidInputError nameSource(const InvalidInputError& e, std::initializer_list<Source> sources,
                             std::size_t pathOffset = 0);

/// simplify() on each feature (its rings under `rule`): one result feature per input feature,
/// in order, keeping its id and properties (a feature without properties gets "area" and
/// "rings", as toFeature()). Degenerate rings are counted (Feature::ignoredRings) or, with
/// DegenerateRings::Refuse, refused.
/// @throws InvalidInputError from the core, or for a degenerate ring with Refuse, naming
///         `source` and the flat path index.
std::vector<Feature> simplifyFeatures(const std::vector<Feature>& features,
                                      const std::string& source, FillRule rule,
                                      const Options& options = {},
                                      DegenerateRings degenerate = DegenerateRings::Count);

/// clip() of each subject feature (its rings under `subjectRule`) by the union of the clip
/// features (each feature's rings under `clipRule`, then the union of all of them): one result
/// per subject feature, in order, ids and properties kept as simplifyFeatures(). Each result
/// counts the subject feature's degenerate rings (Feature::ignoredRings) and the clip operand's
/// (Feature::ignoredClipRings); with DegenerateRings::Refuse, a degenerate ring in either operand
/// is an error (the clip operand's are looked at first, also when `subject` is empty).
/// @throws InvalidInputError from the core, or for a degenerate ring with Refuse, naming the file
///         of the operand it concerns and the flat path index.
std::vector<Feature> clipFeatures(ClipOp op, const std::vector<Feature>& subject,
                                  const std::string& subjectSource,
                                  const std::vector<Feature>& clip, const std::string& clipSource,
                                  FillRule subjectRule, FillRule clipRule,
                                  const Options& options = {},
                                  DegenerateRings degenerate = DegenerateRings::Count);

/// How far snapping to a fixed grid moves input coordinates: the core rounds each coordinate to
/// the nearest grid point (Grid::toUnits()), so a coordinate moves by up to half a grid step.
/// Pixel coordinates (integers, halves, ...) do not move; coordinates with more digits than the
/// grid holds (GIS data, sub-pixel edges) do. A fitted grid (the default) moves none by more than
/// about 2^-31 of the extent and is not measured (an empty SnapShift).
struct SnapShift {
  std::size_t vertices = 0;  ///< vertices looked at
  std::size_t moved = 0;     ///< vertices with a coordinate moved by more than the threshold
  double largest = 0;        ///< largest move of one coordinate, in coordinate units (px)
  std::size_t path = 0;      ///< flat path index of the vertex with the largest move
  std::size_t vertex = 0;    ///< its index in the path
};

/// Coordinates moving by more than this fraction of a grid step count as moved (SnapShift):
/// 1/4 step, i.e. 1/1024 px at the default 1/256 px grid.
inline constexpr double kSnapWarningFraction = 0.25;

/// The SnapShift of `paths` on `grid` (a fixed grid; a fitted one gives an empty SnapShift).
SnapShift measureSnapShift(const Paths& paths, const Grid& grid);

/// A Warning for `source` when snapping moves any coordinate of `paths` by more than
/// kSnapWarningFraction of a grid step (how many vertices, the largest move and where), or an
/// empty list when none does.
std::vector<Warning> snapWarnings(const Paths& paths, const std::string& source, const Grid& grid);

/// Read features from `text`: `format` GeoJson (parseFeatures(); plain {"paths": ...} JSON gives
/// one feature with one single-ring polygon per path), Wkt (parseWktFeatures()), or Auto (by
/// content: WKT when the first non-blank character is a letter).
/// @throws InvalidInputError as the reader of that format.
std::vector<Feature> parseAnyFeatures(const std::string& text,
                                      const std::string& source = "<string>",
                                      Format format = Format::Auto,
                                      const ReadOptions& options = {});

/// parseAnyFeatures() on the contents of `file`; "-" reads standard input (named "<stdin>" in
/// messages). @throws InvalidInputError also when the file cannot be read, naming it.
std::vector<Feature> readAnyFeatures(const std::string& file, Format format = Format::Auto,
                                     const ReadOptions& options = {});

/// Open polylines from `text`: parseLines() (GeoJSON, plain JSON) or parseWktLines(), `format`
/// chosen as for parseAnyFeatures().
Paths parseAnyLines(const std::string& text, const std::string& source = "<string>",
                    Format format = Format::Auto, const ReadOptions& options = {});

/// parseAnyLines() on the contents of `file` ("-": standard input).
Paths readAnyLines(const std::string& file, Format format = Format::Auto,
                   const ReadOptions& options = {});

/// The contents of `file` ("-": all of standard input). @throws InvalidInputError naming the file
/// when it cannot be read (or is a directory).
std::string readText(const std::string& file);

/// The name readAnyFeatures() gives `file` in messages: "<stdin>" for "-", else `file`.
std::string sourceName(const std::string& file);

/// Options of the writers.
struct WriteOptions {
  RingOrientation orientation = RingOrientation::Rfc7946;  ///< ring order written
  int indent = -1;  ///< GeoJSON: spaces per indentation level, or -1 for a single line
};

/// `features` as text in `format` (GeoJson: featuresToGeoJson(); Wkt: featuresToWkt()).
std::string formatFeatures(const std::vector<Feature>& features, Format format,
                           const WriteOptions& options = {});

/// formatFeatures() to `file` atomically (writeFileAtomically()), or to standard output when
/// `file` is "-" or empty. @throws Error naming `file` when it cannot be written.
void writeFeatures(const std::vector<Feature>& features, const std::string& file, Format format,
                   const WriteOptions& options = {});

/// Polylines as text in `format` (GeoJson: linesToGeoJson(), with the property
/// "ignoredClipRings" when `ignoredClipRings` is non-zero: the region's degenerate rings, for
/// clipLines() results; Wkt: linesToWkt(), which has no properties).
std::string formatLines(const Paths& lines, Format format, int indent = -1,
                        std::size_t ignoredClipRings = 0);

/// formatLines() to `file` as writeFeatures() writes.
void writeLines(const Paths& lines, const std::string& file, Format format, int indent = -1,
                std::size_t ignoredClipRings = 0);

/// `text` to `file` atomically, or to standard output when `file` is "-" or empty.
/// @throws Error naming `file` (or "<stdout>") when it cannot be written.
void writeText(const std::string& text, const std::string& file);

/// `ring` in the order `orientation` asks of an outer ring (`outer`) or a hole: reversed (the
/// first point kept first) when its shoelace sum has the other sign.
Path orientRing(const Path& ring, bool outer, RingOrientation orientation);

}  // namespace roiclip::io
