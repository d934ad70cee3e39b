// SPDX-License-Identifier: MIT
// roiclip: public geometry types. Includes only the standard library and GLM.
//
// Conventions (the same everywhere in roiclip):
// - Image coordinates: x to the right, y DOWN, in pixels; (0,0) is the centre of the top-left
//   pixel, as in OpenCV.
// - Coordinates are snapped to a fixed-point grid of 1/Grid::scale pixel (default 1/256 px) and
//   must satisfy |coordinate * scale| <= Grid::kMaxUnits (2^30), i.e. |x|,|y| <= 4,194,304 px at
//   the default scale. Every topological decision after snapping is exact (no epsilon).
// - Winding numbers are the mathematical ones computed on the raw (x, y) numbers: a path whose
//   shoelace sum  sum(x_i*y_{i+1} - x_{i+1}*y_i)  is positive winds +1 around its interior.
//   On screen (y down) such a path runs clockwise.
// - Output orientation matches cv::findContours: outer rings have a NEGATIVE shoelace sum
//   (counter-clockwise on screen, cv::contourArea(c, true) < 0) and holes a POSITIVE one.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace roiclip {

/// A point in image coordinates (pixels, y down).
using Point = glm::dvec2;
/// A closed path: the last point connects back to the first (it need not repeat it).
using Path = std::vector<Point>;
/// A set of closed paths, read together under one fill rule.
using Paths = std::vector<Path>;

/// Which points a set of closed paths covers, by their winding number w.
enum class FillRule {
  EvenOdd,   ///< w is odd (what cv::fillPoly draws)
  NonZero,   ///< w != 0
  Positive,  ///< w > 0
  Negative,  ///< w < 0
};

/// Boolean operation between a subject and a clip region.
enum class ClipOp {
  Intersection,  ///< subject AND clip (the region-of-interest case)
  Union,         ///< subject OR clip
  Difference,    ///< subject AND NOT clip
  Xor,           ///< subject XOR clip
};

/// The fixed-point grid every input coordinate is snapped to.
struct Grid {
  /// Largest allowed |coordinate * scale|.
  static constexpr std::int64_t kMaxUnits = std::int64_t{1} << 30;
  /// Grid units per pixel. Must be positive and finite; a power of two keeps snapping exact for
  /// pixel and half-pixel coordinates.
  double scale = 256.0;
};

/// One connected filled region: an outer ring and the holes inside it. Rings are simple (no
/// self-intersection, no repeated vertex), do not repeat their first point, and never cross
/// each other; distinct rings may touch at isolated vertices.
struct Polygon {
  Path outer;               ///< negative shoelace sum (counter-clockwise on screen)
  std::vector<Path> holes;  ///< positive shoelace sum (clockwise on screen)
  /// Nesting: the polygon whose hole this polygon lies in, or -1 at the top level.
  int parent = -1;
  /// Index into polygons[parent].holes of that hole, or -1 at the top level.
  int parentHole = -1;
};

/// A region as a forest of polygons with holes (like OpenCV's contour hierarchy: each hole
/// knows its outer ring, each island knows the hole it sits in). Parents come before children.
struct PolygonSet {
  std::vector<Polygon> polygons;  ///< parents before children

  /// True when the region is empty (no polygons).
  [[nodiscard]] bool empty() const { return polygons.empty(); }
  /// Total filled area in square pixels (outer areas minus hole areas).
  [[nodiscard]] double area() const;
  /// Number of rings (outer rings plus holes).
  [[nodiscard]] std::size_t ringCount() const;
  /// Every ring as one path set (outer rings and holes, with their orientations); filling it
  /// with FillRule::NonZero or EvenOdd gives back this region.
  [[nodiscard]] Paths toPaths() const;
};

/// The fill rule that reads a PolygonSet's rings (PolygonSet::toPaths()) as its region, wherever
/// roiclip takes a PolygonSet as input (clip() operands, opencv::rasterize()). In a PolygonSet as
/// documented above the winding number is 0 or -1 everywhere (outer rings wind -1, holes +1 and
/// lie inside their outer ring, islands lie inside holes), so NonZero and EvenOdd give the same
/// region. NonZero is the one used, so that a PolygonSet means the same everywhere: it is what
/// rasterize(set), and with it the mask checks, fill. (The choice only shows on hand-made sets
/// that break the rules above: NonZero reads overlapping polygons as their union.)
constexpr FillRule kPolygonSetFillRule = FillRule::NonZero;

/// Signed shoelace area of a closed path: positive when it winds +1 (see conventions above).
double signedArea(const Path& path);

}  // namespace roiclip
