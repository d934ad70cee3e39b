// SPDX-License-Identifier: MIT
// The core at its limits, scaled down to keep the suite fast (bench/limits runs the full sizes
// with time and memory figures): degenerate and invalid operands of clip() (simplify()'s are in
// stages/input_test.cpp), deep nesting through clip, long pixel contours and many crossings, each
// against areas known in closed form (limit_shapes.hpp) or the slab integration
// (support/oracle.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <roiclip/roiclip.hpp>

#include "limit_shapes.hpp"
#include "support/oracle.hpp"

namespace roiclip {
namespace {

const Path kSquare = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};

TEST(Limits, DegenerateOperandsOfClipContributeNothing) {
  const std::vector<Paths> degenerate = {
      {},
      {{}},
      {{{3, 3}}},
      {{{3, 3}, {3, 3}, {3, 3}}},                  // one distinct point, repeated
      {{{1, 1}, {5, 5}}},                          // two distinct points
      {{{1, 1}, {5, 5}, {1, 1}, {5, 5}, {1, 1}}},  // two distinct points, back and forth
      {{{1, 1}, {1, 1 + 1.0 / 1024}, {1, 1}}},     // distinct doubles, one grid point
  };
  for (std::size_t i = 0; i < degenerate.size(); ++i) {
    const Paths& d = degenerate[i];
    SCOPED_TRACE("degenerate operand " + std::to_string(i));
    for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
      EXPECT_TRUE(clip(ClipOp::Intersection, {kSquare}, d, rule, rule).empty());
      EXPECT_TRUE(clip(ClipOp::Intersection, d, {kSquare}, rule, rule).empty());
      EXPECT_NEAR(clip(ClipOp::Union, {kSquare}, d, rule, rule).area(), 100, 1e-12);
      EXPECT_NEAR(clip(ClipOp::Difference, {kSquare}, d, rule, rule).area(), 100, 1e-12);
      EXPECT_NEAR(clip(ClipOp::Xor, d, {kSquare}, rule, rule).area(), 100, 1e-12);
      EXPECT_TRUE(clip(ClipOp::Union, d, d, rule, rule).empty());
    }
  }
}

// stages/input_test.cpp covers NaN, +inf and 1e7 in a subject path and the range edge on one side.
// A fixed 1/256 px grid: the fitted default has no range to leave.
TEST(Limits, InvalidClipOperandIsRejectedWithItsLocation) {
  const double edge = 4194304.0;  // 2^30 grid units at scale 256
  const auto message = [](const Paths& subject, const Paths& region) -> std::string {
    try {
      intersect(subject, region, FillRule::EvenOdd, Grid::fixed(256));
    } catch (const InvalidInputError& e) {
      return e.what();
    }
    return "accepted";
  };
  const std::string nanClip = message({kSquare}, {kSquare, {{0, 0}, {1, std::nan("")}, {2, 0}}});
  EXPECT_NE(nanClip.find("clip path 1, vertex 1"), std::string::npos) << nanClip;
  EXPECT_NE(nanClip.find("not a finite number"), std::string::npos) << nanClip;
  const std::string negInf = message({{{0, 0}, {-INFINITY, 0}, {1, 1}}}, {kSquare});
  EXPECT_NE(negInf.find("subject path 0, vertex 1"), std::string::npos) << negInf;
  const std::string below = message({kSquare}, {{{0, 0}, {1, 0}, {1, -edge - 1.0 / 256}}});
  EXPECT_NE(below.find("clip path 0, vertex 2"), std::string::npos) << below;
  EXPECT_NE(below.find("outside the supported range"), std::string::npos) << below;
  // Both ends of the range are accepted, in either operand, and give exact areas.
  const Path huge = {{-edge, -edge}, {edge, -edge}, {edge, edge}, {-edge, edge}};
  EXPECT_EQ(message({huge}, {kSquare}), "accepted");
  EXPECT_NEAR(intersect({huge}, {kSquare}).area(), 100, 0);
  EXPECT_NEAR(unite({kSquare}, {huge}).area(), 4 * edge * edge, 0);
}

TEST(Limits, ThousandAlternatingNestedSquaresThroughSimplifyAndClip) {
  const int k = 1000;
  const Paths squares = testing::alternatingNestedSquares(k);
  const PolygonSet all = simplify(squares, FillRule::NonZero);
  EXPECT_NEAR(all.area(), testing::nestedSquaresAreaInBox(k, k), 1e-6);
  ASSERT_EQ(all.polygons.size(), 500u);
  for (std::size_t i = 0; i < all.polygons.size(); ++i) {
    EXPECT_EQ(all.polygons[i].parent, int(i) - 1);
  }
  // A quad cutting through the middle of the nest: the 250 innermost annuli stay whole.
  const double h = 500.5;
  const Path box = {{-h, -h}, {h, -h}, {h, h}, {-h, h}};
  for (FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
    const PolygonSet in = clip(ClipOp::Intersection, squares, {box}, rule, FillRule::EvenOdd);
    EXPECT_NEAR(in.area(), testing::nestedSquaresAreaInBox(k, h), 1e-6);
    EXPECT_EQ(in.polygons.size(), 250u);
    EXPECT_EQ(in.ringCount(), 500u);
    EXPECT_EQ(testing::structureProblems(in), "");
  }
}

TEST(Limits, LongPixelContourThroughSimplifyAndClip) {
  const testing::Crenellated shape{2000};  // 32,004 vertices
  const Path ring = shape.path();
  ASSERT_EQ(ring.size(), shape.vertices());
  for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
    const PolygonSet r = simplify({ring}, rule);
    EXPECT_NEAR(r.area(), shape.area(), 0);
    ASSERT_EQ(r.polygons.size(), 1u);
    EXPECT_EQ(r.polygons[0].outer.size(), ring.size());
  }
  // A box cutting through the teeth of three sides and through the body.
  const double x0 = -0.5, y0 = -0.75, x1 = 4001.5, y1 = 3000.25;
  const Path box = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  const PolygonSet in = intersect({ring}, {box});
  EXPECT_NEAR(in.area(), shape.areaInBox(x0, y0, x1, y1), 1e-6);
  EXPECT_NEAR(subtract({ring}, {box}).area() + in.area(), shape.area(), 1e-6);
}

TEST(Limits, CombsCrossingThemselvesManyTimes) {
  // The closed forms against the slab integration on a small pair of combs.
  const testing::Combs small{6};
  const Paths smallPaths = {small.path()};
  for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
    const double slab = testing::slabArea(
        {&smallPaths}, [&](const std::vector<long long>& w) { return isFilled(rule, w[0]); });
    EXPECT_NEAR(slab, rule == FillRule::EvenOdd ? small.evenOddArea() : small.nonZeroArea(), 1e-9);
  }
  const testing::Combs combs{40};  // 6,400 crossings
  const Paths paths = {combs.path()};
  const PolygonSet nonZero = simplify(paths, FillRule::NonZero);
  EXPECT_NEAR(nonZero.area(), combs.nonZeroArea(), 1e-9);
  // The gaps between neighbouring teeth are holes (40 x 40 cells, less the one at the corner
  // where the combs' spines do not meet).
  ASSERT_EQ(nonZero.polygons.size(), 1u);
  EXPECT_EQ(nonZero.polygons[0].holes.size(), 40u * 40u - 1u);
  // Even-odd also empties every square where two teeth overlap, which leaves the pieces of
  // teeth between them touching only at corners: the output grows with the crossings.
  const PolygonSet evenOdd = simplify(paths, FillRule::EvenOdd);
  EXPECT_NEAR(evenOdd.area(), combs.evenOddArea(), 1e-9);
  EXPECT_GT(evenOdd.ringCount(), 40u * 40u);
  // Clipped by a quad through the middle of the teeth, against the slab integration.
  const Path quad = {{10.5, -1.5}, {60.25, 20}, {70, 70.75}, {-1.5, 30}};
  const Paths quadPaths = {quad};
  const PolygonSet in =
      clip(ClipOp::Intersection, paths, quadPaths, FillRule::EvenOdd, FillRule::EvenOdd);
  const double slab = testing::slabArea({&paths, &quadPaths}, [](const std::vector<long long>& w) {
    return (w[0] % 2 != 0) && (w[1] % 2 != 0);
  });
  EXPECT_NEAR(in.area(), slab, 1e-9 * slab);
}

// The work budget (Limits::maxCrossings): a typed error naming the limit, raised while the sweep
// finds crossings, on the general and the convex (pre-clipped) path alike; nothing is returned.
TEST(Limits, MaxCrossingsStopsTheSweepWithResourceLimitError) {
  // Two combs of 10 teeth each: 100 or more crossings.
  Path a, b;
  for (int i = 0; i < 10; ++i) {
    a.push_back({2.0 * i, 0});
    a.push_back({2.0 * i + 1, 30});
    b.push_back({0, 2.0 * i + 0.5});
    b.push_back({30, 2.0 * i + 1.5});
  }
  a.push_back({20, -5});
  b.push_back({-5, 20});
  const Options tight(Grid::fitted(), Limits{10});
  try {
    intersect({a}, {b}, FillRule::EvenOdd, tight);
    FAIL() << "no ResourceLimitError";
  } catch (const ResourceLimitError& e) {
    EXPECT_EQ(e.limit(), "maxCrossings");
    EXPECT_EQ(e.value(), 10u);
    EXPECT_STREQ(e.what(), "more than 10 crossings (the limit maxCrossings)");
  }
  EXPECT_THROW(simplify({a, b}, FillRule::NonZero, tight), ResourceLimitError);
  // Through the convex pre-clip: the comb against a square still crosses itself.
  const Paths square = {{{-1, -1}, {40, -1}, {40, 40}, {-1, 40}}};
  EXPECT_THROW(intersect({a, b}, square, FillRule::EvenOdd, tight), ResourceLimitError);
  EXPECT_THROW(clipLines({b}, {a, b}, FillRule::EvenOdd, LinePart::Inside, tight),
               ResourceLimitError);
  // A ResourceLimitError is a roiclip::Error; a large enough budget gives the full result.
  EXPECT_THROW(simplify({a, b}, FillRule::NonZero, tight), Error);
  const double area = simplify({a, b}, FillRule::NonZero).area();
  EXPECT_EQ(simplify({a, b}, FillRule::NonZero, Options(Grid::fitted(), Limits{100000})).area(),
            area);
}

// The budget holds exactly in slab mode too, where one slab pass finds many crossings: two
// columns of 201 bow-ties crossing once each, from x = 0 to 2000 and from x = 2000 to 4000. The
// first column's crossings are found as neighbours (and put the sweep in slab mode), the
// second's all by the pass over the slab from x = 2000 to 4000: 402 in all.
TEST(Limits, MaxCrossingsHoldsExactlyForASlabsCrossings) {
  Paths columns;
  for (int j = 0; j <= 200; ++j) {
    for (const double x : {0.0, 2000.0}) {
      const double y = 20000.0 * j + (x > 0 ? 5000 : 0);
      columns.push_back({{x, y}, {x + 2000, y + 16000}, {x + 2000, y}, {x, y + 16000}});
    }
  }
  const auto limited = [](std::uint64_t crossings) {
    return Options(Grid::fitted(), Limits{crossings});
  };
  EXPECT_THROW(simplify(columns, FillRule::NonZero, limited(401)), ResourceLimitError);
  EXPECT_EQ(simplify(columns, FillRule::NonZero, limited(402)).area(),
            simplify(columns, FillRule::NonZero).area());
}

}  // namespace
}  // namespace roiclip
