// SPDX-License-Identifier: MIT
// Rings touching at vertices (src/core/pinches.cpp): the sweep-free paths on rings split and
// separated at their pinches, against the general path polygon for polygon and vertex for
// vertex; and the configurations separatePinches() must refuse.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <roiclip/roiclip.hpp>

#include "data_files.hpp"
#include "pipeline.hpp"
#include "stage_support.hpp"
#include "support/oracle.hpp"
#include "support/same_set.hpp"
#include "workspace.hpp"

namespace roiclip {
namespace {

const FillRule kRules[] = {FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive,
                           FillRule::Negative};

// A star-shaped ring around `centre` with `through` as one of its vertices (at its angle), the
// others at random angles and radii in [0.6, 1] of `radius`, rounded to integers; starting at
// `through`.
Path starThrough(std::mt19937& rng, int n, Point centre, double radius, Point through) {
  const double at = std::atan2(through.y - centre.y, through.x - centre.x);
  std::vector<double> angles;
  for (int i = 0; i < n; ++i) {
    const double offset = std::uniform_real_distribution<double>(0.15, 2 * M_PI - 0.15)(rng);
    angles.push_back(offset);
  }
  std::sort(angles.begin(), angles.end());
  Path path{through};
  for (const double a : angles) {
    const double r = radius * std::uniform_real_distribution<double>(0.6, 1.0)(rng);
    path.emplace_back(std::round(centre.x + r * std::cos(at + a)),
                      std::round(centre.y + r * std::sin(at + a)));
  }
  return path;
}

Path reversed(Path p) {
  std::reverse(p.begin() + 1, p.end());  // still starting at the shared vertex
  return p;
}

// The snapped rings of `paths` on the grid intersect() fits, with the ROI.
detail::Rings snapped(const Paths& paths, const Path& roi) {
  const Grid grid = resolveGrid(Options{}.grid, paths, Paths{roi});
  return detail::snapRings(paths, 0, grid);
}

// Whether the pinch path can take the set (separated rings simple).
bool separable(const Paths& paths, const Path& roi) {
  detail::PinchedRings pinched;
  detail::Workspace ws;
  return detail::separatePinches(snapped(paths, roi), pinched) == detail::Pinches::separated &&
         detail::ringsAreSimple(pinched.separated.rings, ws.chains);
}

// The region of `paths` through the stage and the nesting of the separated rings, against
// simplify() on stages 0 to 4. Whether the stage took them.
bool regionMatches(const Paths& paths, FillRule rule, const std::string& what) {
  const Grid grid = resolveGrid(Options{}.grid, paths);
  detail::PinchedRings pinched;
  detail::Workspace ws;
  const detail::Rings rings = detail::snapRings(paths, 0, grid);  // pinched.rings may point here
  if (detail::separatePinches(rings, pinched) != detail::Pinches::separated ||
      !detail::ringsAreSimple(pinched.separated.rings, ws.chains)) {
    return false;
  }
  PolygonSet region;
  if (!detail::pinchedRingsRegion(pinched, rule, ws.chains, grid, region)) return false;
  testing::expectSameSet(region, stages::generalSimplify(paths, rule), what + ", region");
  return true;
}

// Random sets of rings touching at vertices: two rings sharing a vertex (side by side, or one
// inside the other touching it), the same joined into one ring through the vertex twice (a
// figure eight, or a loop inside), either part reversed; against ROIs that hold all of it or cut
// it; every fill rule.
TEST(StagePinches, RandomTouchingRingsMatchTheGeneralPath) {
  std::mt19937 rng(20261206);
  int taken = 0, total = 0, regions = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Point v(200, 200);
    const double angle = std::uniform_real_distribution<double>(0, 2 * M_PI)(rng);
    const Point dir(std::cos(angle), std::sin(angle));
    Path a, b;
    if (trial % 2 == 0) {  // side by side
      a = starThrough(rng, 6 + int(rng() % 10), v + dir * 60.0, 60, v);
      b = starThrough(rng, 6 + int(rng() % 10), v - dir * 50.0, 50, v);
    } else {  // b inside a, touching it at v
      a = starThrough(rng, 6 + int(rng() % 10), v + dir * 80.0, 80, v);
      b = starThrough(rng, 4 + int(rng() % 6), v + dir * 25.0, 22, v);
    }
    if (rng() % 2 == 0) a = reversed(a);
    if (rng() % 2 == 0) b = reversed(b);
    Paths set;
    if (trial % 3 == 0) {  // one ring through v twice
      Path joined = a;
      joined.insert(joined.end(), b.begin(), b.end());
      set.push_back(joined);
    } else {
      set = {a, b};
    }
    // A far ring now and then (a set of more than the touching ones).
    if (trial % 5 == 0) set.push_back(stages::starShapedRing(rng, 8, Point(330, 330), 20, 0.7));
    std::vector<Point> corners;
    const double lo = trial % 4 == 0 ? 0 : 100, hi = trial % 4 == 0 ? 400 : 300;
    for (int i = 0; i < 3 + int(rng() % 6); ++i) {
      corners.emplace_back(std::round(std::uniform_real_distribution<double>(lo, hi)(rng)),
                           std::round(std::uniform_real_distribution<double>(lo, hi)(rng)));
    }
    const Path roi = testing::convexHull({Path(corners.begin(), corners.end())}, trial % 2 == 1)[0];
    if (roi.size() < 3) continue;
    const FillRule rule = kRules[trial % 4];
    const std::string what = "trial " + std::to_string(trial);
    testing::expectSameSet(intersect(set, {roi}, rule),
                           stages::generalIntersect(set, {roi}, rule, rule), what);
    taken += separable(set, roi) ? 1 : 0;
    regions += regionMatches(set, rule, what) ? 1 : 0;
    ++total;
  }
  EXPECT_GT(taken, total / 2);  // most sets touch only at the shared vertex
  EXPECT_GT(regions, total / 2);
}

// Pixel-corner pinches: unit squares touching diagonally (a chessboard), one ring each, and the
// same squares' outline as one ring through each shared corner twice.
TEST(StagePinches, ChessboardSquaresMatchTheGeneralPath) {
  Paths squares;
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      if ((i + j) % 2 != 0) continue;
      const double x = 10 * i, y = 10 * j;
      squares.push_back({{x, y}, {x + 10, y}, {x + 10, y + 10}, {x, y + 10}});
    }
  }
  const Path roi{{-5, -5}, {65, -5}, {65, 65}, {-5, 65}};
  const Path cut{{3, -5}, {60, 12}, {45, 62}, {-5, 30}};
  for (const FillRule rule : kRules) {
    for (const Path& c : {roi, cut}) {
      testing::expectSameSet(intersect(squares, {c}, rule),
                             stages::generalIntersect(squares, {c}, rule, rule), "chessboard");
    }
  }
  EXPECT_TRUE(separable(squares, roi));
  // Two squares touching at a corner, as one ring: a figure eight.
  const Paths eight{{{0, 0}, {10, 0}, {10, 10}, {20, 10}, {20, 20}, {10, 20}, {10, 10}, {0, 10}}};
  for (const FillRule rule : kRules) {
    testing::expectSameSet(intersect(eight, {roi}, rule),
                           stages::generalIntersect(eight, {roi}, rule, rule), "figure eight");
  }
  EXPECT_TRUE(separable(eight, roi));
  for (const FillRule rule : kRules) {
    EXPECT_TRUE(regionMatches(eight, rule, "figure eight"));
    EXPECT_TRUE(regionMatches(squares, rule, "chessboard"));
  }
  const PolygonSet out = intersect(eight, {roi}, FillRule::NonZero);
  ASSERT_EQ(out.polygons.size(), 2U);  // split at the shared corner, as stages 1 to 4 do
}

// Pinches that join rings in a cycle: stages 1 to 4 split the region there into other rings
// than the given ones. A hole touching its outer ring at two vertices leaves two polygons (not
// one with a hole touching its boundary twice): inside the ROI the stage traces those rings
// itself; across the ROI's boundary it refuses them. A ring inside the ROI touching two rings
// that both cross its boundary, which the walked rings join.
TEST(StagePinches, CyclesOfPinchesMatchTheGeneralPath) {
  const Path outer{{0, 0}, {40, 0}, {40, 20}, {45, 40}, {0, 40}, {-5, 20}};
  const Path hole{{-5, 20}, {20, 30}, {40, 20}, {20, 10}};
  const Path all{{-10, -10}, {50, -10}, {50, 50}, {-10, 50}};
  const Path cut{{-10, -10}, {30, -10}, {30, 50}, {-10, 50}};
  for (const Paths& set :
       {Paths{outer, hole}, Paths{outer, reversed(hole)}, Paths{reversed(outer), hole}}) {
    for (const FillRule rule : kRules) {
      EXPECT_TRUE(regionMatches(set, rule, "two pinches")) << int(rule);
      for (const Path& c : {all, cut}) {
        testing::expectSameSet(intersect(set, {c}, rule),
                               stages::generalIntersect(set, {c}, rule, rule), "two pinches");
      }
    }
  }
  EXPECT_EQ(intersect({outer, hole}, {all}, FillRule::EvenOdd).polygons.size(), 2U);
  // d touches the outer ring at (-5, 50) and the hole at its corner (30, 40); the ROI cuts both
  // of them, and the region inside it falls apart into two polygons through both pinches.
  const Path o{{0, 0}, {100, 0}, {100, 100}, {0, 100}, {-5, 50}};
  const Path h{{30, 40}, {30, 60}, {90, 60}, {90, 40}};
  const Path d{{-5, 50}, {12, 50}, {30, 40}, {12, 42}};
  const Path roi{{-10, -10}, {80, -10}, {80, 110}, {-10, 110}};
  const Paths bridged{o, h, d};
  EXPECT_TRUE(separable(bridged, roi));  // a tree of pinches: the cycle comes from the ROI
  for (const FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
    const PolygonSet got = intersect(bridged, {roi}, rule);
    testing::expectSameSet(got, stages::generalIntersect(bridged, {roi}, rule, rule), "bridged");
    EXPECT_EQ(got.polygons.size(), 2U);
  }
}

// Random holes touching their outer ring at two or three vertices (a cycle of pinches in one
// face: the stage must refuse or match), with an island touching the hole now and then (a pinch
// between two faces, which it may take), either ring reversed, against ROIs that hold them or
// cut them, under every rule.
TEST(StagePinches, RandomHolesTouchingTheirOuterRingMatchTheGeneralPath) {
  std::mt19937 rng(20261207);
  const Point c(200, 200);
  int taken = 0;
  for (int trial = 0; trial < 300; ++trial) {
    // A convex outer ring: points on a circle at sorted random angles.
    const int n = 8 + int(rng() % 10);
    std::vector<double> angles;
    for (int i = 0; i < n; ++i) {
      angles.push_back(std::uniform_real_distribution<double>(0, 2 * M_PI)(rng));
    }
    std::sort(angles.begin(), angles.end());
    Path outer;
    for (const double a : angles) {
      outer.emplace_back(std::round(c.x + 150 * std::cos(a)), std::round(c.y + 150 * std::sin(a)));
    }
    // The hole through `touches` of the outer ring's vertices, inward points between them.
    const int touches = 2 + int(trial % 2);
    std::vector<int> at;
    for (int t = 0; t < touches; ++t) at.push_back(t * n / touches + int(rng() % 2));
    Path hole;
    for (int t = 0; t < touches; ++t) {
      const int from = at[std::size_t(t)],
                to = t + 1 < touches ? at[std::size_t(t) + 1] : at[0] + n;
      hole.push_back(outer[std::size_t(from % n)]);
      const double a0 = angles[std::size_t(from % n)] + (from >= n ? 2 * M_PI : 0);
      const double a1 = angles[std::size_t(to % n)] + (to >= n ? 2 * M_PI : 0);
      const int inner = 1 + int(rng() % 3);
      for (int i = 1; i <= inner; ++i) {
        const double a = a0 + (a1 - a0) * i / (inner + 1);
        const double r = std::uniform_real_distribution<double>(40, 110)(rng);
        hole.emplace_back(std::round(c.x + r * std::cos(a)), std::round(c.y + r * std::sin(a)));
      }
    }
    Paths set{rng() % 2 == 0 ? outer : reversed(outer), rng() % 2 == 0 ? hole : reversed(hole)};
    if (trial % 3 == 0) {
      // An island in the hole touching it at the hole's first inward point.
      const Point v = hole[1];
      const Point towards = (c - v) * (12.0 / std::max(1.0, std::hypot(c.x - v.x, c.y - v.y)));
      set.push_back({v, v + towards + Point(-towards.y, towards.x) * 0.5,
                     v + towards - Point(-towards.y, towards.x) * 0.5});
      for (Point& p : set.back()) p = Point(std::round(p.x), std::round(p.y));
    }
    const Path all{{0, 0}, {400, 0}, {400, 400}, {0, 400}};
    const Path cut{
        {0, 0}, {220 + double(rng() % 60), 0}, {180 + double(rng() % 60), 400}, {0, 400}};
    const FillRule rule = kRules[trial % 4];
    const std::string what = "trial " + std::to_string(trial);
    for (const Path& roi : {all, cut}) {
      testing::expectSameSet(intersect(set, {roi}, rule),
                             stages::generalIntersect(set, {roi}, rule, rule), what);
    }
    taken += regionMatches(set, rule, what) ? 1 : 0;
    EXPECT_TRUE(testing::structureProblems(intersect(set, {all}, rule)).empty()) << what;
  }
  // The stage traces the rings of a face that pinches join in a cycle (232 of 300 taken; 119
  // when it refused them, taking only the sets where one ring bounds nothing).
  EXPECT_GT(taken, 200);
}

// A ring through a vertex twice is split there, and the pairs of visits are moved to the split
// rings (not found again): the pinches and the separated rings must be those the stage makes of
// the split rings given as they are. Rings through v twice (a figure eight or a loop inside,
// either part reversed), with another ring touching them at a second vertex now and then.
TEST(StagePinches, SplitRingsKeepTheirPinches) {
  std::mt19937 rng(20261208);
  const Path roi{{-1000, -1000}, {1000, -1000}, {1000, 1000}, {-1000, 1000}};
  int compared = 0, withSecond = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Point v(200, 200);
    const double angle = std::uniform_real_distribution<double>(0, 2 * M_PI)(rng);
    const Point dir(std::cos(angle), std::sin(angle));
    const bool inside = trial % 2 == 1;
    Path a = starThrough(rng, 6 + int(rng() % 10), v + dir * (inside ? 80.0 : 60.0),
                         inside ? 80 : 60, v);
    Path b = inside ? starThrough(rng, 4 + int(rng() % 6), v + dir * 25.0, 22, v)
                    : starThrough(rng, 6 + int(rng() % 10), v - dir * 50.0, 50, v);
    if (rng() % 2 == 0) a = reversed(a);
    if (rng() % 2 == 0) b = reversed(b);
    Path joined = a;
    joined.insert(joined.end(), b.begin(), b.end());
    Paths set{joined};
    if (trial % 3 == 0) {  // a ring outside touching a at one of its other vertices
      const Point u = a[a.size() / 2];
      const Point centre = v + dir * (inside ? 80.0 : 60.0);
      const Point out =
          (u - centre) * (20.0 / std::max(1.0, std::hypot(u.x - centre.x, u.y - centre.y)));
      set.push_back(starThrough(rng, 5, u + out, 18, u));
    }
    const detail::Rings rings = snapped(set, roi);
    detail::PinchedRings once, again;
    if (detail::separatePinches(rings, once) != detail::Pinches::separated) continue;
    // Snapping may leave v out of the joined ring (a straight-on vertex): nothing was split.
    if (once.rings == &rings) continue;
    const detail::Rings split = *once.rings;
    ASSERT_EQ(detail::separatePinches(split, again), detail::Pinches::separated) << trial;
    EXPECT_EQ(once.separated.rings, again.separated.rings) << trial;
    // The same pinches, in any order.
    const auto listed = [](const detail::PinchedRings& p) {
      std::vector<std::array<std::int64_t, 4>> list;
      for (const auto& pinch : p.pinches)
        list.push_back({pinch.at.x, pinch.at.y, pinch.ring, pinch.other});
      std::sort(list.begin(), list.end());
      return list;
    };
    EXPECT_EQ(listed(once), listed(again)) << trial;
    ++compared;
    withSecond += once.pinches.size() > 1 ? 1 : 0;
  }
  EXPECT_GT(compared, 150);
  EXPECT_GT(withSecond, 20);
}

// The pinch fixtures (tests/data/core/pinch_*.json: holes touching their outer ring twice and
// three times, one of them W5 scene_08's; an island above a piece cut at its smallest vertex):
// taken by the stage inside the ROI, and the same as the general path against it, under every
// rule.
TEST(StagePinches, FixturesMatchTheGeneralPath) {
  const std::vector<testing::SubjectAndRoi> fixtures = testing::coreFixtures("pinch_");
  for (const auto& [file, set, roi] : fixtures) {
    for (const FillRule rule : kRules) {
      EXPECT_TRUE(regionMatches(set, rule, file)) << int(rule);
      testing::expectSameSet(intersect(set, {roi}, rule),
                             stages::generalIntersect(set, {roi}, rule, rule), file);
    }
  }
  EXPECT_EQ(fixtures.size(), 3U);
}

TEST(StagePinches, RefusesWhatItCannotSeparate) {
  const Path roi{{-50, -50}, {50, -50}, {50, 50}, {-50, 50}};
  // Two rings crossing at a shared vertex.
  const Paths crossing{{{0, 0}, {20, 10}, {20, -10}},
                       {{0, 0}, {-20, -10}, {-20, 10}},
                       {{0, 0}, {10, 20}, {-10, 20}}};
  detail::PinchedRings pinched;
  EXPECT_EQ(detail::separatePinches(snapped(crossing, roi), pinched),
            detail::Pinches::overlapping);  // three visits: the overlap stage's case
  const Paths x{{{0, 0}, {20, 10}, {20, 20}, {-20, -10}, {-20, -20}},
                {{0, 0}, {-10, 20}, {-20, 20}, {10, -20}, {20, -20}}};
  EXPECT_EQ(detail::separatePinches(snapped(x, roi), pinched), detail::Pinches::refused);
  // The same as one ring through the vertex twice: split there, then found crossing.
  Path xJoined = x[0];
  xJoined.insert(xJoined.end(), x[1].begin(), x[1].end());
  EXPECT_EQ(detail::separatePinches(snapped({xJoined}, roi), pinched), detail::Pinches::refused);
  EXPECT_FALSE(separable(x, roi));
  // Edges overlapping at the shared vertex.
  const Paths overlap{{{0, 0}, {20, 0}, {20, 20}}, {{0, 0}, {10, 0}, {10, -20}}};
  EXPECT_EQ(detail::separatePinches(snapped(overlap, roi), pinched), detail::Pinches::overlapping);
  // A vertex of a third ring on an edge at the pinch: the kept pass there touches it.
  const Paths onEdge{
      {{0, 0}, {10, 10}, {0, 10}}, {{0, 0}, {-10, -10}, {0, -10}}, {{-5, 5}, {5, -5}, {10, -20}}};
  EXPECT_FALSE(separable(onEdge, roi));
  // No vertex visited twice.
  EXPECT_EQ(detail::separatePinches(snapped({{{0, 0}, {10, 0}, {0, 10}}}, roi), pinched),
            detail::Pinches::none);
  // Unit coordinates on the unit grid: no low zero bits to cut a corner with.
  const detail::Rings unit{{{0, 0}, {10, 0}, {10, 10}}, {{10, 10}, {20, 10}, {20, 20}}};
  EXPECT_EQ(detail::separatePinches(unit, pinched), detail::Pinches::none);
  for (const Paths* set : {&x, &overlap, &onEdge}) {
    for (const FillRule rule : kRules) {
      testing::expectSameSet(intersect(*set, {roi}, rule),
                             stages::generalIntersect(*set, {roi}, rule, rule), "refused");
    }
  }
}

}  // namespace
}  // namespace roiclip
