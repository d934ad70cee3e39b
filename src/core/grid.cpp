// SPDX-License-Identifier: MIT
// The grid: the one snapping rule (Grid::toUnits) and the grid fitted to a call's operands
// (resolveGrid). docs/algorithm.md, "Grid", states the guarantee and its error bound.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <roiclip/roiclip.hpp>

#include "pipeline.hpp"

namespace roiclip {
namespace {

constexpr double kMaxOriginUnits = 0x1p100;  // |origin * scale|: the output stage's bit budget

inline double roundUnits(double u) { return detail::roundToUnits(u); }

void checkFixed(const Grid& grid) {
  if (!(grid.scale > 0.0) || !std::isfinite(grid.scale)) {
    throw InvalidInputError("grid scale must be positive and finite, got " +
                            std::to_string(grid.scale));
  }
  for (const double o : {grid.origin.x * grid.scale, grid.origin.y * grid.scale}) {
    if (!(std::fabs(o) <= kMaxOriginUnits) || o != std::floor(o)) {
      throw InvalidInputError(
          "grid origin must lie on the grid (origin * scale an integer of "
          "magnitude at most 2^100)");
    }
  }
}

// The origin units of one axis: the grid point nearest the middle of [lo, hi] at scale s.
double middleUnits(double lo, double hi, double s) {
  return roundUnits(roundUnits(lo * s) * 0.5 + roundUnits(hi * s) * 0.5);
}

}  // namespace

Grid resolveGrid(const Grid& grid, const Paths& subject, const Paths& clip) {
  if (!grid.isFitted()) {
    checkFixed(grid);
    return grid;
  }
  detail::Box box;
  box.add(subject);
  box.add(clip);
  if (box.empty()) return Grid::fixed(1.0);
  const double extent = std::max(box.maxX - box.minX, box.maxY - box.minY);
  if (!std::isfinite(extent)) {
    throw InvalidInputError("the input's bounding box (x " + std::to_string(box.minX) + " to " +
                            std::to_string(box.maxX) + ", y " + std::to_string(box.minY) + " to " +
                            std::to_string(box.maxY) +
                            ") is too large for doubles: its side overflows");
  }
  const double magnitude = std::max(
      {std::fabs(box.minX), std::fabs(box.maxX), std::fabs(box.minY), std::fabs(box.maxY)});
  // A side of zero (all points on one line) would allow any scale; one that keeps the
  // coordinates' units below 2^92 keeps origin * scale within the output's bit budget. (Two
  // distinct doubles differ by at least 2^-54 of the larger, so this changes nothing otherwise.)
  double span = std::max(extent, magnitude * 0x1p-60);
  if (!(span > 0.0)) span = 1.0;
  // The largest power of two s with s * span <= 2^31 - 8: with the origin in the middle, every
  // coordinate lies within span * s / 2 + 1 <= 2^30 units of it.
  int exponent = std::ilogb((0x1p31 - 8.0) / span);
  exponent = std::clamp(exponent, -1022, 1000);
  for (;; --exponent) {
    const double s = std::ldexp(1.0, exponent);
    const Grid candidate = Grid::fixed(
        s, {middleUnits(box.minX, box.maxX, s) / s, middleUnits(box.minY, box.maxY, s) / s});
    // The corners in range means every coordinate is (rounding is monotonic). Only boxes a few
    // doubles wide, where the middle is not exact, ever need a second round.
    if (candidate.toUnits(box.minX, candidate.origin.x) &&
        candidate.toUnits(box.maxX, candidate.origin.x) &&
        candidate.toUnits(box.minY, candidate.origin.y) &&
        candidate.toUnits(box.maxY, candidate.origin.y)) {
      return candidate;
    }
  }
}

}  // namespace roiclip
