// Degenerate clipping cases, every operation, areas and ring counts worked out by hand.
#include <gtest/gtest.h>

#include <roiclip/roiclip.hpp>

#include "support/oracle.hpp"

namespace roiclip {
namespace {

struct Expect {
  double area;
  std::size_t rings;
};

struct Case {
  const char* name;
  Paths a, b;
  Expect intersection, unite, difference, xored;
};

const Paths kSquare = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}};

std::vector<Case> cases() {
  return {
      {"shared vertex only",
       kSquare,
       {{{10, 10}, {20, 10}, {10, 20}}},
       {0, 0},
       {150, 2},
       {100, 1},
       {150, 2}},
      {"vertex on the other's edge",
       kSquare,
       {{{10, 5}, {20, 0}, {20, 10}}},
       {0, 0},
       {150, 2},
       {100, 1},
       {150, 2}},
      {"collinear edge inside",
       kSquare,
       {{{5, 2}, {10, 2}, {10, 8}, {5, 8}}},
       {30, 1},
       {100, 1},
       {70, 1},
       {70, 1}},
      {"collinear edge outside",
       kSquare,
       {{{10, 2}, {20, 2}, {20, 8}, {10, 8}}},
       {0, 0},
       {160, 1},
       {100, 1},
       {160, 1}},
      {"identical", kSquare, kSquare, {100, 1}, {100, 1}, {0, 0}, {0, 0}},
      {"identical, opposite direction",
       kSquare,
       {{{0, 0}, {0, 10}, {10, 10}, {10, 0}}},
       {100, 1},
       {100, 1},
       {0, 0},
       {0, 0}},
      {"inside, no crossings",
       kSquare,
       {{{2, 2}, {8, 2}, {8, 8}, {2, 8}}},
       {36, 1},
       {100, 1},
       {64, 2},
       {64, 2}},
      {"sharing a whole edge",
       kSquare,
       {{{10, 0}, {20, 0}, {20, 10}, {10, 10}}},
       {0, 0},
       {200, 1},
       {100, 1},
       {200, 1}},
      {"self-intersecting clip (bow-tie)",
       kSquare,
       {{{0, 0}, {10, 10}, {10, 0}, {0, 10}}},
       {50, 2},
       {100, 1},
       {50, 2},
       {50, 2}},
      {"disjoint", kSquare, {{{20, 0}, {30, 0}, {30, 10}}}, {0, 0}, {150, 2}, {100, 1}, {150, 2}},
  };
}

TEST(ClipDegenerate, EveryOperation) {
  for (const Case& c : cases()) {
    const PolygonSet results[4] = {intersect(c.a, c.b), unite(c.a, c.b), subtract(c.a, c.b),
                                   symmetricDifference(c.a, c.b)};
    const Expect expected[4] = {c.intersection, c.unite, c.difference, c.xored};
    const char* names[4] = {"intersection", "union", "difference", "xor"};
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(results[i].area(), expected[i].area, 1e-9) << c.name << ": " << names[i];
      EXPECT_EQ(results[i].ringCount(), expected[i].rings) << c.name << ": " << names[i];
      EXPECT_EQ(testing::structureProblems(results[i]), "") << c.name << ": " << names[i];
    }
  }
}

TEST(ClipDegenerate, OperandsAreSymmetricWhereTheyShouldBe) {
  for (const Case& c : cases()) {
    EXPECT_NEAR(intersect(c.a, c.b).area(), intersect(c.b, c.a).area(), 1e-9) << c.name;
    EXPECT_NEAR(unite(c.a, c.b).area(), unite(c.b, c.a).area(), 1e-9) << c.name;
    EXPECT_NEAR(symmetricDifference(c.a, c.b).area(), symmetricDifference(c.b, c.a).area(), 1e-9)
        << c.name;
  }
}

TEST(ClipDegenerate, EachOperandKeepsItsOwnFillRule) {
  // Subject: square wound twice (w = 2). Clip: the square once.
  const Paths twice = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}, {10, 0}, {10, 10}, {0, 10}}};
  EXPECT_NEAR(
      clip(ClipOp::Intersection, twice, kSquare, FillRule::EvenOdd, FillRule::EvenOdd).area(), 0,
      1e-9);
  EXPECT_NEAR(
      clip(ClipOp::Intersection, twice, kSquare, FillRule::NonZero, FillRule::EvenOdd).area(), 100,
      1e-9);
  EXPECT_NEAR(clip(ClipOp::Xor, twice, kSquare, FillRule::EvenOdd, FillRule::Negative).area(), 0,
              1e-9);
}

TEST(ClipDegenerate, SubPixelQuadAgainstPixelContour) {
  // A pixel staircase clipped by a quad whose corners are sub-pixel: the answer is the slab
  // integration of the exact winding numbers.
  const Paths stairs = {
      {{0, 0}, {4, 0}, {4, 1}, {3, 1}, {3, 2}, {2, 2}, {2, 3}, {1, 3}, {1, 4}, {0, 4}}};
  const Paths quad = {{{0.5, -0.25}, {3.75, 0.5}, {3.25, 3.5}, {-0.5, 2.75}}};
  const double truth = testing::slabArea(
      {&stairs, &quad}, [](const std::vector<long long>& w) { return (w[0] & 1) && (w[1] & 1); });
  const PolygonSet r = intersect(stairs, quad);
  EXPECT_NEAR(r.area(), truth, 1e-9);
  EXPECT_GT(truth, 5.0);
  EXPECT_EQ(testing::structureProblems(r), "");
}

}  // namespace
}  // namespace roiclip
