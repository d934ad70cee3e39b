// SPDX-License-Identifier: MIT
// roiclip private header: a strictly convex ring's sides, to classify grid points against all of
// them at once (simple_convex.cpp and convex_groups.cpp).
#pragma once

#include <algorithm>
#include <cstdint>
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
  int m = 0;
  IPoint lo, hi;  ///< the convex ring's bounding box
  SideLines(const std::vector<IPoint>& convex, int orientation)
      : m(int(convex.size())), lo(convex[0]), hi(convex[0]) {
    const CcwRing c{&convex, orientation < 0};
    for (int j = 0; j < m; ++j) {
      const IPoint a = c[j], b = c[(j + 1) % m];
      dir[j] = {b.x - a.x, b.y - a.y};
      at[j] = dir[j].x * a.y - dir[j].y * a.x;
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
  /// classify() for points known to lie strictly left of the sides in `strictlyLeft` (the
  /// vertices of a ring whose bounding box does): only the other sides are asked, mostly one or
  /// two of a hull's; the known ones come back set in `left`.
  struct OtherSides {
    IPoint dir[kMaxSides];
    std::int64_t at[kMaxSides];
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
  };
  [[nodiscard]] OtherSides otherThan(unsigned strictlyLeft) const {
    OtherSides o;
    o.known = strictlyLeft;
    for (int j = 0; j < m; ++j) {
      if ((strictlyLeft >> j & 1U) != 0) continue;
      o.dir[o.count] = dir[j];
      o.at[o.count] = at[j];
      o.bit[o.count++] = 1U << j;
    }
    return o;
  }
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
