// SPDX-License-Identifier: MIT
// Output stage (output.hpp): exact points to doubles, correctly rounded. The reference is Boost's
// cpp_rational of the exact value, with the nearest double chosen here among convert_to<double>()
// and its two neighbours (ties to the even mantissa), so it does not rely on Boost rounding
// correctly.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <random>

#include <boost/multiprecision/cpp_int.hpp>

#include "output.hpp"
#include "stage_support.hpp"

namespace roiclip {
namespace {

using boost::multiprecision::cpp_rational;
using detail::i128;
using detail::IPoint;
using detail::XPoint;

// 2^n as a rational.
cpp_rational twoTo(int n) { return cpp_rational(boost::multiprecision::cpp_int(1) << n); }

cpp_rational rational(i128 v) { return cpp_rational(detail::wide(v)); }

// The double nearest to q, ties to even.
double nearest(const cpp_rational& q) {
  const double d = q.convert_to<double>();
  double best = d;
  cpp_rational bestErr = abs(q - cpp_rational(d));
  for (const double c : {std::nextafter(d, -INFINITY), std::nextafter(d, INFINITY)}) {
    const cpp_rational err = abs(q - cpp_rational(c));
    int e = 0;
    const bool cEven = (std::int64_t(std::ldexp(std::frexp(c, &e), 53)) & 1) == 0;
    if (err < bestErr || (err == bestErr && cEven)) {
      best = c;
      bestErr = err;
    }
  }
  return best;
}

// The exact coordinate (units / w) / scale + origin, as a rational.
cpp_rational exactCoordinate(i128 units, i128 w, const Grid& grid, double origin) {
  return rational(units) / rational(w) / cpp_rational(grid.scale) + cpp_rational(origin);
}

void expectCorrectlyRounded(const XPoint& p, const Grid& grid, const std::string& what) {
  const Point got = detail::OutputFrame(grid).point(p);
  EXPECT_EQ(got.x, nearest(exactCoordinate(p.x, p.w, grid, grid.origin.x))) << what;
  EXPECT_EQ(got.y, nearest(exactCoordinate(p.y, p.w, grid, grid.origin.y))) << what;
}

IPoint randomUnits(std::mt19937_64& rng, std::int64_t range) {
  std::uniform_int_distribution<std::int64_t> u(-range, range);
  return {u(rng), u(rng)};
}

const Grid kGrids[] = {
    Grid::fixed(256),                                      // pixels
    Grid::fixed(0x1p24, {512345.5, 5087776.25}),           // UTM, fitted-like
    Grid::fixed(0x1p35, {13.40625 + 0x1p-30, 52.515625}),  // lon/lat
    Grid::fixed(1000.0),                                   // a decimal (non power of two) scale
    Grid::fixed(0x1p-20, {0x1p40, -0x1p41}),               // coarse and far
};

TEST(StageOutput, CrossingsOfRandomSegmentsAreCorrectlyRounded) {
  std::mt19937_64 rng(21);
  int checked = 0;
  for (const Grid& grid : kGrids) {
    for (int i = 0; i < 3000; ++i) {
      // Short and long segments, in the whole +-2^30 range and near the origin.
      const std::int64_t range = i % 3 == 0 ? 1000 : Grid::kMaxUnits;
      const IPoint a = randomUnits(rng, range), b = randomUnits(rng, range);
      const IPoint c = randomUnits(rng, range), d = randomUnits(rng, range);
      XPoint x;
      if (!detail::lineIntersection(a, b, c, d, x)) continue;
      // lineIntersection gives the line crossing; off the segments is fine for rounding.
      expectCorrectlyRounded(x, grid, "grid " + std::to_string(grid.scale));
      ++checked;
    }
  }
  EXPECT_GT(checked, 14000);
}

// The arrangement's crossings convert from their lines' parameter (crossingParameter(),
// OutputFrame::alongFast()) without their exact coordinates: the same correctly rounded doubles
// as the exact point gives, on every power-of-two grid (the others take the exact point).
TEST(StageOutput, CrossingsByParameterAreCorrectlyRounded) {
  std::mt19937_64 rng(23);
  int checked = 0;
  for (const Grid& grid : kGrids) {
    const detail::OutputFrame frame(grid);
    for (int i = 0; i < 3000; ++i) {
      // The whole +-2^30 range (the range's corners among them), and short segments.
      const std::int64_t range = i % 3 == 0 ? 1000 : Grid::kMaxUnits;
      detail::GridSegment l1, l2;
      l1.setLine(randomUnits(rng, range), randomUnits(rng, range));
      l2.setLine(randomUnits(rng, range), randomUnits(rng, range));
      if (i % 100 == 1) {  // the diagonals of the range: W = 2^63, beyond the 64-bit route
        const std::int64_t k = Grid::kMaxUnits;
        l1.setLine({-k, -k}, {k, k});
        l2.setLine({-k, k}, {k, -k});
      }
      std::int64_t num = 0, den = 0;
      const bool narrow = detail::crossingParameter(l1, l2, num, den);
      if (i % 100 == 1) {
        EXPECT_FALSE(narrow);
      }
      if (!narrow) continue;
      Point p;
      if (!frame.alongFast(l1.lineA(), l1.direction(), num, den, p)) {
        EXPECT_FALSE(frame.gridPointsExact()) << "a power-of-two grid takes the fast route";
        continue;
      }
      const detail::ExactCoords x = detail::crossingOfLines(l1, l2);
      const XPoint exact(x.x, x.y, x.w);
      EXPECT_EQ(p.x, nearest(exactCoordinate(exact.x, exact.w, grid, grid.origin.x)));
      EXPECT_EQ(p.y, nearest(exactCoordinate(exact.y, exact.w, grid, grid.origin.y)));
      ++checked;
    }
  }
  EXPECT_GT(checked, 11000);
}

// The same exact crossing from different segment pairs (other ends on the same lines, so other
// unreduced X/W) gives the same doubles.
TEST(StageOutput, EqualCrossingsFromDifferentSegmentsGiveEqualDoubles) {
  std::mt19937_64 rng(22);
  for (const Grid& grid : kGrids) {
    const detail::OutputFrame frame(grid);
    for (int i = 0; i < 2000; ++i) {
      const IPoint a = randomUnits(rng, 1 << 20), b = randomUnits(rng, 1 << 20);
      const IPoint c = randomUnits(rng, 1 << 20), d = randomUnits(rng, 1 << 20);
      // Other segments on the same lines: a - k (b - a) .. b + m (b - a).
      const std::int64_t k = 1 + std::int64_t(rng() % 300), m = 1 + std::int64_t(rng() % 300);
      const IPoint a2{a.x - k * (b.x - a.x), a.y - k * (b.y - a.y)};
      const IPoint b2{b.x + m * (b.x - a.x), b.y + m * (b.y - a.y)};
      const IPoint c2{c.x - m * (d.x - c.x), c.y - m * (d.y - c.y)};
      XPoint x1, x2, x3;
      if (!detail::lineIntersection(a, b, c, d, x1)) continue;
      ASSERT_TRUE(detail::lineIntersection(a2, b2, c, d, x2));
      ASSERT_TRUE(detail::lineIntersection(c2, d, a2, b, x3));
      ASSERT_TRUE(detail::equal(x1, x2) && detail::equal(x1, x3));
      const Point p1 = frame.point(x1), p2 = frame.point(x2), p3 = frame.point(x3);
      EXPECT_EQ(p1.x, p2.x);
      EXPECT_EQ(p1.y, p2.y);
      EXPECT_EQ(p1.x, p3.x);
      EXPECT_EQ(p1.y, p3.y);
      expectCorrectlyRounded(x2, grid, "equal crossing " + std::to_string(i));
    }
  }
}

TEST(StageOutput, NearestDoubleRoundsHalfToEvenAndHandlesSubnormals) {
  using detail::i256;
  // 2^53 + 1 is a tie between 2^53 and 2^53 + 2: to even (2^53); 2^53 + 3 goes up to 2^53 + 4.
  EXPECT_EQ(detail::nearestDouble(i256(1) << 53 | 1, 1, 0), 0x1p53);
  EXPECT_EQ(detail::nearestDouble((i256(1) << 53) + 3, 1, 0), 0x1p53 + 4);
  // Ties inside a binade: 3 * 2^52 + 1 lies halfway between 3 * 2^52 (even
  // mantissa) and 3 * 2^52 + 2; 3 * 2^52 + 3 between + 2 (odd) and + 4 (even). Also as n / 5.
  const i256 three = i256(3) << 52;
  EXPECT_EQ(detail::nearestDouble(three + 1, 1, 0), 0x1.8p53);
  EXPECT_EQ(detail::nearestDouble(three + 3, 1, 0), 0x1.8p53 + 4);
  EXPECT_EQ(detail::nearestDouble((three + 1) * 5, 5, 0), 0x1.8p53);
  EXPECT_EQ(detail::nearestDouble(-(three + 3) * 5, 5, -3), -(0x1.8p53 + 4) / 8);
  EXPECT_EQ(detail::nearestDouble((three + 2) * 7 + 3, 7, 0), 0x1.8p53 + 2);
  // 1/3 and -2/3 as their nearest doubles.
  EXPECT_EQ(detail::nearestDouble(1, 3, 0), 1.0 / 3.0);
  EXPECT_EQ(detail::nearestDouble(-2, 3, 0), -2.0 / 3.0);
  // A value beyond 128 bits, and one in the subnormal range.
  const i256 big = (i256(1) << 200) + 12345;
  EXPECT_EQ(detail::nearestDouble(big, 7, -150), nearest(cpp_rational(big) / 7 / twoTo(150)));
  EXPECT_EQ(detail::nearestDouble(3, 1, -1076), nearest(cpp_rational(3) / twoTo(1076)));
  EXPECT_EQ(detail::nearestDouble(1, 3, -1070), nearest(cpp_rational(1) / 3 / twoTo(1070)));
  EXPECT_EQ(detail::nearestDouble(0, 5, 0), 0.0);
}

// The 128-by-64-bit division path (dividend below 2^119, divisor below 2^64; a crossing's
// coordinate and its W) on exact ties between two doubles and one unit either side of them,
// with the quotient shifted both ways (n / d above and below 2^55), and past that path's limits.
TEST(StageOutput, NearestDoubleByDivisionRoundsTiesAndNearTies) {
  using detail::i256;
  std::mt19937_64 rng(23);
  int ties = 0;
  for (int i = 0; i < 4000; ++i) {
    const int db = 1 + int(rng() % 64);
    const std::uint64_t d = (std::uint64_t{1} << (db - 1)) | (db > 1 ? rng() >> (65 - db) : 0);
    // A midpoint (2M + 1) / 2 between the doubles M and M + 1 (53-bit M), times d and 2^t.
    const std::uint64_t m = (std::uint64_t{1} << 52) | (rng() >> 12);
    const int room = 119 - 54 - db;  // the bits left below 2^119
    const int t = room > 0 ? int(rng() % std::uint64_t(room + 1)) : 0;
    const i256 tie = (i256(2 * m + 1) * d) << t;
    const int exp2 = -1 - int(rng() % 40);
    for (const int off : {0, 1, -1, 2}) {
      const i256 n = tie + off;
      const double want =
          nearest(cpp_rational(n) / cpp_rational(i256(d)) * twoTo(exp2 + 40) / twoTo(40));
      ASSERT_EQ(detail::nearestDouble(n, i256(d), exp2), want) << i << " off " << off;
      ASSERT_EQ(detail::nearestDouble(-n, i256(d), exp2), -want) << i << " off " << off;
    }
    // The tie (M + 1/2) 2^(t + 1 + exp2) went to the even one of M 2^(t + 1 + exp2) and the next.
    const double low = std::ldexp(double(m), exp2 + t + 1);
    const double got = detail::nearestDouble(tie, i256(d), exp2);
    ASSERT_EQ(got, (m & 1) == 0 ? low : std::nextafter(low, INFINITY)) << i;
    ++ties;
  }
  EXPECT_EQ(ties, 4000);
  // Past the path's limits (dividend of 119 to 126 bits, divisor of 65 bits) and at them.
  for (const int nb : {118, 119, 120, 126}) {
    for (const int dbits : {1, 63, 64, 65}) {
      const i256 n = (i256(1) << (nb - 1)) + (i256(rng()) << 20) + 12345;
      const i256 d =
          (i256(1) << (dbits - 1)) + (dbits > 20 ? i256(rng() >> (65 - dbits + 1)) : 0) + 1;
      EXPECT_EQ(detail::nearestDouble(n, d, -7),
                nearest(cpp_rational(n) / cpp_rational(d) / twoTo(7)))
          << nb << " " << dbits;
    }
  }
}

// The snapping rule and its inverse: grid points come back exactly.
// OutputFrame::point() converts a grid point (W = 1) the short way where the grid allows it (a
// power-of-two scale, an origin within 2^52 units): the same correctly rounded doubles.
TEST(StageOutput, GridPointsOfEveryGridAreCorrectlyRounded) {
  std::mt19937_64 rng(11);
  std::vector<Grid> grids(std::begin(kGrids), std::end(kGrids));
  grids.push_back(Grid::fixed(0x1p-40, {0x1p60, -0x1p61}));  // the origin beyond 2^52 units
  grids.push_back(Grid::fixed(0x1p30, {-0.75, 3.0}));
  for (const Grid& grid : grids) {
    const std::int64_t range = Grid::kMaxUnits;
    std::vector<IPoint> points = {{0, 0}, {range, -range}, {-range, range}, {1, -1}};
    for (int i = 0; i < 2000; ++i) points.push_back(randomUnits(rng, i % 2 == 0 ? range : 1000));
    for (const IPoint& p : points) {
      expectCorrectlyRounded(XPoint(p), grid,
                             "scale " + std::to_string(grid.scale) + ", units " +
                                 std::to_string(p.x) + " " + std::to_string(p.y));
    }
  }
}

TEST(StageOutput, GridPointsComeBackExactly) {
  const Grid grid = Grid::fixed(0x1p24, {5087776.0, 5087776.0});
  for (const double v : {5087776.0, 5087776.0 + 0x1p-24, 5087750.125, 5087800.5}) {
    const auto units = grid.toUnits(v, grid.origin.x);
    ASSERT_TRUE(units);
    EXPECT_EQ(grid.toCoordinate(*units, grid.origin.x), v);
  }
  // Ties to even in absolute units, whatever the origin: 2.5 -> 2, 3.5 -> 4.
  const Grid unit = Grid::fixed(1.0, {1.0, 1.0});
  EXPECT_EQ(unit.toUnits(2.5, 1.0), 1);
  EXPECT_EQ(unit.toUnits(3.5, 1.0), 3);
  EXPECT_FALSE(unit.toUnits(NAN, 1.0));
  EXPECT_FALSE(unit.toUnits(1.0 + 0x1p30 + 1, 1.0));
  EXPECT_TRUE(unit.toUnits(1.0 + 0x1p30, 1.0));
}

}  // namespace
}  // namespace roiclip
