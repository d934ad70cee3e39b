// SPDX-License-Identifier: MIT
// The oracle (tests/support/oracle.hpp) judges both engines, so it is tested on its own:
// exactness where doubles fail, winding numbers with both orientations, points on the boundary.
#include <cmath>
#include <optional>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "support/oracle.hpp"

namespace roiclip::testing {
namespace {

TEST(Oracle, OrientationIsExactWhereDoublesRoundToZero) {
  const Point a(12, 12), b(24, 24);
  // p is one ulp right of the diagonal y = x; (p.x - a.x) rounds to -11.5 in double, so the
  // naive determinant is 0 and only the exact fallback sees the side.
  const Point right(std::nextafter(0.5, 1.0), 0.5);
  const Point left(0.5, std::nextafter(0.5, 1.0));
  EXPECT_EQ((b.x - a.x) * (right.y - a.y) - (b.y - a.y) * (right.x - a.x), 0.0);
  EXPECT_EQ(orientation(a, b, right), -1);
  EXPECT_EQ(orientation(a, b, left), 1);
  EXPECT_EQ(orientation(a, b, Point(0.5, 0.5)), 0);
  EXPECT_EQ(orientation(a, b, Point(-1e300, -1e300)), 0);
  EXPECT_EQ(orientation(Point(0, 0), Point(1, 0), Point(0.5, 1e-300)), 1);
}

// A hole may touch its outer ring (or another hole) at one point; around a cycle of such
// touches the polygon's interior falls apart (OGC: not valid).
TEST(Oracle, StructureSeesAnInteriorThatIsNotConnected) {
  Polygon p;
  p.outer = {{0, 40}, {45, 40}, {40, 20}, {40, 0}, {0, 0}, {-5, 20}};  // negative shoelace
  p.holes = {{{-5, 20}, {20, 10}, {40, 20}, {20, 30}}};                // positive: touches twice
  PolygonSet twice;
  twice.polygons = {p};
  EXPECT_NE(structureProblems(twice).find("interior not connected"), std::string::npos);
  p.holes = {{{-5, 20}, {20, 10}, {30, 20}, {20, 30}}};  // touches once
  PolygonSet once;
  once.polygons = {p};
  EXPECT_EQ(structureProblems(once), "");
  // Two holes touching each other twice cut off the part between them.
  p.holes = {{{5, 20}, {20, 10}, {30, 20}, {20, 15}}, {{5, 20}, {20, 25}, {30, 20}, {20, 30}}};
  PolygonSet lens;
  lens.polygons = {p};
  EXPECT_NE(structureProblems(lens).find("interior not connected"), std::string::npos);
}

TEST(Oracle, WindingNumberFollowsOrientation) {
  const Path square = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};  // shoelace > 0: winds +1
  const Path reversed = {{0, 4}, {4, 4}, {4, 0}, {0, 0}};
  EXPECT_EQ(windingNumber(square, Point(1, 1)), 1);
  EXPECT_EQ(windingNumber(reversed, Point(1, 1)), -1);
  EXPECT_EQ(windingNumber(square, Point(5, 1)), 0);
  EXPECT_EQ(windingNumber(Paths{square, square}, Point(3.5, 0.25)), 2);
  // A bow-tie: its two lobes wind in opposite directions.
  const Path bowtie = {{0, 0}, {10, 10}, {10, 0}, {0, 10}};
  EXPECT_EQ(windingNumber(bowtie, Point(1, 5)) + windingNumber(bowtie, Point(9, 5)), 0);
  EXPECT_NE(windingNumber(bowtie, Point(1, 5)), 0);
  EXPECT_EQ(windingNumber(bowtie, Point(5, 1)), 0);
}

TEST(Oracle, ExactWindingSeesTheBoundaryOnAndOffTheGrid) {
  const Paths square = {{{0, 0}, {4, 0}, {4, 4}, {0, 4}}};
  EXPECT_EQ(exactWinding(square, Point(1, 1)), 1);
  EXPECT_EQ(exactWinding(square, Point(5, 1)), 0);
  EXPECT_EQ(exactWinding(square, Point(4, 2)), std::nullopt);  // on an edge (1/4096 grid)
  EXPECT_EQ(exactWinding(square, Point(0, 0)), std::nullopt);  // at a vertex
  // Off the grid the exact rational path decides: 0.1 is not a multiple of 1/4096.
  EXPECT_EQ(exactWinding(square, Point(0.1, 0)), std::nullopt);
  EXPECT_EQ(exactWinding(square, Point(0.1, 1e-300)), 1);
  EXPECT_EQ(exactWinding(square, Point(0.1, -1e-300)), 0);
  const Paths diagonal = {{{0, 0}, {0.3, 0.1}, {0.3, 1}}};
  EXPECT_EQ(exactWinding(diagonal, Point(0.3, 0.1)), std::nullopt);
  // The grid shortcut and the exact fallback agree where both apply.
  EXPECT_EQ(orientation(Point(0, 0), Point(3, 1), Point(6, 2)), 0);
  EXPECT_EQ(orientation(Point(0, 0), Point(3, 1), Point(6, 2 + 1.0 / 4096)), 1);
  EXPECT_EQ(orientation(Point(0, 0), Point(3, 1), Point(6, 2 + 1e-9)), 1);
}

TEST(Oracle, ProximityFindsOnlyNearbyEdges) {
  const Paths rings = {{{0, 0}, {100, 0}, {100, 100}, {0, 100}}};
  const SegmentProximity near(rings, 0.5);
  EXPECT_TRUE(near.near(Point(50, 0.4)));
  EXPECT_TRUE(near.near(Point(100.3, 70)));
  EXPECT_FALSE(near.near(Point(50, 0.6)));
  EXPECT_FALSE(near.near(Point(50, 50)));
  EXPECT_FALSE(near.near(Point(-3, -3)));
}

// The fast exact area gives exactSlabArea()'s double bit for bit: random self-crossing rings on a
// coarse grid (many shared vertices, touching and overlapping edges, vertical edges), the same
// moved off any binary grid and far from the origin (every double decision near a tie), and both
// under every fill rule and operation.
TEST(Oracle, RegionAreaEqualsTheSlabAreaBitForBit) {
  std::mt19937 rng(20261202u);
  const FillRule rules[] = {FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive};
  const ClipOp ops[] = {ClipOp::Intersection, ClipOp::Union, ClipOp::Difference, ClipOp::Xor};
  int checked = 0, nonZero = 0;
  for (int round = 0; round < 24; ++round) {
    Paths a = {randomPolygon(rng, 3 + round % 9, 6), randomPolygon(rng, 3 + round % 4, 6)};
    Paths b = {randomGridWalk(rng, 4 + round % 7, 1, 6)};
    if (round % 3 == 1) {  // decimal offsets: coordinates off every binary grid
      for (Paths* paths : {&a, &b}) {
        for (Path& ring : *paths) {
          for (Point& p : ring) p = Point(1e6 + p.x * 0.1, -3e5 + p.y * 0.3);
        }
      }
    } else if (round % 3 == 2) {  // nearly collinear: one ulp off
      for (Point& p : a[0]) p.y = std::nextafter(p.y * 1e-3 + 41.0, 1e300);
    }
    // Every fill rule with every operation twice over the rounds.
    const FillRule rule = rules[round % 3];
    const ClipOp op = ops[(round / 3) % 4];
    const auto in = [&](const std::vector<long long>& w) {
      return combine(op, isFilled(rule, w[0]), isFilled(rule, w[1]));
    };
    const double slow = exactSlabArea({&a, &b}, in);
    const double fast = exactRegionArea({&a, &b}, in);
    EXPECT_EQ(fast, slow) << "round " << round << " " << describe(a) << " " << describe(b);
    ++checked;
    nonZero += slow != 0 ? 1 : 0;
  }
  EXPECT_EQ(checked, 24);
  EXPECT_GT(nonZero, 15);
  // A unit square exactly: 1; the same square as two triangles sharing the diagonal: still 1.
  const Paths square = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  const Paths halves = {{{0, 0}, {1, 0}, {1, 1}}, {{0, 0}, {1, 1}, {0, 1}}};
  const auto any = [](const std::vector<long long>& w) { return w[0] != 0; };
  EXPECT_EQ(exactRegionArea({&square}, any), 1.0);
  EXPECT_EQ(exactRegionArea({&halves}, any), 1.0);
}

}  // namespace
}  // namespace roiclip::testing
