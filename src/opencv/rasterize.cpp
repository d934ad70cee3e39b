// SPDX-License-Identifier: MIT
// Exact scanline rasteriser: pixel centres against snapped paths, any fill rule.
#include <roiclip/opencv/rasterize.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace roiclip::opencv {
namespace {

using i128 = __int128;

// The core's snapping rule (Grid::toUnits()); the grid's origin is (0, 0).
std::int64_t snap(double v, const Grid& grid, const char* axis, std::size_t path,
                  std::size_t vertex) {
  const std::optional<std::int64_t> units = grid.toUnits(v, 0.0);
  if (units) return *units;
  const std::string where =
      "rasterize: path " + std::to_string(path) + ", vertex " + std::to_string(vertex) + ": ";
  if (!std::isfinite(v)) throw InvalidInputError(where + axis + " is not a finite number");
  throw InvalidInputError(where + axis + " = " + std::to_string(v) +
                          " is outside the supported range");
}

// Smallest integer >= n / d for d > 0.
std::int64_t ceilDiv(i128 n, i128 d) {
  const i128 q = n / d;
  return std::int64_t((n % d != 0 && n > 0) ? q + 1 : q);
}

struct Crossing {
  int row;
  int col;    // first column whose centre lies right of (or on) the crossing
  int delta;  // change of the winding number from left to right of the crossing
  bool operator<(const Crossing& o) const { return row < o.row || (row == o.row && col < o.col); }
};

}  // namespace

cv::Mat rasterize(const Paths& paths, FillRule rule, cv::Size size, const Grid& requested) {
  const Grid grid = requested.isFitted() ? kRasterGrid : requested;
  if (grid.origin != Point(0.0, 0.0)) {
    throw InvalidInputError("rasterize: the grid's origin must be (0, 0)");
  }
  if (!(grid.scale >= 1.0 && grid.scale <= 65536.0 && grid.scale == std::floor(grid.scale))) {
    throw InvalidInputError("rasterize: grid scale must be an integer in 1..65536, got " +
                            std::to_string(grid.scale));
  }
  if (size.width < 0 || size.height < 0) {
    throw InvalidInputError("rasterize: negative image size");
  }
  cv::Mat mask(size, CV_8UC1, cv::Scalar(0));
  if (size.width == 0 || size.height == 0) return mask;
  const std::int64_t s = std::int64_t(grid.scale);

  std::vector<Crossing> crossings;
  std::vector<std::pair<std::int64_t, std::int64_t>> ring;
  for (std::size_t p = 0; p < paths.size(); ++p) {
    ring.clear();
    for (std::size_t v = 0; v < paths[p].size(); ++v) {
      ring.emplace_back(snap(paths[p][v].x, grid, "x", p, v), snap(paths[p][v].y, grid, "y", p, v));
    }
    for (std::size_t v = 0; v < ring.size(); ++v) {
      auto [x0, y0] = ring[v];
      auto [x1, y1] = ring[(v + 1) % ring.size()];
      if (y0 == y1) continue;  // horizontal edges cross no row at the perturbed height row + e
      // Seen from the left, an edge running down the image (y increasing) lowers the winding
      // number, one running up raises it (positive shoelace sum = winding +1).
      int delta = -1;
      if (y0 > y1) {
        std::swap(x0, x1);
        std::swap(y0, y1);
        delta = +1;
      }
      // Rows r with y0 <= r*s < y1: the half-open span is the "+ e" of the documented rule.
      const std::int64_t firstRow = std::max<std::int64_t>(ceilDiv(y0, s), 0);
      const std::int64_t lastRow = std::min<std::int64_t>(ceilDiv(y1, s) - 1, size.height - 1);
      const i128 dy = y1 - y0;
      for (std::int64_t r = firstRow; r <= lastRow; ++r) {
        // Crossing x = x0 + (r*s - y0) * (x1 - x0) / dy; the pixel column c counts when
        // c*s >= x (the "+ d" of the rule puts centres on the edge to its right).
        const i128 num = i128(x0) * dy + i128(r * s - y0) * (x1 - x0);
        const std::int64_t col = ceilDiv(num, dy * s);
        if (col >= size.width) {
          continue;
        }
        crossings.push_back({int(r), int(std::max<std::int64_t>(col, 0)), delta});
      }
    }
  }
  std::sort(crossings.begin(), crossings.end());

  for (std::size_t i = 0; i < crossings.size();) {
    const int row = crossings[i].row;
    auto* line = mask.ptr<std::uint8_t>(row);
    long long w = 0;
    while (i < crossings.size() && crossings[i].row == row) {
      const int col = crossings[i].col;
      while (i < crossings.size() && crossings[i].row == row && crossings[i].col == col) {
        w += crossings[i].delta;
        ++i;
      }
      const int end =
          (i < crossings.size() && crossings[i].row == row) ? crossings[i].col : size.width;
      if (isFilled(rule, w)) std::fill(line + col, line + end, std::uint8_t(255));
    }
  }
  return mask;
}

cv::Mat rasterize(const PolygonSet& set, cv::Size size, const Grid& grid) {
  return rasterize(set.toPaths(), kPolygonSetFillRule, size, grid);
}

}  // namespace roiclip::opencv
