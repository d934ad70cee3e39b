// SPDX-License-Identifier: MIT
// The sweep's own corner cases (src/core/split_edges.cpp), judged by the oracle: chains sharing
// end points, vertical and horizontal runs, collinear chains, one chain crossing many others,
// and a 100k-vertex contour with a single crossing. Exact areas (slabs or closed forms) and
// winding samples.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <roiclip/roiclip.hpp>

#include "support/oracle.hpp"

namespace roiclip {
namespace {

using testing::sampleRegion;
using testing::slabArea;
using testing::structureProblems;

// simplify() under every rule against slab areas and winding samples.
void checkSimplify(const Paths& in, double lo, double hi, const std::string& what) {
  for (FillRule rule :
       {FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive, FillRule::Negative}) {
    SCOPED_TRACE(what + " " + toString(rule));
    const PolygonSet r = simplify(in, rule);
    EXPECT_EQ(structureProblems(r), "");
    const auto inside = [rule](const std::vector<long long>& w) { return isFilled(rule, w[0]); };
    EXPECT_NEAR(r.area(), slabArea({&in}, inside), 1e-9);
    const auto report = sampleRegion(r, {&in}, inside, lo, hi, 600, 3u);
    EXPECT_EQ(report.mismatches, 0) << report.firstMismatch;
    EXPECT_GT(report.checked, 400);
  }
}

// clip() under every operation against slab areas and winding samples.
void checkClip(const Paths& s, const Paths& c, double lo, double hi, const std::string& what) {
  for (ClipOp op : {ClipOp::Intersection, ClipOp::Union, ClipOp::Difference, ClipOp::Xor}) {
    SCOPED_TRACE(what + " " + toString(op));
    const PolygonSet r = clip(op, s, c, FillRule::NonZero, FillRule::NonZero);
    EXPECT_EQ(structureProblems(r), "");
    const auto inside = [op](const std::vector<long long>& w) {
      return testing::combine(op, w[0] != 0, w[1] != 0);
    };
    EXPECT_NEAR(r.area(), slabArea({&s, &c}, inside), 1e-9);
    const auto report = sampleRegion(r, {&s, &c}, inside, lo, hi, 600, 5u);
    EXPECT_EQ(report.mismatches, 0) << report.firstMismatch;
  }
}

TEST(SweepCases, ChainsSharingEndPoints) {
  // Six triangles whose chains all start and end at (10,10), and a square touching them there.
  Paths fan;
  const Point apex(10, 10);
  const Point rim[] = {{20, 10}, {17, 17}, {10, 20}, {3, 17}, {0, 10}, {3, 3}, {10, 0}, {17, 3}};
  for (int i = 0; i < 8; i += 2) fan.push_back({apex, rim[i], rim[i + 1]});
  fan.push_back({apex, rim[7], rim[0]});  // shares the edge apex-rim[0] with the first
  checkSimplify(fan, -1, 21, "fan");
  checkClip(fan, {{{10, 10}, {20, 10}, {20, 20}, {10, 20}}}, -1, 21, "fan and square");
}

TEST(SweepCases, VerticalAndHorizontalRuns) {
  // Crenellations: teeth of vertical and horizontal unit runs, clipped by a box whose sides run
  // along and across them.
  Path teeth;
  for (int i = 0; i < 20; ++i) {
    teeth.emplace_back(2 * i, 0);
    teeth.emplace_back(2 * i, 2);
    teeth.emplace_back(2 * i + 1, 2);
    teeth.emplace_back(2 * i + 1, 0);
  }
  teeth.emplace_back(40, 0);
  teeth.emplace_back(40, -5);
  teeth.emplace_back(0, -5);
  checkSimplify({teeth}, -1, 41, "teeth");
  checkClip({teeth}, {{{1, -3}, {31, -3}, {31, 2}, {1, 2}}}, -1, 41, "teeth and box");
  checkClip({teeth}, {{{-1, 1}, {41, 1}, {41, 4}, {-1, 4}}}, -1, 41, "teeth and strip");
}

TEST(SweepCases, CollinearChains) {
  // A zigzag and its copy shifted along its first edge's direction: their edges overlap in
  // collinear pieces; and the zigzag wound twice (every piece coincident with another).
  Path zig;
  for (int i = 0; i <= 8; ++i) zig.emplace_back(3 * i, i % 2 == 0 ? 0 : 3);
  zig.emplace_back(24, -4);
  zig.emplace_back(0, -4);
  Path shifted = zig;
  for (Point& q : shifted) q += Point(1, 1);
  checkSimplify({zig, shifted}, -5, 26, "zigzag and shift");
  checkClip({zig}, {shifted}, -5, 26, "zigzag against shift");
  Path twice = zig;
  twice.insert(twice.end(), zig.begin(), zig.end());
  checkSimplify({twice}, -5, 26, "zigzag twice");
}

TEST(SweepCases, AChainThatCrossesManyOthers) {
  // A long thin diagonal strip over 40 vertical bars: 160 crossings, many at grid points.
  Paths bars;
  for (int i = 0; i < 40; ++i) {
    bars.push_back({{2.0 * i, 0}, {2.0 * i + 1, 0}, {2.0 * i + 1, 40}, {2.0 * i, 40}});
  }
  const Paths strip = {{{-1, 2}, {81, 38}, {81, 39.5}, {-1, 3.5}}};
  checkClip(bars, strip, -2, 82, "bars and strip");
  Paths together = bars;
  together.push_back(strip[0]);
  checkSimplify(together, -2, 82, "bars with strip");
}

TEST(SweepCases, AHundredThousandVertexContourWithOneCrossing) {
  // A bow-tie whose bottom side is a square wave of 25,000 downward teeth (100k vertices): the
  // two diagonals cross once, at (L/2, H/2); lobes wind +1 (bottom, counter-clockwise in the
  // raw frame) and -1 (top).
  constexpr int kTeeth = 25000;
  constexpr double L = 2.0 * kTeeth, H = 1000;
  Path ring;
  for (int k = 0; k < kTeeth; ++k) {
    ring.emplace_back(2 * k, 0);
    ring.emplace_back(2 * k, -1);
    ring.emplace_back(2 * k + 1, -1);
    ring.emplace_back(2 * k + 1, 0);
  }
  ring.emplace_back(L, 0);
  ring.emplace_back(0, H);
  ring.emplace_back(L, H);
  ASSERT_EQ(ring.size(), 100003u);
  const Paths in = {ring};
  const double lobe = L * H / 4;  // each triangle
  const double teeth = kTeeth;    // unit squares under the bottom lobe
  const struct {
    FillRule rule;
    double area;
  } expected[] = {{FillRule::NonZero, 2 * lobe + teeth},
                  {FillRule::EvenOdd, 2 * lobe + teeth},
                  {FillRule::Positive, lobe + teeth},
                  {FillRule::Negative, lobe}};
  for (const auto& e : expected) {
    SCOPED_TRACE(toString(e.rule));
    const PolygonSet r = simplify(in, e.rule);
    EXPECT_DOUBLE_EQ(r.area(), e.area);
    const auto inside = [&](const std::vector<long long>& w) { return isFilled(e.rule, w[0]); };
    const auto report = sampleRegion(r, {&in}, inside, -2, L + 2, 60, 9u);
    EXPECT_EQ(report.mismatches, 0) << report.firstMismatch;
    EXPECT_GT(report.checked, 50);
  }
  // Through the convex path: a quad over the crossing.
  const Paths quad = {{{L / 4, -0.5}, {3 * L / 4, -0.5}, {3 * L / 4, H}, {L / 4, H}}};
  const PolygonSet r = intersect(in, quad, FillRule::NonZero);
  // Inside x in [L/4, 3L/4]: both lobes' trapezoid parts and the teeth there (y >= -0.5 only).
  const double lobesPart = 2 * (lobe - 2 * (L / 4) * (H / 4) / 2);
  EXPECT_DOUBLE_EQ(r.area(), lobesPart + 0.5 * (kTeeth / 2.0));
  EXPECT_EQ(r.polygons.size(), 2u);
}

}  // namespace
}  // namespace roiclip
