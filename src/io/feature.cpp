// SPDX-License-Identifier: MIT
// Features (feature.hpp): the core's operations feature by feature, ring orientation, format
// detection, "-" for standard input and output, and the snapping check.
#include <roiclip/io/feature.hpp>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <utility>

#include <nlohmann/json.hpp>

#include <roiclip/io/atomic_file.hpp>
#include <roiclip/io/geojson.hpp>
#include <roiclip/io/wkt.hpp>

#include "reading.hpp"

namespace roiclip::io {
namespace {

constexpr const char* kStdin = "<stdin>";

std::string lower(const char* name) {
  std::string s = name;
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool looksLikeWkt(const std::string& text) {
  for (const char c : text) {
    if (std::isspace(static_cast<unsigned char>(c)) == 0) {
      return std::isalpha(static_cast<unsigned char>(c)) != 0;
    }
  }
  return false;  // empty text: the JSON reader says what is wrong with it
}

Format detect(const std::string& text, Format format) {
  if (format != Format::Auto) return format;
  return looksLikeWkt(text) ? Format::Wkt : Format::GeoJson;
}

std::size_t ringCount(const Feature& feature) {
  std::size_t count = 0;
  for (const Paths& polygon : feature.polygons) count += polygon.size();
  return count;
}

// The result of an operation on `input` as a feature: `input`'s id and properties, or the
// summary properties of toFeature() when it has none.
Feature withIdentity(const PolygonSet& set, const Feature& input, std::size_t ignoredRings,
                     std::size_t ignoredClipRings = 0) {
  Feature out = toFeature(set, ignoredRings, ignoredClipRings);
  out.id = input.id;
  if (!input.propertiesJson.empty()) {
    out.propertiesJson = input.propertiesJson;
    out.properties = input.properties;
  }
  return out;
}

// The feature's rings (of `operand`) that the call on `rings` and `other` ignores: counted, or
// with DegenerateRings::Refuse an error.
std::size_t ignored(const Paths& rings, const Options& options, Operand operand,
                    DegenerateRings mode, const Paths& other = {}) {
  return checkDegenerateRings(rings, resolveGrid(options.grid, rings, other), operand, mode);
}

// "1/256 px" (or "1/0.5 px" for a fractional scale).
std::string gridStep(double scale) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "1/%g px", scale);
  return buffer;
}

}  // namespace

Format parseFormat(const char* name) {
  const std::string s = lower(name);
  if (s == "auto") return Format::Auto;
  if (s == "geojson" || s == "json") return Format::GeoJson;
  if (s == "wkt") return Format::Wkt;
  throw InvalidInputError("unknown format \"" + std::string(name) + "\" (auto, geojson, wkt)");
}

RingOrientation parseRingOrientation(const char* name) {
  const std::string s = lower(name);
  if (s == "rfc7946") return RingOrientation::Rfc7946;
  if (s == "opencv") return RingOrientation::OpenCv;
  throw InvalidInputError("unknown ring orientation \"" + std::string(name) +
                          "\" (rfc7946, opencv)");
}

std::size_t checkDegenerateRings(const Paths& rings, const Grid& grid, Operand operand,
                                 DegenerateRings mode) {
  const std::size_t count = countDegeneratePaths(rings, grid);
  if (mode == DegenerateRings::Count || count == 0) return count;
  for (std::size_t i = 0; i < rings.size(); ++i) {
    if (countDegeneratePaths({rings[i]}, grid) == 0) continue;
    InputLocation location;
    location.operand = operand;
    location.path = i;
    throw InvalidInputError(location, detail::distinctPointsUpTo3(rings[i]) < 3
                                          ? detail::kTooFewPoints
                                          : "ring has no area (all its points on one line)");
  }
  return 0;  // not reached: countDegeneratePaths() counts each path on its own
}

std::size_t countDegenerateRings(const std::vector<Feature>& features, const Options& options) {
  std::size_t count = 0;
  for (const Feature& feature : features) {
    count += ignored(allRings({feature}), options, Operand::None, DegenerateRings::Count);
  }
  return count;
}

Paths allRings(const std::vector<Feature>& features) {
  Paths out;
  for (const Feature& feature : features) {
    for (const Paths& polygon : feature.polygons)
      out.insert(out.end(), polygon.begin(), polygon.end());
  }
  return out;
}

Feature dissolve(const std::vector<Feature>& features) {
  Feature out;
  for (const Feature& feature : features) {
    out.polygons.insert(out.polygons.end(), feature.polygons.begin(), feature.polygons.end());
  }
  return out;
}

Feature toFeature(const PolygonSet& set, std::size_t ignoredRings, std::size_t ignoredClipRings) {
  Feature out;
  out.ignoredRings = ignoredRings;
  out.ignoredClipRings = ignoredClipRings;
  out.polygons.reserve(set.polygons.size());
  for (const Polygon& polygon : set.polygons) {
    Paths rings;
    rings.reserve(1 + polygon.holes.size());
    rings.push_back(polygon.outer);
    rings.insert(rings.end(), polygon.holes.begin(), polygon.holes.end());
    out.polygons.push_back(std::move(rings));
  }
  nlohmann::ordered_json properties{{"area", set.area()}, {"rings", set.ringCount()}};
  if (ignoredRings > 0) properties["ignoredRings"] = ignoredRings;
  if (ignoredClipRings > 0) properties["ignoredClipRings"] = ignoredClipRings;
  out.propertiesJson = properties.dump();
  return out;
}

InvalidInputError nameSource(const InvalidInputError& e, std::initializer_list<Source> sources,
                             std::size_t pathOffset) {
  if (!e.location().source.empty()) return e;
  InputLocation location = e.location();
  if (location.path) *location.path += pathOffset;
  std::string all;
  for (const Source& source : sources) {
    if (location.operand == source.operand) {
      location.source = source.name;
      return {location, e.problem()};
    }
    all += (all.empty() ? "" : ", ") + source.name;
  }
  location.source = all;
  return {location, e.problem()};
}

std::vector<Feature> simplifyFeatures(const std::vector<Feature>& features,
                                      const std::string& source, FillRule rule,
                                      const Options& options, DegenerateRings degenerate) {
  std::vector<Feature> out;
  out.reserve(features.size());
  std::size_t offset = 0;
  for (const Feature& feature : features) {
    try {
      const Paths rings = allRings({feature});
      const PolygonSet set = simplify(rings, rule, options);
      out.push_back(
          withIdentity(set, feature, ignored(rings, options, Operand::Subject, degenerate)));
    } catch (const InvalidInputError& e) {
      throw nameSource(e, {{Operand::Subject, source}}, offset);
    }
    offset += ringCount(feature);
  }
  return out;
}

std::vector<Feature> clipFeatures(ClipOp op, const std::vector<Feature>& subject,
                                  const std::string& subjectSource,
                                  const std::vector<Feature>& clip, const std::string& clipSource,
                                  FillRule subjectRule, FillRule clipRule, const Options& options,
                                  DegenerateRings degenerate) {
  // The union of the clip features: each one's region under clipRule (the union of nothing with
  // it), its rings then read together under NonZero. One feature gives the region its rings make
  // under clipRule, as when every ring is clipped against at once.
  Paths region;
  std::size_t offset = 0, ignoredClipRings = 0;
  for (const Feature& feature : clip) {
    try {
      const Paths rings = allRings({feature});
      const PolygonSet set =
          roiclip::clip(ClipOp::Union, {}, rings, FillRule::NonZero, clipRule, options);
      ignoredClipRings += ignored(rings, options, Operand::Clip, degenerate);
      const Paths united = set.toPaths();
      region.insert(region.end(), united.begin(), united.end());
    } catch (const InvalidInputError& e) {
      throw nameSource(e, {{Operand::Subject, subjectSource}, {Operand::Clip, clipSource}}, offset);
    }
    offset += ringCount(feature);
  }
  std::vector<Feature> out;
  out.reserve(subject.size());
  offset = 0;
  for (const Feature& feature : subject) {
    try {
      const Paths rings = allRings({feature});
      const PolygonSet set =
          roiclip::clip(op, rings, region, subjectRule, FillRule::NonZero, options);
      out.push_back(withIdentity(set, feature,
                                 ignored(rings, options, Operand::Subject, degenerate, region),
                                 ignoredClipRings));
    } catch (const InvalidInputError& e) {
      throw nameSource(e, {{Operand::Subject, subjectSource}, {Operand::Clip, clipSource}}, offset);
    }
    offset += ringCount(feature);
  }
  return out;
}

SnapShift measureSnapShift(const Paths& paths, const Grid& grid) {
  SnapShift shift;
  if (grid.isFitted() || !(grid.scale > 0.0) || !std::isfinite(grid.scale)) return shift;
  const double origins[2] = {grid.origin.x, grid.origin.y};
  for (std::size_t p = 0; p < paths.size(); ++p) {
    for (std::size_t v = 0; v < paths[p].size(); ++v) {
      ++shift.vertices;
      bool moved = false;
      const double coordinates[2] = {paths[p][v].x, paths[p][v].y};
      for (int axis = 0; axis < 2; ++axis) {
        // The core's own snapping (Grid::toUnits()); NaN and out-of-range are the core's to say.
        const std::optional<std::int64_t> units = grid.toUnits(coordinates[axis], origins[axis]);
        if (!units) continue;
        const double move = std::fabs(coordinates[axis] - grid.toCoordinate(*units, origins[axis]));
        moved = moved || move * grid.scale > kSnapWarningFraction;
        if (move > shift.largest) {
          shift.largest = move;
          shift.path = p;
          shift.vertex = v;
        }
      }
      if (moved) ++shift.moved;
    }
  }
  return shift;
}

std::vector<Warning> snapWarnings(const Paths& paths, const std::string& source, const Grid& grid) {
  const SnapShift shift = measureSnapShift(paths, grid);
  if (shift.moved == 0) return {};
  char largest[64];
  std::snprintf(largest, sizeof largest, "%.3g", shift.largest);
  return {
      {source, "snapping to the " + gridStep(grid.scale) + " grid moved " +
                   std::to_string(shift.moved) + " of " + std::to_string(shift.vertices) +
                   " vertices by more than 1/4 grid step (up to " + largest + " px, path " +
                   std::to_string(shift.path) + ", vertex " + std::to_string(shift.vertex) +
                   "); a larger --grid SCALE, or --grid auto (the default), keeps more digits"}};
}

std::string sourceName(const std::string& file) { return file == "-" ? kStdin : file; }

std::string readText(const std::string& file) {
  std::ostringstream buffer;
  if (file == "-") {
    buffer << std::cin.rdbuf();
    if (std::cin.bad()) detail::fail(kStdin, "", "read error");
    return buffer.str();
  }
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) detail::fail(file, "", "is a directory");
  std::ifstream in(file, std::ios::binary);
  if (!in) detail::fail(file, "", "cannot open file for reading");
  buffer << in.rdbuf();
  if (in.bad()) detail::fail(file, "", "read error");
  return buffer.str();
}

std::vector<Feature> parseAnyFeatures(const std::string& text, const std::string& source,
                                      Format format, const ReadOptions& options) {
  if (detect(text, format) == Format::Wkt) return parseWktFeatures(text, source, options);
  return detail::parseGeoJsonFeatures(text, source, options, true);
}

std::vector<Feature> readAnyFeatures(const std::string& file, Format format,
                                     const ReadOptions& options) {
  return parseAnyFeatures(readText(file), sourceName(file), format, options);
}

Paths parseAnyLines(const std::string& text, const std::string& source, Format format,
                    const ReadOptions& options) {
  if (detect(text, format) == Format::Wkt) return parseWktLines(text, source, options);
  return parseLines(text, source, options);
}

Paths readAnyLines(const std::string& file, Format format, const ReadOptions& options) {
  return parseAnyLines(readText(file), sourceName(file), format, options);
}

std::string formatFeatures(const std::vector<Feature>& features, Format format,
                           const WriteOptions& options) {
  return format == Format::Wkt ? featuresToWkt(features, options.orientation)
                               : featuresToGeoJson(features, options);
}

std::string formatLines(const Paths& lines, Format format, int indent,
                        std::size_t ignoredClipRings) {
  return format == Format::Wkt ? linesToWkt(lines)
                               : linesToGeoJson(lines, indent, ignoredClipRings);
}

void writeText(const std::string& text, const std::string& file) {
  if (!file.empty() && file != "-") {
    writeFileAtomically(file, text);
    return;
  }
  std::cout << text;
  std::cout.flush();
  if (!std::cout) throw Error("cannot write <stdout>: write failed");
}

void writeFeatures(const std::vector<Feature>& features, const std::string& file, Format format,
                   const WriteOptions& options) {
  writeText(formatFeatures(features, format, options), file);
}

void writeLines(const Paths& lines, const std::string& file, Format format, int indent,
                std::size_t ignoredClipRings) {
  writeText(formatLines(lines, format, indent, ignoredClipRings), file);
}

Path orientRing(const Path& ring, bool outer, RingOrientation orientation) {
  const double area = signedArea(ring);
  const bool wantPositive = outer == (orientation == RingOrientation::Rfc7946);
  if (area == 0.0 || (area > 0.0) == wantPositive) return ring;
  Path reversed;
  reversed.reserve(ring.size());
  reversed.push_back(ring.front());
  reversed.insert(reversed.end(), ring.rbegin(), ring.rend() - 1);
  return reversed;
}

}  // namespace roiclip::io
