// SPDX-License-Identifier: MIT
// Clipper 1 (libpolyclipping) as an independent oracle: on random self-intersecting inputs the
// areas of simplify() and clip() agree with Clipper's for every fill rule and operation, within
// the error Clipper makes by rounding crossing points to its integer grid.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <roiclip/roiclip.hpp>

#include "support/clipper1.hpp"
#include "support/oracle.hpp"

namespace roiclip {
namespace {

using testing::measure;
using testing::roundingTolerance;
using testing::toClipper;

constexpr FillRule kRules[] = {FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive,
                               FillRule::Negative};
constexpr ClipOp kOps[] = {ClipOp::Intersection, ClipOp::Union, ClipOp::Difference, ClipOp::Xor};

Paths randomSet(std::mt19937& rng, int kind) {
  if (kind == 0) return {testing::randomPolygon(rng, 5 + int(rng() % 20), 50)};
  if (kind == 1) return {testing::randomGridWalk(rng, 10 + int(rng() % 40), 1, 12)};
  Path chain = testing::pixelChain(rng, 40 + int(rng() % 100));
  for (Point& q : chain) q += Point(25, 25);
  return {chain, testing::randomPolygon(rng, 4, 50)};
}

TEST(ClipperOracle, SimplifyAreasAgree) {
  std::mt19937 rng(2024);
  int compared = 0, agreed = 0, clipperWrong = 0, nonEmpty = 0;
  for (int iter = 0; iter < 300; ++iter) {
    const Paths input = randomSet(rng, iter % 3);
    for (FillRule rule : kRules) {
      ClipperLib::Paths solution;
      ClipperLib::SimplifyPolygons(toClipper(input), solution, toClipper(rule));
      const testing::ClipperMeasure expected = measure(solution);
      const double ours = simplify(input, rule).area();
      if (ours > 0) ++nonEmpty;
      if (std::fabs(ours - std::fabs(expected.area)) > roundingTolerance(expected)) {
        // Disagreement: the slab integration of the exact winding numbers decides.
        const double truth = testing::slabArea(
            {&input}, [&](const std::vector<long long>& w) { return isFilled(rule, w[0]); });
        ASSERT_NEAR(ours, truth, 1e-6 * (truth + 1))
            << toString(rule) << " input " << testing::describe(input);
        if (clipperWrong < 3 && std::getenv("ROICLIP_FIXTURE_OUT") != nullptr) {
          testing::saveFixture(testing::fixtureDir() + "/clipper1_wrong_simplify_" +
                                   std::to_string(clipperWrong) + ".json",
                               "Clipper 1 SimplifyPolygons area is off by more than its rounding; "
                               "slab integration agrees with roiclip",
                               input, nullptr, "simplify", rule, rule);
        }
        ++clipperWrong;
      } else {
        ++agreed;
      }
      ++compared;
    }
  }
  // Most cases must have a filled region to compare (1171 of 1200 at this seed).
  EXPECT_GT(nonEmpty, compared * 3 / 4);
  // Clipper 1 is the oracle for the bulk of cases; it must not disagree more than rarely.
  EXPECT_GT(agreed, compared * 9 / 10);
  std::printf(
      "simplify: %d cases, %d agree with Clipper 1, %d where Clipper 1 is wrong "
      "(slab integration agrees with roiclip)\n",
      compared, agreed, clipperWrong);
}

TEST(ClipperOracle, ClipAreasAgree) {
  std::mt19937 rng(4048);
  int compared = 0, agreed = 0, clipperWrong = 0, nonEmpty = 0;
  for (int iter = 0; iter < 150; ++iter) {
    const Paths a = randomSet(rng, iter % 3);
    const Paths b = randomSet(rng, (iter / 3) % 3);
    for (FillRule ra : kRules) {
      for (FillRule rb : kRules) {
        for (ClipOp op : kOps) {
          ClipperLib::Clipper c;
          c.AddPaths(toClipper(a), ClipperLib::ptSubject, true);
          c.AddPaths(toClipper(b), ClipperLib::ptClip, true);
          ClipperLib::Paths solution;
          ASSERT_TRUE(c.Execute(toClipper(op), solution, toClipper(ra), toClipper(rb)));
          const testing::ClipperMeasure expected = measure(solution);
          const double ours = clip(op, a, b, ra, rb).area();
          if (ours > 0) ++nonEmpty;
          if (std::fabs(ours - expected.area) > roundingTolerance(expected)) {
            const double truth = testing::slabArea({&a, &b}, [&](const std::vector<long long>& w) {
              return testing::combine(op, isFilled(ra, w[0]), isFilled(rb, w[1]));
            });
            ASSERT_NEAR(ours, truth, 1e-6 * (truth + 1))
                << toString(op) << " " << toString(ra) << "/" << toString(rb) << " A "
                << testing::describe(a) << " B " << testing::describe(b);
            if (clipperWrong < 3 && std::getenv("ROICLIP_FIXTURE_OUT") != nullptr) {
              testing::saveFixture(testing::fixtureDir() + "/clipper1_wrong_clip_" +
                                       std::to_string(clipperWrong) + ".json",
                                   "Clipper 1 Execute area is off by more than its rounding; "
                                   "slab integration agrees with roiclip",
                                   a, &b, toString(op), ra, rb);
            }
            ++clipperWrong;
          } else {
            ++agreed;
          }
          ++compared;
        }
      }
    }
  }
  // Most cases must have a filled result to compare (8255 of 9600 at this seed).
  EXPECT_GT(nonEmpty, compared * 3 / 4);
  EXPECT_GT(agreed, compared * 9 / 10);
  std::printf(
      "clip: %d cases, %d agree with Clipper 1, %d where Clipper 1 is wrong "
      "(slab integration agrees with roiclip)\n",
      compared, agreed, clipperWrong);
}

TEST(ClipperOracle, LargePixelContourAgainstQuad) {
  // A closed 8-connected pixel chain of ~70k vertices around a noisy circle of radius 3000,
  // clipped by a perspective quad with sub-pixel corners: the convex path and the general path
  // both agree with Clipper 1.
  std::mt19937 rng(1);
  Path contour;
  double r = 3000;
  int px = 3000, py = 0;
  for (int i = 0; i < 100000; ++i) {
    const double t = 2 * M_PI * i / 100000;
    r += double(int(rng() % 3) - 1);
    const int tx = int(std::lround(r * std::cos(t))), ty = int(std::lround(r * std::sin(t)));
    while (px != tx || py != ty) {
      px += (tx > px) - (tx < px);
      py += (ty > py) - (ty < py);
      contour.emplace_back(px, py);
    }
  }
  ASSERT_GT(contour.size(), 50000u);
  const Paths subject = {contour};
  const Paths quad = {{{-2000.3, -2500.7}, {2600.2, -1800.1}, {2100.9, 2300.4}, {-2400.5, 1900.2}}};
  ClipperLib::Clipper c;
  c.AddPaths(toClipper(subject), ClipperLib::ptSubject, true);
  c.AddPaths(toClipper(quad), ClipperLib::ptClip, true);
  ClipperLib::Paths solution;
  ASSERT_TRUE(c.Execute(ClipperLib::ctIntersection, solution, ClipperLib::pftEvenOdd,
                        ClipperLib::pftEvenOdd));
  const testing::ClipperMeasure expected = measure(solution);
  const PolygonSet convexPath = intersect(subject, quad);
  EXPECT_NEAR(convexPath.area(), expected.area, roundingTolerance(expected));
  // Union and difference take the general path; |A| = |A - Q| + |A n Q| ties them together.
  const double whole = simplify(subject, FillRule::EvenOdd).area();
  EXPECT_NEAR(subtract(subject, quad).area() + convexPath.area(), whole, 1e-6 * whole);
  EXPECT_NEAR(unite(subject, quad).area() + convexPath.area(),
              whole + std::fabs(signedArea(quad[0])), 1e-6 * whole);
}

}  // namespace
}  // namespace roiclip
