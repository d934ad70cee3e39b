// SPDX-License-Identifier: MIT
// What the GeoJSON and WKT readers share: how they fail, how they check a ring or a line, how they
// name a path by its flat index, and how they report dropped z coordinates.
#pragma once

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include <roiclip/io/feature.hpp>

namespace roiclip::io::detail {

// The source is a field of the error; `where` (feature, polygon, ring, point) stays in the text.
[[noreturn]] inline void fail(const std::string& source, const std::string& where,
                              const std::string& problem) {
  InputLocation location;
  location.source = source;
  throw InvalidInputError(location, (where.empty() ? "" : where + ": ") + problem);
}

// How many distinct points `path` has, counting up to 3 (a ring needs 3). Rings are short in
// practice and this runs once per ring: a quadratic count is fine and keeps the order untouched.
inline std::size_t distinctPointsUpTo3(const Path& path) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < path.size() && count < 3; ++i) {
    bool seen = false;
    for (std::size_t j = 0; j < i && !seen; ++j) seen = path[j] == path[i];
    if (!seen) ++count;
  }
  return count;
}

inline constexpr const char* kTooFewPoints = "ring has fewer than 3 distinct points";

// Keeps the flat path index (the core's messages use it) and the count of dropped z values while
// a reader walks its input, and checks each ring or line as it is finished.
class RingChecker {
 public:
  RingChecker(const std::string& source, const ReadOptions& options)
      : source_(source), options_(options) {}

  // "polygon 1, ring 0" becomes "polygon 1, ring 0 (path 3)"; plain "path i" names stay.
  [[nodiscard]] std::string flatName(const std::string& where) const {
    return where.rfind("path ", 0) == 0 ? where
                                        : where + " (path " + std::to_string(pathCount_) + ")";
  }

  // A coordinate read at `at`: it must be finite (JSON has no NaN, but WKT's "nan" parses).
  double coordinate(double value, const std::string& at, const char* axis) const {
    if (!std::isfinite(value)) fail(source_, at, std::string(axis) + " is not finite");
    return value;
  }

  void droppedZ() { ++zDropped_; }

  // A closed ring: a repeated closing point dropped, then at least 3 distinct points required.
  void finishRing(Path& path, const std::string& at) {
    if (path.size() > 1 && path.front() == path.back()) path.pop_back();
    if (!options_.allowDegenerateRings && distinctPointsUpTo3(path) < 3) {
      fail(source_, at, kTooFewPoints);
    }
    ++pathCount_;
  }

  // An open polyline: every point kept, a repeated first point included (the core reads it as a
  // loop). Equal points are not counted away: a zero-length line is valid and clips to nothing.
  void finishLine(const Path& path, const std::string& at) {
    if (!options_.allowDegenerateRings && path.size() < 2) {
      fail(source_, at, "line has fewer than 2 points");
    }
    ++pathCount_;
  }

  void setPathCount(std::size_t count) { pathCount_ = count; }

  // At the end of a read: one warning for all dropped z values.
  void reportWarnings() const {
    if (zDropped_ == 0 || options_.warnings == nullptr) return;
    options_.warnings->push_back(
        {source_, "ignored the z coordinate of " + std::to_string(zDropped_) +
                      (zDropped_ == 1 ? " point" : " points") + " (roiclip is 2-D)"});
  }

  [[nodiscard]] const std::string& source() const { return source_; }

 private:
  const std::string& source_;
  const ReadOptions& options_;
  std::size_t pathCount_ = 0;
  std::size_t zDropped_ = 0;
};

// parseFeatures() (geojson.cpp); with `acceptPlain`, plain {"paths": ...} JSON gives one feature
// without properties, each path a polygon of one ring.
std::vector<Feature> parseGeoJsonFeatures(const std::string& text, const std::string& source,
                                          const ReadOptions& options, bool acceptPlain);

}  // namespace roiclip::io::detail
