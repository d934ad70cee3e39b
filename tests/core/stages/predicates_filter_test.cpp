// SPDX-License-Identifier: MIT
// The floating-point filters of src/core/predicates.hpp at their boundary: coordinates near the
// grid's range 2^30 and crossings with huge W, where the filter must abstain and the exact
// arithmetic decide. Every answer is checked against exact rationals (Boost.Multiprecision).
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include <boost/multiprecision/cpp_int.hpp>

#include <roiclip/roiclip.hpp>

#include "predicates.hpp"
#include "support/oracle.hpp"

namespace roiclip::detail {
namespace {

using Rational = boost::multiprecision::cpp_rational;
using Int = boost::multiprecision::cpp_int;

constexpr std::int64_t kMax = Grid::kMaxUnits;

Int big(i128 v) {
  const bool negative = v < 0;
  unsigned __int128 u =
      negative ? static_cast<unsigned __int128>(-(v + 1)) + 1u : static_cast<unsigned __int128>(v);
  Int r = Int(static_cast<std::uint64_t>(u >> 64)) << 64;
  r += Int(static_cast<std::uint64_t>(u));
  return negative ? Int(-r) : r;
}
Rational xOf(const XPoint& p) { return Rational(big(p.x), big(p.w)); }
Rational yOf(const XPoint& p) { return Rational(big(p.y), big(p.w)); }
int sign(const Rational& v) { return v.sign(); }
int exactCompare(const XPoint& a, const XPoint& b) {
  const int cx = sign(xOf(a) - xOf(b));
  return cx != 0 ? cx : sign(yOf(a) - yOf(b));
}
int exactOrient(IPoint a, IPoint b, const XPoint& c) {
  const Rational ux = b.x - a.x, uy = b.y - a.y;
  return sign(ux * (yOf(c) - a.y) - uy * (xOf(c) - a.x));
}

// A random crossing of two segments within the grid's range near its corner (2^30, 2^30):
// long segments with nearly parallel directions give W up to about 2^62.
bool randomCrossing(std::mt19937_64& rng, XPoint& out) {
  std::uniform_int_distribution<std::int64_t> near(kMax - 4096, kMax);
  std::uniform_int_distribution<std::int64_t> far(-kMax, -kMax + 4096);
  const IPoint a{far(rng), far(rng)}, b{near(rng), near(rng)};
  const IPoint c{far(rng), near(rng) - 8192}, d{near(rng), far(rng) + 8192};
  return lineIntersection(a, b, c, d, out);
}

TEST(PredicateFilters, InBoxCompareAbstainsOnNearTies) {
  // Two crossings whose x differ by about 1 / W^2 right at the grid's edge: the doubles agree
  // to the last bit, the filter must abstain, and compare() must still order them.
  const IPoint a{-kMax, -kMax}, b{kMax, kMax - 1};
  XPoint p, q;
  ASSERT_TRUE(lineIntersection(a, b, {kMax - 1, -kMax}, {kMax, kMax}, p));
  ASSERT_TRUE(lineIntersection(a, b, {kMax - 1, -kMax + 1}, {kMax, kMax}, q));
  ASSERT_NE(p.w, 1);
  ASSERT_NE(exactCompare(p, q), 0);
  EXPECT_EQ(compareCachedInBox(p.fx, q.fx), 0);
  EXPECT_EQ(compare(p, q), exactCompare(p, q));
  EXPECT_EQ(compare(q, p), -exactCompare(p, q));
  // Both on the line a-b: exactly collinear, which only the exact path can say.
  EXPECT_EQ(orient(a, b, p), 0);
  EXPECT_EQ(orient(a, b, q), 0);
  EXPECT_EQ(orient({kMax - 1, -kMax}, {kMax, kMax}, q),
            exactOrient({kMax - 1, -kMax}, {kMax, kMax}, q));
}

TEST(PredicateFilters, InBoxCompareMatchesRationalsNearTheEdge) {
  std::mt19937_64 rng(20261202);
  int decided = 0, abstained = 0;
  for (int i = 0; i < 4000; ++i) {
    XPoint p, q;
    if (!randomCrossing(rng, p) || !randomCrossing(rng, q)) continue;
    // A near tie too: q moved by one grid step along y only, same x.
    const XPoint r(p.x, p.y + p.w, p.w);
    for (const XPoint* other : {static_cast<const XPoint*>(&q), &r}) {
      const int exact = sign(xOf(p) - xOf(*other));
      const int filtered = compareCachedInBox(p.fx, other->fx);
      if (filtered != 0) {
        ++decided;
        EXPECT_EQ(filtered, exact) << i;
      } else {
        ++abstained;
      }
      EXPECT_EQ(compare(p, *other), exactCompare(p, *other)) << i;
    }
  }
  EXPECT_GT(decided, 3000);    // the filter does decide most pairs
  EXPECT_GT(abstained, 3000);  // and abstains on every same-x pair
}

TEST(PredicateFilters, EqualDenominatorsCompareNumerators) {
  EXPECT_EQ(compare(XPoint(5, 1, 7), XPoint(5, 2, 7)), -1);
  EXPECT_EQ(compare(XPoint(-5, 1, 7), XPoint(-6, 9, 7)), 1);
  EXPECT_EQ(compare(XPoint(-5, 1, 7), XPoint(-5, 1, 7)), 0);
  // The same rational in two representations: equal through the filtered path.
  EXPECT_EQ(compare(XPoint(3, -5, 7), XPoint(6, -10, 14)), 0);
  const i128 w = i128(1) << 62;
  EXPECT_EQ(compare(XPoint(i128(kMax) * w - 1, 0, w), XPoint(i128(kMax) * w - 2, 0, w)), 1);
}

TEST(PredicateFilters, CrossingCachesTheConstructorsDoubles) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 2000; ++i) {
    XPoint p;
    if (!randomCrossing(rng, p)) continue;
    const XPoint q(p.x, p.y, p.w);
    EXPECT_EQ(p.fx, q.fx);
    EXPECT_EQ(p.fy, q.fy);
    // And the crossing lies exactly inside the grid's range, as compareCachedInBox() assumes.
    EXPECT_LE(abs(xOf(p)), Rational(kMax));
    EXPECT_LE(abs(yOf(p)), Rational(kMax));
  }
}

TEST(PredicateFilters, OrientOfCrossingsNearTheirLines) {
  // Points a tiny distance off a long line (a neighbouring crossing one grid step away).
  std::mt19937_64 rng(11);
  int zero = 0;
  for (int i = 0; i < 2000; ++i) {
    std::uniform_int_distribution<std::int64_t> any(-kMax, kMax);
    const IPoint a{any(rng), any(rng)}, b{any(rng), any(rng)}, c{any(rng), any(rng)};
    const IPoint d{c.x + (i % 3) - 1, c.y + 1 - (i % 2) * 2};  // a short segment near c
    XPoint x;
    if (!lineIntersection(a, b, c, d, x)) continue;
    EXPECT_EQ(orient(a, b, x), 0);
    const IPoint a2{a.x, a.y + 1};  // the same line moved one unit: x is just off it
    EXPECT_EQ(orient(a2, b, x), exactOrient(a2, b, x)) << i;
    zero += orient(a2, b, x) == 0;
  }
  EXPECT_LT(zero, 2000);
}

// segmentCrossing() (the sweep's crossing test, three cross products) gives the answer of the
// four orientation tests and lineIntersection() it replaced, on segments of a small grid (shared
// ends, collinear and parallel pairs, touching ends, T junctions) and at the grid's range (the
// cross products near 2^63).
TEST(PredicateFilters, SegmentCrossingMatchesFourOrientationsAndLineIntersection) {
  std::mt19937_64 rng(13);
  int crossing = 0, rejected = 0, touching = 0;
  for (int i = 0; i < 40000; ++i) {
    const std::int64_t range = i % 2 == 0 ? 4 : kMax;
    std::uniform_int_distribution<std::int64_t> any(-range, range);
    const IPoint a{any(rng), any(rng)}, b{any(rng), any(rng)}, c{any(rng), any(rng)},
        d{any(rng), any(rng)};
    const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a),
              o4 = orient(c, d, b);
    XPoint expected;
    const bool meets = !(o1 * o2 > 0 || (o1 == 0 && o2 == 0)) && o3 * o4 <= 0 &&
                       lineIntersection(a, b, c, d, expected);
    XPoint got;
    ASSERT_EQ(segmentCrossing(a, b, c, d, got), meets) << i;
    if (!meets) {
      ++rejected;
      continue;
    }
    ++crossing;
    touching += o1 * o2 * o3 * o4 == 0;
    EXPECT_TRUE(got.x == expected.x && got.y == expected.y && got.w == expected.w) << i;
    EXPECT_EQ(got.fx, expected.fx);
    EXPECT_EQ(got.fy, expected.fy);
  }
  EXPECT_GT(crossing, 1000);
  EXPECT_GT(rejected, 1000);
  EXPECT_GT(touching, 100);
}

// The sweep on crossings far from the origin: the same random polygons simplified near the
// origin and translated by about 4 million pixels (close to the grid's range at the default
// scale) give the same arrangement: the event order near ties is exact, not a filter's guess.
TEST(PredicateFilters, SweepFarFromTheOriginMatchesNearIt) {
  std::mt19937 rng(5);
  for (int round = 0; round < 6; ++round) {
    const Path near = testing::randomPolygon(rng, 60, 150000);
    for (const double shift : {4.0e6, -4.0e6}) {
      Path far = near;
      for (Point& p : far) p += Point(shift, round % 2 == 0 ? shift : -shift);
      for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
        SCOPED_TRACE(std::to_string(round) + " " + std::to_string(shift) + " " + toString(rule));
        const PolygonSet a = simplify(Paths{near}, rule), b = simplify(Paths{far}, rule);
        ASSERT_EQ(a.polygons.size(), b.polygons.size());
        std::size_t va = 0, vb = 0;
        for (const Polygon& p : a.polygons) va += p.outer.size() + p.holes.size();
        for (const Polygon& p : b.polygons) vb += p.outer.size() + p.holes.size();
        EXPECT_EQ(va, vb);
        EXPECT_NEAR(b.area(), a.area(), 1e-9 * a.area());
      }
    }
  }
}

}  // namespace
}  // namespace roiclip::detail
