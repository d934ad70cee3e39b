// The convex fast path (exact Sutherland-Hodgman pre-clip, then resolve) gives the same region
// as the general path, for random self-intersecting subjects and random convex clips, under
// every pair of fill rules.
#include <gtest/gtest.h>

#include <cmath>

#include <roiclip/roiclip.hpp>

#include "support/oracle.hpp"
#include "pipeline.hpp"

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
    const auto rings = detail::snapRings(convex, 1, Grid{});
    if (rings.size() != 1 || detail::convexOrientation(rings[0]) == 0) continue;
    ++convexClips;
    for (FillRule rs : kRules) {
      for (FillRule rc : kRules) {
        detail::Combination how;
        how.binary = true;
        how.op = ClipOp::Intersection;
        how.subjectRule = rs;
        how.clipRule = rc;
        const PolygonSet general = detail::booleanGeneral(subject, &convex, how, Grid{});
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
