// SPDX-License-Identifier: MIT
// The convex pre-clip (src/core/convex_clip.cpp): which rings count as convex, the exact
// Sutherland-Hodgman step on its own (rings inside pass untouched, rings outside vanish, winding
// numbers inside are kept), and the fast path giving the same region as the general path for
// random self-intersecting subjects and random convex clips, under every pair of fill rules.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <roiclip/roiclip.hpp>

#include "pipeline.hpp"
#include "stage_support.hpp"
#include "support/oracle.hpp"
#include "workspace.hpp"

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

// Triangles and quadrilaterals of points at the ends of the grid's range, where the products of
// the orientation test reach 2^62: a ring of at most 4 vertices whose turns all have one sign
// (the exact 128-bit orient()) winds once, so that sign is its convex orientation.
TEST(ConvexOrientation, AgreesWithExactTurnsAtTheRangesEnds) {
  const std::int64_t m = Grid::kMaxUnits;
  const std::int64_t values[] = {-m, -m + 1, -1, 0, 1, m - 1, m};
  std::mt19937 rng(20261203);
  int convex = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    std::vector<IPoint> ring(3 + rng() % 2);
    for (IPoint& p : ring) p = {values[rng() % 7], values[rng() % 7]};
    int turn = 0;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const int o =
          detail::orient(ring[i], ring[(i + 1) % ring.size()], ring[(i + 2) % ring.size()]);
      turn = o == 0 || (turn != 0 && o != turn) ? 2 : turn == 2 ? 2 : o;
    }
    const int expected = turn == 2 ? 0 : turn;
    ASSERT_EQ(detail::convexOrientation(ring), expected) << "trial " << trial;
    convex += expected != 0 ? 1 : 0;
  }
  EXPECT_GT(convex, 1000);
}

// Rings of 3 to 9 vertices: random points on a small grid, rounded star polygons {n/k} (every
// turn one sign, winding k times) and regular polygons, each also reversed and rotated. Oracle:
// every turn has one sign (exact 128-bit orient()) and the turning angles, summed in doubles, come
// to one full turn.
TEST(ConvexOrientation, AgreesWithTheTurningAngleOnRandomRings) {
  std::mt19937 rng(20261203);
  int convex = 0, sameTurnNotOnce = 0;
  for (int trial = 0; trial < 30000; ++trial) {
    std::vector<IPoint> ring;
    const int n = 3 + int(rng() % 7);
    if (trial % 3 == 0) {
      for (int i = 0; i < n; ++i)
        ring.push_back({std::int64_t(rng() % 7), std::int64_t(rng() % 7)});
    } else {
      const int k = trial % 3 == 1 ? 1 : 1 + int(rng() % std::max(1, (n - 1) / 2));
      const double r = 4.0 + double(rng() % 200), phase = double(rng() % 628) / 100.0;
      for (int i = 0; i < n; ++i) {
        const double a = phase + 2.0 * M_PI * double(i * k) / double(n);
        ring.push_back({std::llround(r * std::cos(a)), std::llround(r * std::sin(a))});
      }
    }
    if (rng() % 2 == 0) std::reverse(ring.begin(), ring.end());
    std::rotate(ring.begin(), ring.begin() + std::ptrdiff_t(rng() % ring.size()), ring.end());
    const std::size_t m = ring.size();
    int turn = 0;
    double angle = 0.0;
    for (std::size_t i = 0; i < m; ++i) {
      const IPoint a = ring[i], b = ring[(i + 1) % m], c = ring[(i + 2) % m];
      const int o = detail::orient(a, b, c);
      turn = o == 0 || (turn != 0 && o != turn) ? 2 : turn == 2 ? 2 : o;
      const double ux = double(b.x - a.x), uy = double(b.y - a.y);
      const double vx = double(c.x - b.x), vy = double(c.y - b.y);
      angle += std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
    }
    const bool once = std::fabs(std::fabs(angle) - 2.0 * M_PI) < 1e-6;
    const int expected = turn != 2 && once ? turn : 0;
    ASSERT_EQ(detail::convexOrientation(ring), expected) << "trial " << trial;
    convex += expected != 0 ? 1 : 0;
    sameTurnNotOnce += turn != 2 && !once ? 1 : 0;
  }
  EXPECT_GT(convex, 5000);
  EXPECT_GT(sameTurnNotOnce, 1000);  // stars: every turn one sign, winding more than once
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

// The pre-clip (edges in the quad passed as they are, only chains leaving it clipped) against
// the plain Sutherland-Hodgman reference on whole rings: the same region under every fill rule,
// and the region the subject's winding numbers give inside the quad at sampled points.
Paths toPaths(const detail::Rings& rings) {
  Paths paths;
  for (const auto& r : rings) {
    Path p;
    for (const IPoint q : r) p.emplace_back(double(q.x), double(q.y));
    paths.push_back(p);
  }
  return paths;
}

PolygonSet resolveBoth(const std::vector<detail::InputEdge>& edges,
                       const std::vector<detail::ExactEdge>& exact, FillRule rule) {
  const detail::Arrangement a = detail::splitEdges(edges, exact, stages::simplifyWith(rule));
  return detail::buildNesting(a, detail::traceContours(a), stages::kUnitGrid);
}

// A random ring of `n` vertices on a few lattice lines through the quad's corners and sides, so
// vertices fall on its sides, edges run along them and through its corners.
std::vector<IPoint> snappedRing(std::mt19937& rng, int n, int lo, int hi) {
  std::uniform_int_distribution<int> pick(0, 5), coord(lo, hi);
  const int special[] = {4, 16, 10, 4, 16, 10};  // the quad's sides x = 4, x = 16 ...
  std::vector<IPoint> r;
  for (int i = 0; i < n; ++i) {
    const int x = pick(rng) < 2 ? special[pick(rng)] : coord(rng);
    const int y = pick(rng) < 2 ? special[pick(rng)] : coord(rng);
    r.push_back({x, y});
  }
  return r;
}

void expectSameAsReference(const detail::Rings& rings, const std::vector<IPoint>& convex,
                           std::uint32_t seed) {
  SCOPED_TRACE(testing::describe(toPaths(rings)));
  detail::Rings snapped;  // as snapRings() makes them (repeats and straight runs removed)
  for (const Path& p : toPaths(rings)) {
    auto r = detail::snapRings({p}, 0, stages::kUnitGrid);
    if (!r.empty()) snapped.push_back(r[0]);
  }
  std::vector<detail::ExactEdge> reference, exact;
  std::vector<detail::InputEdge> edges;
  detail::preclipConvexReference(snapped, convex, reference);
  detail::Workspace ws;
  detail::preclipConvex(snapped, convex, detail::convexOrientation(convex), ws, edges, exact);
  const Paths subject = toPaths(snapped), clipPaths = toPaths({convex});
  for (FillRule rule :
       {FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive, FillRule::Negative}) {
    const PolygonSet fast = resolveBoth(edges, exact, rule);
    const PolygonSet slow = resolveBoth({}, reference, rule);
    ASSERT_NEAR(fast.area(), slow.area(), 1e-9) << toString(rule);
    EXPECT_EQ(fast.ringCount(), slow.ringCount()) << toString(rule);
    const auto report = testing::sampleRegion(
        fast, {&subject, &clipPaths},
        [&](const std::vector<long long>& w) { return isFilled(rule, w[0]) && w[1] != 0; }, 0, 22,
        80, seed);
    ASSERT_EQ(report.mismatches, 0) << toString(rule) << " " << report.firstMismatch;
  }
}

const std::vector<IPoint> kQuad = {{4, 4}, {16, 6}, {14, 16}, {5, 12}};
const std::vector<IPoint> kSquare = {{4, 4}, {16, 4}, {16, 16}, {4, 16}};

TEST(ConvexPreclip, SameAsWholeRingReference) {
  // Hand-picked: inside, outside, around the quad, touching its corners, along its sides, on
  // its sides' lines only, crossing a side many times.
  const detail::Rings cases[] = {
      {{{6, 6}, {12, 6}, {12, 12}, {6, 12}}},
      {{{20, 0}, {30, 0}, {30, 10}}},
      {{{0, 0}, {20, 0}, {20, 20}, {0, 20}}},
      {{{4, 4}, {16, 4}, {16, 16}, {4, 16}}},
      {{{4, 4}, {0, 0}, {4, 0}}, {{16, 16}, {20, 16}, {20, 20}}},
      {{{4, 4}, {10, 4}, {10, 0}}},
      {{{0, 4}, {20, 4}, {20, 2}, {0, 2}}},
      {{{4, 8}, {10, 8}, {10, 20}, {4, 20}}},
      {{{8, 8}, {20, 8}, {8, 9}}},
      {{{2, 2}, {18, 2}, {18, 18}, {2, 18}}, {{6, 6}, {6, 10}, {10, 10}, {10, 6}}},
  };
  std::uint32_t seed = 1;
  for (const auto& c : cases) {
    expectSameAsReference(c, kSquare, seed++);
    expectSameAsReference(c, kQuad, seed++);
    std::vector<IPoint> cw(kQuad.rbegin(), kQuad.rend());
    expectSameAsReference(c, cw, seed++);
  }
  // A zigzag crossing the square's bottom side 40 times, in and out of the ring.
  std::vector<IPoint> zigzag;
  for (int i = 0; i <= 20; ++i) zigzag.push_back({i, i % 2 == 0 ? 2 : 6});
  zigzag.push_back({20, 10});
  zigzag.push_back({0, 10});
  expectSameAsReference({zigzag}, kSquare, 100);
  expectSameAsReference({zigzag}, kQuad, 101);
}

TEST(ConvexPreclip, RandomRingsSameAsWholeRingReference) {
  std::mt19937 rng(4242);
  for (int iter = 0; iter < 400; ++iter) {
    detail::Rings rings;
    const int count = 1 + int(rng() % 3);
    for (int r = 0; r < count; ++r) {
      rings.push_back(iter % 4 == 3 ? snappedRing(rng, 3 + int(rng() % 5), 6, 14)
                                    : snappedRing(rng, 3 + int(rng() % 25), 0, 20));
    }
    expectSameAsReference(rings, iter % 2 == 0 ? kQuad : kSquare, std::uint32_t(iter));
    if (HasFatalFailure()) return;
  }
}

}  // namespace
}  // namespace roiclip
