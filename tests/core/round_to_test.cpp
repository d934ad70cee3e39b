// SPDX-License-Identifier: MIT
// roundTo(): snap rounding onto a step grid. Every output vertex on the grid, the result valid
// for GEOS (as printed with %.17g), close to the exact region (area within perimeter x step / 2,
// membership unchanged farther than step * sqrt(2) / 2 from the exact boundary).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include <roiclip/roiclip.hpp>

#include "support/geos_validity.hpp"
#include "support/oracle.hpp"

namespace roiclip {
namespace {

using testing::geosValidityProblem;

double perimeter(const PolygonSet& set) {
  double total = 0;
  for (const Path& ring : set.toPaths()) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Point d = ring[(i + 1) % ring.size()] - ring[i];
      total += std::hypot(d.x, d.y);
    }
  }
  return total;
}

// Empty when every vertex is n * step for an integer n, as roundTo() prints it.
std::string offGridVertex(const PolygonSet& set, double step) {
  for (const Path& ring : set.toPaths()) {
    for (const Point& v : ring) {
      for (const double c : {v.x, v.y}) {
        const double n = std::round(c / step);
        if (c != n * step && c != n / (1.0 / step)) return std::to_string(c) + " is off the grid";
      }
    }
  }
  return "";
}

bool inside(const PolygonSet& set, Point p) {
  int w = 0;
  for (const Path& ring : set.toPaths()) w -= testing::ringWinding(ring, p);
  return w == 1;
}

// The checks every rounded result must pass; returns the area error over its bound.
double checkRounded(const PolygonSet& exact, const PolygonSet& rounded, double step,
                    const std::string& what, std::mt19937& rng, double lo, double hi) {
  EXPECT_EQ(geosValidityProblem(rounded), "") << what;
  EXPECT_EQ(testing::structureProblems(rounded), "") << what;
  EXPECT_EQ(offGridVertex(rounded, step), "") << what;
  const double bound = perimeter(exact) * step / 2;
  const double error = std::fabs(rounded.area() - exact.area());
  EXPECT_LE(error, bound) << what;
  // Away from the exact boundary by more than a pixel's half diagonal, nothing changes.
  const testing::SegmentProximity boundary(exact.toPaths(), step * 0.7072);
  std::uniform_real_distribution<double> coord(lo, hi);
  int differ = 0;
  for (int s = 0; s < 200; ++s) {
    const Point p(coord(rng), coord(rng));
    if (boundary.near(p)) continue;
    differ += inside(exact, p) != inside(rounded, p);
  }
  EXPECT_EQ(differ, 0) << what;
  return bound > 0 ? error / bound : 0;
}

TEST(RoundTo, SnapsVerticesToTheStepGrid) {
  const PolygonSet exact =
      simplify({{{0.3, 0.3}, {9.6, 0.2}, {9.7, 9.6}, {0.4, 9.8}}}, FillRule::NonZero);
  const PolygonSet pixels = roundTo(exact, 1.0);
  ASSERT_EQ(pixels.polygons.size(), 1u);
  EXPECT_EQ(pixels.area(), 100.0);
  EXPECT_EQ(pixels.polygons[0].outer.size(), 4u);
  EXPECT_LT(signedArea(pixels.polygons[0].outer), 0);  // the output orientation
  const PolygonSet halves = roundTo(exact, 0.5);
  EXPECT_EQ(halves.area(), 85.5);  // (0.5,0.5) (9.5,0) (9.5,9.5) (0.5,10)
  EXPECT_EQ(offGridVertex(halves, 0.5), "");
  // GIS degrees: 1e-6 steps print as n / 1e6, the double nearest to the decimal.
  const PolygonSet city =
      simplify({{{13.3777777, 52.5111111}, {13.4222222, 52.5166666}, {13.4111111, 52.5333333}}},
               FillRule::NonZero);
  const PolygonSet micro = roundTo(city, 1e-6);
  ASSERT_EQ(micro.polygons.size(), 1u);
  for (const Point& v : micro.polygons[0].outer) {
    EXPECT_EQ(v.x, std::round(v.x * 1e6) / 1e6);
    EXPECT_EQ(v.y, std::round(v.y * 1e6) / 1e6);
  }
  EXPECT_NEAR(micro.area(), city.area(), perimeter(city) * 1e-6 / 2);
}

TEST(RoundTo, PartsThinnerThanAStepVanish) {
  const PolygonSet sliver =
      simplify({{{0, 0.1}, {10, 0.1}, {10, 0.3}, {0, 0.3}}}, FillRule::EvenOdd);
  EXPECT_TRUE(roundTo(sliver, 1.0).empty());
  EXPECT_TRUE(roundTo(PolygonSet{}, 1.0).empty());
}

TEST(RoundTo, RoutesAnEdgeThroughAVertexInsteadOfCrossingIt) {
  // B's apex (5.4, 0.52) lies 0.02 below A's edge (0,0)-(10,1). Rounded on its own it goes to
  // (5,1), above the edge: the parts overlap. Snap rounding routes A's edge through (5,1) too.
  const Paths a = {{{0, 0}, {10, 1}, {10, 5}, {0, 5}}};
  const Paths b = {{{5.4, 0.52}, {7, -3}, {4, -3}}};
  const PolygonSet exact = unite(a, b, FillRule::NonZero);
  ASSERT_EQ(exact.polygons.size(), 2u);
  PolygonSet naive = exact;
  for (Polygon& p : naive.polygons) {
    for (Point& v : p.outer) v = {std::round(v.x), std::round(v.y)};
  }
  EXPECT_NE(geosValidityProblem(naive), "");
  const PolygonSet rounded = roundTo(exact, 1.0);
  EXPECT_EQ(geosValidityProblem(rounded), "");
  ASSERT_EQ(rounded.polygons.size(), 2u);  // touching at (5,1), not overlapping
  EXPECT_NEAR(rounded.area(), exact.area(), perimeter(exact) / 2);
  bool through = false;
  for (const Point& v : rounded.polygons[0].outer) through = through || v == Point(5, 1);
  EXPECT_TRUE(through);
}

TEST(RoundTo, HoleTouchingItsOuterRingStaysInside) {
  // The hole's vertex lies on the outer ring's diagonal edge at a crossing off the grid.
  const Paths shell = {{{0, 0}, {30.3, 10.1}, {30, 30}, {0, 30}}};
  const Paths hole = {{{15.15, 5.05}, {20, 15}, {10, 15}}};
  const PolygonSet exact = subtract(shell, hole, FillRule::NonZero);
  EXPECT_EQ(geosValidityProblem(exact), "");
  std::mt19937 rng(3);
  for (const double step : {1.0, 1.0 / 256, 0.1}) {
    checkRounded(exact, roundTo(exact, step), step, "step " + std::to_string(step), rng, 0, 30);
  }
}

TEST(RoundTo, RejectsBadSteps) {
  const PolygonSet square = simplify({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, FillRule::NonZero);
  EXPECT_THROW(roundTo(square, 0.0), InvalidInputError);
  EXPECT_THROW(roundTo(square, -1.0), InvalidInputError);
  EXPECT_THROW(roundTo(square, NAN), InvalidInputError);
  EXPECT_THROW(roundTo(square, 1e-12), InvalidInputError);  // 1e12 steps across
  PolygonSet broken = square;
  broken.polygons[0].outer[1].x = INFINITY;
  EXPECT_THROW(roundTo(broken, 1.0), InvalidInputError);
}

// Dense random inputs: self-intersecting polygons with many crossings on the 1/256 grid,
// simplified and clipped, rounded to integers and to 1/256.
TEST(RoundTo, DenseRandomInputsStayValidAndClose) {
  std::mt19937 rng(2024);
  std::uniform_int_distribution<int> coord(0, 40 * 256);
  const auto polygon = [&](int n) {
    Path p;
    for (int i = 0; i < n; ++i) p.emplace_back(coord(rng) / 256.0, coord(rng) / 256.0);
    return p;
  };
  double worst[2] = {0, 0};
  int changed = 0, naiveInvalid = 0;
  for (int iter = 0; iter < 60; ++iter) {
    const Paths a = {polygon(20 + iter % 40)};
    const Paths b = {polygon(10 + iter % 15), polygon(5)};
    const PolygonSet results[] = {simplify(a, FillRule::EvenOdd), simplify(a, FillRule::NonZero),
                                  clip(ClipOp::Xor, a, b, FillRule::EvenOdd, FillRule::NonZero),
                                  intersect(a, b, FillRule::EvenOdd)};
    for (const PolygonSet& exact : results) {
      for (int s = 0; s < 2; ++s) {
        const double step = s == 0 ? 1.0 : 1.0 / 256;
        const PolygonSet rounded = roundTo(exact, step);
        changed += rounded.area() != exact.area();
        PolygonSet naive = exact;  // each vertex rounded on its own
        const auto roundRing = [step](Path& ring) {
          for (Point& v : ring) v = {std::round(v.x / step) * step, std::round(v.y / step) * step};
        };
        for (Polygon& p : naive.polygons) {
          roundRing(p.outer);
          for (Path& hole : p.holes) roundRing(hole);
        }
        naiveInvalid += !geosValidityProblem(naive).empty();
        const double ratio = checkRounded(exact, rounded, step,
                                          "step " + std::to_string(step) + " A " +
                                              testing::describe(a) + " B " + testing::describe(b),
                                          rng, 0, 40);
        worst[s] = std::max(worst[s], ratio);
      }
    }
  }
  // The rounding did something (most results have crossings off the grid).
  // Rounding each vertex on its own breaks many of them.
  EXPECT_GT(changed, 200);
  EXPECT_GT(naiveInvalid, 50);
  std::cout << naiveInvalid << " of 480 rounded vertex by vertex are invalid\n";
  std::cout << "area error / (perimeter x step / 2): worst " << worst[0] << " at step 1, "
            << worst[1] << " at step 1/256\n";
}

}  // namespace
}  // namespace roiclip
