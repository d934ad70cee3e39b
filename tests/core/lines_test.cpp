// SPDX-License-Identifier: MIT
// Open polylines clipped to a region: hand-worked cases, a property test against exact winding
// numbers at sample points, and Boost.Geometry as an independent library on valid regions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/linestring.hpp>
#include <boost/geometry/geometries/multi_linestring.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>

#include <roiclip/roiclip.hpp>

#include "support/oracle.hpp"

namespace roiclip {
namespace {

constexpr FillRule kRules[] = {FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive,
                               FillRule::Negative};

using testing::inClosure;
using testing::length;
using testing::onPolylines;

const Path kSquare = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};

TEST(ClipLines, CrossingLineIsCutAtTheBoundary) {
  const Paths line = {{{-5, 5}, {15, 5}}};
  const Paths in = clipLines(line, {kSquare}, FillRule::EvenOdd);
  ASSERT_EQ(in.size(), 1u);
  EXPECT_EQ(in[0], (Path{{0, 5}, {10, 5}}));
  const Paths out = clipLines(line, {kSquare}, FillRule::EvenOdd, LinePart::Outside);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0], (Path{{-5, 5}, {0, 5}}));
  EXPECT_EQ(out[1], (Path{{10, 5}, {15, 5}}));
}

TEST(ClipLines, DirectionAndVerticesAreKept) {
  // Right to left through a U-shaped region (notch 4 <= x <= 6, y <= 8), out over the top edge
  // and back in: (8,5)-(5,12) leaves at y = 10, x = 41/7 (it passes y = 8 at x = 47/7, right of
  // the notch); (5,12)-(2,5) comes back at y = 10, x = 29/7.
  const Path u = {{0, 0}, {4, 0}, {4, 8}, {6, 8}, {6, 0}, {10, 0}, {10, 10}, {0, 10}};
  const Paths line = {{{12, 5}, {8, 5}, {5, 12}, {2, 5}, {-2, 5}}};
  const Paths in = clipLines(line, {u}, FillRule::NonZero);
  ASSERT_EQ(in.size(), 2u);
  ASSERT_EQ(in[0].size(), 3u);
  ASSERT_EQ(in[1].size(), 3u);
  EXPECT_EQ(in[0][0], Point(10, 5));
  EXPECT_EQ(in[0][1], Point(8, 5));
  EXPECT_NEAR(in[0][2].x, 41.0 / 7, 1e-12);
  EXPECT_NEAR(in[0][2].y, 10.0, 1e-12);
  EXPECT_NEAR(in[1][0].x, 29.0 / 7, 1e-12);
  EXPECT_NEAR(in[1][0].y, 10.0, 1e-12);
  EXPECT_EQ(in[1][1], Point(2, 5));
  EXPECT_EQ(in[1][2], Point(0, 5));
  const Paths out = clipLines(line, {u}, FillRule::NonZero, LinePart::Outside);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[1][1], Point(5, 12));
  EXPECT_NEAR(length(in) + length(out), length(line), 1e-9);
}

TEST(ClipLines, BoundaryRunsAreInside) {
  // Along the top edge, and along the edge shared by two squares that are both filled.
  const Paths top = {{{-5, 0}, {15, 0}}};
  EXPECT_EQ(clipLines(top, {kSquare}, FillRule::EvenOdd), (Paths{{{0, 0}, {10, 0}}}));
  EXPECT_EQ(clipLines(top, {kSquare}, FillRule::EvenOdd, LinePart::Outside).size(), 2u);
  // Every edge, from either side of the sweep's ordering, in both directions.
  for (const Paths& along : {Paths{{{-5, 10}, {15, 10}}}, Paths{{{15, 10}, {-5, 10}}},
                             Paths{{{0, -5}, {0, 15}}}, Paths{{{10, 15}, {10, -5}}}}) {
    const Paths in = clipLines(along, {kSquare}, FillRule::EvenOdd);
    ASSERT_EQ(in.size(), 1u);
    EXPECT_NEAR(length(in), 10.0, 1e-12);
  }
  const Path right = {{10, 0}, {20, 0}, {20, 10}, {10, 10}};
  const Paths shared = {{{10, -5}, {10, 15}}};
  EXPECT_EQ(clipLines(shared, {kSquare, right}, FillRule::NonZero), (Paths{{{10, 0}, {10, 10}}}));
}

TEST(ClipLines, EdgeBetweenTwoUnfilledSidesIsOutside) {
  // A square wound twice is empty under even-odd: its edges bound nothing.
  const Paths twice = {kSquare, kSquare};
  const Paths top = {{{-5, 0}, {15, 0}}};
  EXPECT_TRUE(clipLines(top, twice, FillRule::EvenOdd).empty());
  EXPECT_EQ(clipLines(top, twice, FillRule::EvenOdd, LinePart::Outside), top);
  EXPECT_EQ(clipLines(top, twice, FillRule::NonZero), (Paths{{{0, 0}, {10, 0}}}));
}

TEST(ClipLines, HolesAndSelfIntersectingRegions) {
  const Path hole = {{3, 3}, {3, 7}, {7, 7}, {7, 3}};
  const Paths line = {{{-1, 5}, {11, 5}}};
  const Paths in = clipLines(line, {kSquare, hole}, FillRule::EvenOdd);
  ASSERT_EQ(in.size(), 2u);
  EXPECT_EQ(in[0], (Path{{0, 5}, {3, 5}}));
  EXPECT_EQ(in[1], (Path{{7, 5}, {10, 5}}));
  // Bow-tie: the two lobes meet at (5,5); a line through the crossing is inside both lobes.
  const Path bowtie = {{0, 0}, {10, 10}, {10, 0}, {0, 10}};
  const Paths across = {{{-1, 5}, {11, 5}}};
  EXPECT_EQ(clipLines(across, {bowtie}, FillRule::EvenOdd), (Paths{{{0, 5}, {10, 5}}}));
  // Under Positive only one lobe counts.
  const Paths positive = clipLines(across, {bowtie}, FillRule::Positive);
  const Paths negative = clipLines(across, {bowtie}, FillRule::Negative);
  ASSERT_EQ(positive.size(), 1u);
  ASSERT_EQ(negative.size(), 1u);
  EXPECT_NEAR(length(positive), 5.0, 1e-12);
  EXPECT_NEAR(length(negative), 5.0, 1e-12);
  EXPECT_NE(positive[0].front().x, negative[0].front().x);
}

TEST(ClipLines, TouchingAtOnePointGivesNothingInside) {
  const Paths line = {{{-5, 5}, {5, -5}}};  // touches the square's corner (0,0) only
  EXPECT_TRUE(clipLines(line, {kSquare}, FillRule::EvenOdd).empty());
  EXPECT_EQ(clipLines(line, {kSquare}, FillRule::EvenOdd, LinePart::Outside), line);
}

TEST(ClipLines, OverlappingLinesAreEachClipped) {
  const Paths lines = {{{-5, 5}, {15, 5}}, {{2, 5}, {12, 5}}};
  const Paths in = clipLines(lines, {kSquare}, FillRule::EvenOdd);
  ASSERT_EQ(in.size(), 2u);
  EXPECT_EQ(in[0], (Path{{0, 5}, {10, 5}}));
  EXPECT_EQ(in[1], (Path{{2, 5}, {10, 5}}));
}

TEST(ClipLines, ClosedLoopIsNotSplitAtItsStart) {
  // A loop starting at (5,-2) (outside), crossing the square: its inside part is one piece.
  const Paths loop = {{{5, 2}, {12, 2}, {12, 8}, {5, 8}, {5, 2}}};
  const Paths in = clipLines(loop, {kSquare}, FillRule::EvenOdd);
  ASSERT_EQ(in.size(), 1u);
  EXPECT_EQ(in[0], (Path{{10, 8}, {5, 8}, {5, 2}, {10, 2}}));
  EXPECT_EQ(clipLines(loop, {kSquare}, FillRule::EvenOdd, LinePart::Outside),
            (Paths{{{10, 2}, {12, 2}, {12, 8}, {10, 8}}}));
}

TEST(ClipLines, DegenerateAndInvalidInput) {
  EXPECT_TRUE(clipLines({}, {kSquare}, FillRule::EvenOdd).empty());
  EXPECT_TRUE(clipLines({{{1, 1}}, {{2, 2}, {2, 2}}, {}}, {kSquare}, FillRule::EvenOdd).empty());
  EXPECT_TRUE(clipLines({{{1, 1}, {2, 2}}}, {}, FillRule::EvenOdd).empty());
  // Straight-on vertices and repeats are dropped.
  EXPECT_EQ(clipLines({{{1, 1}, {1, 1}, {2, 2}, {3, 3}}}, {kSquare}, FillRule::EvenOdd),
            (Paths{{{1, 1}, {3, 3}}}));
  try {
    clipLines({{{1, 1}, {NAN, 2}}}, {kSquare}, FillRule::EvenOdd);
    FAIL() << "NaN accepted";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("line path 0, vertex 1"), std::string::npos) << e.what();
  }
  EXPECT_THROW(clipLines({{{1, 1}, {2, 2}}}, {{{0, 0}, {1e9, 0}, {0, 1}}}, FillRule::EvenOdd,
                         LinePart::Inside, Grid::fixed(256)),
               InvalidInputError);
}

// Random lines with many degenerate contacts: unit steps on a small grid, against random
// self-intersecting regions on the same grid.
Paths randomLines(std::mt19937& rng, int kind) {
  Paths lines;
  const int count = 1 + int(rng() % 4);
  for (int i = 0; i < count; ++i) {
    if (kind == 0) {
      lines.push_back(testing::randomGridWalk(rng, 2 + int(rng() % 10), 2, 20));
    } else {
      lines.push_back(testing::randomPolygon(rng, 2 + int(rng() % 6), 20));
      if (kind == 2) {
        for (Point& p : lines.back()) p += Point(double(rng() % 256) / 256, 0.5);
      }
    }
  }
  return lines;
}

TEST(ClipLines, PropertyAgainstExactWindingNumbers) {
  std::mt19937 rng(20261122);
  int samples = 0;
  int boundarySamples = 0;
  for (int iteration = 0; iteration < 600; ++iteration) {
    const int kind = iteration % 3;
    const Paths lines = randomLines(rng, kind);
    const Paths region = iteration % 2 == 0
                             ? Paths{testing::randomPolygon(rng, 3 + int(rng() % 10), 20)}
                             : Paths{testing::randomGridWalk(rng, 6 + int(rng() % 16), 2, 20),
                                     testing::randomPolygon(rng, 3 + int(rng() % 5), 20)};
    for (const FillRule rule : kRules) {
      const Paths in = clipLines(lines, region, rule);
      const Paths out = clipLines(lines, region, rule, LinePart::Outside);
      const std::string what = testing::describe(lines) + " region " + testing::describe(region) +
                               " rule " + toString(rule);
      // Inside and outside split every line exactly once.
      ASSERT_NEAR(length(in) + length(out), length(lines), 1e-9 * (1 + length(lines))) << what;
      // Sample points along the input (multiples of 1/4096 px), away from the region's edges.
      for (const Path& line : lines) {
        for (std::size_t i = 1; i < line.size(); ++i) {
          if (line[i] == line[i - 1]) continue;  // a repeated point: nothing to sample
          for (int j = 1; j < 16; ++j) {
            const Point q = line[i - 1] + (line[i] - line[i - 1]) * (double(j) / 16);
            if (testing::distanceToEdges(region, q) < 1e-4) {
              // On (or next to) the region's boundary: in the closed region when a side is filled.
              const std::optional<bool> closure = inClosure(region, rule, q);
              if (closure) {
                ASSERT_EQ(onPolylines(in, q), *closure) << what << " on edge " << q.x << "," << q.y;
                ++boundarySamples;
              }
              continue;
            }
            const auto w = testing::exactWinding(region, q);
            ASSERT_TRUE(w.has_value());
            const bool expected = isFilled(rule, *w);
            ASSERT_EQ(onPolylines(in, q), expected) << what << " at " << q.x << "," << q.y;
            ASSERT_EQ(onPolylines(out, q), !expected) << what << " at " << q.x << "," << q.y;
            ++samples;
          }
        }
      }
    }
  }
  EXPECT_GT(samples, 100000);
  EXPECT_GT(boundarySamples, 2000);
}

// A random convex polygon: the convex hull (Andrew's monotone chain) of random points.
// Integer corners half of the time, so that grid lines run along and through its edges.
Path randomConvex(std::mt19937& rng, int n) {
  Path p = testing::randomPolygon(rng, n, 20);
  if (rng() % 2 == 0) {
    for (Point& q : p) q += Point(double(rng() % 256) / 256, double(rng() % 256) / 256);
  }
  Path hull = testing::convexHull({p}, false)[0];
  if (rng() % 2 == 0) std::reverse(hull.begin(), hull.end());
  return hull;
}

TEST(ClipLines, ConvexPathEqualsSweep) {
  // One convex ring takes the half-plane path; the same ring given three times (+1 +1 -1: the
  // same winding numbers everywhere) goes through the sweep. The pieces must be identical.
  std::mt19937 rng(11);
  int convexCases = 0;
  for (int iteration = 0; iteration < 3000; ++iteration) {
    const Path ring = randomConvex(rng, 3 + int(rng() % 8));
    if (ring.size() < 3) continue;
    Path reversed(ring.rbegin(), ring.rend());
    const Paths lines = randomLines(rng, iteration % 3);
    const FillRule rule = kRules[iteration % 4];
    for (const LinePart part : {LinePart::Inside, LinePart::Outside}) {
      const Paths fast = clipLines(lines, {ring}, rule, part);
      const Paths sweep = clipLines(lines, {ring, ring, reversed}, rule, part);
      ASSERT_EQ(fast, sweep) << testing::describe(lines) << " ring " << testing::describe({ring})
                             << " " << toString(rule) << " " << toString(part);
    }
    ++convexCases;
  }
  EXPECT_GT(convexCases, 2900);
}

namespace bg = boost::geometry;
using BPoint = bg::model::d2::point_xy<double>;
using BLine = bg::model::linestring<BPoint>;
using BMultiLine = bg::model::multi_linestring<BLine>;
using BPolygon = bg::model::polygon<BPoint>;

// A simple star-shaped polygon: valid for Boost.Geometry.
Path randomStar(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> radius(3, 10);
  Path p;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * (i + 0.5 * double(rng() % 100) / 100) / n;
    const double r = radius(rng);
    p.emplace_back(std::round((10 + r * std::cos(a)) * 256) / 256,
                   std::round((10 + r * std::sin(a)) * 256) / 256);
  }
  return p;
}

TEST(ClipLines, AgreesWithBoostGeometryOnSimplePolygons) {
  std::mt19937 rng(7);
  for (int iteration = 0; iteration < 500; ++iteration) {
    const Path star = randomStar(rng, 5 + int(rng() % 20));
    const Paths lines = randomLines(rng, 1 + iteration % 2);
    BPolygon polygon;
    for (const Point& p : star) polygon.outer().emplace_back(p.x, p.y);
    bg::correct(polygon);
    ASSERT_TRUE(bg::is_valid(polygon));
    double boostIn = 0, boostOut = 0;
    for (const Path& line : lines) {
      BLine l;
      for (const Point& p : line) l.emplace_back(p.x, p.y);
      BMultiLine in, out;
      bg::intersection(l, polygon, in);
      bg::difference(l, polygon, out);
      boostIn += static_cast<double>(bg::length(in));
      boostOut += static_cast<double>(bg::length(out));
    }
    const double tolerance = 1e-6 * (1 + length(lines));
    EXPECT_NEAR(length(clipLines(lines, {star}, FillRule::NonZero)), boostIn, tolerance);
    EXPECT_NEAR(length(clipLines(lines, {star}, FillRule::NonZero, LinePart::Outside)), boostOut,
                tolerance);
  }
}

}  // namespace
}  // namespace roiclip
