// SPDX-License-Identifier: MIT
// The pipeline (src/core/boolean_op.cpp): stages 0 to 4 strung together for every operation, and
// the choice between the general path and the convex pre-clip.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <roiclip/roiclip.hpp>

#include "pipeline.hpp"
#include "stage_support.hpp"
#include "support/oracle.hpp"

namespace roiclip {
namespace {

const Paths kSquare = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}};
const Paths kShifted = {{{5, 5}, {15, 5}, {15, 15}, {5, 15}}};

TEST(StageBooleanOp, GeneralPathGivesEveryOperation) {
  const std::pair<ClipOp, double> expected[] = {{ClipOp::Intersection, 25},
                                                {ClipOp::Union, 175},
                                                {ClipOp::Difference, 75},
                                                {ClipOp::Xor, 150}};
  for (const auto& [op, area] : expected) {
    SCOPED_TRACE(toString(op));
    const PolygonSet general =
        detail::booleanGeneral(kSquare, &kShifted, stages::clipWith(op), Grid::fixed(256));
    EXPECT_NEAR(general.area(), area, 1e-12);
    EXPECT_EQ(testing::structureProblems(general), "");
    // The public entry point gives the same region (for the intersection with a convex ring it
    // takes the pre-clip path: stages/convex_clip_test.cpp).
    EXPECT_NEAR(clip(op, kSquare, kShifted, FillRule::EvenOdd, FillRule::EvenOdd).area(), area,
                1e-12);
  }
  EXPECT_EQ(
      detail::booleanGeneral(kSquare, &kShifted, stages::clipWith(ClipOp::Xor), Grid::fixed(256))
          .ringCount(),
      2u);
}

TEST(StageBooleanOp, SimplifyIsTheGeneralPathWithOneOperand) {
  const Paths twice = {kSquare[0], kShifted[0]};
  for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero, FillRule::Negative}) {
    const PolygonSet general =
        detail::booleanGeneral(twice, nullptr, stages::simplifyWith(rule), Grid::fixed(256));
    EXPECT_EQ(general.area(), simplify(twice, rule).area()) << toString(rule);
  }
  EXPECT_NEAR(simplify(twice, FillRule::EvenOdd).area(), 150, 1e-12);
  EXPECT_NEAR(simplify(twice, FillRule::NonZero).area(), 175, 1e-12);
  EXPECT_TRUE(simplify(twice, FillRule::Negative).empty());
}

TEST(StageBooleanOp, ConvexShortcutHonoursTheConvexOperandsFillRule) {
  // A clockwise (raw frame) square winds -1: under Positive it covers nothing, so the pre-clip
  // path must return nothing, as the general path does.
  const Paths clockwise = {{{0, 0}, {0, 10}, {10, 10}, {10, 0}}};
  EXPECT_TRUE(clip(ClipOp::Intersection, kShifted, clockwise, FillRule::NonZero, FillRule::Positive)
                  .empty());
  EXPECT_NEAR(
      clip(ClipOp::Intersection, kShifted, clockwise, FillRule::NonZero, FillRule::Negative).area(),
      25, 1e-12);
  // Either operand may be the convex one.
  EXPECT_NEAR(clip(ClipOp::Intersection, clockwise,
                   {{{5, 5}, {15, 5}, {15, 15}, {5, 15}, {5, 5}, {15, 5}, {15, 15}, {5, 15}}},
                   FillRule::Negative, FillRule::EvenOdd)
                  .area(),
              0, 1e-12);
}

}  // namespace
}  // namespace roiclip
