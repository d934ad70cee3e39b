// Hand-made cases with answers worked out by hand (areas in px^2, ring counts).
#include <gtest/gtest.h>

#include <cmath>

#include <roiclip/roiclip.hpp>

#include "support/oracle.hpp"

namespace roiclip {
namespace {

struct Expect {
  double area;
  std::size_t rings;
};

void expectResult(const PolygonSet& r, Expect e, const char* what) {
  EXPECT_NEAR(r.area(), e.area, 1e-9) << what;
  EXPECT_EQ(r.ringCount(), e.rings) << what;
  EXPECT_EQ(testing::structureProblems(r), "") << what;
}

bool covers(const PolygonSet& r, Point p) {
  int w = 0;
  for (const Path& ring : r.toPaths()) w -= testing::ringWinding(ring, p);
  return w == 1;
}

TEST(Simplify, SquareKeepsAreaAndOrientation) {
  const Paths square = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}};
  const PolygonSet r = simplify(square, FillRule::NonZero);
  ASSERT_EQ(r.polygons.size(), 1u);
  EXPECT_EQ(r.polygons[0].outer.size(), 4u);
  EXPECT_DOUBLE_EQ(r.area(), 100.0);
  EXPECT_LT(signedArea(r.polygons[0].outer), 0.0);
}

TEST(Simplify, BowTieLoopsHaveOppositeWinding) {
  // Two triangles of area 25 meeting at (5,5); the left one winds -1, the right one +1.
  const Paths bowTie = {{{0, 0}, {10, 10}, {10, 0}, {0, 10}}};
  expectResult(simplify(bowTie, FillRule::EvenOdd), {50, 2}, "evenodd");
  expectResult(simplify(bowTie, FillRule::NonZero), {50, 2}, "nonzero");
  const PolygonSet pos = simplify(bowTie, FillRule::Positive);
  const PolygonSet neg = simplify(bowTie, FillRule::Negative);
  expectResult(pos, {25, 1}, "positive");
  expectResult(neg, {25, 1}, "negative");
  EXPECT_TRUE(covers(pos, {9, 5}) != covers(neg, {9, 5}));
}

TEST(Simplify, FigureEightThroughOneVertex) {
  // Two counter-clockwise (raw frame) squares joined at (10,10): both wind +1.
  const Paths eight = {
      {{0, 0}, {10, 0}, {10, 10}, {20, 10}, {20, 20}, {10, 20}, {10, 10}, {0, 10}}};
  for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive}) {
    const PolygonSet r = simplify(eight, rule);
    expectResult(r, {200, 2}, toString(rule));
    EXPECT_EQ(r.polygons.size(), 2u);
  }
  expectResult(simplify(eight, FillRule::Negative), {0, 0}, "negative");
}

TEST(Simplify, SquareWoundTwice) {
  const Paths twice = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}, {10, 0}, {10, 10}, {0, 10}}};
  expectResult(simplify(twice, FillRule::EvenOdd), {0, 0}, "evenodd: w = 2 is even");
  expectResult(simplify(twice, FillRule::NonZero), {100, 1}, "nonzero");
  expectResult(simplify(twice, FillRule::Positive), {100, 1}, "positive");
  expectResult(simplify(twice, FillRule::Negative), {0, 0}, "negative");
}

TEST(Simplify, PentagramCentreDependsOnFillRule) {
  Path star;
  for (int k = 0; k < 5; ++k) {
    const double a = (90.0 + 144.0 * k) * M_PI / 180.0;
    star.emplace_back(std::round(100 * std::cos(a) * 256) / 256,
                      std::round(100 * std::sin(a) * 256) / 256);
  }
  const Paths in = {star};
  const PolygonSet evenOdd = simplify(in, FillRule::EvenOdd);
  const PolygonSet nonZero = simplify(in, FillRule::NonZero);
  EXPECT_FALSE(covers(evenOdd, {0.1, 0.1}));
  EXPECT_TRUE(covers(nonZero, {0.1, 0.1}));
  // Non-zero: one ring of 10 vertices. Even-odd: the 5 tips (w = 1) without the centre (w = 2).
  EXPECT_EQ(nonZero.ringCount(), 1u);
  EXPECT_EQ(nonZero.polygons[0].outer.size(), 10u);
  const double pentagon = nonZero.area() - evenOdd.area();
  // Inner pentagon of a {5/2} star with circumradius R has circumradius R*sin(18)/sin(126).
  const double r = 100 * std::sin(M_PI / 10) / std::sin(7 * M_PI / 10);
  EXPECT_NEAR(pentagon, 2.5 * r * r * std::sin(2 * M_PI / 5), 0.5);
  EXPECT_EQ(testing::structureProblems(evenOdd), "");
}

TEST(Simplify, RingTouchingItselfAtOneVertex) {
  // Hourglass: two triangles of area 9 meeting at (3,3), both winding +1.
  const Paths hourglass = {{{0, 0}, {6, 0}, {3, 3}, {6, 6}, {0, 6}, {3, 3}}};
  expectResult(simplify(hourglass, FillRule::NonZero), {18, 2}, "nonzero");
  expectResult(simplify(hourglass, FillRule::Negative), {0, 0}, "negative");
  // A hole touching its outer ring at a corner: one polygon, one hole, 100 - 10.5.
  const Paths touching = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{0, 0}, {5, 2}, {2, 5}}};
  const PolygonSet r = simplify(touching, FillRule::EvenOdd);
  expectResult(r, {89.5, 2}, "hole touching outer");
  ASSERT_EQ(r.polygons.size(), 1u);
  EXPECT_EQ(r.polygons[0].holes.size(), 1u);
}

TEST(Simplify, CollinearOverlappingEdges) {
  const Paths sharedEdge = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                            {{10, 2}, {20, 2}, {20, 8}, {10, 8}}};
  const PolygonSet merged = simplify(sharedEdge, FillRule::NonZero);
  expectResult(merged, {160, 1}, "shared part of an edge");
  EXPECT_EQ(merged.polygons[0].outer.size(), 8u);
  const Paths overlapping = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                             {{5, 0}, {15, 0}, {15, 10}, {5, 10}}};
  expectResult(simplify(overlapping, FillRule::EvenOdd), {100, 2}, "evenodd drops the overlap");
  expectResult(simplify(overlapping, FillRule::NonZero), {150, 1}, "nonzero");
  expectResult(simplify(overlapping, FillRule::Positive), {150, 1}, "positive");
}

TEST(Simplify, SpikeAndDuplicatePointsVanish) {
  const Paths spike = {{{0, 0}, {10, 0}, {10, 10}, {10, 20}, {10, 10}, {0, 10}}};
  const PolygonSet r = simplify(spike, FillRule::NonZero);
  expectResult(r, {100, 1}, "spike");
  EXPECT_EQ(r.polygons[0].outer.size(), 4u);
  const Paths dup = {{{0, 0}, {0, 0}, {10, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}}};
  const PolygonSet d = simplify(dup, FillRule::EvenOdd);
  expectResult(d, {100, 1}, "duplicates");
  EXPECT_EQ(d.polygons[0].outer.size(), 4u);
}

TEST(Simplify, PapersExampleInnerLoopIsHoleOnlyUnderEvenOdd) {
  // Outer square, then an inner square in the same direction through a connector that is
  // walked there and back: the inner loop has winding number 2.
  const Paths curl = {
      {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}, {2, 2}, {8, 2}, {8, 8}, {2, 8}, {2, 2}}};
  const PolygonSet evenOdd = simplify(curl, FillRule::EvenOdd);
  expectResult(evenOdd, {64, 2}, "evenodd: inner loop is a hole");
  ASSERT_EQ(evenOdd.polygons.size(), 1u);
  EXPECT_EQ(evenOdd.polygons[0].holes.size(), 1u);
  expectResult(simplify(curl, FillRule::NonZero), {100, 1}, "nonzero: not a hole");
  // The same with the inner loop clockwise: winding 0 inside, a hole under every rule.
  const Paths reversed = {
      {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}, {2, 2}, {2, 8}, {8, 8}, {8, 2}, {2, 2}}};
  expectResult(simplify(reversed, FillRule::NonZero), {64, 2}, "nonzero, clockwise inner");
}

TEST(Simplify, IslandInsideHoleKnowsItsParent) {
  const Paths nested = {{{0, 0}, {30, 0}, {30, 30}, {0, 30}},
                        {{5, 5}, {25, 5}, {25, 25}, {5, 25}},
                        {{10, 10}, {20, 10}, {20, 20}, {10, 20}}};
  const PolygonSet r = simplify(nested, FillRule::EvenOdd);
  expectResult(r, {900 - 400 + 100, 3}, "island");
  ASSERT_EQ(r.polygons.size(), 2u);
  EXPECT_EQ(r.polygons[0].parent, -1);
  EXPECT_EQ(r.polygons[1].parent, 0);
  EXPECT_EQ(r.polygons[1].parentHole, 0);
}

TEST(Simplify, DegenerateInputGivesEmptyResult) {
  EXPECT_TRUE(simplify({}, FillRule::NonZero).empty());
  EXPECT_TRUE(simplify({{}}, FillRule::NonZero).empty());
  EXPECT_TRUE(simplify({{{1, 1}}}, FillRule::NonZero).empty());
  EXPECT_TRUE(simplify({{{1, 1}, {5, 5}}}, FillRule::NonZero).empty());
  EXPECT_TRUE(simplify({{{0, 0}, {5, 5}, {10, 10}}}, FillRule::NonZero).empty());
}

TEST(Simplify, InvalidInputIsRejectedWithItsLocation) {
  const double nan = std::nan("");
  try {
    simplify({{{0, 0}, {1, 0}, {1, nan}}}, FillRule::NonZero);
    FAIL() << "NaN accepted";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("path 0, vertex 2"), std::string::npos) << e.what();
  }
  EXPECT_THROW(simplify({{{0, 0}, {1e7, 0}, {1, 1}}}, FillRule::NonZero), InvalidInputError);
  EXPECT_THROW(simplify({{{0, 0}, {INFINITY, 0}, {1, 1}}}, FillRule::NonZero), InvalidInputError);
  EXPECT_THROW(simplify({{{0, 0}, {1, 0}, {1, 1}}}, FillRule::NonZero, Grid{0.0}),
               InvalidInputError);
  // The range edge is accepted: 2^30 units at the default scale.
  EXPECT_NO_THROW(simplify({{{0, 0}, {4194304, 0}, {0, -4194304}}}, FillRule::NonZero));
}

TEST(Simplify, ParsesNames) {
  EXPECT_EQ(parseFillRule("even-odd"), FillRule::EvenOdd);
  EXPECT_EQ(parseFillRule("NonZero"), FillRule::NonZero);
  EXPECT_EQ(parseClipOp("xor"), ClipOp::Xor);
  EXPECT_THROW(parseFillRule("odd"), InvalidInputError);
  EXPECT_THROW(parseClipOp("merge"), InvalidInputError);
}

}  // namespace
}  // namespace roiclip

namespace roiclip {
namespace {

TEST(Simplify, ThousandNestedSquaresFormAParentChain) {
  // Squares of half-size 1..1000 around the origin; even-odd keeps every other annulus.
  Paths squares;
  for (int k = 1; k <= 1000; ++k) {
    squares.push_back({{-k, -k}, {k, -k}, {k, k}, {-k, k}});
  }
  const PolygonSet r = simplify(squares, FillRule::EvenOdd);
  // Annuli between half-sizes 2j-1 and 2j (j = 1..500): area 4((2j)^2 - (2j-1)^2) = 4(4j - 1).
  double expected = 0;
  for (int j = 1; j <= 500; ++j) expected += 4.0 * (4 * j - 1);
  EXPECT_NEAR(r.area(), expected, 1e-6);
  ASSERT_EQ(r.polygons.size(), 500u);
  EXPECT_EQ(r.ringCount(), 1000u);
  // Outermost first; each next one lies in the previous one's hole.
  for (std::size_t i = 0; i < r.polygons.size(); ++i) {
    EXPECT_EQ(r.polygons[i].parent, int(i) - 1);
    EXPECT_EQ(r.polygons[i].holes.size(), 1u);
  }
  // Non-zero: one solid square.
  EXPECT_NEAR(simplify(squares, FillRule::NonZero).area(), 4e6, 1e-6);
}

}  // namespace
}  // namespace roiclip

namespace roiclip {
namespace {

// Long steep edges at the edge of the coordinate range cross a vertical edge: the crossings
// share their x exactly and have large denominators, so ordering them needs products beyond
// 128 bits (the 256-bit branch of the exact comparison).
TEST(Simplify, CrossingsSharingXAtRangeEdge) {
  const double m = 4194300.0;
  const Paths in = {{{1000.5, -m}, {1000.5, m}, {1001.25, m}, {1001.25, -m}},
                    {{-m, -m + 3.0 / 256}, {m, m - 7.0 / 256}, {m, -m + 5.0 / 256}},
                    {{-m + 11.0 / 256, m}, {m - 1.0 / 256, -m + 13.0 / 256}, {-m, -m}}};
  for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
    const PolygonSet r = simplify(in, rule);
    const double truth = testing::slabArea(
        {&in}, [&](const std::vector<long long>& w) { return isFilled(rule, w[0]); });
    EXPECT_NEAR(r.area(), truth, 1e-7 * truth);
    const auto report = testing::sampleRegion(
        r, {&in}, [&](const std::vector<long long>& w) { return isFilled(rule, w[0]); }, 990, 1010,
        400, 3u);
    EXPECT_EQ(report.mismatches, 0) << report.firstMismatch;
    EXPECT_GT(report.checked, 300);
  }
}

}  // namespace
}  // namespace roiclip
