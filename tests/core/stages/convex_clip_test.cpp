// SPDX-License-Identifier: MIT
// The convex pre-clip (src/core/convex_clip.cpp): which rings count as convex, the exact
// Sutherland-Hodgman step on its own (rings inside pass untouched, rings outside vanish, winding
// numbers inside are kept), and the fast path giving the same region as the general path for
// random self-intersecting subjects and random convex clips, under every pair of fill rules.
#include <gtest/gtest.h>

#include <cmath>

#include <roiclip/roiclip.hpp>

#include "pipeline.hpp"
#include "stage_support.hpp"
#include "support/oracle.hpp"

namespace roiclip {
namespace {

using detail::IPoint;

TEST(ConvexOrientation, RecognisesConvexRingsWindingOnce) {
  EXPECT_EQ(detail::convexOrientation({{0, 0}, {10, 0}, {10, 10}, {0, 10}}), 1);
  EXPECT_EQ(detail::convexOrientation({{0, 0}, {0, 10}, {10, 10}, {10, 0}}), -1);
  EXPECT_EQ(detail::convexOrientation({{0, 0}, {10, 0}, {5, 7}}), 1);
  // Pentagram: every turn has the same sign but it winds twice.
  EXPECT_EQ(detail::convexOrientation({{0, 10}, {6, -8}, {-9, 3}, {9, 3}, {-6, -8}}), 0);
  EXPECT_EQ(detail::convexOrientation({{0, 0}, {10, 10}, {10, 0}, {0, 10}}), 0);  // bow-tie
  EXPECT_EQ(detail::convexOrientation({{0, 0}, {10, 0}, {5, 2}, {10, 10}, {0, 10}}), 0);
  EXPECT_EQ(detail::convexOrientation({{0, 0}, {10, 0}, {5, 0}}), 0);  // reversal
  EXPECT_EQ(detail::convexOrientation({{0, 0}, {10, 0}}), 0);
}

// The pre-clipped edges of `rings` resolved alone (stages 1 to 4), as the fast path does.
PolygonSet resolvePreclipped(const std::vector<detail::ExactEdge>& edges, FillRule rule) {
  const detail::Arrangement a = detail::splitEdges({}, edges, stages::simplifyWith(rule));
  return detail::buildNesting(a, detail::traceContours(a), stages::kUnitGrid);
}

const std::vector<IPoint> kConvex = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};

TEST(ConvexPreclip, RingsInsidePassUntouchedAndRingsOutsideVanish) {
  std::vector<detail::ExactEdge> out;
  detail::preclipConvex({{{2, 2}, {8, 2}, {8, 8}, {2, 8}}}, kConvex, out);
  ASSERT_EQ(out.size(), 4u);
  for (const detail::ExactEdge& e : out) {
    EXPECT_EQ(e.left.w, 1);
    EXPECT_EQ(e.right.w, 1);
    EXPECT_TRUE(e.left.x == 2 || e.left.x == 8);
    EXPECT_TRUE(e.right.y == 2 || e.right.y == 8);
    EXPECT_EQ(e.operand, 0);
  }
  detail::preclipConvex({{{20, 0}, {30, 0}, {30, 10}, {20, 10}}}, kConvex, out);
  EXPECT_TRUE(out.empty());
}

TEST(ConvexPreclip, KeepsWindingNumbersInsideAndNothingOutside) {
  std::vector<detail::ExactEdge> out;
  // A square half over the ring's right side: everything left lies inside the ring.
  detail::preclipConvex({{{5, 5}, {15, 5}, {15, 15}, {5, 15}}}, kConvex, out);
  ASSERT_FALSE(out.empty());
  for (const detail::ExactEdge& e : out) {
    for (std::size_t i = 0; i < kConvex.size(); ++i) {
      const IPoint a = kConvex[i], b = kConvex[(i + 1) % kConvex.size()];
      EXPECT_GE(detail::orient(a, b, e.left), 0);
      EXPECT_GE(detail::orient(a, b, e.right), 0);
    }
  }
  EXPECT_EQ(resolvePreclipped(out, FillRule::NonZero).area(), 25.0);
  // A bow-tie over the ring's right half: its left lobe winds +1, the right one -1; the pre-clip
  // keeps the right lobe with its sign, so Negative keeps it and Positive nothing.
  const std::vector<IPoint> rightHalf = {{5, 0}, {10, 0}, {10, 10}, {5, 10}};
  detail::preclipConvex({{{0, 0}, {10, 10}, {10, 0}, {0, 10}}}, rightHalf, out);
  EXPECT_EQ(resolvePreclipped(out, FillRule::NonZero).area(), 25.0);
  EXPECT_EQ(resolvePreclipped(out, FillRule::Negative).area(), 25.0);
  EXPECT_TRUE(resolvePreclipped(out, FillRule::Positive).empty());
}

// A random convex polygon with sub-pixel corners (multiples of 1/256): sorted random angles.
Path randomConvex(std::mt19937& rng, int corners, bool clockwise) {
  std::uniform_real_distribution<double> angle(0, 2 * M_PI), radius(4, 11);
  std::vector<double> a(corners);
  for (double& v : a) v = angle(rng);
  std::sort(a.begin(), a.end());
  const double r = radius(rng);
  Path p;
  for (double t : a) {
    p.emplace_back(std::round((10 + r * std::cos(t)) * 256) / 256,
                   std::round((10 + r * std::sin(t)) * 256) / 256);
  }
  if (clockwise) std::reverse(p.begin(), p.end());
  return p;
}

TEST(ConvexPath, SameRegionAsGeneralPath) {
  constexpr FillRule kRules[] = {FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive,
                                 FillRule::Negative};
  std::mt19937 rng(31337);
  int compared = 0, convexClips = 0, nonEmpty = 0;
  for (int iter = 0; iter < 300; ++iter) {
    Paths subject;
    switch (iter % 3) {
      case 0:
        subject = {testing::randomPolygon(rng, 5 + int(rng() % 15), 20)};
        break;
      case 1:
        subject = {testing::randomGridWalk(rng, 10 + int(rng() % 30), 1, 20)};
        break;
      default: {
        Path chain = testing::pixelChain(rng, 30 + int(rng() % 60));
        for (Point& q : chain) q += Point(10, 10);
        subject = {chain, testing::randomPolygon(rng, 4, 20)};
      }
    }
    const Paths convex = {randomConvex(rng, 3 + int(rng() % 6), iter % 2 == 1)};
    // Only grid-snapped convex rings take the fast path; make sure this one does.
    const auto rings = detail::snapRings(convex, 1, Grid::fixed(256));
    if (rings.size() != 1 || detail::convexOrientation(rings[0]) == 0) continue;
    ++convexClips;
    for (FillRule rs : kRules) {
      for (FillRule rc : kRules) {
        detail::BooleanSpec how;
        how.binary = true;
        how.op = ClipOp::Intersection;
        how.subjectRule = rs;
        how.clipRule = rc;
        const PolygonSet general = detail::booleanGeneral(subject, &convex, how, Grid::fixed(256));
        const PolygonSet fast = clip(ClipOp::Intersection, subject, convex, rs, rc);
        ASSERT_NEAR(fast.area(), general.area(), 1e-9)
            << toString(rs) << "/" << toString(rc) << " S " << testing::describe(subject) << " C "
            << testing::describe(convex);
        EXPECT_EQ(fast.ringCount(), general.ringCount());
        EXPECT_EQ(testing::structureProblems(fast), "");
        const auto report = testing::sampleRegion(
            fast, {&subject, &convex},
            [&](const std::vector<long long>& w) {
              return isFilled(rs, w[0]) && isFilled(rc, w[1]);
            },
            -1, 21, 60, unsigned(iter));
        ASSERT_EQ(report.mismatches, 0) << report.firstMismatch;
        if (general.area() > 0) ++nonEmpty;
        ++compared;
      }
    }
  }
  EXPECT_GT(convexClips, 250);
  EXPECT_GT(nonEmpty, compared / 4);
}

}  // namespace
}  // namespace roiclip
