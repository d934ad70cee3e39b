// SPDX-License-Identifier: MIT
// Stage 0, the simple-ring test (src/core/simple_ring.cpp): the monotone-chain sweep's verdict
// against a brute-force test of every pair of edges, and the region of a simple ring against
// what stages 1 to 4 make of it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <roiclip/roiclip.hpp>

#include "limit_shapes.hpp"
#include "pipeline.hpp"
#include "radix_sort.hpp"
#include "stage_support.hpp"
#include "support/same_set.hpp"
#include "workspace.hpp"

namespace roiclip {
namespace {

using detail::i128;
using detail::IPoint;
using Ring = std::vector<IPoint>;

const FillRule kRules[] = {FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive,
                           FillRule::Negative};

int sign(i128 v) { return (v > 0) - (v < 0); }
int turn(IPoint a, IPoint b, IPoint c) {
  return sign(i128(b.x - a.x) * (c.y - a.y) - i128(b.y - a.y) * (c.x - a.x));
}
bool within(std::int64_t v, std::int64_t a, std::int64_t b) {
  return std::min(a, b) <= v && v <= std::max(a, b);
}
// p lies on the closed segment a-b.
bool onSegment(IPoint p, IPoint a, IPoint b) {
  return turn(a, b, p) == 0 && within(p.x, a.x, b.x) && within(p.y, a.y, b.y);
}
bool closedSegmentsMeet(IPoint a, IPoint b, IPoint c, IPoint d) {
  const int o1 = turn(a, b, c), o2 = turn(a, b, d), o3 = turn(c, d, a), o4 = turn(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return onSegment(c, a, b) || onSegment(d, a, b) || onSegment(a, c, d) || onSegment(b, c, d);
}

// The definition, pair by pair: consecutive edges are not collinear, other edges never meet.
bool bruteForceSimple(const Ring& r) {
  const std::size_t n = r.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    if (r[i] == r[(i + 1) % n]) return false;
    if (turn(r[i], r[(i + 1) % n], r[(i + 2) % n]) == 0) return false;
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // consecutive through the wrap
      if (closedSegmentsMeet(r[i], r[(i + 1) % n], r[j], r[(j + 1) % n])) return false;
    }
  }
  return true;
}

// A set of rings, by the definition: each ring simple, no two rings meet.
bool bruteForceSetSimple(const std::vector<Ring>& set) {
  for (std::size_t a = 0; a < set.size(); ++a) {
    if (!bruteForceSimple(set[a])) return false;
    for (std::size_t b = 0; b < a; ++b) {
      for (std::size_t i = 0; i < set[a].size(); ++i) {
        for (std::size_t j = 0; j < set[b].size(); ++j) {
          if (closedSegmentsMeet(set[a][i], set[a][(i + 1) % set[a].size()], set[b][j],
                                 set[b][(j + 1) % set[b].size()])) {
            return false;
          }
        }
      }
    }
  }
  return true;
}

std::string describe(const Ring& r) {
  std::string s;
  for (const IPoint& p : r) s += " (" + std::to_string(p.x) + "," + std::to_string(p.y) + ")";
  return s;
}

bool chainSweepSimple(const Ring& r) {
  detail::ChainScratch scratch;
  return detail::ringIsSimple(r, scratch);
}

Path toPath(const Ring& r) {
  Path p;
  for (const IPoint& q : r) p.emplace_back(double(q.x), double(q.y));
  return p;
}

// The verdict on `trials` rings from `make` (rings under three vertices are skipped) against
// brute force, each ring also reversed; a simple ring turns once (Hopf: necessary). Both
// verdicts must occur: more than total / `fewest` rings simple, at least 1,000 not.
template <class Make>
void expectRingVerdicts(Make make, int trials, int fewest) {
  int simple = 0, total = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const Ring r = make();
    if (r.size() < 3) continue;
    const bool expected = bruteForceSimple(r);
    if (expected) {
      ASSERT_TRUE(detail::turnsOnce(r)) << "trial " << trial;
    }
    ASSERT_EQ(chainSweepSimple(r), expected) << "trial " << trial << ":" << describe(r);
    const Ring reversed(r.rbegin(), r.rend());
    ASSERT_EQ(chainSweepSimple(reversed), expected) << "trial " << trial << ", reversed";
    simple += expected ? 1 : 0;
    ++total;
  }
  EXPECT_GT(simple, total / fewest);
  EXPECT_LT(simple, total - 1000);
}

// The same for sets of rings from `make`: ringsAreSimple() against bruteForceSetSimple(), more
// than `fewestSimple` sets simple and at least 1,000 not. Each set is also snapped (its
// straight-on and spike vertices merged, as intersectRings() gets its rings) and asked without
// the rotation index (`merged`): against brute force on the snapped set, with both verdicts
// more than `fewestSimple` / 4 times.
template <class Make>
void expectSetVerdicts(Make make, int trials, int fewestSimple) {
  detail::ChainScratch scratch;
  int simple = 0, total = 0, mergedSimple = 0, mergedTotal = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const std::vector<Ring> set = make();
    if (std::any_of(set.begin(), set.end(), [](const Ring& r) { return r.size() < 3; })) continue;
    const bool expected = bruteForceSetSimple(set);
    ASSERT_EQ(detail::ringsAreSimple(set, scratch), expected) << "trial " << trial;
    simple += expected ? 1 : 0;
    ++total;
    Paths paths;
    for (const Ring& r : set) paths.push_back(toPath(r));
    const detail::Rings merged = detail::snapRings(paths, 0, Grid::fixed(1.0));
    if (merged.size() != set.size()) continue;  // a ring merged into a line
    const bool mergedExpected = bruteForceSetSimple(merged);
    ASSERT_EQ(detail::ringsAreSimple(merged, scratch, /*merged=*/true), mergedExpected)
        << "trial " << trial << ", snapped";
    mergedSimple += mergedExpected ? 1 : 0;
    ++mergedTotal;
  }
  EXPECT_GT(simple, fewestSimple);
  EXPECT_LT(simple, total - 1000);
  EXPECT_GT(mergedSimple, fewestSimple / 4);
  EXPECT_LT(mergedSimple, mergedTotal - fewestSimple / 4);
}

// A random ring of up to `n` points on a 6 x 6 grid, consecutive repeats dropped.
Ring smallGridRing(std::mt19937& rng, int n) {
  Ring r;
  for (int i = 0; i < n; ++i) {
    const IPoint p{std::int64_t(rng() % 6), std::int64_t(rng() % 6)};
    if (r.empty() || p != r.back()) r.push_back(p);
  }
  while (r.size() > 1 && r.back() == r.front()) r.pop_back();
  return r;
}

Ring toRing(const Path& p) {
  Ring r;
  for (const Point& q : p) r.push_back({std::int64_t(q.x), std::int64_t(q.y)});
  return r;
}

void expectVerdict(const Ring& r, bool simple, const std::string& what) {
  ASSERT_EQ(bruteForceSimple(r), simple) << what << ": the fixture is not what it claims";
  EXPECT_EQ(chainSweepSimple(r), simple) << what;
  // Reversed and rotated: the same ring.
  Ring reversed(r.rbegin(), r.rend());
  EXPECT_EQ(chainSweepSimple(reversed), simple) << what << ", reversed";
  Ring rotated = r;
  std::rotate(rotated.begin(), rotated.begin() + std::ptrdiff_t(r.size() / 3), rotated.end());
  EXPECT_EQ(chainSweepSimple(rotated), simple) << what << ", rotated";
  for (FillRule rule : kRules) {
    testing::expectSameSet(simplify({toPath(r)}, rule), stages::generalSimplify({toPath(r)}, rule),
                           what);
  }
}

TEST(StageSimpleRing, ChainsSharingEndPoints) {
  // A diamond: two chains start at the left vertex and end at the right one.
  expectVerdict({{0, 0}, {4, -3}, {8, 0}, {4, 3}}, true, "diamond");
  // Two lobes pinched at (4, 0), where two chains end and two others start: a repeated vertex.
  expectVerdict({{0, -2}, {4, 0}, {8, -2}, {8, 2}, {4, 0}, {0, 2}}, false, "pinched lobes");
  // The turning vertex (4, 0) of two chains lies on another chain's edge.
  // A wedge cut into a square from its left side: its tip (8, 4), where two chains end, lies on
  // the square's right side.
  expectVerdict({{0, 0}, {8, 0}, {8, 8}, {0, 8}, {0, 6}, {8, 4}, {0, 2}}, false,
                "turning vertex on an edge");
  // Chains whose ends share x but not y: they pass each other without contact.
  expectVerdict({{0, 0}, {4, 0}, {4, 1}, {2, 1}, {2, 3}, {4, 3}, {4, 4}, {0, 4}}, true,
                "ends one above the other");
}

TEST(StageSimpleRing, VerticalAndHorizontalRuns) {
  // The region under a descending staircase, every edge axis-parallel: going round, the
  // staircase alternates up (lexicographically increasing) and left (decreasing), so every
  // vertex of it is a turning vertex where two chains start or end.
  Ring stairs = {{0, 0}, {100, 0}};
  for (int k = 1; k <= 50; ++k) {
    stairs.push_back({102 - 2 * k, 2 * k});
    stairs.push_back({100 - 2 * k, 2 * k});
  }
  expectVerdict(stairs, true, "staircase");
  // A slot cut into a square back along one vertical line: the two sides of the slot overlap.
  expectVerdict({{0, 0}, {10, 0}, {10, 10}, {5, 10}, {5, 4}, {5, 10}, {0, 10}}, false,
                "zero-width slot");
  // Two rectangles joined along part of one vertical side, traced as one ring: the ring runs
  // down and up the shared stretch.
  expectVerdict({{0, 0}, {4, 0}, {4, 2}, {8, 2}, {8, 6}, {4, 6}, {4, 1}, {4, 8}, {0, 8}}, false,
                "vertical overlap");
}

TEST(StageSimpleRing, CollinearChains) {
  // A U: the tops of its two arms lie on one line, apart.
  expectVerdict({{0, 0}, {9, 0}, {9, 6}, {6, 6}, {6, 2}, {3, 2}, {3, 6}, {0, 6}}, true,
                "U with collinear tops");
  // The arms' inner sides on one vertical line each, apart; two edges on the line x = 3 that do
  // not touch (a notch below and one above).
  expectVerdict({{0, 0},
                 {6, 0},
                 {6, 9},
                 {0, 9},
                 {0, 7},
                 {3, 7},
                 {3, 6},
                 {0, 6},
                 {0, 3},
                 {3, 3},
                 {3, 2},
                 {0, 2}},
                true, "notches on one line");
  // Two collinear edges that overlap: a ring folded back onto itself along y = 0.
  expectVerdict({{0, 0}, {6, 0}, {6, 3}, {3, 1}, {2, 0}, {-2, 0}, {-2, -3}}, false,
                "collinear overlap");
}

TEST(StageSimpleRing, AChainThatCrossesManyOthers) {
  // A comb with 200 teeth hanging down to y = 3, closed by an edge at y = 5 that crosses every
  // tooth; and the same comb closed below the teeth (simple).
  for (const int bottom : {5, 0}) {
    Ring comb = {{0, bottom}, {401, bottom}, {401, 10}};
    for (int i = 200; i >= 1; --i) {
      comb.insert(comb.end(), {{2 * i, 10}, {2 * i, 3}, {2 * i - 1, 3}, {2 * i - 1, 10}});
    }
    comb.push_back({0, 10});
    expectVerdict(comb, bottom == 0, "comb, bottom at y = " + std::to_string(bottom));
  }
}

// Where the test stops, it says whether the ring touches itself there (ChainScratch::touched:
// a shared point, a vertex on an edge, edges along each other) or crosses itself; intersect()
// tries the pinch stage on a single ring only in the first case.
TEST(StageSimpleRing, ContactsAreToldFromCrossings) {
  const auto touched = [](const Ring& r) {
    detail::ChainScratch scratch;
    EXPECT_FALSE(detail::ringIsSimple(r, scratch));
    return scratch.touched;
  };
  EXPECT_TRUE(touched({{0, -2}, {4, 0}, {8, -2}, {8, 2}, {4, 0}, {0, 2}})) << "pinched lobes";
  EXPECT_TRUE(touched({{0, 0}, {8, 0}, {8, 8}, {0, 8}, {0, 6}, {8, 4}, {0, 2}}))
      << "turning vertex on an edge";
  EXPECT_TRUE(touched({{0, 0}, {6, 0}, {6, 3}, {3, 1}, {2, 0}, {-2, 0}, {-2, -3}}))
      << "collinear overlap";
  // Two squares touching at a corner, one ring through (4, 4) twice, a vertex inside chains.
  EXPECT_TRUE(touched({{0, 0}, {4, 0}, {4, 4}, {8, 4}, {8, 8}, {4, 8}, {4, 4}, {0, 4}}))
      << "figure eight";
  // The comb closed across its teeth: every tooth crosses the closing edge.
  Ring comb = {{0, 5}, {401, 5}, {401, 10}};
  for (int i = 200; i >= 1; --i) {
    comb.insert(comb.end(), {{2 * i, 10}, {2 * i, 3}, {2 * i - 1, 3}, {2 * i - 1, 10}});
  }
  comb.push_back({0, 10});
  EXPECT_FALSE(touched(comb)) << "comb";
  // A crenellated contour with one tooth turned into a bow tie.
  const testing::Crenellated shape{50};
  Ring ring = toRing(shape.path());
  std::size_t at = 100;  // a bottom tooth from here on: (a, 0), (a, -1), (b, -1), (b, 0)
  while (ring[at].y != ring[at + 1].y + 1 || ring[at + 1].y != ring[at + 2].y) ++at;
  std::swap(ring[at + 1], ring[at + 2]);
  EXPECT_FALSE(touched(ring)) << "bow tie";
}

TEST(StageSimpleRing, ALongContourWithASingleCrossing) {
  const testing::Crenellated shape{6250};  // 100,004 vertices
  Ring ring = toRing(shape.path());
  ASSERT_EQ(ring.size(), 100004U);
  EXPECT_TRUE(chainSweepSimple(ring));
  const Paths paths = {shape.path()};
  const PolygonSet fast = simplify(paths, FillRule::NonZero);
  testing::expectSameSet(fast, stages::generalSimplify(paths, FillRule::NonZero), "crenellated");
  ASSERT_EQ(fast.polygons.size(), 1U);
  EXPECT_EQ(-signedArea(fast.polygons[0].outer), shape.area());
  // One tooth near the middle of the path turned into a bow tie: its two slanted edges cross.
  const std::size_t at = 12001;  // a bottom tooth: (a, 0), (a, -1), (b, -1), (b, 0) from here on
  ASSERT_EQ(ring[at].y, ring[at + 1].y + 1);
  ASSERT_EQ(ring[at + 1].y, ring[at + 2].y);
  std::swap(ring[at + 1], ring[at + 2]);
  EXPECT_FALSE(chainSweepSimple(ring));
  testing::expectSameSet(simplify({toPath(ring)}, FillRule::NonZero),
                         stages::generalSimplify({toPath(ring)}, FillRule::NonZero), "bow tie");
}

// The sweep's vertex order (sortByKey(), radix_sort.hpp) against std::sort: sizes across the
// comparison sort, the radix sort and its split by x's top bits (from 2^20), keys spanning 1 to 32
// bits in each coordinate from random offsets, some with zero low bits (a fitted grid's units) and
// few distinct values (many equal keys).
TEST(StageSimpleRing, TheVertexOrderIsSortedAtEverySizeAndSpan) {
  std::mt19937_64 rng(20261203);
  const detail::StartFrame frame;
  const std::size_t sizes[] = {0, 1, 1023, 1024, 5000, 70'000, (std::size_t{1} << 20) + 3};
  int trial = 0;
  for (const std::size_t n : sizes) {
    for (int variant = 0; variant < (n > 100'000 ? 3 : 8); ++variant, ++trial) {
      const int xBits = 1 + int(rng() % 31), yBits = 1 + int(rng() % 31);
      const int zeros = variant % 3 == 1 ? 9 : 0;
      const std::int64_t x0 = std::int64_t(rng() % (1U << 29)) - (1 << 28);
      const std::int64_t y0 = std::int64_t(rng() % (1U << 29)) - (1 << 28);
      const std::uint64_t distinct = variant % 4 == 3 ? 7 : ~std::uint64_t{0};
      std::vector<detail::ChainEvent> events;
      events.reserve(n);
      for (std::size_t i = 0; i < n; ++i) {
        const auto draw = [&](int bits) {
          const std::uint64_t v =
              (rng() % distinct) & ((std::uint64_t{1} << std::max(bits - zeros, 0)) - 1);
          return std::int64_t(v << zeros);
        };
        const IPoint p{
            std::clamp<std::int64_t>(x0 + draw(xBits), -Grid::kMaxUnits, Grid::kMaxUnits),
            std::clamp<std::int64_t>(y0 + draw(yBits), -Grid::kMaxUnits, Grid::kMaxUnits)};
        events.emplace_back(frame.key(p), int(i), -1);
      }
      std::vector<std::uint64_t> expected;
      for (const detail::ChainEvent& e : events) expected.push_back(e.key);
      std::sort(expected.begin(), expected.end());
      std::vector<detail::ChainEvent> scratch;
      detail::sortByKey(events, scratch);
      ASSERT_EQ(events.size(), n);
      bool same = true;
      std::vector<char> seen(n, 0);
      for (std::size_t i = 0; i < n; ++i) {
        same = same && events[i].key == expected[i];
        seen[std::size_t(events[i].chain)] = 1;  // every event once (its chain field numbers it)
      }
      EXPECT_TRUE(same) << "trial " << trial << ": " << n << " events, " << xBits << " x " << yBits
                        << " bits";
      EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), std::ptrdiff_t(n)) << "trial " << trial;
    }
  }
}

// Rings of more than 2^20 vertices, whose vertex order is sorted in parts split by the top bits
// of x (each part then by the other digits): a crenellated square, as given and scaled (units
// with zero low bits), and with a defect at each end of the x range and in the middle (two far
// vertices on one point, a tooth turned into a bow tie). Its teeth start chains in order up two
// sides, as the status's finger search takes them.
TEST(StageSimpleRing, RingsPastAMillionVerticesKeepTheirVerdict) {
  const testing::Crenellated shape{70'000};  // 1,120,004 vertices
  const Ring ring = toRing(shape.path());
  ASSERT_GT(ring.size(), std::size_t{1} << 20);
  for (const int zeros : {0, 9}) {
    Ring scaled = ring;
    for (IPoint& p : scaled)
      p = {p.x * (std::int64_t{1} << zeros), p.y * (std::int64_t{1} << zeros)};
    const std::string what = "scaled by 2^" + std::to_string(zeros);
    EXPECT_TRUE(chainSweepSimple(scaled)) << what;
    // A tooth starts at k (4 m + 1) + 1 + 4 i on side k (bottom, right, top, left).
    const std::size_t side = std::size_t(4 * shape.m + 1);
    for (const std::size_t at : {std::size_t{1001}, 2 * side + 1, 3 * side + 1 + 4 * 68'000}) {
      Ring pinched = scaled;
      pinched[at] = pinched[(at + scaled.size() / 3) % scaled.size()];
      EXPECT_FALSE(chainSweepSimple(pinched)) << what << ", pinched at " << at;
      // Vertices at..at + 3 are one tooth: its two parallel edges turned into crossing ones.
      Ring crossed = scaled;
      std::swap(crossed[at + 1], crossed[at + 2]);
      EXPECT_FALSE(chainSweepSimple(crossed)) << what << ", crossed at " << at;
    }
  }
}

// Rings long enough for the radix sort of the sweep's vertex order (1,024 vertices and more),
// at spans from 2^7 to 2^28 (one to three passes per coordinate, negative coordinates too),
// some scaled by 2^6 or 2^12 (units with zero low bits):
// the verdict against brute force, also after a far vertex is moved onto another (a pinch) or
// two vertices are swapped (a crossing).
TEST(StageSimpleRing, LongRingsAgreeWithBruteForceAtEverySpan) {
  std::mt19937 rng(20261203);
  int simple = 0, total = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const double radius = std::ldexp(1.0, 6 + (trial % 8) * 3);  // 2^6 .. 2^27
    const int n = 1100 + int(rng() % 400);
    const Point centre{trial % 2 == 0 ? 0.0 : radius / 3, trial % 3 == 0 ? -radius / 2 : 0.0};
    const Paths paths = {stages::starShapedRing(rng, n, centre, radius, 0.6)};
    const auto rings = detail::snapRings(paths, 0, Grid::fixed(1));
    ASSERT_EQ(rings.size(), 1U);
    Ring ring = rings[0];
    if (ring.size() < 1024) continue;  // rounding merged too many vertices
    // Units whose low bits are all zero, as a fitted grid makes of pixels (the sort skips them).
    const int zeros = (trial / 8) * 6;
    if (radius * std::ldexp(1.0, zeros) < 0x1p29) {
      for (IPoint& p : ring)
        p = {p.x * (std::int64_t{1} << zeros), p.y * (std::int64_t{1} << zeros)};
    }
    for (int variant = 0; variant < 3; ++variant) {
      Ring r = ring;
      if (variant == 1) r[r.size() / 2] = r[r.size() / 5];  // a pinch far along the ring
      if (variant == 2) std::swap(r[r.size() / 3], r[r.size() / 3 + 1]);
      const bool expected = bruteForceSimple(r);
      ASSERT_EQ(chainSweepSimple(r), expected) << "trial " << trial << " variant " << variant;
      simple += expected ? 1 : 0;
      ++total;
    }
  }
  EXPECT_GT(simple, 10);
  EXPECT_LT(simple, total - 10);
}

TEST(StageSimpleRing, RotationIndexRejectsMostSelfCrossingRings) {
  EXPECT_TRUE(detail::turnsOnce({{0, 0}, {4, 0}, {4, 4}, {0, 4}}));
  EXPECT_TRUE(detail::turnsOnce({{0, 0}, {0, 4}, {4, 4}, {4, 0}}));   // clockwise: -1
  EXPECT_FALSE(detail::turnsOnce({{0, 0}, {4, 4}, {4, 0}, {0, 4}}));  // figure eight: 0
  // A square whose top side makes a counter-clockwise loop (crossing itself at (8, 10)): it
  // turns twice.
  EXPECT_FALSE(
      detail::turnsOnce({{0, 0}, {10, 0}, {10, 10}, {5, 10}, {5, 7}, {8, 7}, {8, 12}, {0, 12}}));
  EXPECT_FALSE(detail::turnsOnce({{0, 0}, {10, 0}, {5, 0}, {5, 5}}));  // a spike
  // The pentagram: turns twice.
  EXPECT_FALSE(detail::turnsOnce({{0, 10}, {6, -8}, {-10, 3}, {10, 3}, {-6, -8}}));
  // A straight-on vertex is not simple (snapRings() leaves none): turnsOnce() rejects it, and the
  // chain sweep relies on that.
  EXPECT_FALSE(detail::turnsOnce({{0, 0}, {2, 0}, {4, 0}, {4, 4}, {0, 4}}));
  EXPECT_FALSE(detail::turnsOnce({{0, 0}, {4, 0}, {4, 2}, {4, 4}, {0, 4}}));
  // Touching itself at a vertex keeps the rotation index 1: only the chain sweep sees it.
  const Ring pinched = {{0, -2}, {4, 0}, {8, -2}, {8, 2}, {4, 0}, {0, 2}};
  EXPECT_TRUE(detail::turnsOnce(pinched));
  EXPECT_FALSE(chainSweepSimple(pinched));
}

// Sets of rings that touch nothing: nesting from the chain sweep against stages 1 to 4.
void expectSetLikeGeneralPath(const Paths& paths, const std::string& what) {
  const Grid grid = resolveGrid(Options{}.grid, paths);
  const detail::Rings rings = detail::snapRings(paths, 0, grid);
  for (FillRule rule : kRules) {
    testing::expectSameSet(simplify(paths, rule), stages::generalSimplify(paths, rule),
                           what + " " + std::string(toString(rule)));
  }
}

Path square(double c, double h, bool counterClockwise) {
  Path p = {{c - h, c - h}, {c + h, c - h}, {c + h, c + h}, {c - h, c + h}};
  if (!counterClockwise) std::reverse(p.begin(), p.end());
  return p;
}

TEST(StageSimpleRing, SetsOfRingsNestLikeTheGeneralPath) {
  detail::ChainScratch scratch;
  // Five nested squares, alternating and equal orientations; two nests side by side.
  for (const bool alternate : {true, false}) {
    Paths nest;
    for (int k = 0; k < 5; ++k) nest.push_back(square(50, 40 - 7 * k, !alternate || k % 2 == 0));
    Paths two = nest;
    for (const Path& p : nest) {
      Path q = p;
      for (Point& v : q) v += Point(100, 30);
      two.push_back(q);
    }
    for (const Paths* set : {&nest, &two}) {
      const Grid grid = resolveGrid(Options{}.grid, *set);
      ASSERT_TRUE(detail::ringsAreSimple(detail::snapRings(*set, 0, grid), scratch));
      expectSetLikeGeneralPath(*set, alternate ? "alternating nest" : "same-way nest");
    }
  }
  // Random: a 4 x 4 grid of cells, each empty or holding 1 or 2 concentric star-shaped rings
  // of random orientation, each well inside the one around it (mostly not touching it).
  std::mt19937 rng(99);
  int taken = 0;
  for (int trial = 0; trial < 150; ++trial) {
    Paths set;
    for (int cell = 0; cell < 16; ++cell) {
      const int depth = int(rng() % 3);
      double radius = 45;
      for (int d = 0; d < depth; ++d) {
        Path ring =
            stages::starShapedRing(rng, d == 0 ? 12 + int(rng() % 12) : 6 + int(rng() % 4),
                                   {100.0 * (cell % 4) + 50, 100.0 * (cell / 4) + 50}, radius, 0.7);
        if (rng() % 2 == 0) std::reverse(ring.begin(), ring.end());
        set.push_back(ring);
        // Well inside: an edge between vertices at 0.7 * radius a third of a turn apart passes
        // 0.35 * radius from the centre.
        radius *= 0.3;
      }
    }
    if (set.size() < 2) continue;
    const Grid grid = resolveGrid(Options{}.grid, set);
    taken += detail::ringsAreSimple(detail::snapRings(set, 0, grid), scratch) ? 1 : 0;
    expectSetLikeGeneralPath(set, "trial " + std::to_string(trial));
  }
  EXPECT_GT(taken, 60);  // most sets take the sweep-free path (rounding makes some touch)
}

// Small random rings on a 6 x 6 grid: repeated vertices, touching and collinear edges are
// common, so both verdicts occur often.
TEST(StageSimpleRing, AgreesWithBruteForceOnSmallDegenerateRings) {
  std::mt19937 rng(20261202);
  expectRingVerdicts([&] { return smallGridRing(rng, 3 + int(rng() % 8)); }, 40000, 50);
}

// Sets of two or three small random rings on a 6 x 6 grid: ringsAreSimple() against the
// definition (each ring simple, no two rings meet). Rings sharing a vertex, one ring's vertex on
// another's edge and overlapping edges are common: the sweep tests the chains of all rings as
// one ring's.
TEST(StageSimpleRing, SetsAgreeWithBruteForceOnSmallDegenerateRings) {
  std::mt19937 rng(20261203);
  expectSetVerdicts(
      [&] {
        std::vector<Ring> set(2 + rng() % 2);
        for (Ring& r : set) r = smallGridRing(rng, 3 + int(rng() % 4));
        return set;
      },
      20000, 100);
}

// A closed lattice walk of `moves` steps on a small grid: pixel directions only (axis-parallel
// and diagonal, as findContours traces), consecutive steps never collinear, closed by one or two
// straight moves back to the start. Vertical steps run both up and down along one x-monotone
// chain, which the chain sweep keeps whole; touches at vertical edges are common.
Ring pixelWalk(std::mt19937& rng, int moves, int span) {
  static const IPoint kDirections[] = {{1, 0},  {1, 1},   {0, 1},  {-1, 1},
                                       {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
  Ring r = {{0, 0}};
  int previous = -1;
  for (int m = 0; m < moves; ++m) {
    int d = int(rng() % 8);
    if (previous >= 0 && (d % 4) == (previous % 4)) d = (d + 1 + int(rng() % 3)) % 8;
    const std::int64_t length = 1 + std::int64_t(rng() % std::uint32_t(span));
    const IPoint q{r.back().x + kDirections[d].x * length, r.back().y + kDirections[d].y * length};
    r.push_back(q);
    previous = d;
  }
  r.push_back({0, r.back().y});  // back along x, then along y to the start
  // Drop repeated points and straight-on vertices (what the snapping leaves).
  Ring out;
  for (const IPoint& q : r) {
    if (!out.empty() && out.back() == q) continue;
    while (out.size() >= 2 && turn(out[out.size() - 2], out.back(), q) == 0 &&
           within(out.back().x, out[out.size() - 2].x, q.x) &&
           within(out.back().y, out[out.size() - 2].y, q.y)) {
      out.pop_back();
    }
    out.push_back(q);
  }
  while (out.size() > 1 && out.back() == out.front()) out.pop_back();
  return out;
}

// Pixel-direction lattice walks: the verdict against brute force. Every edge is axis-parallel
// or diagonal, and vertical edges run up and down inside one chain, so contacts at vertical
// edges (a vertex on one, two overlapping, two chains ending on one x) are what is tested.
TEST(StageSimpleRing, PixelWalksAgreeWithBruteForce) {
  std::mt19937 rng(20261206);
  expectRingVerdicts([&] { return pixelWalk(rng, 3 + int(rng() % 10), 1 + int(rng() % 3)); }, 30000,
                     20);
}

// Sets of two or three pixel walks, moved apart by a few units: ringsAreSimple() against the
// definition. A ring's vertical edge against another's vertex or vertical edge, and chains of
// different rings starting and ending on one x, are common.
TEST(StageSimpleRing, SetsOfPixelWalksAgreeWithBruteForce) {
  std::mt19937 rng(20261207);
  expectSetVerdicts(
      [&] {
        std::vector<Ring> set(2 + rng() % 2);
        for (Ring& r : set) {
          r = pixelWalk(rng, 3 + int(rng() % 6), 1 + int(rng() % 2));
          const IPoint shift{std::int64_t(rng() % 7) - 3, std::int64_t(rng() % 7) - 3};
          for (IPoint& q : r) q = {q.x + shift.x, q.y + shift.y};
        }
        return set;
      },
      20000, 300);
}

// The chains are x-monotone with vertical edges inside: a ring splits only at its x extremes.
// A digital circle traced as findContours(CHAIN_APPROX_SIMPLE) would trace it (horizontal,
// vertical and diagonal runs; vertical steps up on one side and down on the other) is two
// chains, where chains increasing in (x, y) order broke at every downward vertical step.
TEST(StageSimpleRing, PixelStaircasesSplitOnlyAtXExtremes) {
  // The boundary of the pixels (x, y) with x^2 + y^2 <= 60^2, counter-clockwise, as the
  // column tops and bottoms at each x.
  const int radius = 60;
  std::vector<std::int64_t> top;
  for (int x = -radius; x <= radius; ++x) {
    top.push_back(std::int64_t(std::floor(std::sqrt(double(radius * radius - x * x)))));
  }
  Ring steps;  // lower half left to right, then upper half right to left
  for (int x = -radius; x <= radius; ++x) {
    steps.push_back({x, -top[std::size_t(x + radius)]});
    steps.push_back({x + 1, -top[std::size_t(x + radius)]});
  }
  for (int x = radius; x >= -radius; --x) {
    steps.push_back({x + 1, top[std::size_t(x + radius)] + 1});
    steps.push_back({x, top[std::size_t(x + radius)] + 1});
  }
  Ring ring;
  for (const IPoint& q : steps) {
    if (!ring.empty() && ring.back() == q) continue;
    while (ring.size() >= 2 && turn(ring[ring.size() - 2], ring.back(), q) == 0) ring.pop_back();
    ring.push_back(q);
  }
  while (ring.size() >= 3 && turn(ring[ring.size() - 2], ring.back(), ring.front()) == 0) {
    ring.pop_back();
  }
  ASSERT_TRUE(bruteForceSimple(ring)) << describe(ring);
  detail::ChainScratch scratch;
  ASSERT_TRUE(detail::ringIsSimple(ring, scratch));
  EXPECT_EQ(scratch.chains.size(), 2u) << ring.size() << " vertices";
  EXPECT_GT(ring.size(), 100u);
  // The same ring as a hole of a square around it: four chains, nested.
  const std::vector<Ring> set = {{{-100, -100}, {100, -100}, {100, 100}, {-100, 100}},
                                 Ring(ring.rbegin(), ring.rend())};
  ASSERT_TRUE(detail::ringsAreSimple(set, scratch));
  EXPECT_EQ(scratch.chains.size(), 4u);
}

// Star-shaped rings (sorted random angles, random radii, rounded): mostly simple, sometimes a
// rounding makes edges touch. Verdict against brute force, region against the general path.
// Longer rings with many chains on a small grid (star-shaped, radius 5 to 9, up to 64 vertices,
// snapped to integers): pixel-like staircases, vertices on other edges, repeated points and
// edges running along each other, then a pinch or a swap far along the ring. Neighbouring
// chains are tested lazily, when they stop being neighbours, so a contact must be found however
// long two chains stay next to each other and wherever a pair starts or ends between them.
TEST(StageSimpleRing, ContactsBetweenLongNeighbouringChainsAreFound) {
  std::mt19937 rng(20261203);
  int simple = 0, total = 0;
  for (int trial = 0; trial < 6000; ++trial) {
    const double radius = 5.0 + double(trial % 5);
    const Path path = stages::starShapedRing(rng, 12 + int(rng() % 53), {0, 0}, radius, 0.5);
    const detail::Rings rings = detail::snapRings({path}, 0, Grid::fixed(1));
    if (rings.size() != 1 || rings[0].size() < 6) continue;
    for (int variant = 0; variant < 3; ++variant) {
      Ring r = rings[0];
      const std::size_t n = r.size();
      if (variant == 1) r[rng() % n] = r[rng() % n];  // often a pinch
      if (variant == 2) std::swap(r[rng() % n], r[rng() % n]);
      bool repeats = false;
      for (std::size_t i = 0; i < n; ++i) repeats = repeats || r[i] == r[(i + 1) % n];
      if (repeats) continue;
      const bool expected = bruteForceSimple(r);
      ASSERT_EQ(chainSweepSimple(r), expected) << "trial " << trial << " variant " << variant;
      Ring reversed(r.rbegin(), r.rend());
      ASSERT_EQ(chainSweepSimple(reversed), expected) << "trial " << trial << " reversed";
      simple += expected ? 1 : 0;
      ++total;
    }
  }
  EXPECT_GT(simple, total / 10);  // both verdicts are exercised
  EXPECT_LT(simple, total - total / 10);
}

TEST(StageSimpleRing, StarShapedRingsMatchTheGeneralPath) {
  std::mt19937 rng(7);
  int simple = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int n = 3 + int(rng() % 120);
    const double scale = trial % 2 == 0 ? 30.0 : 1000.0;
    Path path = stages::starShapedRing(rng, n, {0, 0}, scale, 0.2);
    if (trial % 3 == 0) std::reverse(path.begin(), path.end());
    const Grid grid = resolveGrid(Options{}.grid, Paths{path});
    const detail::Rings rings = detail::snapRings({path}, 0, grid);
    if (rings.size() != 1) continue;
    const bool expected = bruteForceSimple(rings[0]);
    ASSERT_EQ(chainSweepSimple(rings[0]), expected) << "trial " << trial;
    simple += expected ? 1 : 0;
    for (FillRule rule : kRules) {
      testing::expectSameSet(simplify({path}, rule), stages::generalSimplify({path}, rule),
                             "trial " + std::to_string(trial));
    }
  }
  EXPECT_GT(simple, 200);
}

}  // namespace
}  // namespace roiclip
