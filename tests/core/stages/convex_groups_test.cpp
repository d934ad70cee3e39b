// SPDX-License-Identifier: MIT
// Many contours AND a convex ring, group by group (src/core/convex_groups.cpp): which rings are
// left out and how the rest are grouped, and intersect() against the general path (all rings
// through one sweep), polygon for polygon, vertex for vertex, parents included.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include <roiclip/error.hpp>
#include <roiclip/roiclip.hpp>

#include "convex_sides.hpp"
#include "pipeline.hpp"
#include "stage_support.hpp"
#include "support/oracle.hpp"
#include "support/same_set.hpp"

namespace roiclip {
namespace {

const FillRule kRules[] = {FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive,
                           FillRule::Negative};

Path box(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

struct Grouped {
  bool ok = false;
  detail::RingGroups groups;
};

Grouped groupsOf(const Paths& set, const Path& roi) {
  const Grid grid = resolveGrid(Options{}.grid, set, Paths{roi});
  const detail::Rings rings = detail::snapRings(set, 0, grid);
  const detail::Rings c = detail::snapRings({roi}, 1, grid);
  Grouped out;
  out.ok = detail::groupRingsForConvex(rings, c[0], detail::convexOrientation(c[0]), out.groups);
  return out;
}

// The rings of each group, each group sorted (the order within a group is not specified).
std::vector<std::vector<int>> members(const detail::RingGroups& g) {
  std::vector<std::vector<int>> out;
  for (std::size_t k = 0; k < g.count(); ++k) {
    out.emplace_back(g.rings.begin() + std::ptrdiff_t(g.groupStart[k]),
                     g.rings.begin() + std::ptrdiff_t(g.groupStart[k + 1]));
    std::sort(out.back().begin(), out.back().end());
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(StageConvexGroups, RingsApartFromTheRoiAreLeftOutAndTheRestCutAtGaps) {
  const Path roi = box(0, 0, 100, 100);
  // 0, 1: apart on x inside; 2 inside 0's box (nested); 3 outside a side line; a segment (the
  // snapping drops it); 4 a thin triangle piercing the ROI, every vertex outside it, but no side
  // line apart.
  const Paths set = {box(10, 10, 40, 40),  box(60, 10, 90, 40),  box(20, 20, 30, 30),
                     box(120, 0, 140, 20), {{50, 50}, {55, 55}}, {{-10, 70}, {110, 75}, {-10, 80}}};
  const Grouped g = groupsOf(set, roi);
  ASSERT_TRUE(g.ok);
  EXPECT_EQ(g.groups.apart, 1U);
  const std::vector<std::vector<int>> want = {{0, 2}, {1}, {4}};
  EXPECT_EQ(members(g.groups), want);
}

TEST(StageConvexGroups, CutsAlternateBetweenTheAxes) {
  const Path roi = box(0, 0, 100, 100);
  // No gap on x across all four; on y, {0, 1} and {2, 3}; then on x within each.
  const Paths set = {box(10, 10, 40, 40), box(50, 10, 90, 40), box(30, 60, 60, 90),
                     box(70, 60, 90, 90)};
  const Grouped g = groupsOf(set, roi);
  ASSERT_TRUE(g.ok);
  const std::vector<std::vector<int>> want = {{0}, {1}, {2}, {3}};
  EXPECT_EQ(members(g.groups), want);
  // Boxes that touch (a shared corner) stay one group: the regions may touch there.
  const Grouped touching = groupsOf({box(10, 10, 50, 50), box(50, 50, 90, 90)}, roi);
  ASSERT_TRUE(touching.ok);
  EXPECT_EQ(touching.groups.count(), 1U);
  for (FillRule rule : kRules) {
    testing::expectSameSet(intersect(set, {roi}, rule),
                           stages::generalIntersect(set, {roi}, rule, rule), "four boxes");
  }
}

TEST(StageConvexGroups, RingsAroundTheRoiMustWindZeroInTotal) {
  const Path roi = box(0, 0, 100, 100);
  const Path frame = box(-50, -50, 150, 150);
  Path frameHole = box(-40, -40, 140, 140);
  std::reverse(frameHole.begin(), frameHole.end());
  // A frame and its hole (an image border in RETR_CCOMP): both around the ROI, winding 0 in
  // total. Left out.
  const Grouped framed = groupsOf({frame, frameHole, box(10, 10, 20, 20)}, roi);
  ASSERT_TRUE(framed.ok);
  EXPECT_EQ(framed.groups.apart, 2U);
  EXPECT_EQ(framed.groups.count(), 1U);
  // The frame alone winds around every point of the ROI: no grouping.
  EXPECT_FALSE(groupsOf({frame, box(10, 10, 20, 20)}, roi).ok);
  for (FillRule rule : kRules) {
    const Paths sets[] = {{frame, frameHole, box(10, 10, 20, 20), box(50, 50, 70, 120)},
                          {frame, box(10, 10, 20, 20), box(50, 50, 70, 120)},
                          {frame, frame, box(10, 10, 20, 20)}};
    for (const Paths& set : sets) {
      testing::expectSameSet(intersect(set, {roi}, rule),
                             stages::generalIntersect(set, {roi}, rule, rule), "frames");
    }
  }
}

TEST(StageConvexGroups, TheCrossingBudgetCountsEveryGroup) {
  const Path roi = box(0, 0, 100, 100);
  // Two bow ties far apart: one crossing each, in two groups.
  const Paths set = {{{10, 10}, {30, 30}, {30, 10}, {10, 30}},
                     {{60, 60}, {80, 80}, {80, 60}, {60, 80}}};
  ASSERT_EQ(groupsOf(set, roi).groups.count(), 2U);
  Options options;
  options.limits.maxCrossings = 1;
  EXPECT_THROW(
      clip(ClipOp::Intersection, set, {roi}, FillRule::NonZero, FillRule::NonZero, options),
      ResourceLimitError);
  options.limits.maxCrossings = 2;
  EXPECT_EQ(clip(ClipOp::Intersection, set, {roi}, FillRule::NonZero, FillRule::NonZero, options)
                .polygons.size(),
            4U);
}

// Scenes like an image's contours: cells with a contour, some with holes and islands, some not
// simple, some crossing the ROI or outside it, some touching; an image frame around everything
// in some; the ROI a random convex hull. Coarse scenes make rings touch each other and the ROI.
TEST(StageConvexGroups, RandomScenesMatchTheGeneralPath) {
  std::mt19937 rng(20261203);
  int grouped = 0, inClosed = 0, masksKept = 0, boxInside = 0;
  for (int trial = 0; trial < 240; ++trial) {
    const bool coarse = trial % 4 == 3;
    const double cell = coarse ? 12 : 100;
    Paths set;
    for (int k = 0; k < 16; ++k) {
      const Point centre(cell * (k % 4) + cell / 2, cell * double(k / 4) + cell / 2);
      const double r = cell * std::uniform_real_distribution<double>(0.3, 0.6)(rng);
      Path outer = stages::starShapedRing(rng, 4 + int(rng() % 20), centre, r, 0.5);
      if (rng() % 2 == 0) std::reverse(outer.begin(), outer.end());
      if (rng() % 6 == 0) std::swap(outer[0], outer[outer.size() / 2]);  // not simple
      set.push_back(outer);
      if (rng() % 2 == 0) {
        Path hole = stages::starShapedRing(rng, 3 + int(rng() % 8), centre, r * 0.4, 0.6);
        if (rng() % 3 != 0) std::reverse(hole.begin(), hole.end());
        set.push_back(hole);
        if (rng() % 3 == 0) {
          set.push_back(stages::starShapedRing(rng, 3 + int(rng() % 5), centre, r * 0.15, 0.6));
        }
      }
    }
    if (trial % 5 == 0) {
      set.push_back(box(-cell, -cell, 5 * cell, 5 * cell));
      Path hole = box(-cell / 2, -cell / 2, 4.5 * cell, 4.5 * cell);
      std::reverse(hole.begin(), hole.end());
      set.push_back(hole);
    }
    if (trial % 7 == 0) set.push_back({{cell, cell}, {cell + 1, cell}});  // a segment
    std::vector<Point> corners;
    for (int i = 0; i < 3 + int(rng() % 8); ++i) {
      corners.emplace_back(std::round(std::uniform_real_distribution<double>(0, 4 * cell)(rng)),
                           std::round(std::uniform_real_distribution<double>(0, 4 * cell)(rng)));
    }
    const Path roi = testing::convexHull({Path(corners.begin(), corners.end())}, trial % 2 == 1)[0];
    if (roi.size() < 3) continue;
    const Grouped g = groupsOf(set, roi);
    grouped += g.ok && (g.groups.count() > 1 || g.groups.apart > 0) ? 1 : 0;
    if (g.ok) {  // each ring's flag, which the groups' paths take for ringsInsideConvex()
      const Grid grid = resolveGrid(Options{}.grid, set, Paths{roi});
      const detail::Rings rings = detail::snapRings(set, 0, grid);
      const detail::Rings c = detail::snapRings({roi}, 1, grid);
      ASSERT_EQ(g.groups.inClosed.size(), rings.size());
      // What the grouping keeps of each ring's vertices for Weiler-Atherton (sidesOf()): the
      // masks of every vertex as SideLines classifies it, or every vertex strictly inside C.
      const detail::SideLines sides(c[0], detail::convexOrientation(c[0]));
      for (std::size_t r = 0; r < rings.size(); ++r) {
        if (rings[r].size() < 3) continue;  // apart: in no group
        inClosed += g.groups.inClosed[r] != 0 ? 1 : 0;
        EXPECT_EQ(g.groups.inClosed[r] != 0,
                  detail::ringsInsideConvex({rings[r]}, c[0], detail::convexOrientation(c[0])))
            << "trial " << trial << " ring " << r;
        const detail::KnownSides known = g.groups.sidesOf(r);
        masksKept += known.left != nullptr ? 1 : 0;
        boxInside += known.inside ? 1 : 0;
        for (std::size_t k = 0; k < rings[r].size() && (known.inside || known.left); ++k) {
          const detail::SideLines::Masks m = sides.classify(rings[r][k]);
          EXPECT_EQ(known.inside ? sides.all() : known.left[k], m.left)
              << "trial " << trial << " ring " << r << " vertex " << k;
          EXPECT_EQ(known.inside ? 0U : known.onLine[k], m.zeros)
              << "trial " << trial << " ring " << r << " vertex " << k;
        }
      }
    }
    for (FillRule rule : kRules) {
      testing::expectSameSet(intersect(set, {roi}, rule),
                             stages::generalIntersect(set, {roi}, rule, rule),
                             "trial " + std::to_string(trial));
    }
  }
  EXPECT_GT(grouped, 150);  // the grouped path was taken in most scenes
  EXPECT_GT(inClosed, 500);
  EXPECT_GT(masksKept, 1000);
  EXPECT_GT(boxInside, 300);
}

// placeBox() decides from the unsnapped box what the snapped vertices show: every one in the
// closed outer half-plane of one side of C or at or beyond C's extreme x or y (outside), or every
// one strictly inside C. Random
// rings, simple or not, around and inside random convex ROIs, on integer and on decimal data (a
// decimal grid), against the vertices one by one; and intersect(), which leaves early on either
// answer, against the general path.
TEST(StageConvexGroups, PlaceBoxIsWhereEveryVertexLies) {
  std::mt19937 rng(20261204);
  int outside = 0, inside = 0, insideSimple = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const bool decimal = trial % 3 == 2;
    const auto coordinate = [&](double lo, double hi) {
      const double v = std::uniform_real_distribution<double>(lo, hi)(rng);
      return decimal ? std::round(v * 100) / 100 : std::round(v);
    };
    std::vector<Point> corners;
    for (int i = 0; i < 3 + int(rng() % 6); ++i) {
      corners.emplace_back(coordinate(0, 100), coordinate(0, 100));
    }
    const Path roi = testing::convexHull({Path(corners.begin(), corners.end())}, trial % 2 == 1)[0];
    if (roi.size() < 3) continue;
    // A small ring near or on the ROI's boundary: random points, a star-shaped ring around a
    // point between the ROI's middle and a corner, or a ring along one of its sides (on the side
    // line, just outside, just inside).
    Path ring;
    if (trial % 4 == 0) {
      const std::size_t j = rng() % roi.size();
      const Point a = roi[j], b = roi[(j + 1) % roi.size()];
      const double shift = double(int(trial / 4 % 3) - 1);  // -1, 0, +1: along the outward normal
      const Point n = Point(b.y - a.y, a.x - b.x);          // outward for a counter-clockwise ROI
      const double len = std::hypot(n.x, n.y);
      for (const double t : {0.25, 0.75}) {
        ring.push_back({std::round(a.x + t * (b.x - a.x) + shift * n.x / len * 2),
                        std::round(a.y + t * (b.y - a.y) + shift * n.y / len * 2)});
      }
      ring.push_back({ring[1].x + n.x / len * 5, ring[1].y + n.y / len * 5});
    } else if (trial % 4 != 2) {
      Point mean(0, 0);
      for (const Point& p : roi) mean += p / double(roi.size());
      const Point corner = roi[rng() % roi.size()];
      const double t = std::uniform_real_distribution<double>(0, 1)(rng);
      ring = stages::starShapedRing(rng, 3 + int(rng() % 10), mean + t * (corner - mean),
                                    coordinate(1, 12), 0.5);
      for (Point& p : ring) p = {std::round(p.x), std::round(p.y)};
    } else {
      const double cx = coordinate(-40, 140), cy = coordinate(-40, 140);
      for (int i = 0; i < 3 + int(rng() % 5); ++i) {
        ring.push_back({cx + coordinate(-15, 15), cy + coordinate(-15, 15)});
      }
    }
    const Paths set{ring};
    detail::Box box;
    const Grid grid = detail::resolveGrid(Options{}.grid, set, Paths{roi}, box);
    const detail::Rings c = detail::snapRings({roi}, 1, grid);
    const int orientation = detail::convexOrientation(c[0]);
    if (orientation == 0) continue;
    const detail::Rings rings = detail::snapRings(set, 0, grid);
    bool someSideHasAll = false, strictlyInside = true;
    const std::size_t m = c[0].size();
    for (std::size_t j = 0; j < m; ++j) {
      const detail::IPoint a = c[0][j], b = c[0][(j + 1) % m];
      bool all = true;  // every vertex on the side or right of it (outward)
      for (const auto& r : rings) {
        for (const detail::IPoint p : r) {
          const int o = detail::orient(a, b, p) * orientation;
          all = all && o <= 0;
          strictlyInside = strictlyInside && o > 0;
        }
      }
      someSideHasAll = someSideHasAll || all;
    }
    // Or every vertex at or beyond C's extreme x or y (a half-plane without a point inside C).
    const auto beyond = [&](auto key) {
      std::int64_t cLo = key(c[0][0]), cHi = cLo;
      for (const detail::IPoint p : c[0]) cLo = std::min(cLo, key(p)), cHi = std::max(cHi, key(p));
      bool below = true, above = true;
      for (const auto& r : rings) {
        for (const detail::IPoint p : r)
          below = below && key(p) <= cLo, above = above && key(p) >= cHi;
      }
      return below || above;
    };
    someSideHasAll = someSideHasAll || beyond([](detail::IPoint p) { return p.x; }) ||
                     beyond([](detail::IPoint p) { return p.y; });
    // The box's corners are not vertices: a box may reach past a side where no vertex does, so
    // the box may not tell for a set that lies outside or inside; never the other way round.
    const detail::BoxPlace got = detail::placeBox(box, grid, c[0], orientation);
    if (got == detail::BoxPlace::Outside) {
      EXPECT_TRUE(someSideHasAll) << "trial " << trial;
      ++outside;
    }
    if (got == detail::BoxPlace::Inside) {
      EXPECT_TRUE(strictlyInside) << "trial " << trial;
      ++inside;
      detail::ChainScratch chains;
      insideSimple += rings.size() == 1 && detail::ringIsSimple(rings[0], chains) ? 1 : 0;
    }
    for (FillRule rule : kRules) {
      const PolygonSet result = intersect(set, {roi}, rule);
      testing::expectSameSet(result, stages::generalIntersect(set, {roi}, rule, rule),
                             "trial " + std::to_string(trial));
      testing::expectSameSet(PreparedRegion({roi}, rule).intersect(set, rule), result,
                             "trial " + std::to_string(trial) + ", prepared");
    }
  }
  EXPECT_GT(outside, 100);  // 139, 165 and 155 with this seed
  EXPECT_GT(inside, 100);
  EXPECT_GT(insideSimple, 100);
}

// classifyPath() classifies a vertex only when the path may have reached a side line since the
// last one it classified: every point must still get exactly the masks classify() gives it.
// Random convex rings (3 to kMaxSides corners, pixel-sized and spanning the whole grid range)
// and random paths: unit pixel steps, long jumps, points on the side lines and next to them.
TEST(StageConvexGroups, ClassifyPathGivesEveryPointItsOwnMasks) {
  std::mt19937_64 rng(20261205);
  const auto uniform = [&](std::int64_t lo, std::int64_t hi) {
    return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng);
  };
  constexpr std::int64_t kRange = std::int64_t{1} << 30;  // Grid::kMaxUnits
  std::int64_t points = 0, classified = 0;
  int failures = 0;  // a stale mask is reported for the first few points only
  for (int trial = 0; trial < 400; ++trial) {
    const bool huge = trial % 4 == 3;
    const std::int64_t radius = huge ? kRange / 2 : uniform(4, 600);
    const std::int64_t cx = huge ? 0 : uniform(-1000, 1000), cy = huge ? 0 : uniform(-1000, 1000);
    const int corners = trial % 5 == 4 ? detail::kMaxSides : 3 + int(rng() % 6);
    std::vector<double> angles;
    for (int i = 0; i < corners; ++i) {
      angles.push_back(std::uniform_real_distribution<double>(0, 2 * M_PI)(rng));
    }
    std::sort(angles.begin(), angles.end());
    std::vector<detail::IPoint> convex;
    for (const double a : angles) {
      convex.push_back({cx + std::llround(double(radius) * std::cos(a)),
                        cy + std::llround(double(radius) * std::sin(a) * 0.7)});
    }
    if (trial % 2 == 1) std::reverse(convex.begin(), convex.end());
    const int orientation = detail::convexOrientation(convex);
    if (orientation == 0) continue;
    const detail::SideLines sides(convex, orientation);
    const std::size_t m = convex.size();
    // The path: a walk from a random point, mostly unit steps, sometimes a jump to a point on a
    // side line (a corner plus a multiple of the side's reduced direction) or beside it.
    std::vector<detail::IPoint> path;
    detail::IPoint p{cx + uniform(-radius, radius), cy + uniform(-radius, radius)};
    for (int i = 0; i < 3000; ++i) {
      const int kind = int(rng() % 100);
      if (kind < 3) {
        const std::size_t j = rng() % m;
        const detail::IPoint a = convex[j], b = convex[(j + 1) % m];
        const std::int64_t g = std::gcd(b.x - a.x, b.y - a.y);
        const std::int64_t t = uniform(-2, 2 + int(rng() % 2) * 2);
        p = {a.x + t * (b.x - a.x) / g + uniform(-1, 1) * int(kind == 2),
             a.y + t * (b.y - a.y) / g};
      } else if (kind < 6) {
        p = {cx + uniform(-2 * radius, 2 * radius), cy + uniform(-2 * radius, 2 * radius)};
      } else {
        const std::int64_t step = huge && kind < 50 ? uniform(1, 1 << 20) : 1;
        p = {p.x + uniform(-1, 1) * step, p.y + uniform(-1, 1) * step};
      }
      p = {std::clamp(p.x, -kRange, kRange), std::clamp(p.y, -kRange, kRange)};
      path.push_back(p);
    }
    points += std::int64_t(path.size());
    const auto check = [&](const auto& classify, const auto& reference, const char* what) {
      detail::classifyPath(
          path.data(), path.size(),
          [&](detail::IPoint q, std::int64_t& reach) {
            ++classified;
            return classify(q, reach);
          },
          [&](std::size_t i, detail::SideLines::Masks got) {
            const detail::SideLines::Masks want = reference(path[i]);
            if (failures < 5 && (got.left != want.left || got.zeros != want.zeros)) {
              ++failures;
              ADD_FAILURE() << what << ", trial " << trial << ", point " << i;
            }
          });
    };
    check([&](detail::IPoint q, std::int64_t& reach) { return sides.classify(q, reach); },
          [&](detail::IPoint q) { return sides.classify(q); }, "SideLines");
    detail::withSideCount(sides, [&](auto k) {
      check([&](detail::IPoint q, std::int64_t& reach) { return sides.classify<k()>(q, reach); },
            [&](detail::IPoint q) { return sides.classify<k()>(q); }, "SideLines, unrolled");
    });
    // The other sides' test, as the grouping asks it (the known sides come back set).
    const unsigned known = unsigned(rng()) & sides.all() & ~1U;
    const detail::SideLines::OtherSides asked = sides.otherThan(known);
    check([&](detail::IPoint q, std::int64_t& reach) { return asked.classify(q, reach); },
          [&](detail::IPoint q) { return asked.classify(q); }, "OtherSides");
  }
  // Walks straight through an octagon (sides along the axes and the diagonals) from its middle,
  // in each of the eight directions: points land exactly on side lines after a whole number of
  // steps, where a reach one step too long gives a stale mask.
  for (const std::int64_t scale : {std::int64_t{1}, std::int64_t{3}, std::int64_t{7} << 20}) {
    std::vector<detail::IPoint> octagon = {{10, 0},  {20, 0},  {30, 10}, {30, 20},
                                           {20, 30}, {10, 30}, {0, 20},  {0, 10}};
    for (detail::IPoint& c : octagon) c = {c.x * scale, c.y * scale};
    const detail::SideLines sides(octagon, detail::convexOrientation(octagon));
    // Unit steps on the small octagons; on the large one, steps of `scale` (and of 1 over its
    // first 300 points only).
    for (const std::int64_t step : {std::int64_t{1}, scale}) {
      for (int dx = -1; dx <= 1; ++dx) {
        for (int dy = -1; dy <= 1; ++dy) {
          std::vector<detail::IPoint> path;
          for (std::int64_t i = 0; i <= std::min<std::int64_t>(40 * scale / step, 300); ++i) {
            path.push_back({15 * scale + dx * i * step, 15 * scale + dy * i * step});
          }
          detail::classifyPath(
              path.data(), path.size(),
              [&](detail::IPoint q, std::int64_t& reach) { return sides.classify<8>(q, reach); },
              [&](std::size_t i, detail::SideLines::Masks got) {
                const detail::SideLines::Masks want = sides.classify(path[i]);
                if (failures < 5 && (got.left != want.left || got.zeros != want.zeros)) {
                  ++failures;
                  ADD_FAILURE() << "scale " << scale << ", step " << step << ", direction " << dx
                                << " " << dy << ", point " << i;
                }
              });
        }
      }
    }
  }
  // Most rings are kept, and most points are not classified again: the walks stay away from
  // the side lines most of the time (about 36% classified with this seed).
  EXPECT_GT(points, 300 * 3000);
  EXPECT_LT(classified, points * 3 / 2) << classified << " of " << points * 3;
}

// The box decides only for finite vertices within the grid's range: a NaN or an out-of-range
// vertex far outside the ROI is reported as before, by the free function and a PreparedRegion.
TEST(StageConvexGroups, PlaceBoxLeavesBadVerticesToTheSnapping) {
  const Path roi = box(0, 0, 100, 100);
  detail::Box nanBox;
  nanBox.add({{{200, 200}, {210, std::nan("")}, {220, 230}}});
  EXPECT_FALSE(nanBox.finite);
  EXPECT_EQ(detail::placeBox(nanBox, Grid::fixed(1.0), {{0, 0}, {100, 0}, {100, 100}}, 1),
            detail::BoxPlace::Unknown);
  const Paths withNan{{{200, 200}, {210, std::nan("")}, {220, 230}}};
  EXPECT_THROW(intersect(withNan, {roi}, FillRule::NonZero), InvalidInputError);
  EXPECT_THROW(PreparedRegion({roi}, FillRule::NonZero).intersect(withNan, FillRule::NonZero),
               InvalidInputError);
  const Paths withInfinity{{{200, 200}, {210, INFINITY}, {220, 230}}};
  EXPECT_THROW(intersect(withInfinity, {roi}, FillRule::NonZero), InvalidInputError);
  // On a fixed grid nothing is read before the snapping: out of its range is out of range.
  const Paths far{{{5e9, 5e9}, {5e9 + 10, 5e9}, {5e9, 5e9 + 10}}};
  EXPECT_THROW(intersect(far, {roi}, FillRule::NonZero, Grid::fixed(1.0)), InvalidInputError);
  // The same set without the bad vertex is outside: empty, from both.
  const Paths fine{{{200, 200}, {210, 220}, {220, 230}}};
  EXPECT_TRUE(intersect(fine, {roi}, FillRule::NonZero).empty());
  EXPECT_TRUE(PreparedRegion({roi}, FillRule::NonZero).intersect(fine, FillRule::NonZero).empty());
}

}  // namespace
}  // namespace roiclip
