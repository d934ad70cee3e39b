// SPDX-License-Identifier: MIT
// Stage 0 (src/core/input.cpp): validation, snapping to the grid, repeats and straight runs
// dropped, edges emitted with their direction and operand.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <roiclip/roiclip.hpp>

#include "pipeline.hpp"
#include "stage_support.hpp"
#include "support/oracle.hpp"

namespace roiclip {
namespace {

using detail::IPoint;

using stages::kUnitGrid;

std::vector<IPoint> ring(std::initializer_list<IPoint> points) { return points; }

TEST(StageInput, SnapsToTheGridRoundingTiesToEven) {
  // A fixed 1/256 px grid. 0.5 and 1.5 units are ties: to even, 0 and 2.
  const auto rings =
      detail::snapRings({{{0.5 / 256, 0}, {10, 1.5 / 256}, {10, 10 + 0.6 / 256}, {-0.4 / 256, 10}}},
                        0, Grid::fixed(256));
  ASSERT_EQ(rings.size(), 1u);
  EXPECT_EQ(rings[0], ring({{0, 0}, {2560, 2}, {2560, 2561}, {0, 2560}}));
}

TEST(StageInput, DropsRepeatsTheClosingPointAndStraightRuns) {
  // A 3x3 pixel square walked in unit steps, with a repeated point and its first point again at
  // the end: only the 4 corners are left, starting where the ring turns.
  const Paths chain = {{{0, 0},
                        {1, 0},
                        {1, 0},
                        {2, 0},
                        {3, 0},
                        {3, 1},
                        {3, 2},
                        {3, 3},
                        {2, 3},
                        {1, 3},
                        {0, 3},
                        {0, 2},
                        {0, 1},
                        {0, 0}}};
  const auto rings = detail::snapRings(chain, 0, kUnitGrid);
  ASSERT_EQ(rings.size(), 1u);
  EXPECT_EQ(rings[0], ring({{0, 0}, {3, 0}, {3, 3}, {0, 3}}));
  // Straight on across the closing vertex too: the start (1, 0) lies mid-edge.
  const auto across = detail::snapRings({{{1, 0}, {2, 0}, {2, 2}, {0, 2}, {0, 0}}}, 0, kUnitGrid);
  ASSERT_EQ(across.size(), 1u);
  EXPECT_EQ(across[0].size(), 4u);
  // A spike is not a straight run: it stays (stage 1 cancels it).
  EXPECT_EQ(detail::snapRings({{{0, 0}, {4, 0}, {2, 0}, {2, 2}}}, 0, kUnitGrid)[0].size(), 4u);
  // Fewer than two distinct points enclose nothing; one point twice is one point.
  EXPECT_TRUE(detail::snapRings({{}, {{5, 5}}, {{5, 5}, {5, 5}}}, 0, kUnitGrid).empty());
  EXPECT_EQ(detail::snapRings({{{1, 1}, {5, 5}}}, 0, kUnitGrid).size(), 1u);
}

TEST(StageInput, EdgesAreStoredLeftToRightWithTheirDirectionAndOperand) {
  std::vector<detail::InputEdge> edges;
  // Clockwise in the raw frame: (0,0) -> (0,4) -> (4,4) -> (4,0).
  detail::appendInputEdges({{{0, 0}, {0, 4}, {4, 4}, {4, 0}}}, 1, kUnitGrid, edges);
  ASSERT_EQ(edges.size(), 4u);
  const int directions[] = {+1, +1, -1, -1};
  for (std::size_t i = 0; i < edges.size(); ++i) {
    EXPECT_TRUE(edges[i].a < edges[i].b) << i;
    EXPECT_EQ(edges[i].direction, directions[i]) << i;
    EXPECT_EQ(edges[i].operand, 1);
    EXPECT_FALSE(edges[i].open);
  }
  EXPECT_EQ(edges[3].a, (IPoint{0, 0}));  // (4,0) -> (0,0) stored as (0,0) -> (4,0), reversed
  EXPECT_EQ(edges[3].b, (IPoint{4, 0}));
}

TEST(StageInput, LineEdgesKeepPathOrderAndIndexThePolylines) {
  std::vector<detail::InputEdge> edges;
  std::vector<std::size_t> first;
  // The second polyline goes straight on at (2,0): one segment.
  detail::appendLineEdges({{{0, 0}, {5, 0}, {5, 5}}, {{4, 0}, {2, 0}, {0, 0}}, {{7, 7}}}, kUnitGrid,
                          edges, first);
  ASSERT_EQ(edges.size(), 3u);
  EXPECT_EQ(first, (std::vector<std::size_t>{0, 2, 3, 3}));
  for (const auto& e : edges) EXPECT_TRUE(e.open);
  EXPECT_EQ(edges[2].direction, -1);
  EXPECT_EQ(edges[2].a, (IPoint{0, 0}));
  EXPECT_EQ(edges[2].b, (IPoint{4, 0}));
}

TEST(StageInput, InvalidCoordinatesNameOperandPathAndVertex) {
  std::vector<detail::InputEdge> edges;
  try {
    detail::appendInputEdges({{{0, 0}, {1, 0}, {1, 1}}, {{0, 0}, {std::nan(""), 0}}}, 1,
                             Grid::fixed(256), edges);
    FAIL() << "NaN accepted";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("clip path 1, vertex 1: x"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(resolveGrid(Grid{-1.0}, {{{0, 0}, {1, 0}}}), InvalidInputError);
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
  // Beyond a fixed grid's range (the default, fitted grid takes any finite input).
  EXPECT_THROW(simplify({{{0, 0}, {1e7, 0}, {1, 1}}}, FillRule::NonZero, Grid::fixed(256)),
               InvalidInputError);
  EXPECT_THROW(simplify({{{0, 0}, {INFINITY, 0}, {1, 1}}}, FillRule::NonZero), InvalidInputError);
  EXPECT_THROW(simplify({{{0, 0}, {1, 0}, {1, 1}}}, FillRule::NonZero, Grid{-1.0}),
               InvalidInputError);
  EXPECT_THROW(simplify({{{0, 0}, {1, 0}, {1, 1}}}, FillRule::NonZero, Grid{INFINITY}),
               InvalidInputError);
  // The range edge is accepted: 2^30 units at scale 256.
  EXPECT_NO_THROW(
      simplify({{{0, 0}, {4194304, 0}, {0, -4194304}}}, FillRule::NonZero, Grid::fixed(256)));
}

}  // namespace
}  // namespace roiclip
