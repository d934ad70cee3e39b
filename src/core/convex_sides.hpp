// SPDX-License-Identifier: MIT
// roiclip private header: a strictly convex ring's sides, to classify grid points against all of
// them at once (simple_convex.cpp and convex_groups.cpp).
#pragma once

#include <cstdint>
#include <vector>

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

/// The side lines of a convex ring taken counter-clockwise, each as its start and direction, to
/// classify points against all of them (orientInGrid() with the differences taken once). At most
/// kMaxSides sides.
struct SideLines {
  IPoint start[kMaxSides], dir[kMaxSides];
  int m = 0;
  SideLines(const std::vector<IPoint>& convex, int orientation) : m(int(convex.size())) {
    const CcwRing c{&convex, orientation < 0};
    for (int j = 0; j < m; ++j) {
      start[j] = c[j];
      const IPoint b = c[(j + 1) % m];
      dir[j] = {b.x - start[j].x, b.y - start[j].y};
    }
  }
  [[nodiscard]] unsigned all() const { return (1U << m) - 1; }
  struct Masks {
    unsigned left = 0;   ///< bit j: strictly left of side j
    unsigned zeros = 0;  ///< bit j: on the line of side j
  };
  [[nodiscard]] Masks classify(IPoint p) const {
    unsigned left = 0, zeros = 0;
    for (int j = 0; j < m; ++j) {
      const std::int64_t l = dir[j].x * (p.y - start[j].y);
      const std::int64_t r = dir[j].y * (p.x - start[j].x);
      left |= unsigned(l > r) << j;
      zeros |= unsigned(l == r) << j;
    }
    return {left, zeros};
  }
};

}  // namespace roiclip::detail
