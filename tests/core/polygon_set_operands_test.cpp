// SPDX-License-Identifier: MIT
// PolygonSet operands of clip() and its shorthands: the same result as clipping the set's rings
// under kPolygonSetFillRule, and the region the exact winding numbers of those rings give.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include <roiclip/roiclip.hpp>

#include "support/oracle.hpp"
#include "support/same_set.hpp"

namespace roiclip {
namespace {

constexpr ClipOp kOps[] = {ClipOp::Intersection, ClipOp::Union, ClipOp::Difference, ClipOp::Xor};

// `paths` snapped to `grid` (a resolved grid: the one clip() fits to both operands).
Paths snapped(Paths paths, const Grid& grid) {
  for (Path& path : paths) {
    for (Point& p : path) {
      p = {grid.toCoordinate(*grid.toUnits(p.x, grid.origin.x), grid.origin.x),
           grid.toCoordinate(*grid.toUnits(p.y, grid.origin.y), grid.origin.y)};
    }
  }
  return paths;
}

// A region with a hole and an island in it, from a self-intersecting input: 3 rings.
PolygonSet frameWithIsland() {
  return simplify({{{0, 0}, {20, 0}, {20, 20}, {0, 20}},
                   {{4, 4}, {16, 4}, {16, 16}, {4, 16}},
                   {{8, 8}, {12, 8}, {10, 13}}},
                  FillRule::EvenOdd);
}

TEST(PolygonSetOperands, EveryOverloadEqualsClippingTheRings) {
  const PolygonSet a = frameWithIsland();
  ASSERT_EQ(a.ringCount(), 3u);
  // A bow-tie, so that its rule matters: EvenOdd and NonZero read it differently.
  const Paths bowTie = {{{-2, 6}, {24, 14}, {24, 6}, {-2, 14}},
                        {{-2, 6}, {24, 14}, {24, 6}, {-2, 14}}};
  const PolygonSet b = simplify(bowTie, FillRule::NonZero);
  const Paths aRings = a.toPaths();
  const Paths bRings = b.toPaths();
  const FillRule r = kPolygonSetFillRule;
  double areas[4] = {};
  for (int k = 0; k < 4; ++k) {
    const ClipOp op = kOps[k];
    const std::string name = toString(op);
    for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
      testing::expectSameSet(clip(op, a, bowTie, rule), clip(op, aRings, bowTie, r, rule),
                             name + " set,paths");
      testing::expectSameSet(clip(op, bowTie, a, rule), clip(op, bowTie, aRings, rule, r),
                             name + " paths,set");
    }
    const PolygonSet both = clip(op, a, b);
    testing::expectSameSet(both, clip(op, aRings, bRings, r, r), name + " set,set");
    areas[k] = both.area();
  }
  // The shorthands call the operation their name says (the four areas all differ here).
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) EXPECT_NE(areas[i], areas[j]) << i << " " << j;
  }
  const FillRule eo = FillRule::EvenOdd;
  testing::expectSameSet(intersect(a, bowTie), clip(ClipOp::Intersection, a, bowTie, eo),
                         "intersect");
  testing::expectSameSet(intersect(bowTie, a), clip(ClipOp::Intersection, bowTie, a, eo),
                         "intersect");
  testing::expectSameSet(intersect(a, b), clip(ClipOp::Intersection, a, b), "intersect");
  testing::expectSameSet(unite(a, bowTie), clip(ClipOp::Union, a, bowTie, eo), "unite");
  testing::expectSameSet(unite(bowTie, a), clip(ClipOp::Union, bowTie, a, eo), "unite");
  testing::expectSameSet(unite(a, b), clip(ClipOp::Union, a, b), "unite");
  testing::expectSameSet(subtract(a, bowTie), clip(ClipOp::Difference, a, bowTie, eo), "subtract");
  testing::expectSameSet(subtract(bowTie, a), clip(ClipOp::Difference, bowTie, a, eo), "subtract");
  testing::expectSameSet(subtract(a, b), clip(ClipOp::Difference, a, b), "subtract");
  testing::expectSameSet(symmetricDifference(a, bowTie), clip(ClipOp::Xor, a, bowTie, eo), "xor");
  testing::expectSameSet(symmetricDifference(bowTie, a), clip(ClipOp::Xor, bowTie, a, eo), "xor");
  testing::expectSameSet(symmetricDifference(a, b), clip(ClipOp::Xor, a, b), "xor");
  // The Paths operand's rule is used: the doubled bow-tie covers its lobes twice.
  EXPECT_LT(intersect(a, bowTie, FillRule::EvenOdd).area(),
            intersect(a, bowTie, FillRule::NonZero).area());
  // Subject and clip are not swapped.
  EXPECT_NE(subtract(a, bowTie).area(), subtract(bowTie, a).area());
}

TEST(PolygonSetOperands, ResultsMatchTheExactWindingOfTheRings) {
  std::mt19937 rng(16);
  for (int trial = 0; trial < 40; ++trial) {
    const Paths s = {testing::randomPolygon(rng, 5 + int(rng() % 8), 20)};
    const Paths c = {testing::randomPolygon(rng, 5 + int(rng() % 8), 20)};
    const PolygonSet a = simplify(s, FillRule::NonZero);
    const PolygonSet b = simplify(c, FillRule::EvenOdd);
    // A result's crossing vertices are exact doubles, off the grid; as input they are snapped
    // like any other vertex, so the truth is taken on the snapped rings.
    const Grid grid = resolveGrid({}, a.toPaths(), b.toPaths());
    const Paths aRings = snapped(a.toPaths(), grid);
    const Paths bRings = snapped(b.toPaths(), grid);
    for (ClipOp op : kOps) {
      const PolygonSet got = clip(op, a, b);
      // Independently of roiclip: the rings of both sets under NonZero.
      const double truth =
          testing::slabArea({&aRings, &bRings}, [op](const std::vector<long long>& w) {
            return testing::combine(op, w[0] != 0, w[1] != 0);
          });
      ASSERT_NEAR(got.area(), truth, 1e-6 * (truth + 1))
          << toString(op) << " " << testing::describe(s) << testing::describe(c);
      EXPECT_EQ(testing::structureProblems(got), "");
    }
  }
}

TEST(PolygonSetOperands, ReadsTheRingsWithNonZero) {
  // Hand-made, breaking the PolygonSet rules: two overlapping squares. NonZero reads them as
  // their union (EvenOdd would cut out the overlap).
  PolygonSet overlapping;
  overlapping.polygons.push_back({{{0, 0}, {0, 10}, {10, 10}, {10, 0}}, {}});
  overlapping.polygons.push_back({{{5, 0}, {5, 10}, {15, 10}, {15, 0}}, {}});
  const Paths box = {{{-1, -1}, {20, -1}, {20, 20}, {-1, 20}}};
  EXPECT_DOUBLE_EQ(intersect(overlapping, box).area(), 150.0);
  EXPECT_DOUBLE_EQ(intersect(box, overlapping).area(), 150.0);
}

TEST(PolygonSetOperands, ErrorsNameTheRingOfTheSet) {
  PolygonSet bad = frameWithIsland();
  bad.polygons[0].holes[0][2].y = std::numeric_limits<double>::quiet_NaN();
  const Paths box = {{{0, 0}, {1, 0}, {1, 1}}};
  try {
    (void)subtract(box, bad);
    FAIL() << "no InvalidInputError";
  } catch (const InvalidInputError& e) {
    EXPECT_EQ(e.location().operand, Operand::Clip);
    EXPECT_EQ(e.location().path, 1u);  // the hole is ring 1 of bad.toPaths()
    EXPECT_EQ(e.location().vertex, 2u);
    EXPECT_EQ(e.location().axis, Axis::Y);
  }
}

}  // namespace
}  // namespace roiclip
