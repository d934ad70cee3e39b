// SPDX-License-Identifier: MIT
// Inputs at the limits of the core, built so that their vertex and crossing counts and their
// areas are known in closed form (nothing here calls roiclip). Shared by tests/core/limits_test
// (scaled down, with assertions) and bench/limits (full size, with time and memory figures).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include <roiclip/geometry.hpp>

namespace roiclip::testing {

/// A crenellated square: the square [0, W]^2 (W = 2m + 1) with m unit teeth sticking out of
/// each side at odd positions (bottom side: [2i+1, 2i+2] x [-1, 0]), like the pixel contour
/// cv::findContours returns for a blob with a ragged edge. Simple (no crossing), positive
/// shoelace sum, integer coordinates, 16m + 4 vertices, area W^2 + 4m.
struct Crenellated {
  std::int64_t m = 0;
  [[nodiscard]] std::int64_t side() const { return 2 * m + 1; }
  [[nodiscard]] std::size_t vertices() const { return static_cast<std::size_t>(16 * m + 4); }
  [[nodiscard]] double area() const {
    const double w = static_cast<double>(side());
    return w * w + 4.0 * static_cast<double>(m);
  }

  [[nodiscard]] Path path() const {
    const double w = static_cast<double>(side());
    Path bottom;
    bottom.reserve(static_cast<std::size_t>(4 * m + 1));
    bottom.emplace_back(0, 0);
    for (std::int64_t i = 0; i < m; ++i) {
      const double a = static_cast<double>(2 * i + 1), b = a + 1;
      bottom.insert(bottom.end(), {{a, 0}, {a, -1}, {b, -1}, {b, 0}});
    }
    // The shape is symmetric under a quarter turn about its centre: (x, y) -> (W - y, x) maps
    // the bottom side onto the right one, and so on round the square (counter-clockwise).
    Path out;
    out.reserve(vertices());
    Path side = bottom;
    for (int k = 0; k < 4; ++k) {
      out.insert(out.end(), side.begin(), side.end());
      for (Point& p : side) p = Point(w - p.y, p.x);
    }
    return out;
  }

  /// Area of the shape inside the axis-aligned box [x0, x1] x [y0, y1], summed over the
  /// disjoint unit and core squares the shape is made of.
  [[nodiscard]] double areaInBox(double x0, double y0, double x1, double y1) const {
    const auto overlap = [&](double ax, double ay, double bx, double by) {
      const double dx = std::min(bx, x1) - std::max(ax, x0);
      const double dy = std::min(by, y1) - std::max(ay, y0);
      return dx > 0 && dy > 0 ? dx * dy : 0.0;
    };
    const double w = static_cast<double>(side());
    double a = overlap(0, 0, w, w);
    for (std::int64_t i = 0; i < m; ++i) {
      const double lo = static_cast<double>(2 * i + 1), hi = lo + 1;
      a += overlap(lo, -1, hi, 0);             // bottom
      a += overlap(w, lo, w + 1, hi);          // right
      a += overlap(w - hi, w, w - lo, w + 1);  // top
      a += overlap(-1, w - hi, 0, w - lo);     // left
    }
    return a;
  }
};

/// Two combs in one closed path: comb A has a spine [-2, -1] x [0, L] and n horizontal teeth
/// [-1, L] x [2i+1, 2i+2]; comb B is A mirrored in the line y = x (spine below, n vertical
/// teeth). Every tooth of A crosses every tooth of B at 4 points, so the path crosses itself
/// exactly 4 n^2 times; L = 2n + 1. A segment from (-2, 0) to (0, -2) and back joins the combs
/// (it touches nothing else and encloses nothing). Both combs wind +1, so the n^2 unit squares
/// where teeth overlap wind 2: non-zero area |A| + |B| - n^2, even-odd area |A| + |B| - 2 n^2.
struct Combs {
  std::int64_t n = 0;
  [[nodiscard]] std::int64_t length() const { return 2 * n + 1; }
  [[nodiscard]] std::int64_t crossings() const { return 4 * n * n; }
  [[nodiscard]] double combArea() const {
    const double l = static_cast<double>(length());
    return l + static_cast<double>(n) * (l + 1);
  }
  [[nodiscard]] double nonZeroArea() const {
    return 2 * combArea() - static_cast<double>(n) * static_cast<double>(n);
  }
  [[nodiscard]] double evenOddArea() const {
    return 2 * combArea() - 2.0 * static_cast<double>(n) * static_cast<double>(n);
  }

  /// Comb A, counter-clockwise from (-2, 0).
  [[nodiscard]] Path combA() const {
    const double l = static_cast<double>(length());
    Path a;
    a.reserve(static_cast<std::size_t>(4 * n + 4));
    a.insert(a.end(), {{-2, 0}, {-1, 0}});
    for (std::int64_t i = 0; i < n; ++i) {
      const double lo = static_cast<double>(2 * i + 1), hi = lo + 1;
      a.insert(a.end(), {{-1, lo}, {l, lo}, {l, hi}, {-1, hi}});
    }
    a.insert(a.end(), {{-1, l}, {-2, l}});
    return a;
  }

  [[nodiscard]] Path path() const {
    const Path a = combA();
    // B: A mirrored in y = x (which reverses the winding), walked backwards to wind +1 again,
    // starting at the mirror image (0, -2) of A's start.
    Path b;
    b.reserve(a.size());
    b.emplace_back(a.front().y, a.front().x);
    for (auto it = a.rbegin(); it + 1 != a.rend(); ++it) b.emplace_back(it->y, it->x);
    Path out;
    out.reserve(2 * a.size() + 2);
    out.insert(out.end(), a.begin(), a.end());
    out.push_back(a.front());  // close A, then the joining segment to B's start
    out.insert(out.end(), b.begin(), b.end());
    out.push_back(b.front());  // close B; the closing edge runs back along the join
    return out;
  }
};

/// k nested axis-aligned squares of half-size 1..k around the origin, alternately wound +1 and
/// -1, so under non-zero every other annulus is a hole (the winding goes 0, 1, 0, 1, ...
/// inwards from outside when k is even). Area under non-zero (and even-odd) with k even:
/// sum over j = 1..k/2 of 4((2j)^2 - (2j - 1)^2).
inline Paths alternatingNestedSquares(int k) {
  Paths squares;
  for (int i = 1; i <= k; ++i) {
    const double s = i;
    Path sq = {{-s, -s}, {s, -s}, {s, s}, {-s, s}};  // positive shoelace sum
    if (i % 2 == 1) std::reverse(sq.begin(), sq.end());
    squares.push_back(std::move(sq));
  }
  return squares;
}

/// Area of alternatingNestedSquares(k) inside the centred box [-h, h]^2 (k even), for any h.
inline double nestedSquaresAreaInBox(int k, double h) {
  double a = 0;
  for (int j = 1; 2 * j <= k; ++j) {
    const double outer = std::min<double>(2 * j, h), inner = std::min<double>(2 * j - 1, h);
    a += 4 * (outer * outer - inner * inner);
  }
  return a;
}

}  // namespace roiclip::testing
