// SPDX-License-Identifier: MIT
// roiclip private header: a strictly convex ring's sides, to classify grid points against all of
// them at once (simple_convex.cpp and convex_groups.cpp).
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <type_traits>
#include <utility>
#include <vector>

#include "pipeline.hpp"
#include "predicates.hpp"

namespace roiclip::detail {

/// Ring access in counter-clockwise order.
struct CcwRing {
  const std::vector<IPoint>* ring;
  bool reversed;
  [[nodiscard]] int size() const { return int(ring->size()); }
  [[nodiscard]] IPoint operator[](int k) const {
    const int n = size();
    return (*ring)[std::size_t(reversed ? n - 1 - k : k)];
  }
};

/// The most sides SideLines takes (one bit each in a mask).
constexpr int kMaxSides = 30;

/// Whether the box [aLo, aHi] lies at or beyond an extreme x or y of the box [bLo, bHi].
inline bool boxesApart(IPoint aLo, IPoint aHi, IPoint bLo, IPoint bHi) {
  return aHi.x <= bLo.x || aLo.x >= bHi.x || aHi.y <= bLo.y || aLo.y >= bHi.y;
}

/// The side lines of a convex ring taken counter-clockwise, each as its direction and the cross
/// product of its direction with its start, to classify points against all of them (orientInGrid()
/// with what depends on the side alone taken once: two products and a comparison a side). At most
/// kMaxSides sides.
struct SideLines {
  /// Side j runs from corner j in direction dir[j]; a point p lies left of it when
  /// dir[j] x p = dir[j].x p.y - dir[j].y p.x exceeds at[j] = dir[j] x corner j. Every grid point
  /// lies within 2^30 units of the origin, so |dir| <= 2^31, each product is below 2^61 and both
  /// sides of the comparison fit int64: the same test as dir[j] x (p - corner j) > 0.
  IPoint dir[kMaxSides];
  std::int64_t at[kMaxSides];
  /// 1 / (|dir.x| + |dir.y|): a step of L-infinity length s moves dir x p by at most
  /// s (|dir.x| + |dir.y|) (classify() with a reach).
  double perStep[kMaxSides];
  int m = 0;
  IPoint lo, hi;  ///< the convex ring's bounding box
  SideLines(const std::vector<IPoint>& convex, int orientation)
      : m(int(convex.size())), lo(convex[0]), hi(convex[0]) {
    const CcwRing c{&convex, orientation < 0};
    for (int j = 0; j < m; ++j) {
      const IPoint a = c[j], b = c[(j + 1) % m];
      dir[j] = {b.x - a.x, b.y - a.y};
      at[j] = dir[j].x * a.y - dir[j].y * a.x;
      perStep[j] = 1.0 / double(std::abs(dir[j].x) + std::abs(dir[j].y));
      lo = {std::min(lo.x, a.x), std::min(lo.y, a.y)};
      hi = {std::max(hi.x, a.x), std::max(hi.y, a.y)};
    }
  }
  [[nodiscard]] unsigned all() const { return (1U << m) - 1; }
  struct Masks {
    unsigned left = 0;   ///< bit j: strictly left of side j
    unsigned zeros = 0;  ///< bit j: on the line of side j
  };
  /// kSides > 0: the number of sides known when compiling (m must equal it), for the loop over
  /// a ring's vertices; 0: m.
  template <int kSides = 0>
  [[nodiscard]] Masks classify(IPoint p) const {
    const int count = kSides > 0 ? kSides : m;
    unsigned left = 0, zeros = 0;
    for (int j = 0; j < count; ++j) {
      const std::int64_t v = dir[j].x * p.y - dir[j].y * p.x;
      left |= unsigned(v > at[j]) << j;
      zeros |= unsigned(v == at[j]) << j;
    }
    return {left, zeros};
  }
  /// classify(), and in `reach` how far p lies from the nearest side line in steps (see
  /// reachOf()): every point a path of L-infinity length up to `reach` away gets p's masks.
  template <int kSides = 0>
  [[nodiscard]] Masks classify(IPoint p, std::int64_t& reach) const {
    const int count = kSides > 0 ? kSides : m;
    unsigned left = 0, zeros = 0;
    double nearest = kFarSteps;
    for (int j = 0; j < count; ++j) {
      const std::int64_t d = dir[j].x * p.y - dir[j].y * p.x - at[j];
      left |= unsigned(d > 0) << j;
      zeros |= unsigned(d == 0) << j;
      nearest = std::min(nearest, double(d < 0 ? -d : d) * perStep[j]);
    }
    reach = reachOf(nearest);
    return {left, zeros};
  }
  /// classify() for points known to lie strictly left of the sides in `strictlyLeft` (the
  /// vertices of a ring whose bounding box does): only the other sides are asked, mostly one or
  /// two of a hull's; the known ones come back set in `left`.
  struct OtherSides {
    IPoint dir[kMaxSides];
    std::int64_t at[kMaxSides];
    double perStep[kMaxSides];
    unsigned bit[kMaxSides];
    int count = 0;
    unsigned known = 0;
    [[nodiscard]] Masks classify(IPoint p) const {
      unsigned left = known, zeros = 0;
      for (int i = 0; i < count; ++i) {
        const std::int64_t v = dir[i].x * p.y - dir[i].y * p.x;
        left |= v > at[i] ? bit[i] : 0U;
        zeros |= v == at[i] ? bit[i] : 0U;
      }
      return {left, zeros};
    }
    /// classify() with a reach, as SideLines::classify(p, reach) over the sides asked.
    [[nodiscard]] Masks classify(IPoint p, std::int64_t& reach) const {
      unsigned left = known, zeros = 0;
      double nearest = kFarSteps;
      for (int i = 0; i < count; ++i) {
        const std::int64_t d = dir[i].x * p.y - dir[i].y * p.x - at[i];
        left |= d > 0 ? bit[i] : 0U;
        zeros |= d == 0 ? bit[i] : 0U;
        nearest = std::min(nearest, double(d < 0 ? -d : d) * perStep[i]);
      }
      reach = reachOf(nearest);
      return {left, zeros};
    }
  };
  [[nodiscard]] OtherSides otherThan(unsigned strictlyLeft) const {
    OtherSides o;
    o.known = strictlyLeft;
    for (int j = 0; j < m; ++j) {
      if ((strictlyLeft >> j & 1U) != 0) continue;
      o.dir[o.count] = dir[j];
      o.at[o.count] = at[j];
      o.perStep[o.count] = perStep[j];
      o.bit[o.count++] = 1U << j;
    }
    return o;
  }
  /// The steps a classified point may move without changing its masks. `nearest` is the minimum
  /// over the sides of t_j = |d_j| / (|dir_j.x| + |dir_j.y|), where d_j = dir_j x p - at_j, as
  /// computed in doubles (three roundings: at most t_j (1 + 2^-51)). A path of L-infinity length
  /// s changes d_j by at most s (|dir_j.x| + |dir_j.y|), so every point on it has p's signs, none
  /// zero, while s < t_j for every j. Scaled down by 2^-40 (more than the rounding) the value is
  /// strictly below every t_j, and so is its floor. 0 when p lies on a side line: only a repeat
  /// of p takes its masks. The sides' |d_j| are below 2^63, so the reach is too.
  static std::int64_t reachOf(double nearest) { return std::int64_t(nearest * (1.0 - 0x1p-40)); }
  /// Where the minimum starts: no side asked (OtherSides of a box inside every side) leaves it,
  /// and every point gets the known masks. 2^63 (1 - 2^-40) fits int64.
  static constexpr double kFarSteps = 0x1p63;
  /// The sides that every corner of the box [lo, hi] lies strictly left of (all of them: the box
  /// lies inside the convex ring, which is convex), those every corner lies strictly right of
  /// (the box lies outside that side's line), and those some corner lies strictly left of (not
  /// all of them: the box lies in a side's closed outer half-plane). kSides as classify().
  struct BoxSides {
    unsigned left = 0, right = 0, someLeft = 0;
  };
  template <int kSides = 0>
  [[nodiscard]] BoxSides classifyBox(IPoint boxLo, IPoint boxHi) const {
    BoxSides box{all(), all(), 0};
    for (const IPoint corner : {boxLo, IPoint{boxHi.x, boxLo.y}, boxHi, IPoint{boxLo.x, boxHi.y}}) {
      const auto [left, zeros] = classify<kSides>(corner);
      box.left &= left;
      box.right &= ~(left | zeros);
      box.someLeft |= left;
    }
    return box;
  }
  /// Where the grid points of the box [lo, hi] lie (placeBox()): Outside when the box lies at or
  /// beyond the ring's extreme x or y, or in the closed outer half-plane of a side (either way a
  /// closed half-plane without a point inside the ring holds it); Inside when every corner lies
  /// strictly inside the ring; else Unknown. kSides as classify().
  template <int kSides = 0>
  [[nodiscard]] BoxPlace placeBox(IPoint boxLo, IPoint boxHi) const {
    if (boxesApart(boxLo, boxHi, lo, hi)) return BoxPlace::Outside;
    const BoxSides box = classifyBox<kSides>(boxLo, boxHi);
    return box.someLeft != all() ? BoxPlace::Outside
           : box.left == all()   ? BoxPlace::Inside
                                 : BoxPlace::Unknown;
  }
};

/// Classifies the points of a path in order, giving out(i, masks) for points[i]: a point is
/// classified (classify(point, reach)) only when the path has gone more than the reach of the
/// last classified point since it, in steps of max(|dx|, |dy|); the points in between get its
/// masks. Most vertices of a contour lie far from every side line of a region: they cost a step
/// and a comparison instead of two products a side.
template <class Classify, class Out>
void classifyPath(const IPoint* points, std::size_t n, const Classify& classify, Out&& out) {
  std::int64_t reach = -1, moved = 0;
  SideLines::Masks masks;
  IPoint last{};
  for (std::size_t i = 0; i < n; ++i) {
    const IPoint p = points[i];
    // Grid points lie within 2^30 of the origin: a step is at most 2^31, and `moved` is reset
    // once it exceeds the reach (below 2^63), or stays below 2^31 n without a reach (no side).
    moved += std::max(std::abs(p.x - last.x), std::abs(p.y - last.y));
    last = p;
    if (moved > reach) {
      masks = classify(p, reach);
      moved = 0;
    }
    out(i, masks);
  }
}

/// The most sides for which withSideCount() compiles a loop of its own.
constexpr int kUnrolledSides = 12;

/// Calls f(std::integral_constant<int, k>{}) with k = sides.m for 3 to kUnrolledSides sides (a
/// tag's quad, the hull of a few tags), so that classify<k>() unrolls its loop over the sides,
/// and with k = 0 (classify() over m sides) for more.
template <int kSides = 3, class F>
decltype(auto) withSideCount(const SideLines& sides, F&& f) {
  if constexpr (kSides > kUnrolledSides) {
    return f(std::integral_constant<int, 0>{});
  } else {
    if (sides.m == kSides) return f(std::integral_constant<int, kSides>{});
    return withSideCount<kSides + 1>(sides, std::forward<F>(f));
  }
}

}  // namespace roiclip::detail
