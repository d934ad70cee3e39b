// SPDX-License-Identifier: MIT
// Rings whose edges overlap along collinear parts (src/core/overlaps.cpp): intersect() against
// the general path, polygon for polygon and vertex for vertex, on sets built to overlap.
#include <gtest/gtest.h>

#include <algorithm>
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

// Whether cancelOverlaps() takes the snapped set (edges cancel somewhere and it is not refused)
// and the rings it leaves visit each point once and are simple or separable at their pinches
// (the sweep-free paths can take them).
bool cancels(const Paths& paths, const Path& roi) {
  const Grid grid = resolveGrid(Options{}.grid, paths, Paths{roi});
  detail::KeptRings kept;
  bool touching = false;
  detail::Workspace ws;
  if (!detail::cancelOverlaps(detail::snapRings(paths, 0, grid), kept, touching, ws.overlaps)) {
    return false;
  }
  const detail::Rings& reduced = kept.rings;
  for (std::vector<detail::IPoint> ring : reduced) {
    std::sort(ring.begin(), ring.end());
    if (std::adjacent_find(ring.begin(), ring.end()) != ring.end()) return false;
  }
  if (!touching) return detail::ringsAreSimple(reduced, ws.chains);
  detail::PinchedRings pinched;
  return detail::separatePinches(reduced, pinched) == detail::Pinches::separated &&
         detail::ringsAreSimple(pinched.separated.rings, ws.chains);
}

// Random tilings: blocks of 1x1, 1x2 and 2x1 cells of a 7x7 grid that do not overlap, each a
// ring (counter-clockwise, now and then reversed): neighbours share whole edges or parts of
// them, diagonal neighbours touch at corners. Against an ROI holding them all and a random
// convex one, under every rule.
TEST(StageOverlaps, RandomTilingsMatchTheGeneralPath) {
  std::mt19937 rng(20261206);
  int taken = 0;
  for (int trial = 0; trial < 400; ++trial) {
    bool used[7][7] = {};
    Paths set;
    const int tries = 3 + int(rng() % 12);
    for (int t = 0; t < tries; ++t) {
      const int x = int(rng() % 7), y = int(rng() % 7);
      const int w = x < 6 && rng() % 3 == 0 ? 2 : 1, h = w == 1 && y < 6 && rng() % 3 == 0 ? 2 : 1;
      bool free = true;
      for (int i = x; i < x + w; ++i) {
        for (int j = y; j < y + h; ++j) free = free && !used[i][j];
      }
      if (!free) continue;
      for (int i = x; i < x + w; ++i) {
        for (int j = y; j < y + h; ++j) used[i][j] = true;
      }
      const double x0 = 10.0 * x, y0 = 10.0 * y, x1 = x0 + 10.0 * w, y1 = y0 + 10.0 * h;
      Path block{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
      if (rng() % 6 == 0) std::reverse(block.begin(), block.end());
      set.push_back(block);
    }
    if (set.size() < 2) continue;
    const Path all{{-10, -10}, {80, -10}, {80, 80}, {-10, 80}};
    std::vector<Point> corners;
    for (int i = 0; i < 3 + int(rng() % 5); ++i) {
      corners.emplace_back(double(rng() % 76) - 3.0, double(rng() % 76) - 3.0);
    }
    const Path hull = testing::convexHull({Path(corners.begin(), corners.end())}, true)[0];
    const FillRule rule = kRules[trial % 4];
    const std::string what = "trial " + std::to_string(trial);
    for (const Path& roi : {all, hull}) {
      if (roi.size() < 3) continue;
      const PolygonSet got = intersect(set, {roi}, rule);
      testing::expectSameSet(got, stages::generalIntersect(set, {roi}, rule, rule), what);
      EXPECT_EQ(testing::structureProblems(got), "") << what;
    }
    taken += cancels(set, all) ? 1 : 0;
  }
  EXPECT_GT(taken, 150) << taken;  // 158; 142 when a wall was cancelled from one end only
}

// Sets the stage takes: a contour running back along part of its own edge, holes sharing parts
// of edges with their outer ring, squares sharing edges (four around a point), a wall whose
// cancelling leaves a ring that comes back to a point. Each against the general path under every
// rule, inside an ROI and across one.
TEST(StageOverlaps, SharedEdgesMatchTheGeneralPath) {
  const Path roi{{-10, -10}, {60, -10}, {60, 60}, {-10, 60}};
  const Path cut{{-10, -10}, {25, -10}, {35, 60}, {-10, 60}};
  const Paths sets[] = {
      // One ring running back along part of its own first edge later on (the input stage drops
      // only a spike, an edge straight back along the one before).
      {{{0, 0}, {40, 0}, {40, 20}, {30, 20}, {30, 0}, {10, 0}, {10, -15}, {0, -15}},
       {{30, 30}, {50, 30}, {50, 50}}},
      // A hole sharing the middle of the outer ring's left edge (a notch): no shared vertex.
      {{{0, 0}, {40, 0}, {40, 40}, {0, 40}}, {{0, 10}, {0, 30}, {15, 30}, {15, 10}}},
      // The same notch with the outer ring's vertices at the wall's ends: equal edges.
      {{{0, 0}, {40, 0}, {40, 40}, {0, 40}, {0, 30}, {0, 10}},
       {{0, 10}, {0, 30}, {15, 30}, {15, 10}}},
      // Two squares sharing a whole edge: one ring, its two straight-on vertices dropped.
      {{{0, 0}, {20, 0}, {20, 20}, {0, 20}}, {{20, 0}, {40, 0}, {40, 20}, {20, 20}}},
      // Four squares around (20, 20): four walls end there, and nothing is left of it.
      {{{0, 0}, {20, 0}, {20, 20}, {0, 20}},
       {{20, 0}, {40, 0}, {40, 20}, {20, 20}},
       {{0, 20}, {20, 20}, {20, 40}, {0, 40}},
       {{20, 20}, {40, 20}, {40, 40}, {20, 40}}},
      // Two squares side by side sharing part of an edge, and a third one's corner on it.
      {{{0, 0}, {20, 0}, {20, 20}, {0, 20}},
       {{20, 5}, {35, 5}, {35, 15}, {20, 15}},
       {{35, 15}, {45, 15}, {45, 25}, {35, 25}}},
      // Diagonal walls whose two sides have their vertices one step apart (W5 scene_05).
      {{{0, 0}, {30, 0}, {30, 30}, {0, 30}},
       {{4, 6}, {16, 18}, {8, 22}, {2, 8}},
       {{4, 6}, {8, 4}, {20, 16}, {18, 20}, {16, 18}}},
      // A hole sharing a wall with its outer ring and touching its corner (20, 50): cancelled,
      // the walk comes back to (20, 50) and is split there into two rings touching at it.
      {{{0, 0}, {40, 0}, {40, 40}, {20, 50}, {0, 40}, {0, 30}, {0, 10}},
       {{0, 10}, {0, 30}, {20, 50}, {25, 20}}},
  };
  int index = 0;
  for (const Paths& set : sets) {
    const std::string what = "set " + std::to_string(index++);
    EXPECT_TRUE(cancels(set, roi)) << what;
    for (const FillRule rule : kRules) {
      for (const Path& c : {roi, cut}) {
        const PolygonSet got = intersect(set, {c}, rule);
        testing::expectSameSet(got, stages::generalIntersect(set, {c}, rule, rule), what);
        EXPECT_EQ(testing::structureProblems(got), "") << what;
      }
    }
  }
}

// Sets it refuses, which then take the sweep: edges along each other the same way, a point
// where two cancelled walls end (two pairings).
TEST(StageOverlaps, RefusesWhatItCannotPair) {
  const Path roi{{-10, -10}, {60, -10}, {60, 60}, {-10, 60}};
  const Paths sets[] = {
      // Two squares whose shared side runs the same way in both.
      {{{0, 0}, {20, 0}, {20, 20}, {0, 20}}, {{20, 0}, {20, 20}, {40, 20}, {40, 0}}},
      // Two squares, each cut along a diagonal into two triangles, touching at (20, 20) where
      // both diagonals end: two arriving edges there lost their successors, and which of the
      // two leaving edges follows which needs the order around the point.
      {{{0, 0}, {20, 20}, {0, 20}},
       {{0, 0}, {20, 0}, {20, 20}},
       {{20, 20}, {40, 40}, {20, 40}},
       {{20, 20}, {40, 20}, {40, 40}}},
  };
  for (const Paths& set : sets) {
    EXPECT_FALSE(cancels(set, roi));
    for (const FillRule rule : kRules) {
      testing::expectSameSet(intersect(set, {roi}, rule),
                             stages::generalIntersect(set, {roi}, rule, rule), "refused");
    }
  }
}

// The W5 groups the stage was written for (tests/data/core/overlap_*.json, in grid units): taken,
// and the same as the general path under every rule.
TEST(StageOverlaps, PixelContourWallsMatchTheGeneralPath) {
  const std::vector<testing::SubjectAndRoi> fixtures = testing::coreFixtures("overlap_");
  for (const auto& [file, set, roi] : fixtures) {
    EXPECT_TRUE(cancels(set, roi)) << file;
    for (const FillRule rule : kRules) {
      testing::expectSameSet(intersect(set, {roi}, rule),
                             stages::generalIntersect(set, {roi}, rule, rule), file);
    }
  }
  EXPECT_EQ(fixtures.size(), 2U);
}

}  // namespace
}  // namespace roiclip
