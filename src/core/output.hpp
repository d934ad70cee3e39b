// SPDX-License-Identifier: MIT
// roiclip private header: exact points back to doubles, correctly rounded (the output stage of
// nesting.cpp and clip_lines.cpp, and Grid::toCoordinate()).
#pragma once

#include <roiclip/geometry.hpp>

#include "predicates.hpp"

namespace roiclip::detail {

/// The double nearest to (num / den) * 2^exp2, ties to even (subnormal results included);
/// den > 0. Exact integer division and remainder, no floating-point step.
double nearestDouble(const i256& num, const i256& den, int exp2);

/// Converts exact grid points (X/W, Y/W) on a resolved grid (resolveGrid()) to coordinates:
/// each is the double nearest to (X/W) / scale + origin, so equal exact points give equal doubles
/// whichever segments they were computed from, and whether or not X/W is reduced.
class OutputFrame {
 public:
  /// `grid` must be resolved (fixed): its origin lies on it.
  explicit OutputFrame(const Grid& grid);
  /// The coordinate of units/w on the axis whose origin is originUnits (0: x, 1: y).
  [[nodiscard]] double coordinate(i128 units, i128 w, int axis) const;
  /// Both coordinates of an exact point.
  [[nodiscard]] Point point(const XPoint& p) const { return point(p.x, p.y, p.w); }
  [[nodiscard]] Point point(const ExactCoords& p) const { return point(p.x, p.y, p.w); }
  /// Both coordinates of (x/w, y/w).
  [[nodiscard]] Point point(i128 x, i128 y, i128 w) const {
    if (gridFast_) {
      // A grid point (within the grid's range, as every vertex), else mostly a crossing.
      if (w == 1) return point(IPoint{std::int64_t(x), std::int64_t(y)});
      Point out;
      if (offGridFast(x, y, w, out)) return out;
    }
    return {coordinate(x, w, 0), coordinate(y, w, 1)};
  }
  /// The point a + (num / den) d for a grid point a, |d.x|, |d.y| <= 2^31 and 0 < den < 2^63
  /// (a crossing by its parameter along a grid line: crossingParameter()), on a power-of-two
  /// grid (gridFast_): each coordinate's numerator (a + origin) den + d num in two 64-by-64-bit
  /// products, then one division. False elsewhere, or where a result is not a normal double.
  bool alongFast(IPoint a, IPoint d, std::int64_t num, std::int64_t den, Point& out) const;
  /// Whether grid points convert exactly (point(IPoint)): distinct ones give distinct doubles.
  [[nodiscard]] bool gridPointsExact() const { return gridFast_; }
  /// Both coordinates of a grid point.
  [[nodiscard]] Point point(IPoint p) const {
    if (gridFast_) {
      return {double(p.x + gridOrigin_[0]) * gridFactor_,
              double(p.y + gridOrigin_[1]) * gridFactor_};
    }
    return {coordinate(p.x, 1, 0), coordinate(p.y, 1, 1)};
  }

 private:
  /// point() on a power-of-two grid (gridFast_) for W in (1, 2^64) and |X|, |Y| < 2^100, as
  /// every crossing of two grid segments (W <= 2^63, |X| < 2^95): each coordinate's numerator
  /// X + origin W lies below 2^117, one division each (nearestNarrow()). False where a result
  /// is not a normal double.
  bool offGridFast(i128 x, i128 y, i128 w, Point& out) const;
  /// n / d * 2^-scaleExponent_ to the nearest double for |n| < 2^117, d in [1, 2^64): the fast
  /// grid's one division (nearestNarrow()); false where the result is not a normal double.
  bool quotientFast(i128 n, std::uint64_t d, double& v) const;
  /// coordinate() beyond its 64-bit fast paths: exact division in 128 or 256 bits.
  [[nodiscard]] double coordinateExact(i128 units, i128 w, i128 originUnits) const;

  i128 originUnits_[2] = {0, 0};  ///< origin * scale, exact (|.| <= 2^100)
  i128 scaleMantissa_ = 1;        ///< scale = scaleMantissa_ * 2^scaleExponent_, mantissa odd
  int scaleExponent_ = 0;
  /// Grid points the short way: on a power-of-two grid whose origin lies
  /// within 2^52 units of 0, a grid point's units plus the origin's stay below 2^53 (exact as a
  /// double), and times 2^-scaleExponent_ (a normal power of two whose products with such
  /// integers stay normal) the product is exact: the correctly rounded value, in three steps.
  bool gridFast_ = false;
  std::int64_t gridOrigin_[2] = {0, 0};
  double gridFactor_ = 1;
};

/// A ring as roiclip emits it: `pointAt(k)` for k = 0 .. n - 1 in output order (asked in
/// that order, once each, so a caller may step an index along instead), each point once
/// per run of equal doubles (distinct exact points may round to the same double), the closing
/// repeat of the first dropped. The caller drops a path of fewer than 3 points.
template <class PointAt>
Path outputRing(std::size_t n, PointAt pointAt) {
  Path path;
  path.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Point p = pointAt(k);
    if (path.empty() || p != path.back()) path.push_back(p);
  }
  while (path.size() > 1 && path.back() == path.front()) path.pop_back();
  return path;
}

}  // namespace roiclip::detail
