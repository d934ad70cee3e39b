// SPDX-License-Identifier: MIT
// Stage 3 (src/core/trace_contours.cpp): result pieces linked into simple rings with the paper's
// stack method, filled side on the left, rings touching at a vertex kept apart.
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

TEST(StageTraceContours, TwoSquaresSharingAVertexAreTwoRings) {
  const Paths squares = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                         {{10, 10}, {20, 10}, {20, 20}, {10, 20}}};
  const detail::Arrangement a =
      stages::arrange(squares, nullptr, stages::simplifyWith(FillRule::NonZero));
  const detail::Contours c = detail::traceContours(a);
  const auto names = stages::vertexNames(a);
  ASSERT_EQ(c.rings.size(), 2u);
  const auto shared = std::find(names.begin(), names.end(), "(10,10)") - names.begin();
  for (const detail::TracedRing& ring : c.rings) {
    EXPECT_EQ(ring.vertices.size(), 4u);
    EXPECT_FALSE(ring.hole);
    // Each ring passes the shared vertex once.
    EXPECT_EQ(std::count(ring.vertices.begin(), ring.vertices.end(), int(shared)), 1);
  }
  // Every result piece belongs to a ring, four to each.
  ASSERT_EQ(c.ringOfPiece.size(), a.pieces.size());
  EXPECT_EQ(std::count(c.ringOfPiece.begin(), c.ringOfPiece.end(), 0), 4);
  EXPECT_EQ(std::count(c.ringOfPiece.begin(), c.ringOfPiece.end(), 1), 4);
}

TEST(StageTraceContours, RingsRunWithTheFilledSideOnTheirLeft) {
  // An annulus: the outer ring counter-clockwise in the raw frame, the hole clockwise.
  const Paths annulus = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{2, 2}, {8, 2}, {8, 8}, {2, 8}}};
  const detail::Arrangement a =
      stages::arrange(annulus, nullptr, stages::simplifyWith(FillRule::EvenOdd));
  const detail::Contours c = detail::traceContours(a);
  ASSERT_EQ(c.rings.size(), 2u);
  int holes = 0;
  for (const detail::TracedRing& ring : c.rings) {
    const double area = stages::rawSignedArea(a, ring);
    EXPECT_EQ(area, ring.hole ? -36.0 : 100.0);
    holes += ring.hole ? 1 : 0;
  }
  EXPECT_EQ(holes, 1);
}

TEST(StageTraceContours, VerticesWhereARingGoesStraightOnAreRemoved) {
  // The union outline of a square and a rectangle sharing part of an edge: the square's edges
  // are cut at (10,2) and (10,8), which stay (the ring turns there); nothing else is added.
  const Paths shared = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{10, 2}, {20, 2}, {20, 8}, {10, 8}}};
  // Non-zero: a square and a rectangle overlapping along part of the bottom edge: (5,0) and
  // (10,0) are arrangement vertices on the outline's straight bottom, and are dropped.
  const Paths overlap = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{5, 0}, {15, 0}, {15, 5}, {5, 5}}};
  const detail::Arrangement a =
      stages::arrange(shared, nullptr, stages::simplifyWith(FillRule::NonZero));
  const detail::Contours c = detail::traceContours(a);
  ASSERT_EQ(c.rings.size(), 1u);
  EXPECT_EQ(c.rings[0].vertices.size(), 8u);
  const detail::Arrangement b =
      stages::arrange(overlap, nullptr, stages::simplifyWith(FillRule::NonZero));
  const detail::Contours d = detail::traceContours(b);
  ASSERT_EQ(d.rings.size(), 1u);
  EXPECT_EQ(d.rings[0].vertices.size(), 6u);  // (0,0) (15,0) (15,5) (10,5) (10,10) (0,10)
}

TEST(StageTraceContours, AnUnbalancedBoundaryIsAnInternalError) {
  // Each piece's filled side decides where it leaves and arrives. Flipping one piece, or
  // dropping it, leaves vertices where more pieces leave than arrive and others where fewer do:
  // tracing must refuse, whichever piece it is, not loop or return a broken ring.
  const Paths annulus = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{2, 2}, {8, 2}, {8, 8}, {2, 8}}};
  const detail::Arrangement a =
      stages::arrange(annulus, nullptr, stages::simplifyWith(FillRule::EvenOdd));
  ASSERT_EQ(detail::traceContours(a).rings.size(), 2u);
  for (std::size_t e = 0; e < a.pieces.size(); ++e) {
    if (a.sides[e] == detail::Side::None) continue;
    detail::Arrangement flipped = a;
    flipped.sides[e] =
        a.sides[e] == detail::Side::Above ? detail::Side::Below : detail::Side::Above;
    EXPECT_THROW(detail::traceContours(flipped), InternalError) << "piece " << e << " flipped";
    detail::Arrangement dropped = a;
    dropped.sides[e] = detail::Side::None;
    EXPECT_THROW(detail::traceContours(dropped), InternalError) << "piece " << e << " dropped";
  }
}

}  // namespace
}  // namespace roiclip
