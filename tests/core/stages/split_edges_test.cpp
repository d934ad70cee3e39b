// SPDX-License-Identifier: MIT
// Stage 1 (src/core/split_edges.cpp): the sweep cuts edges at every crossing, touch and overlap,
// merges coincident pieces and labels each kept piece with the winding numbers on its sides.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <roiclip/roiclip.hpp>

#include "pipeline.hpp"
#include "stage_support.hpp"
#include "support/oracle.hpp"

namespace roiclip {
namespace {

// A bow-tie: two triangles meeting at (5,5), the left one winding +1, the right one -1.
const Paths kBowTie = {{{0, 0}, {10, 10}, {10, 0}, {0, 10}}};

TEST(StageSplitEdges, BowTieIsCutAtItsCrossingIntoSixLabelledPieces) {
  const detail::Arrangement a =
      stages::arrange(kBowTie, nullptr, stages::simplifyWith(FillRule::NonZero));
  // The crossing (5,5) is a vertex of its own, on the grid.
  const auto names = stages::vertexNames(a);
  ASSERT_EQ(a.vertices.size(), 5u);
  EXPECT_EQ(std::count(names.begin(), names.end(), "(5,5)"), 1);
  // Every piece, by its ends: the subject's winding number just below and just above it. A
  // vertical piece's "below" is its right side (vertical edges sort as very steep rising ones).
  const std::map<std::string, std::pair<long long, long long>> expected = {
      {"(0,0)-(0,10)", {1, 0}},   {"(0,0)-(5,5)", {0, 1}},   {"(0,10)-(5,5)", {1, 0}},
      {"(5,5)-(10,10)", {-1, 0}}, {"(5,5)-(10,0)", {0, -1}}, {"(10,0)-(10,10)", {0, -1}}};
  ASSERT_EQ(a.pieces.size(), expected.size());
  ASSERT_EQ(a.windings.size(), a.pieces.size());
  for (std::size_t k = 0; k < a.pieces.size(); ++k) {
    const detail::EdgePiece& p = a.pieces[k];
    const std::string name = names[std::size_t(p.left)] + "-" + names[std::size_t(p.right)];
    const auto it = expected.find(name);
    ASSERT_NE(it, expected.end()) << "unexpected piece " << name;
    EXPECT_EQ(a.windings[k].windBelow[0], it->second.first) << name;
    EXPECT_EQ(a.windings[k].windAbove()[0], it->second.second) << name;
  }
}

// On inputs with touching vertices, collinear overlaps and crossings, every kept piece's winding
// numbers match the oracle's exact winding numbers just below and above its middle.
TEST(StageSplitEdges, PieceLabelsMatchTheExactWindingNumbers) {
  const std::vector<Paths> inputs = {
      kBowTie,
      {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{5, 0}, {15, 0}, {15, 10}, {5, 10}}},
      {{{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}, {2, 2}, {8, 2}, {8, 8}, {2, 8}, {2, 2}}},
      {{{0, 0}, {6, 0}, {3, 3}, {6, 6}, {0, 6}, {3, 3}}},
      {{{0, 10}, {6, -8}, {-9, 3}, {9, 3}, {-6, -8}}},
  };
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    std::size_t kept = 0;
    for (FillRule rule :
         {FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive, FillRule::Negative}) {
      SCOPED_TRACE("input " + std::to_string(i) + " " + toString(rule));
      const detail::Arrangement a = stages::arrange(inputs[i], nullptr, stages::simplifyWith(rule));
      kept += a.pieces.size();
      ASSERT_EQ(a.windings.size(), a.pieces.size());
      for (std::size_t k = 0; k < a.pieces.size(); ++k) {
        const auto [below, above] = stages::sidePoints(a, a.pieces[k], 1.0 / 64);
        EXPECT_EQ(testing::exactWinding(inputs[i], below), a.windings[k].windBelow[0]) << k;
        EXPECT_EQ(testing::exactWinding(inputs[i], above), a.windings[k].windAbove()[0]) << k;
        // Only result boundary is kept, with its filled side.
        const bool filledAbove = isFilled(rule, a.windings[k].windAbove()[0]);
        EXPECT_NE(isFilled(rule, a.windings[k].windBelow[0]), filledAbove) << k;
        EXPECT_EQ(a.sides[k], filledAbove ? detail::Side::Above : detail::Side::Below) << k;
      }
    }
    EXPECT_GT(kept, 0u) << "input " << i;
  }
}

TEST(StageSplitEdges, CollinearOverlapIsMergedAndInnerEdgesAreNotKept) {
  // Two rectangles sharing x = 10 from y = 2 to 8: under non-zero that stretch has the region on
  // both sides and is not kept; the square's edge is cut at (10,2) and (10,8).
  const Paths shared = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{10, 2}, {20, 2}, {20, 8}, {10, 8}}};
  const detail::Arrangement a =
      stages::arrange(shared, nullptr, stages::simplifyWith(FillRule::NonZero));
  const auto names = stages::vertexNames(a);
  std::vector<std::string> pieces;
  for (const auto& p : a.pieces) {
    pieces.push_back(names[std::size_t(p.left)] + "-" + names[std::size_t(p.right)]);
  }
  std::vector<std::string> expected = {"(0,0)-(0,10)",  "(0,0)-(10,0)",  "(0,10)-(10,10)",
                                       "(10,0)-(10,2)", "(10,2)-(20,2)", "(10,8)-(10,10)",
                                       "(10,8)-(20,8)", "(20,2)-(20,8)"};
  std::sort(pieces.begin(), pieces.end());
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(pieces, expected);
  // The same square twice: its edges merge into pieces of contribution 2, and under even-odd
  // w = 2 is not filled, so nothing is kept.
  const detail::Arrangement overlap =
      stages::arrange({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{0, 0}, {10, 0}, {10, 10}, {0, 10}}},
                      nullptr, stages::simplifyWith(FillRule::EvenOdd));
  EXPECT_TRUE(overlap.pieces.empty()) << "the same square twice has w = 2: nothing is filled";
}

// The sweep tests a pair of neighbours for a crossing only once (it remembers the last pieces it
// tested above each piece): a pair that a third piece separates for a moment and that meets
// again is not tested again. On two self-intersecting operands on a coarse grid (shared vertices,
// collinear overlaps within and between the operands, crossings between and within both) every
// crossing must still be found: every kept piece's winding numbers of both operands match the
// exact ones on its sides, and the intersection's area matches the slab oracle.
TEST(StageSplitEdges, BothOperandsSelfIntersectingOnACoarseGrid) {
  for (unsigned seed : {7u, 8u, 9u}) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> coord(0, 11);
    Paths subject(1), clipPaths(1);
    for (int i = 0; i < 40; ++i) subject[0].push_back(Point(coord(rng), coord(rng)));
    for (int i = 0; i < 40; ++i) {
      // Every fourth clip vertex is a subject vertex: shared vertices between the operands.
      clipPaths[0].push_back(i % 4 == 0 ? subject[0][std::size_t(i)]
                                        : Point(coord(rng), coord(rng)));
    }
    for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + " " + toString(rule));
      detail::BooleanSpec how = stages::clipWith(ClipOp::Intersection);
      how.subjectRule = how.clipRule = rule;
      const detail::Arrangement a = stages::arrange(subject, &clipPaths, how);
      ASSERT_GT(a.pieces.size(), 20u);
      ASSERT_EQ(a.windings.size(), a.pieces.size());
      for (std::size_t k = 0; k < a.pieces.size(); ++k) {
        const auto [below, above] = stages::sidePoints(a, a.pieces[k], 1e-6);
        EXPECT_EQ(testing::exactWinding(subject, below), a.windings[k].windBelow[0]) << k;
        EXPECT_EQ(testing::exactWinding(subject, above), a.windings[k].windAbove()[0]) << k;
        EXPECT_EQ(testing::exactWinding(clipPaths, below), a.windings[k].windBelow[1]) << k;
        EXPECT_EQ(testing::exactWinding(clipPaths, above), a.windings[k].windAbove()[1]) << k;
      }
      const PolygonSet r = clip(ClipOp::Intersection, subject, clipPaths, rule, rule);
      const double truth =
          testing::slabArea({&subject, &clipPaths}, [&](const std::vector<long long>& w) {
            return isFilled(rule, w[0]) && isFilled(rule, w[1]);
          });
      EXPECT_GT(truth, 1.0);
      EXPECT_NEAR(r.area(), truth, 1e-9 * truth);
    }
  }
}

// Each vertex as reduced fractions: where three or more lines meet, the sweep keeps the crossing
// of the two whose event it took first, and the numerators and denominator depend on the pair.
std::set<std::string> reducedVertexNames(const detail::Arrangement& a) {
  std::set<std::string> names;
  for (std::size_t v = 0; v < a.vertices.size(); ++v) {
    const detail::XPoint p = a.point(int(v));
    const auto x = static_cast<long long>(p.x), y = static_cast<long long>(p.y);
    const auto w = static_cast<long long>(p.w);
    const long long g = std::gcd(std::gcd(x, y), w);
    names.insert(std::to_string(x / g) + "/" + std::to_string(w / g) + "," + std::to_string(y / g) +
                 "/" + std::to_string(w / g));
  }
  return names;
}

// The summed length of an arrangement's pieces.
double pieceLength(const detail::Arrangement& a) {
  double sum = 0;
  for (const detail::EdgePiece& p : a.pieces) {
    const detail::XPoint l = a.point(p.left), r = a.point(p.right);
    sum += std::hypot(r.fx - l.fx, r.fy - l.fy);
  }
  return sum;
}

// The arrangement of subject and clipPaths (null: a simplify) with slab mode against the one
// without: every kept piece's winding numbers are the exact ones on its sides, the vertices of
// both are in sweep order, and the kept pieces are the plain sweep's (the same length, at
// vertices it has too). Returns the slab passes.
std::uint64_t expectSlabsKeepThePlainPieces(const Paths& subject, const Paths* clipPaths,
                                            detail::BooleanSpec how) {
  const detail::Arrangement slabs = stages::arrange(subject, clipPaths, how);
  how.slabs = false;
  const detail::Arrangement plain = stages::arrange(subject, clipPaths, how);
  EXPECT_EQ(plain.slabPasses, 0u);
  EXPECT_GT(slabs.pieces.size(), 20u);
  EXPECT_EQ(slabs.windings.size(), slabs.pieces.size());
  const double eps = 1.0 / double(1 << 20);
  for (std::size_t k = 0; k < slabs.pieces.size() && k < slabs.windings.size(); ++k) {
    const auto [below, above] = stages::sidePoints(slabs, slabs.pieces[k], eps);
    EXPECT_EQ(testing::exactWinding(subject, below), slabs.windings[k].windBelow[0]) << k;
    EXPECT_EQ(testing::exactWinding(subject, above), slabs.windings[k].windAbove()[0]) << k;
    if (clipPaths != nullptr) {
      EXPECT_EQ(testing::exactWinding(*clipPaths, below), slabs.windings[k].windBelow[1]) << k;
      EXPECT_EQ(testing::exactWinding(*clipPaths, above), slabs.windings[k].windAbove()[1]) << k;
    }
  }
  // Vertex ids follow the sweep order, i.e. the points' lexicographic order.
  for (const detail::Arrangement* a : {&slabs, &plain}) {
    std::size_t v = 1;
    while (v < a->vertices.size() &&
           detail::compareInBox(a->point(int(v - 1)), a->point(int(v))) < 0) {
      ++v;
    }
    EXPECT_EQ(v, std::max<std::size_t>(a->vertices.size(), 1)) << "vertex " << v << " out of order";
  }
  const double length = pieceLength(plain);
  EXPECT_NEAR(pieceLength(slabs), length, 1e-9 * length);
  const std::set<std::string> have = reducedVertexNames(slabs);
  const std::set<std::string> all = reducedVertexNames(plain);
  EXPECT_TRUE(std::includes(all.begin(), all.end(), have.begin(), have.end()));
  return slabs.slabPasses;
}

// Slab mode (split_edges.cpp) finds a slab's crossings from the order of its pieces at the
// slab's right end, where the sweep otherwise tests each new pair of neighbours. Random polygons
// on a coarse grid (crossings on slab ends, three or more pieces through one point, collinear
// overlaps, vertical edges) and on a fine one (dozens of crossings a slab) keep the plain
// sweep's pieces. (The plain sweep may have more vertices: a crossing queued for a piece that a
// cancelling overlap then drops is still visited, and the piece that crossed there is cut at it.)
TEST(StageSplitEdges, SlabModeKeepsThePiecesOfTheSweepWithoutIt) {
  struct Case {
    unsigned seed;
    int range, vertices;
  };
  std::uint64_t passes = 0;
  for (const Case& c :
       {Case{11, 12, 60}, Case{12, 12, 60}, Case{13, 40, 120}, Case{14, 5000, 200}}) {
    std::mt19937 rng(c.seed);
    std::uniform_int_distribution<int> coord(0, c.range);
    Paths subject(2), clipPaths(1);
    for (int i = 0; i < c.vertices; ++i) subject[i % 2].push_back(Point(coord(rng), coord(rng)));
    for (int i = 0; i < c.vertices; ++i) clipPaths[0].push_back(Point(coord(rng), coord(rng)));
    for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
      for (ClipOp op : {ClipOp::Intersection, ClipOp::Xor}) {
        SCOPED_TRACE("seed " + std::to_string(c.seed) + " " + toString(rule) + " " + toString(op));
        detail::BooleanSpec how = stages::clipWith(op);
        how.subjectRule = how.clipRule = rule;
        passes += expectSlabsKeepThePlainPieces(subject, &clipPaths, how);
      }
    }
  }
  // Slab mode was taken (a sweep enters it after a slab with crossings for a sixteenth of its
  // pieces).
  EXPECT_GT(passes, 100u);
}

// A slab whose crossings crowd together: the bucket sort of a slab's crossings by cached x
// leaves them to the exact sorts after it. A column of bow-ties between x = 0 and x = 2000, one
// above the other, each crossing once: the sweep finds their crossings at x = 0 (one per two
// pieces: slab mode for the slab to x = 2000). With `spread`, the crossings lie at x = 1000 -
// j / 16 for bow-tie j and one more bow-tie crosses at x = 10: the others fill the last few of
// the slab's buckets, each in the reverse of the exact order (the slab pass finds them bottom to
// top), so the insertion pass exceeds its moves and the comparison sort takes over. Without, all
// cross at x = 1000: one cached x, the comparison sort at once.
TEST(StageSplitEdges, SlabCrossingsCrowdedOnOneXAreSortedExactly) {
  constexpr int kBowTies = 200;
  for (const bool spread : {true, false}) {
    SCOPED_TRACE(spread ? "spread" : "one x");
    Paths subject;
    for (int j = 0; j <= kBowTies; ++j) {
      // Rising at slope 8 from (0, y), falling at slope 8 from (0, y + d): they cross at
      // x = d / 16.
      const int y = 20000 * j;
      const int d = !spread ? 16000 : j == kBowTies ? 160 : 16000 - j;
      subject.push_back(
          {Point(0, y), Point(2000, y + 16000), Point(2000, y + d - 16000), Point(0, y + d)});
    }
    for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
      SCOPED_TRACE(toString(rule));
      EXPECT_EQ(expectSlabsKeepThePlainPieces(subject, nullptr, stages::simplifyWith(rule)), 1u);
    }
  }
}

// A slab's pieces whose order changes at the slab's right end where one of them ends: that is
// the other passing through an input vertex, which the vertex's visit takes, not a crossing the
// slab queues (nor counts for Limits::maxCrossings). The bow-tie column of the test above (slab
// mode for the slab to x = 2000, 201 crossings) and a triangle whose long edge comes down from
// above a rising piece to that piece's right end, (2000, 2016000), and goes on below it.
TEST(StageSplitEdges, SlabPieceThroughAVertexOnTheSlabsEndIsNoCrossing) {
  constexpr int kBowTies = 200;
  Paths subject;
  for (int j = 0; j <= kBowTies; ++j) {
    const int y = 20000 * j;
    subject.push_back(
        {Point(0, y), Point(2000, y + 16000), Point(2000, y + 16000 - 16000), Point(0, y + 16000)});
  }
  const double end = 20000.0 * 100 + 16000;  // bow-tie 100's rising piece ends here, at x = 2000
  subject.push_back({Point(0, end + 1000), Point(4000, end - 1000), Point(4000, end - 999)});
  for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
    SCOPED_TRACE(toString(rule));
    EXPECT_GE(expectSlabsKeepThePlainPieces(subject, nullptr, stages::simplifyWith(rule)), 1u);
    const detail::Arrangement a = stages::arrange(subject, nullptr, stages::simplifyWith(rule));
    EXPECT_EQ(a.crossings, std::uint64_t(kBowTies + 1));
  }
}

// Long steep edges at the edge of the coordinate range cross a vertical edge: the crossings
// share their x exactly and have large denominators, so ordering them needs products beyond
// 128 bits (the 256-bit branch of the exact comparison).
TEST(Simplify, CrossingsSharingXAtRangeEdge) {
  const double m = 4194300.0;
  const Paths in = {{{1000.5, -m}, {1000.5, m}, {1001.25, m}, {1001.25, -m}},
                    {{-m, -m + 3.0 / 256}, {m, m - 7.0 / 256}, {m, -m + 5.0 / 256}},
                    {{-m + 11.0 / 256, m}, {m - 1.0 / 256, -m + 13.0 / 256}, {-m, -m}}};
  for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
    const PolygonSet r = simplify(in, rule);
    const double truth = testing::slabArea(
        {&in}, [&](const std::vector<long long>& w) { return isFilled(rule, w[0]); });
    EXPECT_NEAR(r.area(), truth, 1e-7 * truth);
    const auto report = testing::sampleRegion(
        r, {&in}, [&](const std::vector<long long>& w) { return isFilled(rule, w[0]); }, 990, 1010,
        400, 3u);
    EXPECT_EQ(report.mismatches, 0) << report.firstMismatch;
    EXPECT_GT(report.checked, 300);
  }
}

// A slab crossing of the grid range's two diagonals: in [-1, 1]^2 on the grid of 2^30 units per
// unit the corners lie at +-2^30 units (Grid::kMaxUnits), so the diagonals' cross product is
// 2^63, the most the slab pass's 64-bit unsigned parameter holds (slabCrossing()). A column of
// thin bow-ties across the box puts the sweep in slab mode for the slab from x = -1 to 1.
TEST(Simplify, SlabCrossingOfTheGridRangesDiagonals) {
  Paths in = {{{-1, -1}, {1, 1}, {1, -1}, {-1, 1}}};
  for (int j = 0; j < 40; ++j) {
    const double y = -1 + (j + 0.5) / 20, d = 1.0 / 64;
    in.push_back({{-1, y}, {1, y + d}, {1, y}, {-1, y + d}});
  }
  for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
    SCOPED_TRACE(toString(rule));
    const PolygonSet r = simplify(in, rule, Grid::fixed(0x1p30));
    const auto filled = [&](const std::vector<long long>& w) { return isFilled(rule, w[0]); };
    const double truth = testing::slabArea({&in}, filled);
    EXPECT_NEAR(r.area(), truth, 1e-9 * truth);
    const auto report = testing::sampleRegion(r, {&in}, filled, -1, 1, 400, 5u);
    EXPECT_EQ(report.mismatches, 0) << report.firstMismatch;
    EXPECT_GT(report.checked, 300);
  }
}

// An arrangement keeps a crossing as the indices of two lines (ArrangementVertex) and computes
// it again when read: crossingOfLines() must give the point lineIntersection() gives, also where
// W or the parameter along the first line need more than 64 bits (lines across the whole grid
// range), and the three kinds of vertex must read back as stored.
TEST(StageSplitEdges, ArrangementVerticesReadBackAsTheSweepMadeThem) {
  constexpr std::int64_t kMax = Grid::kMaxUnits;
  std::mt19937_64 rng(17);
  std::uniform_int_distribution<std::int64_t> any(-kMax, kMax);
  std::uniform_int_distribution<std::int64_t> edge(0, 1);
  const auto pick = [&](bool extreme) {
    return extreme ? detail::IPoint{edge(rng) != 0 ? kMax : -kMax, edge(rng) != 0 ? kMax : -kMax}
                   : detail::IPoint{any(rng), any(rng)};
  };
  int wide = 0;
  for (int i = 0; i < 20000; ++i) {
    const bool extreme = i % 4 == 0;
    detail::GridSegment l1, l2;
    l1.setLine(pick(extreme), pick(extreme));
    l2.setLine(pick(extreme), pick(i % 2 == 0));
    detail::XPoint expected;
    if (!detail::lineIntersection(l1.lineA(), l1.lineB(), l2.lineA(), l2.lineB(), expected)) {
      continue;
    }
    const detail::ExactCoords got = detail::crossingOfLines(l1, l2);
    ASSERT_GT(got.w, 0);
    wide += got.w != detail::i128(std::int64_t(got.w)) ? 1 : 0;
    // X / W == X' / W' without a division (|X| < 2^95 and W < 2^64: the products fit 160 bits,
    // compared as exact 256-bit products).
    ASSERT_EQ(detail::i256(got.x) * detail::i256(expected.w),
              detail::i256(expected.x) * detail::i256(got.w))
        << i;
    ASSERT_EQ(detail::i256(got.y) * detail::i256(expected.w),
              detail::i256(expected.y) * detail::i256(got.w))
        << i;
  }
  EXPECT_GT(wide, 0);  // the 128-bit branch ran

  detail::Arrangement a;
  detail::GridSegment l1, l2;
  l1.setLine({0, 0}, {10, 4});
  l2.setLine({0, 4}, {10, 0});
  a.lines = {l1, l2};
  a.offGrid.push_back(detail::PackedPoint(detail::XPoint(7, -3, 2)));
  a.vertices.push_back(detail::ArrangementVertex::grid({-kMax, kMax}));
  a.vertices.push_back(detail::ArrangementVertex::crossing(0, 1));
  a.vertices.push_back(detail::ArrangementVertex::offGrid(0));
  EXPECT_EQ(stages::name(a.point(0)),
            "(" + std::to_string(-kMax) + "," + std::to_string(kMax) + ")");
  const detail::XPoint crossing = a.point(1);  // (5, 2)
  EXPECT_EQ(crossing.x, 5 * crossing.w);
  EXPECT_EQ(crossing.y, 2 * crossing.w);
  EXPECT_EQ(stages::name(a.point(2)), "(7/2,-3/2)");
  EXPECT_TRUE(a.vertices[0].onGrid());
  EXPECT_TRUE(a.vertices[1].isCrossing());
  EXPECT_FALSE(a.vertices[2].onGrid() || a.vertices[2].isCrossing());
}

}  // namespace
}  // namespace roiclip
