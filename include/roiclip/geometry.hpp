// SPDX-License-Identifier: MIT
// roiclip: public geometry types. Includes only the standard library and GLM.
//
// Conventions (the same everywhere in roiclip):
// - Image coordinates: x to the right, y DOWN, in pixels; (0,0) is the centre of the top-left
//   pixel, as in OpenCV. Map coordinates (UTM metres, longitude/latitude) work the same way.
// - Coordinates are snapped to an integer grid: a point's grid units are
//   round(coordinate * scale) - origin * scale (nearest integer, ties to even), and they must lie
//   within +-Grid::kMaxUnits (2^30) of the origin. By default (Grid::fitted()) each call fits the
//   grid to the bounding box of all its operands: the origin is a grid point near the box's
//   centre and the scale the largest power of two that keeps the box inside that range; when
//   that grid would move a coordinate but every coordinate is the double nearest a decimal with
//   at most k decimals (as parsed from text: UTM 512345.6789, degrees 13.4049541), the scale is
//   10^k instead (the smallest such k whose grid holds the box). So any finite double input is
//   accepted wherever it lies, integer (pixel) and binary-fraction coordinates stay exact, such
//   decimals are held as the decimals themselves (each moves by at most half an ulp, from the
//   double to its decimal), and no other coordinate moves by more than half a grid step, about
//   2^-31 of the box's larger side (docs/algorithm.md, "Grid", has the bound).
//   Grid::fixed(scale) keeps one grid for every call (bit-identical snapping across calls;
//   |coordinate * scale| <= 2^30). Every topological decision after snapping is exact.
// - Output vertices are exact points (input vertices or crossings of input edges) rounded once:
//   each coordinate is the double nearest its exact value (ties to even), so equal exact points
//   always give equal doubles.
// - Winding numbers are the mathematical ones computed on the raw (x, y) numbers: a path whose
//   shoelace sum  sum(x_i*y_{i+1} - x_{i+1}*y_i)  is positive winds +1 around its interior.
//   On screen (y down) such a path runs clockwise.
// - Output orientation matches cv::findContours: outer rings have a NEGATIVE shoelace sum
//   (counter-clockwise on screen, cv::contourArea(c, true) < 0) and holes a POSITIVE one.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
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

namespace detail {
/// The nearest integer to u, ties to even (Grid::toUnits()). Adding and subtracting 1.5 * 2^52
/// rounds any |u| < 2^51 exactly in the default rounding mode, without a libm call; larger
/// doubles go through nearbyint (from 2^52 on they are integers already).
inline double roundToUnits(double u) {
  constexpr double kRound = 6755399441055744.0;  // 1.5 * 2^52
  // Not algebraically simplified: without -ffast-math the compiler keeps IEEE semantics.
  if (std::fabs(u) < 0x1p51) return (u + kRound) - kRound;
  return std::nearbyint(u);
}
}  // namespace detail

/// The integer grid every input coordinate is snapped to (see the conventions above).
struct Grid {
  /// Largest allowed |grid units| of a coordinate, counted from the origin.
  static constexpr std::int64_t kMaxUnits = std::int64_t{1} << 30;
  /// Grid units per coordinate unit; 0 (the default) means fitted: every call chooses the scale
  /// and origin for its operands (a power of two, or 10^k for decimal data, see the
  /// conventions). A fixed scale must be positive and finite; a power of two keeps snapping exact
  /// for pixel and half-pixel coordinates, and 10^k (k <= 22) for doubles nearest to decimals
  /// with at most k decimals while |v| * 10^k <= 2^50.
  double scale = 0.0;
  /// The grid point units are counted from. It must lie on the grid (origin * scale an integer,
  /// of magnitude at most 2^100). Ignored while the grid is fitted.
  Point origin{0.0, 0.0};

  /// The default: fitted to each call's operands.
  static Grid fitted() { return {}; }
  /// One grid for every call: `scale` units per coordinate unit, counted from `origin`.
  static Grid fixed(double scale, Point origin = {0.0, 0.0}) {
    Grid grid;
    grid.scale = scale;
    grid.origin = origin;
    return grid;
  }
  /// True for a fitted grid (scale 0).
  [[nodiscard]] bool isFitted() const { return scale == 0.0; }

  /// The snapping rule, the one used everywhere (core, rasteriser, io's snap check): the grid
  /// units of a coordinate on a fixed (or resolved, resolveGrid()) grid,
  /// round(v * scale) - originCoordinate * scale, rounded to the nearest integer, ties to even.
  /// `originCoordinate` is origin.x for x and origin.y for y.
  /// @return nullopt when v is not finite or its units lie beyond +-kMaxUnits.
  [[nodiscard]] std::optional<std::int64_t> toUnits(double v, double originCoordinate) const;
  /// The coordinate of grid unit `units` (origin + units / scale), correctly rounded.
  [[nodiscard]] double toCoordinate(std::int64_t units, double originCoordinate) const;
};

inline std::optional<std::int64_t> Grid::toUnits(double v, double originCoordinate) const {
  const double r = detail::roundToUnits(v * scale);
  // Both are integers, so the difference is exact whenever it is below 2^53, and so is the range
  // test. Infinity and NaN fail it.
  const double d = r - originCoordinate * scale;
  if (!(std::fabs(d) <= double(kMaxUnits))) return std::nullopt;
  return std::int64_t(d);
}

/// The grid a call with these operands snaps to: `grid` itself when it is fixed, else the grid
/// fitted to the bounding box of every finite vertex of `subject` and `clip` together: the
/// power-of-two grid when it holds every coordinate exactly, else the decimal grid (scale 10^k,
/// the smallest k from 0 to 22) that does, if one fits the box, else the power-of-two grid.
/// @throws InvalidInputError when a fixed grid is invalid (scale not positive and finite, origin
///         off the grid) or the box is too large for doubles (its side overflows).
Grid resolveGrid(const Grid& grid, const Paths& subject, const Paths& clip = {});

/// How much work one call may do before it gives up with ResourceLimitError (error.hpp), checked
/// as the work is found, before its memory is taken.
struct Limits {
  /// No limit.
  static constexpr std::uint64_t kUnlimited = std::numeric_limits<std::uint64_t>::max();
  /// The crossing budget roiclip's tools set by default (the CLI per call, `roiclip run` per
  /// clip of an image): at 200 to 320 bytes per crossing, about 5 to 8 GB.
  static constexpr std::uint64_t kToolMaxCrossings = 25'000'000;
  /// Crossings of edges the sweep may find (each costs about 200 to 320 bytes while the call
  /// runs). Unlimited by default in the library; the CLI and `roiclip run` set 25,000,000.
  std::uint64_t maxCrossings = kUnlimited;
};

/// The numeric set-up of a call: the grid and the work limits. A Grid converts to Options (no
/// limits), so every function that takes Options also takes a Grid.
struct Options {
  Grid grid;      ///< the snapping grid (fitted by default)
  Limits limits;  ///< the work budget (unlimited by default)
  /// A fitted grid, no limits.
  Options() = default;
  /// `g` with `l` (implicit, so that a Grid can be passed where Options are taken).
  Options(const Grid& g, const Limits& l = {})  // NOLINT(google-explicit-constructor)
      : grid(g), limits(l) {}
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
