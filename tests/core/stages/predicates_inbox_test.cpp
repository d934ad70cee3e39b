// SPDX-License-Identifier: MIT
// The sweep's in-box filters (src/core/predicates.hpp): orientInBox() and compareInBox() against
// the exact answers (orientExact(), compareCoord()) on crossings of segments reaching the grid's
// range 2^30, near-degenerate on purpose: lines through the crossing itself (exactly 0, the
// filter must abstain), lines one unit off, and crossings of one segment with nearly parallel
// ones (near-equal points).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "predicates.hpp"

namespace roiclip::detail {
namespace {

constexpr std::int64_t kMax = Grid::kMaxUnits;

int exactOrient(IPoint a, IPoint b, const XPoint& c) {
  if (c.w == 1) return orient(a, b, IPoint{std::int64_t(c.x), std::int64_t(c.y)});
  return orientExact(a, b, c);
}

int exactCompare(const XPoint& a, const XPoint& b) {
  const int cx = compareCoord(a.x, a.w, b.x, b.w);
  return cx != 0 ? cx : compareCoord(a.y, a.w, b.y, b.w);
}

struct Crossings {
  std::vector<XPoint> points;
  std::vector<std::array<IPoint, 4>> lines;  // the two segments of each point
};

// Crossings of random segments with ends near the box's corners and edges, and of each with a
// few nearly parallel ones (one end moved by a unit).
Crossings randomCrossings(std::uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::int64_t> edge(kMax - 16, kMax);
  std::uniform_int_distribution<std::int64_t> any(-kMax, kMax);
  std::uniform_int_distribution<int> coin(0, 1);  // NOLINT: two draws per coordinate
  const auto coord = [&] {
    const std::int64_t v = coin(rng) ? edge(rng) : any(rng);
    return coin(rng) ? v : -v;
  };
  Crossings out;
  while (int(out.points.size()) < count) {
    const IPoint a{coord(), coord()}, b{coord(), coord()}, c{coord(), coord()};
    // A random segment, and two through the middle of a-b (the same point with other
    // denominators), clamped to the box.
    const auto clamp = [](IPoint p) {
      return IPoint{std::clamp(p.x, -kMax, kMax), std::clamp(p.y, -kMax, kMax)};
    };
    const std::array<std::array<IPoint, 2>, 3> others = {
        {{c, IPoint{coord(), coord()}},
         {clamp({a.x, a.y + 1}), clamp({b.x, b.y - 1})},
         {clamp({a.x, a.y + 2}), clamp({b.x, b.y - 2})}}};
    for (const auto& o : others) {
      XPoint x;
      if (segmentCrossing(a, b, o[0], o[1], x)) {
        out.points.push_back(x);
        out.lines.push_back({a, b, o[0], o[1]});
      }
    }
  }
  return out;
}

TEST(InBoxFilters, OrientAgreesWithExactNearDegenerateLines) {
  const Crossings cr = randomCrossings(4242, 3000);
  for (std::size_t i = 0; i < cr.points.size(); ++i) {
    const XPoint& x = cr.points[i];
    const auto& l = cr.lines[i];
    ASSERT_EQ(orientInBox(l[0], l[1], x), 0);  // on both of its lines
    ASSERT_EQ(orientInBox(l[2], l[3], x), 0);
    // Lines one unit off through the grid points around the crossing.
    for (const IPoint off : {IPoint{1, 0}, IPoint{0, 1}, IPoint{-1, 0}, IPoint{0, -1}}) {
      const IPoint a{l[0].x + off.x, l[0].y + off.y};
      if (std::abs(a.x) > kMax || std::abs(a.y) > kMax) continue;
      ASSERT_EQ(orientInBox(a, l[1], x), exactOrient(a, l[1], x)) << i;
      ASSERT_EQ(orientInBox(l[1], a, x), exactOrient(l[1], a, x)) << i;
    }
    for (std::size_t j = i + 1; j < std::min(cr.points.size(), i + 4); ++j) {
      const auto& m = cr.lines[j];
      ASSERT_EQ(orientInBox(m[0], m[1], x), exactOrient(m[0], m[1], x)) << i << " " << j;
    }
  }
}

TEST(InBoxFilters, CompareAgreesWithExactOnNearEqualPoints) {
  const Crossings cr = randomCrossings(777, 3000);
  for (std::size_t i = 0; i < cr.points.size(); ++i) {
    const XPoint& a = cr.points[i];
    ASSERT_EQ(compareInBox(a, a), 0);
    XPoint scaled = a;  // the same point with another denominator
    if (a.w < (i128(1) << 62)) {
      scaled.x *= 2, scaled.y *= 2, scaled.w *= 2;
      ASSERT_EQ(compareInBox(a, scaled), 0);
    }
    for (std::size_t j = i + 1; j < std::min(cr.points.size(), i + 6); ++j) {
      const XPoint& b = cr.points[j];
      ASSERT_EQ(compareInBox(a, b), exactCompare(a, b)) << i << " " << j;
      ASSERT_EQ(compareInBox(b, a), exactCompare(b, a)) << i << " " << j;
      ASSERT_EQ(compareInBox(a, b), compare(a, b)) << i << " " << j;
    }
    // Grid points right next to the crossing.
    const XPoint g(IPoint{std::int64_t(a.fx), std::int64_t(a.fy)});
    ASSERT_EQ(compareInBox(a, g), exactCompare(a, g)) << i;
    ASSERT_EQ(compareInBox(g, a), exactCompare(g, a)) << i;
  }
}

// compareInBoxCachedFirst() (the sweep's crossing test) asks the cached x before the
// denominators: the same answers on the same near-equal crossings, their copies with another
// denominator and the grid points next to them.
TEST(InBoxFilters, CachedFirstCompareAgreesWithExact) {
  const Crossings cr = randomCrossings(778, 3000);
  for (std::size_t i = 0; i < cr.points.size(); ++i) {
    const XPoint& a = cr.points[i];
    ASSERT_EQ(compareInBoxCachedFirst(a, a), 0);
    if (a.w < (i128(1) << 62)) {
      XPoint scaled = a;
      scaled.x *= 3, scaled.y *= 3, scaled.w *= 3;
      ASSERT_EQ(compareInBoxCachedFirst(a, scaled), 0);
    }
    for (std::size_t j = i + 1; j < std::min(cr.points.size(), i + 6); ++j) {
      const XPoint& b = cr.points[j];
      ASSERT_EQ(compareInBoxCachedFirst(a, b), exactCompare(a, b)) << i << " " << j;
      ASSERT_EQ(compareInBoxCachedFirst(b, a), exactCompare(b, a)) << i << " " << j;
    }
    const XPoint g(IPoint{std::int64_t(a.fx), std::int64_t(a.fy)});
    const XPoint h(IPoint{std::int64_t(a.fx), std::int64_t(a.fy) + 1});  // same x, above
    for (const XPoint& q : {g, h}) {
      ASSERT_EQ(compareInBoxCachedFirst(a, q), exactCompare(a, q)) << i;
      ASSERT_EQ(compareInBoxCachedFirst(q, a), exactCompare(q, a)) << i;
      ASSERT_EQ(compareInBoxCachedFirst(q, g), exactCompare(q, g)) << i;
    }
  }
}

}  // namespace
}  // namespace roiclip::detail
