// SPDX-License-Identifier: MIT
// PreparedRegion: the clip operand prepared once gives exactly what the free functions give,
// call after call, after calls that threw, and from several threads at once.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <thread>
#include <vector>

#include <roiclip/roiclip.hpp>

#include "support/oracle.hpp"
#include "support/same_set.hpp"

namespace roiclip {
namespace {

constexpr ClipOp kOps[] = {ClipOp::Intersection, ClipOp::Union, ClipOp::Difference, ClipOp::Xor};

const Paths kQuad = {{{30.25, 20.5}, {170.75, 35.5}, {160.5, 180.25}, {25.5, 150.75}}};

// Subjects of several kinds and sizes, large and small mixed so reuse follows both.
std::vector<Paths> subjects() {
  std::mt19937 rng(1312);
  std::vector<Paths> out;
  for (int i = 0; i < 12; ++i) {
    if (i % 3 == 0) {
      Path chain = testing::pixelChain(rng, i == 0 ? 3000 : 200);
      for (Point& q : chain) q += Point(100, 100);
      out.push_back({chain});
    } else if (i % 3 == 1) {
      out.push_back({testing::randomPolygon(rng, 8 + 20 * i, 200)});
    } else {
      out.push_back({testing::randomPolygon(rng, 5, 200), testing::randomPolygon(rng, 7, 200)});
    }
  }
  return out;
}

TEST(PreparedRegion, GivesTheFreeFunctionsResultsOnRandomSubjects) {
  std::mt19937 rng(99);
  const std::vector<Paths> regions = {kQuad, {testing::randomPolygon(rng, 40, 200)}};
  const std::vector<Paths> all = subjects();
  for (std::size_t r = 0; r < regions.size(); ++r) {
    for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
      const PreparedRegion region(regions[r], rule);
      EXPECT_EQ(region.convex(), r == 0);
      std::size_t nonEmpty = 0;
      for (std::size_t i = 0; i < all.size(); ++i) {
        for (ClipOp op : kOps) {
          const std::string what = "region " + std::to_string(r) + " " + toString(rule) +
                                   " subject " + std::to_string(i) + " " + toString(op);
          const PolygonSet want = clip(op, all[i], regions[r], FillRule::NonZero, rule);
          nonEmpty += want.polygons.empty() ? 0 : 1;
          testing::expectSameSet(region.clip(op, all[i], FillRule::NonZero), want, what);
        }
        testing::expectSameSet(
            region.intersect(all[i]),
            clip(ClipOp::Intersection, all[i], regions[r], FillRule::EvenOdd, rule), "intersect");
        // Mixed rules: the subject's own rule is used.
        testing::expectSameSet(
            region.intersect(all[i], FillRule::Positive),
            clip(ClipOp::Intersection, all[i], regions[r], FillRule::Positive, rule),
            "intersect positive");
      }
      EXPECT_GT(nonEmpty, all.size());  // real clipping happened
    }
  }
}

TEST(PreparedRegion, ClipsPolygonSetsAndLinesAsTheFreeFunctions) {
  // PolygonSet subjects have crossings as vertices, which only a fixed grid snaps the same way
  // in both calls; integer lines agree on the default fitted grid too.
  std::mt19937 rng(5);
  const Grid fixed = Grid::fixed(256.0);
  const Paths star = {{{0, 100}, {60, -80}, {-90, 30}, {90, 30}, {-60, -80}}};
  for (const Paths& regionPaths : {kQuad, star}) {
    const PreparedRegion region(regionPaths, FillRule::NonZero, fixed);
    const PolygonSet set =
        simplify({testing::randomPolygon(rng, 30, 200)}, FillRule::EvenOdd, fixed);
    for (ClipOp op : kOps) {
      testing::expectSameSet(region.clip(op, set),
                             clip(op, set, regionPaths, FillRule::NonZero, fixed), "set");
    }
    const PreparedRegion fitted(regionPaths, FillRule::NonZero);
    const Paths lines = {testing::randomPolygon(rng, 20, 200), {{-10, 50}, {210, 60}}};
    for (LinePart part : {LinePart::Inside, LinePart::Outside}) {
      const Paths got = fitted.clipLines(lines, part);
      EXPECT_EQ(got, clipLines(lines, regionPaths, FillRule::NonZero, part));
      EXPECT_FALSE(got.empty());
    }
  }
  const PreparedRegion fromSet(simplify(star, FillRule::NonZero, fixed), fixed);
  const Paths subject = {testing::randomPolygon(rng, 25, 100)};
  testing::expectSameSet(
      fromSet.intersect(subject),
      intersect(subject, simplify(star, FillRule::NonZero, fixed), FillRule::EvenOdd, fixed),
      "from set");
}

// With the default fitted grid the region's grid covers its box grown twice its side on every
// side; a subject reaching beyond it is clipped by the free function, so nothing is refused.
TEST(PreparedRegion, FittedGridHandsFarSubjectsToTheFreeFunction) {
  const PreparedRegion region(kQuad);
  const Paths far = {{{0, 0}, {4e7, 0}, {4e7, 4e7}, {0, 4e7}}};
  testing::expectSameSet(region.intersect(far), intersect(far, kQuad), "far subject");
  EXPECT_NEAR(region.intersect(far).area(), simplify(kQuad, FillRule::EvenOdd).area(), 1e-6);
}

TEST(PreparedRegion, AnExceptionLeavesItReusable) {
  const std::vector<Paths> all = subjects();
  const Paths general = {{{0, 0}, {200, 0}, {100, 180}, {100, 20}}};
  for (const Paths& regionPaths : {kQuad, general}) {
    const PreparedRegion region(regionPaths);
    Paths bad = all[0];
    bad[0][bad[0].size() / 2].y = std::nan("");
    for (std::size_t i = 0; i < all.size(); ++i) {
      try {
        (void)region.clip(ClipOp::Union, bad);
        ADD_FAILURE() << "NaN accepted";
      } catch (const InvalidInputError& e) {
        EXPECT_EQ(e.location().operand, Operand::Subject);
        EXPECT_EQ(e.location().vertex, bad[0].size() / 2);
      }
      EXPECT_THROW((void)region.clipLines(bad), InvalidInputError);
      testing::expectSameSet(
          region.clip(ClipOp::Xor, all[i]),
          clip(ClipOp::Xor, all[i], regionPaths, FillRule::EvenOdd, FillRule::EvenOdd),
          "after a throw");
    }
  }
  // A bad region is reported when the object is made, as the clip operand.
  Paths badRegion = kQuad;
  badRegion[0][2].x = INFINITY;
  try {
    const PreparedRegion region(badRegion);
    ADD_FAILURE() << "infinity accepted";
  } catch (const InvalidInputError& e) {
    EXPECT_EQ(e.location().operand, Operand::Clip);
    EXPECT_EQ(e.location().vertex, 2u);
  }
}

TEST(PreparedRegion, ReleaseMemoryMovesAndThreadsKeepItsResults) {
  const std::vector<Paths> all = subjects();
  PreparedRegion moved(kQuad, FillRule::NonZero);
  std::vector<PolygonSet> want;
  for (const Paths& s : all) want.push_back(moved.intersect(s));
  moved.releaseMemory();
  const PreparedRegion region = std::move(moved);
  for (std::size_t i = 0; i < all.size(); ++i) {
    testing::expectSameSet(region.intersect(all[i]), want[i], "after releaseMemory and a move");
  }
  // One object, four threads at once: a call that finds the memory in use takes its own.
  std::vector<std::vector<PolygonSet>> got(4);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < got.size(); ++t) {
    threads.emplace_back([&, t] {
      for (int round = 0; round < 3; ++round) {
        for (std::size_t k = 0; k < all.size(); ++k) {
          got[t].push_back(region.intersect(all[(k + t) % all.size()]));
        }
      }
    });
  }
  for (std::thread& th : threads) th.join();
  for (std::size_t t = 0; t < got.size(); ++t) {
    for (std::size_t n = 0; n < got[t].size(); ++n) {
      testing::expectSameSet(got[t][n], want[(n % all.size() + t) % all.size()], "threads");
    }
  }
}

// A region of many contours apart and a convex subject: the intersection groups the region's
// rings against the subject, copying each group's rings (a prepared region is shared; only the
// call's own subject lends its rings). Call after call and from threads at once, the result is
// the free function's, and it holds every contour the subject meets.
TEST(PreparedRegion, ManyContoursAgainstAConvexSubjectStayWhole) {
  std::mt19937 rng(5150);
  Paths contours;
  for (int gy = 0; gy < 5; ++gy) {
    for (int gx = 0; gx < 5; ++gx) {
      Path ring = testing::randomPolygon(rng, 6 + int(rng() % 6), 28);
      for (Point& q : ring) q += Point(40.0 * gx, 40.0 * gy);
      contours.push_back(ring);
    }
  }
  const PreparedRegion region(contours, FillRule::NonZero);
  ASSERT_FALSE(region.convex());
  const PolygonSet want =
      clip(ClipOp::Intersection, kQuad, contours, FillRule::EvenOdd, FillRule::NonZero);
  EXPECT_GT(want.polygons.size(), 10u);
  for (int call = 0; call < 3; ++call) {
    testing::expectSameSet(region.clip(ClipOp::Intersection, kQuad), want,
                           "call " + std::to_string(call));
  }
  std::vector<PolygonSet> got(4);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < got.size(); ++t) {
    threads.emplace_back([&, t] {
      for (int round = 0; round < 5; ++round) got[t] = region.clip(ClipOp::Intersection, kQuad);
    });
  }
  for (std::thread& th : threads) th.join();
  for (const PolygonSet& g : got) testing::expectSameSet(g, want, "threads");
}

}  // namespace
}  // namespace roiclip
