// SPDX-License-Identifier: MIT
// The region-of-interest case without a sweep (src/core/simple_convex.cpp): a simple ring AND a
// convex ring by Weiler-Atherton, against the general path (both operands through the sweep),
// polygon for polygon and vertex for vertex; and the configurations it must leave to the general
// path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <roiclip/roiclip.hpp>

#include "pipeline.hpp"
#include "stage_support.hpp"
#include "support/oracle.hpp"
#include "support/same_set.hpp"
#include "workspace.hpp"

namespace roiclip {
namespace {

const FillRule kRules[] = {FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive,
                           FillRule::Negative};

// Whether Weiler-Atherton takes the case, and if so, that it gives the general path's result;
// and that intersect() (whichever way it goes) gives it too.
bool checkCase(const Path& s, const Path& c, FillRule rule, const std::string& what) {
  const Grid grid = resolveGrid(Options{}.grid, Paths{s}, Paths{c});
  const detail::Rings rs = detail::snapRings({s}, 0, grid);
  const detail::Rings rc = detail::snapRings({c}, 1, grid);
  // intersect() reads both operands with `rule`; Weiler-Atherton is asked only for a filled
  // convex ring (non-zero).
  testing::expectSameSet(intersect({s}, {c}, rule), stages::generalIntersect({s}, {c}, rule, rule),
                         what + ", intersect()");
  const PolygonSet general = stages::generalIntersect({s}, {c}, rule, FillRule::NonZero);
  if (rs.size() != 1 || rc.size() != 1) return false;
  const int orientation = detail::convexOrientation(rc[0]);
  if (orientation == 0) return false;
  detail::Workspace ws;
  PolygonSet direct;
  if (!detail::intersectSimpleConvex(rs[0], rule, rc[0], orientation, grid, ws.chains, ws.weiler,
                                     direct)) {
    EXPECT_TRUE(direct.polygons.empty()) << what;
    return false;
  }
  // Taken: a simple ring, or one that lies outside a side line of the convex ring (nothing).
  EXPECT_TRUE(detail::ringIsSimple(rs[0], ws.chains) || direct.polygons.empty()) << what;
  testing::expectSameSet(direct, general, what + ", Weiler-Atherton");
  return true;
}

Path box(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

TEST(StageSimpleConvex, ContainmentAndDisjointRings) {
  const Path square = box(0, 0, 10, 10);
  for (FillRule rule : kRules) {
    EXPECT_TRUE(checkCase(box(2, 2, 5, 5), square, rule, "subject inside"));
    EXPECT_TRUE(checkCase(box(-20, -20, 30, 30), square, rule, "clip inside"));
    EXPECT_TRUE(checkCase(box(20, 20, 30, 30), square, rule, "disjoint"));
    Path reversed = box(-20, -20, 30, 30);
    std::reverse(reversed.begin(), reversed.end());
    EXPECT_TRUE(checkCase(reversed, square, rule, "clip inside a clockwise subject"));
  }
}

TEST(StageSimpleConvex, ManyCrossingsAndOneEdgeThroughTheWholeRing) {
  const Path roi = {{930, 70}, {1640, 170}, {1560, 1000}, {900, 950}};
  // A comb whose 40 teeth cross the ROI's top side: 80 crossings, 41 pieces. (With the teeth
  // 5 px further right, one would pass through the corner (1640, 170).)
  Path comb = {{800, 5}, {1700, 5}};
  for (int i = 0; i < 40; ++i) {
    const double x = 1695 - 20.0 * i;
    comb.insert(comb.end(), {{x, 300.5}, {x - 10, 300.5}, {x - 10, 30}});
  }
  comb.push_back({800, 30});
  for (FillRule rule : kRules) EXPECT_TRUE(checkCase(comb, roi, rule, "comb"));
  // A thin triangle whose long edge passes through the ROI from side to side: both crossings on
  // one edge of the subject, and the ring is left and re-entered there.
  const Path sliver = {{100, 500}, {2000, 520}, {2000, 530}};
  for (FillRule rule : kRules) EXPECT_TRUE(checkCase(sliver, roi, rule, "sliver"));
  Path reversed(sliver.rbegin(), sliver.rend());
  for (FillRule rule : kRules) EXPECT_TRUE(checkCase(reversed, roi, rule, "sliver, reversed"));
}

TEST(StageSimpleConvex, ARingOutsideOneSideLineGivesNothingSimpleOrNot) {
  const Path square = box(0, 0, 10, 10);
  for (FillRule rule : kRules) {
    // Two lobes pinched at (16, 0) (rotation index 1, not simple) right of x = 10, with two
    // vertices on that line's extension: nothing, without the simple-ring test.
    EXPECT_TRUE(checkCase({{12, -2}, {16, 0}, {20, -2}, {20, 2}, {16, 0}, {12, 2}}, square, rule,
                          "pinched, right"));
    // A triangle above the square with a vertex on the line x = 10.
    EXPECT_TRUE(checkCase({{10, 12}, {14, 16}, {6, 16}}, square, rule, "above, on x = 10"));
    // A bow tie (rotation index 0) below the square leaves before the vertex test: the
    // general path.
    EXPECT_FALSE(checkCase({{0, -5}, {8, -1}, {8, -5}, {0, -1}}, square, rule, "bow tie below"));
  }
  // A ring touching itself across the square: the general path.
  EXPECT_FALSE(checkCase({{-2, -2}, {5, 4}, {12, -2}, {12, 12}, {5, 4}, {-2, 12}}, square,
                         FillRule::NonZero, "pinched across"));
}

TEST(StageSimpleConvex, VerticesOnTheBoundaryGoToTheGeneralPath) {
  const Path square = box(0, 0, 10, 10);
  // An edge along a side's line outside the side, an edge through a corner: resolved by the
  // general path (checkCase compares intersect()).
  EXPECT_FALSE(checkCase({{12, 0}, {15, 0}, {5, 5}}, square, FillRule::NonZero, "on a line"));
  EXPECT_FALSE(checkCase({{-2, -2}, {12, 12}, {-2, 12}}, square, FillRule::NonZero, "corner"));
  // Outside the square along one side: nothing, taken.
  EXPECT_TRUE(checkCase({{2, 0}, {8, 0}, {5, -5}}, square, FillRule::NonZero, "along a side"));
}

// A ring across the convex ring with vertices on its sides: crossing there, touching from inside
// (leaving and entering at one point) or from outside. Taken, as the general path gives it.
TEST(StageSimpleConvex, VerticesOnSidesOfARingAcrossTheConvexRing) {
  const Path square = box(0, 0, 10, 10);
  const std::pair<Path, const char*> cases[] = {
      {{{5, 0}, {12, 5}, {5, 12}}, "touching inside at one, crossing elsewhere"},
      {{{5, 0}, {5, -5}, {12, 5}}, "crossing at a vertex"},
      {{{5, -5}, {5, 0}, {12, 5}, {-3, 5}}, "a vertex on the side, both ways"},
      {{{5, 0}, {8, 4}, {12, 0}, {12, 12}, {-2, 12}, {-2, 0}, {2, 4}}, "two touches from inside"},
      {{{-5, -5}, {15, -5}, {15, 15}, {5, 10}, {-5, 15}}, "around it, touching from outside"},
      {{{5, 10}, {3, 15}, {-5, 5}, {3, -5}, {5, 0}, {7, -5}, {15, 5}, {7, 15}}, "touching at two"},
  };
  // A slot whose tip touches a side from inside: two parts of the result meet at the tip, which
  // the walk does not split; whichever path takes it, intersect() must match the general path.
  const Path slot = {{-5, -5}, {15, -5}, {15, 15}, {7, 15}, {7, 3},
                     {5, 0},   {3, 3},   {3, 15},  {-5, 15}};
  for (FillRule rule : kRules) {
    for (const auto& [ring, what] : cases) {
      EXPECT_TRUE(checkCase(ring, square, rule, what)) << what;
    }
    checkCase(slot, square, rule, "a slot's tip on a side");
  }
}

// A ring across the convex ring with vertices at its corners: near corner j the convex ring is
// the wedge of sides j - 1 and j, so each edge at the vertex is inside or outside by its other
// end. Taken, as the general path gives it.
TEST(StageSimpleConvex, VerticesAtCornersOfARingAcrossTheConvexRing) {
  const Path square = box(0, 0, 10, 10);
  const std::pair<Path, const char*> cases[] = {
      {{{0, 0}, {5, -5}, {5, 5}}, "crossing at a corner"},
      {{{0, 0}, {6, 2}, {15, 5}, {4, 15}, {2, 6}}, "touching a corner from inside"},
      {{{0, 0}, {10, 10}, {0, 15}, {-5, 5}}, "a diagonal from corner to corner"},
      {{{0, 0}, {10, 5}, {15, 15}, {-5, 12}}, "from a corner to the opposite side"},
      {{{0, 0}, {5, -5}, {16, 4}, {10, 10}, {4, 6}}, "crossing at two corners"},
      {{{0, 0}, {-1, -5}, {15, -5}, {15, 15}, {-5, 15}, {-5, -1}}, "around it, touching a corner"},
      {{{0, 0}, {-3, -3}, {3, -3}}, "outside, touching a corner"},
  };
  for (FillRule rule : kRules) {
    for (const auto& [ring, what] : cases) {
      EXPECT_TRUE(checkCase(ring, square, rule, what)) << what;
      Path reversedRing(ring.rbegin(), ring.rend());
      EXPECT_TRUE(checkCase(reversedRing, square, rule, std::string(what) + ", reversed"));
    }
  }
  // Around a diamond whose first corner is its rightmost, a notch's tip at that corner: just
  // right of the corner lies outside the ring, so a ray from the corner tells nothing.
  const Path diamond = {{10, 5}, {5, 10}, {0, 5}, {5, 0}};
  const Path notched = {{-5, -5}, {20, -5}, {20, 4}, {10, 5}, {20, 6}, {20, 20}, {-5, 20}};
  for (FillRule rule : kRules) {
    EXPECT_TRUE(checkCase(notched, diamond, rule, "around it, a notch's tip at a corner"));
  }
  // Around the square, touching all four corners from outside: no corner is left to tell
  // whether the square lies inside; the general path.
  const Path aroundCorners = {{0, 0},   {5, -3}, {10, 0}, {13, 5},
                              {10, 10}, {5, 13}, {0, 10}, {-3, 5}};
  EXPECT_FALSE(checkCase(aroundCorners, square, FillRule::NonZero, "touching every corner"));
  // A corner where two parts of the result meet (the ring touches it from inside, its inside
  // on both sides of the corner's wedge): whichever path takes it, intersect() must match.
  const Path twoParts = {{10, 0}, {15, -5}, {15, 15}, {-5, 15}, {-5, -5}, {4, -5}, {0, 10}};
  for (FillRule rule : kRules) {
    checkCase(twoParts, square, rule, "two parts meeting at a corner");
    checkCase(Path(twoParts.rbegin(), twoParts.rend()), square, rule, "two parts, reversed");
  }
}

// Coarse random rings against coarse random hulls: many vertices on the hull's sides and at its
// corners.
TEST(StageSimpleConvex, RandomRingsWithVerticesOnTheSidesMatchTheGeneralPath) {
  std::mt19937 rng(20261204);
  int takenOnBoundary = 0, takenAtCorner = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const Path s = stages::starShapedRing(rng, 3 + int(rng() % 12), {4, 4}, 4, 0.3);
    Path c = box(0, 0, 1 + double(rng() % 8), 1 + double(rng() % 8));
    if (trial % 2 == 1) {
      std::vector<Point> points;
      for (int i = 0; i < 3 + int(rng() % 5); ++i) {
        points.emplace_back(double(rng() % 9), double(rng() % 9));
      }
      c = testing::convexHull({points}, trial % 4 == 1)[0];
      if (c.size() < 3) continue;
    }
    const bool onSide = std::any_of(s.begin(), s.end(), [&](const Point& p) {
      for (std::size_t j = 0; j < c.size(); ++j) {
        const Point a = c[j], b = c[(j + 1) % c.size()];
        if ((b.x - a.x) * (p.y - a.y) == (b.y - a.y) * (p.x - a.x) && std::min(a.x, b.x) <= p.x &&
            p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y)) {
          return true;
        }
      }
      return false;
    });
    const bool atCorner = std::any_of(s.begin(), s.end(), [&](const Point& p) {
      return std::find(c.begin(), c.end(), p) != c.end();
    });
    const bool taken = checkCase(s, c, kRules[trial % 4], "trial " + std::to_string(trial));
    takenOnBoundary += taken && onSide ? 1 : 0;
    takenAtCorner += taken && atCorner ? 1 : 0;
  }
  EXPECT_GT(takenOnBoundary, 300);
  EXPECT_GT(takenAtCorner, 100);
}

// A simple ring inside the convex ring that touches its boundary (a tag's square at a corner of
// the ROI, a contour along its side) is its own region: taken, as the general path gives it.
TEST(StageSimpleConvex, RingsInsideTouchingTheBoundaryAreTheirOwnRegion) {
  const Path square = box(0, 0, 10, 10);
  for (FillRule rule : kRules) {
    EXPECT_TRUE(checkCase({{2, 0}, {8, 0}, {5, 5}}, square, rule, "edge along a side"));
    EXPECT_TRUE(checkCase({{0, 0}, {4, 1}, {1, 4}}, square, rule, "vertex at a corner"));
    EXPECT_TRUE(checkCase({{5, 0}, {10, 5}, {5, 10}, {0, 5}}, square, rule, "a vertex a side"));
    EXPECT_TRUE(checkCase(square, square, rule, "the square itself"));
    EXPECT_TRUE(checkCase({{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 6}, {5, 5}, {0, 4}}, square,
                          rule, "a notch from a side"));
  }
  // Not simple: the general path, also inside.
  EXPECT_FALSE(checkCase({{0, 0}, {6, 6}, {6, 0}, {0, 6}}, square, FillRule::NonZero, "bow tie"));
}

TEST(StageSimpleConvex, VerticesOnASideLineOutsideTheRingAreCrossingsElsewhere) {
  const Path square = box(0, 0, 10, 10);
  for (FillRule rule : kRules) {
    // (-5, 10) lies on the line of the top side, outside the square; its edges cross the left
    // side, not the top one.
    EXPECT_TRUE(checkCase({{-5, 10}, {-6, 3}, {4, 4}}, square, rule, "vertex on a side line"));
    // Vertices on the lines of two sides (beyond two corners), and an edge between them.
    EXPECT_TRUE(checkCase({{-3, 0}, {5, 5}, {0, 13}}, square, rule, "vertices on two lines"));
  }
}

// Several rings inside the convex ring, touching nothing (a contour group with its holes inside
// the ROI): nested by the chain sweep, as the general path nests them.
TEST(StageSimpleConvex, RingSetsInsideTheConvexRingNestLikeTheGeneralPath) {
  const Path roi = {{0, 0}, {400, -20}, {420, 400}, {-10, 380}};
  std::mt19937 rng(5);
  int taken = 0;
  for (int trial = 0; trial < 100; ++trial) {
    Paths set;
    for (int cell = 0; cell < 9; ++cell) {
      const Point centre(100.0 * (cell % 3) + 100, 100.0 * (cell / 3) + 100);
      Path outer = stages::starShapedRing(rng, 12 + int(rng() % 12), centre, 45, 0.7);
      Path hole = stages::starShapedRing(rng, 6 + int(rng() % 4), centre, 13, 0.7);
      if (rng() % 2 == 0) std::reverse(outer.begin(), outer.end());
      if (rng() % 2 == 0) std::reverse(hole.begin(), hole.end());
      set.push_back(outer);
      if (rng() % 2 == 0) set.push_back(hole);
    }
    if (trial % 10 == 0) set.push_back({{390, 390}, {500, 390}, {500, 500}});  // one crosses
    const Grid grid = resolveGrid(Options{}.grid, set, Paths{roi});
    const detail::Rings rings = detail::snapRings(set, 0, grid);
    const detail::Rings roiRing = detail::snapRings({roi}, 1, grid);
    detail::Workspace ws;
    const bool inside =
        detail::ringsInsideConvex(rings, roiRing[0], detail::convexOrientation(roiRing[0]));
    EXPECT_EQ(inside, trial % 10 != 0) << trial;
    taken += inside && detail::ringsAreSimple(rings, ws.chains) ? 1 : 0;
    for (FillRule rule : kRules) {
      testing::expectSameSet(intersect(set, {roi}, rule),
                             stages::generalIntersect(set, {roi}, rule, rule),
                             "trial " + std::to_string(trial));
    }
  }
  EXPECT_GT(taken, 50);
}

// Random simple rings against random convex rings. Coarse coordinates make vertices land on
// side lines and edges pass through corners (the general path); fine ones mostly not.
TEST(StageSimpleConvex, RandomRingsMatchTheGeneralPath) {
  std::mt19937 rng(20261202);
  int direct = 0, total = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    const double size = trial % 3 == 0 ? 12.0 : 1000.0;
    const Path s =
        stages::starShapedRing(rng, 3 + int(rng() % 60), {size / 2, size / 2}, size / 2, 0.3);
    std::vector<Point> points;
    const int corners = 3 + int(rng() % 6);
    for (int i = 0; i < corners; ++i) {
      points.emplace_back(std::round(std::uniform_real_distribution<double>(0, size)(rng)),
                          std::round(std::uniform_real_distribution<double>(0, size)(rng)));
    }
    const Path c = testing::convexHull({Path(points.begin(), points.end())}, trial % 2 == 1)[0];
    if (c.size() < 3) continue;
    const FillRule rule = kRules[trial % 4];
    direct += checkCase(s, c, rule, "trial " + std::to_string(trial)) ? 1 : 0;
    ++total;
  }
  EXPECT_GT(direct, total / 2);  // Weiler-Atherton took most cases
  EXPECT_LT(direct, total);      // and left some to the general path
}

}  // namespace
}  // namespace roiclip

namespace roiclip {
namespace {

// Weiler-Atherton over a set of rings that touch nothing (intersectSimpleRingsConvex()): whether
// it takes the case, and if so that it gives the general path's result; intersect() must give it
// either way.
bool checkSet(const Paths& set, const Path& c, FillRule rule, const std::string& what) {
  testing::expectSameSet(intersect(set, {c}, rule), stages::generalIntersect(set, {c}, rule, rule),
                         what + ", intersect()");
  const Grid grid = resolveGrid(Options{}.grid, set, Paths{c});
  const detail::Rings rs = detail::snapRings(set, 0, grid);
  const detail::Rings rc = detail::snapRings({c}, 1, grid);
  const int orientation = detail::convexOrientation(rc[0]);
  detail::Workspace ws;
  if (orientation == 0 || !detail::ringsAreSimple(rs, ws.chains)) return false;
  PolygonSet direct;
  if (!detail::intersectSimpleRingsConvex(rs, rule, rc[0], orientation, grid, ws.chains, ws.weiler,
                                          direct)) {
    return false;
  }
  testing::expectSameSet(direct, stages::generalIntersect(set, {c}, rule, FillRule::NonZero),
                         what + ", Weiler-Atherton over the set");
  return true;
}

Path reversed(Path p) {
  std::reverse(p.begin(), p.end());
  return p;
}

TEST(StageSimpleConvex, SetsAcrossTheConvexRingWalkEveryBoundaryRing) {
  const Path roi = box(0, 0, 100, 100);
  // A tag across the ROI's corner: its square crosses two sides, its inner squares lie inside
  // (holes, one with an island), one hole crosses a side too.
  const Paths tag = {box(70, 70, 110, 110), reversed(box(75, 75, 85, 85)),
                     reversed(box(88, 75, 96, 85)), box(90, 78, 94, 82),
                     reversed(box(75, 95, 85, 105))};
  // Two contours across opposite sides, each with a hole inside the ROI, and one inside.
  const Paths pair = {{{-10, 10}, {30, 12}, {28, 40}, {-10, 38}},
                      reversed(box(5, 20, 15, 30)),
                      {{60, -10}, {80, -10}, {82, 30}, {58, 30}},
                      reversed(box(65, 5, 75, 15)),
                      box(40, 45, 50, 55)};
  for (FillRule rule : kRules) {
    EXPECT_TRUE(checkSet(tag, roi, rule, "tag across a corner"));
    EXPECT_TRUE(checkSet(pair, roi, rule, "contours across two sides"));
  }
  // The same orientation nested (non-zero fills through, even-odd makes a hole).
  const Paths sameWay = {{{-10, 10}, {50, 10}, {50, 60}, {-10, 60}}, box(10, 20, 30, 40)};
  EXPECT_TRUE(checkSet(sameWay, roi, FillRule::NonZero, "same way, non-zero"));
  EXPECT_TRUE(checkSet(sameWay, roi, FillRule::EvenOdd, "same way, even-odd"));
}

TEST(StageSimpleConvex, SetsThatNeedMoreGoToTheGeneralPath) {
  const Path roi = box(0, 0, 100, 100);
  // A hole crossing the ROI cuts its outer contour's part into two; a hole inside could lie in
  // either: no point test, the general path.
  const Paths cut = {box(-10, 20, 110, 80), reversed(box(40, -20, 60, 120)),
                     reversed(box(10, 40, 20, 50))};
  // A contour around the whole ROI with a hole across it.
  const Paths around = {box(-50, -50, 150, 150), reversed(box(50, -20, 60, 120))};
  // A hole inside the ROI touching its side, in a contour across it: the walked ring would run
  // through the touching point.
  const Paths holeTouching = {box(-10, -10, 50, 50), reversed({{20, 0}, {30, 10}, {10, 10}})};
  for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
    EXPECT_FALSE(checkSet(cut, roi, rule, "hole in one of two parts"));
    EXPECT_FALSE(checkSet(around, roi, rule, "around the ROI"));
    EXPECT_FALSE(checkSet(holeTouching, roi, rule, "a hole touching a side"));
  }
}

// Vertices on the ROI's boundary: a contour across it with a vertex on a side and one at a
// corner, a tag's square inside touching a corner, one touching a side, a contour outside
// touching a corner. Taken, as the general path gives it.
TEST(StageSimpleConvex, SetsWithVerticesOnTheBoundaryWalkLikeOneRing) {
  const Path roi = box(0, 0, 100, 100);
  const Paths set = {{{50, 0}, {60, -10}, {70, 20}},
                     {{20, -10}, {30, 10}, {10, 10}},
                     {{100, 100}, {120, 90}, {110, 120}, {90, 110}, {80, 80}},
                     box(0, 80, 15, 100),
                     {{40, 100}, {45, 90}, {50, 100}, {45, 95}},
                     {{0, 0}, {-10, 5}, {-10, -10}}};
  for (FillRule rule : kRules) {
    EXPECT_TRUE(checkSet(set, roi, rule, "vertices on the boundary"));
    Paths flipped;
    for (const Path& ring : set) flipped.push_back(reversed(ring));
    EXPECT_TRUE(checkSet(flipped, roi, rule, "vertices on the boundary, reversed"));
  }
}

// Sets of small rings on a coarse grid against coarse hulls: vertices on sides and at corners,
// rings inside touching the boundary, holes touching it.
TEST(StageSimpleConvex, RandomSetsWithVerticesOnTheBoundaryMatchTheGeneralPath) {
  std::mt19937 rng(20261205);
  int taken = 0, takenAtCorner = 0;
  for (int trial = 0; trial < 8000; ++trial) {
    Paths set;
    for (int k = 0; k < 2 + int(rng() % 3); ++k) {
      const Point centre(double(rng() % 13), double(rng() % 13));
      set.push_back(
          stages::starShapedRing(rng, 3 + int(rng() % 6), centre, double(1 + rng() % 4), 0.4));
      if (rng() % 3 == 0) {  // a hole (or island) inside
        set.push_back(reversed(stages::starShapedRing(rng, 3 + int(rng() % 4), centre, 1, 0.5)));
      }
    }
    std::vector<Point> points;
    for (int i = 0; i < 3 + int(rng() % 4); ++i) {
      points.emplace_back(double(2 + rng() % 9), double(2 + rng() % 9));
    }
    const Path roi = testing::convexHull({points}, trial % 2 == 1)[0];
    if (roi.size() < 3) continue;
    const bool atCorner = std::any_of(set.begin(), set.end(), [&](const Path& ring) {
      return std::any_of(ring.begin(), ring.end(), [&](const Point& p) {
        return std::find(roi.begin(), roi.end(), p) != roi.end();
      });
    });
    const bool t = checkSet(set, roi, kRules[trial % 4], "trial " + std::to_string(trial));
    taken += t ? 1 : 0;
    takenAtCorner += t && atCorner ? 1 : 0;
  }
  EXPECT_GT(taken, 800);
  EXPECT_GT(takenAtCorner, 150);
}

// Random sets of concentric star-shaped rings (outer, hole, island, each way round) in a 3 x 3
// layout against random convex hulls over part of it, under four rules.
TEST(StageSimpleConvex, RandomSetsAcrossTheConvexRingMatchTheGeneralPath) {
  std::mt19937 rng(20261203);
  int taken = 0, total = 0;
  for (int trial = 0; trial < 300; ++trial) {
    Paths set;
    for (int cell = 0; cell < 9; ++cell) {
      const Point centre(100.0 * (cell % 3) + 100, 100.0 * (cell / 3) + 100);
      const double radii[] = {45, 25, 10};
      for (int level = 0; level < 1 + int(rng() % 3); ++level) {
        Path ring = stages::starShapedRing(rng, 12 + int(rng() % 14), centre, radii[level], 0.75);
        if (rng() % 2 == 0) std::reverse(ring.begin(), ring.end());
        set.push_back(ring);
      }
    }
    std::vector<Point> corners;
    for (int i = 0; i < 3 + int(rng() % 6); ++i) {
      corners.emplace_back(std::round(std::uniform_real_distribution<double>(30, 370)(rng)),
                           std::round(std::uniform_real_distribution<double>(30, 370)(rng)));
    }
    const Path roi = testing::convexHull({Path(corners.begin(), corners.end())}, trial % 2 == 1)[0];
    if (roi.size() < 3) continue;
    taken += checkSet(set, roi, kRules[trial % 4], "trial " + std::to_string(trial)) ? 1 : 0;
    ++total;
  }
  EXPECT_GT(taken, total / 3);  // the walk over the set took many of them
  EXPECT_LT(taken, total);      // and left some to the general path
}

// The side tests run a loop compiled for each count of 3 to 12 sides and a general one above
// (withSideCount(), convex_sides.hpp): ROIs with 3 to 20 sides, each against one ring across it
// (Weiler-Atherton) and sets of rings across and apart from it (grouping, the walk over the set).
TEST(StageSimpleConvex, EverySideCountGivesTheGeneralPathsResult) {
  std::mt19937 rng(20261204);
  const double pi = std::acos(-1.0);
  for (int m = 3; m <= 20; ++m) {
    Path roi;
    for (int k = 0; k < m; ++k) {
      const double t = 2 * pi * (k + 0.3) / m;
      roi.emplace_back(std::round(500 + 400 * std::cos(t)), std::round(500 + 300 * std::sin(t)));
    }
    const Grid grid = resolveGrid(Options{}.grid, Paths{roi});
    ASSERT_EQ(detail::snapRings({roi}, 1, grid)[0].size(), std::size_t(m)) << m << " sides";
    int taken = 0;
    for (int trial = 0; trial < 12; ++trial) {
      const std::string what = std::to_string(m) + " sides, trial " + std::to_string(trial);
      const FillRule rule = kRules[trial % 4];
      const Path ring = stages::starShapedRing(rng, 8 + int(rng() % 40), {500, 500}, 480, 0.4);
      taken += checkCase(ring, roi, rule, what) ? 1 : 0;
      Paths set;
      for (int k = 0; k < 6; ++k) {
        const Point centre(std::uniform_real_distribution<double>(0, 1000)(rng),
                           std::uniform_real_distribution<double>(0, 1000)(rng));
        set.push_back(stages::starShapedRing(rng, 6 + int(rng() % 12), centre, 60, 0.5));
      }
      checkSet(set, roi, rule, what + ", a set");
    }
    EXPECT_GT(taken, 0) << m << " sides: Weiler-Atherton took none";
  }
}

}  // namespace
}  // namespace roiclip
