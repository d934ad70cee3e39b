// SPDX-License-Identifier: MIT
// The fitted grid's choice (resolveGrid): the power-of-two grid for data it holds, a decimal grid
// (10^k units per coordinate unit, the smallest k) for doubles nearest to decimals, and the
// power-of-two grid again for data neither holds. docs/algorithm.md, "Grid".
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <roiclip/roiclip.hpp>

#include "pipeline.hpp"

namespace roiclip {
namespace {

bool isPowerOfTwo(double s) {
  int e = 0;
  return std::frexp(s, &e) == 0.5;
}

// Every coordinate's grid point gives it back, and the origin lies on the grid.
void expectHeldExactly(const Grid& grid, const Paths& paths) {
  EXPECT_EQ(std::floor(grid.origin.x * grid.scale), grid.origin.x * grid.scale);
  EXPECT_EQ(std::floor(grid.origin.y * grid.scale), grid.origin.y * grid.scale);
  for (const Path& path : paths) {
    for (const Point& p : path) {
      const auto ux = grid.toUnits(p.x, grid.origin.x), uy = grid.toUnits(p.y, grid.origin.y);
      ASSERT_TRUE(ux && uy);
      EXPECT_EQ(grid.toCoordinate(*ux, grid.origin.x), p.x);
      EXPECT_EQ(grid.toCoordinate(*uy, grid.origin.y), p.y);
    }
  }
}

TEST(Grid, DecimalDataGetsTheDecimalsItWasWrittenWith) {
  // Two decimals (0.25 needs them; 56.7 needs one, 13 none).
  const Paths two = {{{12.34, 56.7}, {13, 57.25}, {-0.05, 60}}};
  EXPECT_EQ(resolveGrid({}, two).scale, 100.0);
  expectHeldExactly(resolveGrid({}, two), two);
  EXPECT_EQ(resolveGrid({}, {{{0.1, 0.2}, {0.3, 0.2}, {0.3, 0.7}}}).scale, 10.0);
  // The clip operand counts too.
  EXPECT_EQ(
      resolveGrid({}, {{{0.1, 0.2}, {0.3, 0.2}, {0.3, 0.7}}}, {{{0.125, 1}, {2, 1}, {2, 3}}}).scale,
      1000.0);
}

TEST(Grid, UtmAtATenthOfAMillimetreGetsScaleTenThousand) {
  const Paths utm = {{{5000000.1234, 5000000.0001},
                      {5000100.5, 5000000.0001},
                      {5000100.5, 5000099.9999},
                      {5000000.1234, 5000099.9999}}};
  const Grid grid = resolveGrid({}, utm);
  EXPECT_EQ(grid.scale, 1e4);
  EXPECT_NEAR(grid.origin.x, 5e6 + 50.3117, 1e-3);
  EXPECT_NEAR(grid.origin.y, 5e6 + 50, 1e-3);
  expectHeldExactly(grid, utm);
  // The power-of-two grid (2^24 per metre at this extent) would move them.
  const Grid binary = Grid::fixed(0x1p24, {5e6, 5e6});
  EXPECT_NE(binary.toCoordinate(*binary.toUnits(utm[0][0].x, 5e6), 5e6), utm[0][0].x);
}

TEST(Grid, DataOnThePowerOfTwoGridKeepsIt) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> pixel(0, 1919);
  Paths pixels(1);
  for (int i = 0; i < 50; ++i) pixels[0].push_back({double(pixel(rng)), double(pixel(rng))});
  const Grid grid = resolveGrid({}, pixels);
  detail::Box box;
  box.add(pixels);
  const Grid binary = detail::fitBinaryGrid(box);
  EXPECT_TRUE(isPowerOfTwo(grid.scale));
  EXPECT_EQ(grid.scale, binary.scale);
  EXPECT_EQ(grid.origin, binary.origin);
  // Binary fractions are decimals too (0.25, 0.5), but the power-of-two grid holds them.
  EXPECT_EQ(resolveGrid({}, {{{0.25, 0.5}, {10.75, 0.5}, {3, 8.125}}}).scale, 0x1p27);
}

TEST(Grid, DataNeitherGridHoldsKeepsThePowerOfTwoGrid) {
  // A third is no decimal.
  const Paths third = {{{0.1, 0.2}, {1.0 / 3.0, 0.2}, {0.3, 0.7}}};
  EXPECT_TRUE(isPowerOfTwo(resolveGrid({}, third).scale));
  // Decimals computed in doubles are not the doubles nearest to them: 0.1 + 0.2.
  EXPECT_TRUE(isPowerOfTwo(resolveGrid({}, {{{0.1 + 0.2, 0}, {1, 0}, {1, 1}}}).scale));
  // Seventeen digits: finer than any decimal grid the range allows (10^9 at this extent).
  EXPECT_TRUE(isPowerOfTwo(resolveGrid({}, {{{0.12345678901234567, 0}, {1, 0}, {1, 1}}}).scale));
  // Seven decimals over 1000 units: 10^7 * 1000 is beyond the range of 2^31 units.
  EXPECT_TRUE(isPowerOfTwo(resolveGrid({}, {{{0.1234567, 0}, {1000, 0}, {1000, 1}}}).scale));
  // Integers over 10^10: not even 10^0 fits the range, and the power-of-two grid rounds them.
  const Grid wide = resolveGrid({}, {{{1, 0}, {1e10, 0}, {1e10, 3}}});
  EXPECT_TRUE(isPowerOfTwo(wide.scale));
  EXPECT_LT(wide.scale, 1.0);
  // NaN is left to the snapping, which names it.
  EXPECT_TRUE(isPowerOfTwo(resolveGrid({}, {{{0.1, 0}, {NAN, 0}, {1, 1}}}).scale));
  EXPECT_THROW(simplify({{{0.1, 0}, {NAN, 0}, {1, 1}}}, FillRule::EvenOdd), InvalidInputError);
}

TEST(Grid, TheDecimalOriginMultipliesBackExactly) {
  // Many boxes: the origin lies on the grid as toUnits and the output compute it.
  std::mt19937 rng(3);
  std::uniform_int_distribution<long long> units(-4'000'000'000'000LL, 4'000'000'000'000LL);
  for (int i = 0; i < 2000; ++i) {
    const long long x = units(rng), y = units(rng);
    const Paths p = {{{double(x) / 1e6, double(y) / 1e6},
                      {double(x + 123) / 1e6, double(y) / 1e6},
                      {double(x) / 1e6, double(y + 150'000'000) / 1e6}}};
    const Grid grid = resolveGrid({}, p);
    ASSERT_EQ(grid.scale, 1e6) << x << " " << y;
    expectHeldExactly(grid, p);
  }
}

// Triangle x + y <= 0.7 over the square [0.2, 0.45]^2: the result's corners (0.45, 0.25) and
// (0.25, 0.45) are crossings. On the decimal grid every vertex is the double nearest to the
// exact answer for the decimals; the power-of-two grid moves the inputs and so the crossings.
TEST(Grid, DecimalClipGivesTheExactAnswerOfTheDecimals) {
  const Paths triangle = {{{0.1, 0.1}, {0.6, 0.1}, {0.1, 0.6}}};
  const Paths square = {{{0.2, 0.2}, {0.45, 0.2}, {0.45, 0.45}, {0.2, 0.45}}};
  const std::vector<Point> want = {
      {0.2, 0.2}, {0.45, 0.2}, {0.45, 0.25}, {0.25, 0.45}, {0.2, 0.45}};
  const auto corners = [](const PolygonSet& set) {
    EXPECT_EQ(set.polygons.size(), 1u);
    std::vector<Point> got = set.polygons.empty() ? Path{} : set.polygons[0].outer;
    std::sort(got.begin(), got.end(),
              [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    return got;
  };
  std::vector<Point> sorted = want;
  std::sort(sorted.begin(), sorted.end(),
            [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  EXPECT_EQ(resolveGrid({}, triangle, square).scale, 100.0);
  const PolygonSet got = intersect(triangle, square);
  EXPECT_EQ(corners(got), sorted);
  EXPECT_NEAR(got.area(), 0.0425, 1e-17);
  // The power-of-two grid the call had before (2^32 per unit at this extent) misses them.
  const Grid binary = detail::fitBinaryGrid([&] {
    detail::Box box;
    box.add(triangle);
    box.add(square);
    return box;
  }());
  EXPECT_NE(corners(clip(ClipOp::Intersection, triangle, square, FillRule::EvenOdd,
                         FillRule::EvenOdd, binary)),
            sorted);
}

// PreparedRegion fits a decimal grid to a decimal region (its grown box, the finest k it allows),
// and hands subjects its grid does not hold to the free function: its results are the free
// function's.
TEST(Grid, PreparedRegionGivesTheFreeFunctionsDecimalResults) {
  const Paths region = {
      {{512345.6789, 5087776.1234}, {512445.1, 5087776.1234}, {512400.25, 5087870.5}}};
  std::mt19937 rng(21);
  std::uniform_int_distribution<long long> offset(-200'000, 1'200'000);
  const PreparedRegion prepared(region);
  const PreparedRegion integers({{{512300, 5087700}, {512500, 5087700}, {512400, 5087900}}});
  for (int decimals : {0, 1, 4, 9}) {
    const double ten = std::pow(10.0, decimals);
    const auto coordinate = [&](double base) {
      return double(std::llround(base * ten) + std::llround(double(offset(rng)) * ten / 1e4)) / ten;
    };
    Paths subject(1);
    for (int i = 0; i < 7; ++i) {
      subject[0].push_back({coordinate(512345.0), coordinate(5087776.0)});
    }
    for (const ClipOp op : {ClipOp::Intersection, ClipOp::Difference}) {
      const PolygonSet want = clip(op, subject, region, FillRule::EvenOdd, FillRule::EvenOdd);
      const PolygonSet got = prepared.clip(op, subject);
      ASSERT_EQ(got.polygons.size(), want.polygons.size()) << decimals;
      for (std::size_t k = 0; k < got.polygons.size(); ++k) {
        EXPECT_EQ(got.polygons[k].outer, want.polygons[k].outer) << decimals;
        EXPECT_EQ(got.polygons[k].holes, want.polygons[k].holes) << decimals;
      }
      const Paths square = {{{512300, 5087700}, {512500, 5087700}, {512400, 5087900}}};
      const PolygonSet wantInt = clip(op, subject, square, FillRule::EvenOdd, FillRule::EvenOdd);
      const PolygonSet gotInt = integers.clip(op, subject);
      ASSERT_EQ(gotInt.polygons.size(), wantInt.polygons.size()) << decimals;
      for (std::size_t k = 0; k < gotInt.polygons.size(); ++k) {
        EXPECT_EQ(gotInt.polygons[k].outer, wantInt.polygons[k].outer) << decimals;
      }
    }
  }
}

// The box's integral flag: set only when every coordinate is a finite integer below 2^51 in
// magnitude (from -2^52 to -2^51 the short rounding keeps halves).
TEST(Grid, TheBoxIsIntegralOnlyForFiniteIntegers) {
  const auto integral = [](std::initializer_list<double> xs) {
    Path path;
    for (const double x : xs) path.push_back({x, 7.0});
    detail::Box box;
    box.add({path});
    return box.integral;
  };
  EXPECT_TRUE(integral({0.0, -0.0, 1.0, -1.0, 1920.0, 0x1p50, -0x1p50 - 1, 0x1p51 - 1}));
  EXPECT_FALSE(integral({0.0, 0.5}));
  EXPECT_FALSE(integral({0.0, -1.25}));
  EXPECT_FALSE(integral({0.0, 0x1p51 + 0.5}));
  EXPECT_FALSE(integral({0.0, -0x1p51 - 1.5}));
  EXPECT_FALSE(integral({0.0, -0x1p51 - 1.0}));  // an integer, but past the short rounding
  EXPECT_FALSE(integral({0.0, 0x1p52}));
  EXPECT_FALSE(integral({0.0, 1e-300}));
  EXPECT_FALSE(integral({0.0, std::nan("")}));
  EXPECT_FALSE(integral({0.0, INFINITY}));
  EXPECT_FALSE(integral({0.0, -INFINITY}));
  detail::Box box;  // integral until a path that is not
  box.add({{{1, 2}, {3, 4}}});
  EXPECT_TRUE(box.integral);
  box.add({{{1, 2.5}}});
  EXPECT_FALSE(box.integral);
  box.add({{{1, 2}}});
  EXPECT_FALSE(box.integral);
}

// The box's finite flag: false when a coordinate is NaN or infinite (the box skips those), and
// when one reaches 2^51 in magnitude (not told apart there); true for any other data.
TEST(Grid, TheBoxIsFiniteOnlyWithoutNanOrInfinity) {
  const auto finite = [](const Path& path) {
    detail::Box box;
    box.add({path});
    return box.finite;
  };
  EXPECT_TRUE(finite({{0.0, 7.0}, {-1920.5, 1e-300}, {0x1p51 - 1, -0x1p51 + 1}, {0.1, -0.0}}));
  EXPECT_TRUE(finite({}));
  EXPECT_FALSE(finite({{0.0, 7.0}, {1.0, std::nan("")}}));
  EXPECT_FALSE(finite({{0.0, 7.0}, {-std::nan(""), 1.5}}));
  EXPECT_FALSE(finite({{0.0, 7.0}, {INFINITY, 1.5}}));
  EXPECT_FALSE(finite({{0.25, 7.0}, {1.0, -INFINITY}}));
  EXPECT_FALSE(finite({{0.0, 7.0}, {0x1p52, 1.5}}));
  detail::Box box;  // finite until a path that is not
  box.add({{{1.5, 2}, {3, 4}}});
  EXPECT_TRUE(box.finite);
  box.add({{{1, std::nan("")}}});
  EXPECT_FALSE(box.finite);
  box.add({{{1, 2}}});
  EXPECT_FALSE(box.finite);
}

// resolveGrid() takes the power-of-two grid without the second pass (holdsExactly()) for integer
// data; on random data of every kind it chooses what the two passes choose.
TEST(Grid, TheIntegerShortcutChoosesWhatTheExactTestChooses) {
  const auto reference = [](const Paths& a, const Paths& b) {
    detail::Box box;
    box.add(a);
    box.add(b);
    if (box.empty()) return Grid::fixed(1.0);
    const Grid binary = detail::fitBinaryGrid(box);
    if (detail::holdsExactly(binary, a) && detail::holdsExactly(binary, b)) return binary;
    return detail::fitDecimalGrid(box, a, b, detail::DecimalPick::Coarsest).value_or(binary);
  };
  std::mt19937 rng(20261203);
  int shortcut = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const int kind = trial % 6;
    const double span = std::ldexp(1.0, int(rng() % 60));  // up to 2^59: past the short rounding
    const auto coordinate = [&] {
      const double v = std::floor(std::uniform_real_distribution<double>(-span, span)(rng));
      switch (kind) {
        case 0:
          return v;  // integers
        case 1:
          return v + 0.5;  // halves (a grid of scale 2 or more)
        case 2:
          return v / 100.0;  // decimals
        case 3:
          return rng() % 8 == 0 ? v + 0.25 : v;  // mostly integers
        case 4:
          return rng() % 16 == 0 ? std::nan("") : v;  // integers and NaN (snapping rejects it)
        default:
          return v * 3.0;
      }
    };
    Paths a(1), b(1);
    for (int i = 0; i < 6; ++i) a[0].push_back({coordinate(), coordinate()});
    for (int i = 0; i < 4; ++i) b[0].push_back({coordinate(), coordinate()});
    const Grid expected = reference(a, b);
    const Grid got = resolveGrid(Grid::fitted(), a, b);
    ASSERT_EQ(got.scale, expected.scale) << "trial " << trial;
    ASSERT_EQ(got.origin.x, expected.origin.x) << "trial " << trial;
    ASSERT_EQ(got.origin.y, expected.origin.y) << "trial " << trial;
    detail::Box box;
    box.add(a);
    box.add(b);
    shortcut += box.integral && got.scale >= 1.0 ? 1 : 0;
  }
  EXPECT_GT(shortcut, 500);
}

}  // namespace
}  // namespace roiclip
