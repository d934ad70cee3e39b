// SPDX-License-Identifier: MIT
// Clipping against the slab integration of the exact winding numbers. The hand-worked degenerate
// cases (shared vertices, vertices on edges, collinear edges, identical operands, containment, a
// bow-tie clip, disjoint operands, per-operand fill rules) are data: tests/data/core/cases/, run
// by case_test.cpp.
#include <gtest/gtest.h>

#include <roiclip/roiclip.hpp>

#include "support/oracle.hpp"

namespace roiclip {
namespace {

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
