// SPDX-License-Identifier: MIT
// Stage 4 (src/core/nesting.cpp): each hole gets its outer ring, each outer ring the hole it lies
// in, from the piece the sweep found below each ring; output in roiclip's orientation.
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
#include "support/same_set.hpp"

namespace roiclip {
namespace {

TEST(StageNesting, ThreeNestedSquaresNestTwoDeep) {
  // Even-odd: the outer square, its hole, an island in the hole.
  const Paths nested = {{{0, 0}, {30, 0}, {30, 30}, {0, 30}},
                        {{5, 5}, {25, 5}, {25, 25}, {5, 25}},
                        {{10, 10}, {20, 10}, {20, 20}, {10, 20}}};
  const detail::Arrangement a =
      stages::arrange(nested, nullptr, stages::simplifyWith(FillRule::EvenOdd));
  const detail::Contours c = detail::traceContours(a);
  ASSERT_EQ(c.rings.size(), 3u);
  // From the sweep: below each ring's reference piece lies the ring that bounds the region just
  // below it: nothing for the outer square, the outer square for the hole, the hole for the
  // island.
  std::vector<int> depth(c.rings.size(), 0);
  for (std::size_t r = 0; r < c.rings.size(); ++r) {
    for (int piece = c.rings[r].referencePiece;
         a.pieces[std::size_t(piece)].below >= 0 && depth[r] < 10;) {
      piece = c.rings[std::size_t(c.ringOfPiece[std::size_t(a.pieces[std::size_t(piece)].below)])]
                  .referencePiece;
      ++depth[r];
    }
  }
  std::vector<int> sorted = depth;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, (std::vector<int>{0, 1, 2}));
  for (std::size_t r = 0; r < c.rings.size(); ++r) EXPECT_EQ(c.rings[r].hole, depth[r] == 1) << r;

  const PolygonSet set = detail::buildNesting(a, c, stages::kUnitGrid);
  ASSERT_EQ(set.polygons.size(), 2u);
  EXPECT_EQ(set.polygons[0].parent, -1);
  EXPECT_EQ(set.polygons[0].holes.size(), 1u);
  EXPECT_EQ(set.polygons[1].parent, 0);
  EXPECT_EQ(set.polygons[1].parentHole, 0);
  EXPECT_TRUE(set.polygons[1].holes.empty());
  // roiclip's output orientation: outer rings negative, holes positive (cv::findContours).
  EXPECT_EQ(signedArea(set.polygons[0].outer), -900.0);
  EXPECT_EQ(signedArea(set.polygons[0].holes[0]), 400.0);
  EXPECT_EQ(signedArea(set.polygons[1].outer), -100.0);
}

// The pipeline frees the pieces before nesting (boolean_op.cpp): nesting reads only what the
// rings carry of them (belowPiece), so it gives the same polygons without them.
TEST(StageNesting, SameResultWithThePiecesFreed) {
  const Paths nested = {{{0, 0}, {30, 0}, {30, 30}, {0, 30}},
                        {{5, 5}, {25, 5}, {25, 25}, {5, 25}},
                        {{10, 10}, {20, 10}, {20, 20}, {10, 20}},
                        {{0, 0}, {12, 27}, {27, 3}}};
  detail::Arrangement a = stages::arrange(nested, nullptr, stages::simplifyWith(FillRule::EvenOdd));
  const detail::Contours c = detail::traceContours(a);
  ASSERT_GE(c.rings.size(), 4u);
  for (const detail::TracedRing& ring : c.rings) {
    EXPECT_EQ(ring.belowPiece, a.pieces[std::size_t(ring.referencePiece)].below);
  }
  const PolygonSet kept = detail::buildNesting(a, c, stages::kUnitGrid);
  detail::EdgePieces().swap(a.pieces);
  std::vector<detail::Side>().swap(a.sides);
  testing::expectSameSet(detail::buildNesting(a, c, stages::kUnitGrid), kept, "pieces freed");
}

TEST(StageNesting, TouchingRingsAndSiblingIslands) {
  // Two islands in one hole, and a square outside touching the outer one at a corner.
  const Paths shapes = {{{0, 0}, {30, 0}, {30, 30}, {0, 30}},
                        {{2, 2}, {28, 2}, {28, 28}, {2, 28}},
                        {{4, 4}, {10, 4}, {10, 10}, {4, 10}},
                        {{20, 20}, {26, 20}, {26, 26}, {20, 26}},
                        {{30, 30}, {40, 30}, {40, 40}, {30, 40}}};
  const detail::Arrangement a =
      stages::arrange(shapes, nullptr, stages::simplifyWith(FillRule::EvenOdd));
  const PolygonSet set = detail::buildNesting(a, detail::traceContours(a), Grid{0.5});
  ASSERT_EQ(set.polygons.size(), 4u);
  int top = 0, islands = 0;
  for (const Polygon& p : set.polygons) {
    if (p.parent < 0) {
      ++top;
    } else {
      ++islands;
      EXPECT_EQ(set.polygons[std::size_t(p.parent)].holes.size(), 1u);
      EXPECT_EQ(p.parentHole, 0);
    }
  }
  EXPECT_EQ(top, 2);
  EXPECT_EQ(islands, 2);
  // The grid scale converts back to pixels: Grid{0.5} means one unit is 2 px.
  EXPECT_NEAR(set.area(), 4 * (900 - 26 * 26 + 36 + 36 + 100), 1e-9);
}

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
