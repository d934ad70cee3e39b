// SPDX-License-Identifier: MIT
// Stage 0 (src/core/input.cpp): validation, snapping to the grid, repeats and straight runs
// dropped, edges emitted with their direction and operand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <roiclip/roiclip.hpp>

#include "pipeline.hpp"
#include "stage_support.hpp"
#include "support/oracle.hpp"

namespace roiclip {
namespace {

using detail::IPoint;

using stages::kUnitGrid;

std::vector<IPoint> ring(std::initializer_list<IPoint> points) { return points; }

TEST(StageInput, SnapsToTheGridRoundingTiesToEven) {
  // A fixed 1/256 px grid. 0.5 and 1.5 units are ties: to even, 0 and 2.
  const auto rings =
      detail::snapRings({{{0.5 / 256, 0}, {10, 1.5 / 256}, {10, 10 + 0.6 / 256}, {-0.4 / 256, 10}}},
                        0, Grid::fixed(256));
  ASSERT_EQ(rings.size(), 1u);
  EXPECT_EQ(rings[0], ring({{0, 0}, {2560, 2}, {2560, 2561}, {0, 2560}}));
}

TEST(StageInput, DropsRepeatsTheClosingPointAndStraightRuns) {
  // A 3x3 pixel square walked in unit steps, with a repeated point and its first point again at
  // the end: only the 4 corners are left, starting where the ring turns.
  const Paths chain = {{{0, 0},
                        {1, 0},
                        {1, 0},
                        {2, 0},
                        {3, 0},
                        {3, 1},
                        {3, 2},
                        {3, 3},
                        {2, 3},
                        {1, 3},
                        {0, 3},
                        {0, 2},
                        {0, 1},
                        {0, 0}}};
  const auto rings = detail::snapRings(chain, 0, kUnitGrid);
  ASSERT_EQ(rings.size(), 1u);
  EXPECT_EQ(rings[0], ring({{0, 0}, {3, 0}, {3, 3}, {0, 3}}));
  // Straight on across the closing vertex too: the start (1, 0) lies mid-edge.
  // The ring keeps its cyclic order (from some vertex); here the first, the last or both go.
  const auto cyclic = [](std::vector<detail::IPoint> got, const std::vector<detail::IPoint>& want) {
    const auto first = std::find(got.begin(), got.end(), want[0]);
    if (first == got.end()) return false;
    std::rotate(got.begin(), first, got.end());
    return got == want;
  };
  const auto across = detail::snapRings({{{1, 0}, {2, 0}, {2, 2}, {0, 2}, {0, 0}}}, 0, kUnitGrid);
  ASSERT_EQ(across.size(), 1u);
  EXPECT_TRUE(cyclic(across[0], ring({{2, 0}, {2, 2}, {0, 2}, {0, 0}})));
  const auto last = detail::snapRings({{{2, 0}, {2, 2}, {0, 2}, {0, 0}, {1, 0}}}, 0, kUnitGrid);
  EXPECT_TRUE(cyclic(last[0], ring({{2, 0}, {2, 2}, {0, 2}, {0, 0}})));
  const auto both =
      detail::snapRings({{{2, 0}, {3, 0}, {3, 3}, {0, 3}, {0, 0}, {1, 0}}}, 0, kUnitGrid);
  EXPECT_TRUE(cyclic(both[0], ring({{3, 0}, {3, 3}, {0, 3}, {0, 0}})));
  // Fewer than three distinct points enclose nothing; one point twice is one point.
  EXPECT_TRUE(
      detail::snapRings({{}, {{5, 5}}, {{5, 5}, {5, 5}}, {{1, 1}, {5, 5}}}, 0, kUnitGrid).empty());
}

TEST(StageInput, DropsSpikes) {
  // Back along the last edge, shorter (the spike's tip goes) or longer (so does its base).
  EXPECT_EQ(detail::snapRings({{{0, 0}, {4, 0}, {2, 0}, {2, 2}}}, 0, kUnitGrid),
            detail::Rings({ring({{0, 0}, {2, 0}, {2, 2}})}));
  EXPECT_EQ(detail::snapRings({{{2, 0}, {4, 0}, {0, 0}, {0, 2}}}, 0, kUnitGrid),
            detail::Rings({ring({{2, 0}, {0, 0}, {0, 2}})}));
  // A one-pixel spur traced out and back with a bend (two spikes, one inside the other), and
  // one across the closing vertex: only the square is left.
  const auto spur = detail::snapRings(
      {{{0, 0}, {3, 0}, {3, 1}, {5, 1}, {5, 2}, {5, 1}, {3, 1}, {3, 3}, {0, 3}, {-2, 3}, {0, 3}}},
      0, kUnitGrid);
  ASSERT_EQ(spur.size(), 1u);
  EXPECT_EQ(spur[0], ring({{0, 0}, {3, 0}, {3, 3}, {0, 3}}));
  // Nothing but spikes: no ring.
  EXPECT_TRUE(
      detail::snapRings({{{0, 0}, {4, 0}, {4, 3}, {4, 0}}, {{1, 1}, {5, 5}, {3, 3}}}, 0, kUnitGrid)
          .empty());
}

// Random rings with spikes and straight runs in them (fixed seed), snapped with the one-pass
// snapping and, through a grid whose origin is too far for it, with the general one: both give
// the same rings; no ring keeps a repeated point, a straight-on vertex or a spike (also across
// its closing vertex), or fewer than three vertices; and the exact winding number of the rings
// around every point of a fine lattice off their edges is the path's.
TEST(StageInput, DroppingSpikesKeepsEveryWindingNumber) {
  std::mt19937 rng(20261205);
  const double far = 0x1p51;  // origin * scale beyond 2^50: no point takes the one-pass snapping
  const Grid nearGrid = Grid::fixed(1.0), farGrid = Grid::fixed(1.0, {far, far});
  std::size_t spikesSeen = 0, dropped = 0, compared = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    Path path;
    Point at{double(rng() % 9), double(rng() % 9)};
    path.push_back(at);
    const int steps = 3 + int(rng() % 10);
    for (int k = 0; k < steps; ++k) {
      const Point d{double(int(rng() % 5) - 2), double(int(rng() % 5) - 2)};
      switch (rng() % 4) {
        case 0: {  // a spike: out and back, to a point on the way or beyond
          const double back = double(int(rng() % 4));
          path.push_back({at.x + 2 * d.x, at.y + 2 * d.y});
          at = {at.x + (2 - back) * d.x, at.y + (2 - back) * d.y};
          ++spikesSeen;
          break;
        }
        case 1:  // a straight run
          path.push_back({at.x + d.x, at.y + d.y});
          at = {at.x + 2 * d.x, at.y + 2 * d.y};
          break;
        default:
          at = {at.x + d.x, at.y + d.y};
      }
      path.push_back(at);
    }
    const auto nearRings = detail::snapRings({path}, 0, nearGrid);
    Path shifted = path;
    for (Point& q : shifted) q = {q.x + far, q.y + far};
    const auto farRings = detail::snapRings({shifted}, 0, farGrid);
    ASSERT_EQ(nearRings, farRings) << "trial " << trial;
    dropped += nearRings.empty() ? 1 : 0;
    Paths kept;
    for (const auto& r : nearRings) {
      const std::size_t n = r.size();
      ASSERT_GE(n, 3u) << "trial " << trial;
      Path out;
      for (std::size_t i = 0; i < n; ++i) {
        const IPoint a = r[i], b = r[(i + 1) % n], c = r[(i + 2) % n];
        ASSERT_NE(a, b) << "trial " << trial;
        ASSERT_NE(detail::orient(a, b, c), 0) << "trial " << trial << " vertex " << i << [&] {
          std::string t;
          for (auto q : path) t += " " + std::to_string(q.x) + "," + std::to_string(q.y);
          t += " ->";
          for (auto q : r) t += " " + std::to_string(q.x) + "," + std::to_string(q.y);
          return t;
        }();
        out.push_back({double(a.x), double(a.y)});
      }
      kept.push_back(out);
    }
    // Every point of the path's box on a lattice of half units, shifted off the grid lines;
    // points on an edge of either have no winding number and are left out.
    double x0 = path[0].x, x1 = x0, y0 = path[0].y, y1 = y0;
    for (const Point q : path) {
      x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), y0 = std::min(y0, q.y),
      y1 = std::max(y1, q.y);
    }
    for (double x = x0 - 0.75; x <= x1 + 1; x += 0.5) {
      for (double y = y0 - 0.5; y <= y1 + 1; y += 0.5) {
        const auto want = testing::exactWinding(Paths{path}, {x, y});
        const auto got = testing::exactWinding(kept, {x, y});
        if (!want || !got) continue;
        ASSERT_EQ(*got, *want) << "trial " << trial << " at (" << x << ", " << y << ")";
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 500000u);
  EXPECT_GT(spikesSeen, 1000u);
  EXPECT_GT(dropped, 10u);  // rings of nothing but spikes and runs occur, and go
}

TEST(StageInput, EdgesAreStoredLeftToRightWithTheirDirectionAndOperand) {
  std::vector<detail::InputEdge> edges;
  // Clockwise in the raw frame: (0,0) -> (0,4) -> (4,4) -> (4,0).
  detail::appendInputEdges({{{0, 0}, {0, 4}, {4, 4}, {4, 0}}}, 1, kUnitGrid, edges);
  ASSERT_EQ(edges.size(), 4u);
  const int directions[] = {+1, +1, -1, -1};
  for (std::size_t i = 0; i < edges.size(); ++i) {
    EXPECT_TRUE(edges[i].a < edges[i].b) << i;
    EXPECT_EQ(edges[i].direction, directions[i]) << i;
    EXPECT_EQ(edges[i].operand, 1);
    EXPECT_FALSE(edges[i].open);
  }
  EXPECT_EQ(edges[3].a, (IPoint{0, 0}));  // (4,0) -> (0,0) stored as (0,0) -> (4,0), reversed
  EXPECT_EQ(edges[3].b, (IPoint{4, 0}));
}

TEST(StageInput, LineEdgesKeepPathOrderAndIndexThePolylines) {
  std::vector<detail::InputEdge> edges;
  std::vector<std::size_t> first;
  // The second polyline goes straight on at (2,0): one segment.
  detail::appendLineEdges({{{0, 0}, {5, 0}, {5, 5}}, {{4, 0}, {2, 0}, {0, 0}}, {{7, 7}}}, kUnitGrid,
                          edges, first);
  ASSERT_EQ(edges.size(), 3u);
  EXPECT_EQ(first, (std::vector<std::size_t>{0, 2, 3, 3}));
  for (const auto& e : edges) EXPECT_TRUE(e.open);
  EXPECT_EQ(edges[2].direction, -1);
  EXPECT_EQ(edges[2].a, (IPoint{0, 0}));
  EXPECT_EQ(edges[2].b, (IPoint{4, 0}));
}

TEST(StageInput, InvalidCoordinatesNameOperandPathAndVertex) {
  std::vector<detail::InputEdge> edges;
  try {
    detail::appendInputEdges({{{0, 0}, {1, 0}, {1, 1}}, {{0, 0}, {std::nan(""), 0}}}, 1,
                             Grid::fixed(256), edges);
    FAIL() << "NaN accepted";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("clip path 1, vertex 1: x"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(resolveGrid(Grid{-1.0}, {{{0, 0}, {1, 0}}}), InvalidInputError);
}

TEST(Simplify, DegenerateInputGivesEmptyResult) {
  EXPECT_TRUE(simplify({}, FillRule::NonZero).empty());
  EXPECT_TRUE(simplify({{}}, FillRule::NonZero).empty());
  EXPECT_TRUE(simplify({{{1, 1}}}, FillRule::NonZero).empty());
  EXPECT_TRUE(simplify({{{1, 1}, {5, 5}}}, FillRule::NonZero).empty());
  EXPECT_TRUE(simplify({{{0, 0}, {5, 5}, {10, 10}}}, FillRule::NonZero).empty());
}

TEST(Simplify, InvalidInputIsRejectedWithItsLocation) {
  const double nan = std::nan("");
  try {
    simplify({{{0, 0}, {1, 0}, {1, nan}}}, FillRule::NonZero);
    FAIL() << "NaN accepted";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("path 0, vertex 2"), std::string::npos) << e.what();
  }
  // Beyond a fixed grid's range (the default, fitted grid takes any finite input).
  EXPECT_THROW(simplify({{{0, 0}, {1e7, 0}, {1, 1}}}, FillRule::NonZero, Grid::fixed(256)),
               InvalidInputError);
  EXPECT_THROW(simplify({{{0, 0}, {INFINITY, 0}, {1, 1}}}, FillRule::NonZero), InvalidInputError);
  EXPECT_THROW(simplify({{{0, 0}, {1, 0}, {1, 1}}}, FillRule::NonZero, Grid{-1.0}),
               InvalidInputError);
  EXPECT_THROW(simplify({{{0, 0}, {1, 0}, {1, 1}}}, FillRule::NonZero, Grid{INFINITY}),
               InvalidInputError);
  // The range edge is accepted: 2^30 units at scale 256.
  EXPECT_NO_THROW(
      simplify({{{0, 0}, {4194304, 0}, {0, -4194304}}}, FillRule::NonZero, Grid::fixed(256)));
}

}  // namespace
}  // namespace roiclip

namespace roiclip {
namespace {

// The inline snapping takes a point only when Grid::toUnits() would; every other point goes
// through the checked path, so each error still names its path, vertex and axis.
TEST(StageInput, SnappingErrorsNameTheirPathVertexAndAxis) {
  struct Bad {
    double x, y;
    std::size_t path, vertex;
    Axis axis;
  };
  const Grid grid = Grid::fixed(1.0);
  const double big = double(Grid::kMaxUnits) + 1;  // one unit beyond the range
  for (const Bad& bad :
       {Bad{NAN, 0, 2, 3, Axis::X}, Bad{0, NAN, 2, 3, Axis::Y}, Bad{big, 0, 1, 0, Axis::X},
        Bad{0, -big, 0, 4, Axis::Y}, Bad{INFINITY, NAN, 1, 2, Axis::X},
        Bad{1e300, 0, 2, 1, Axis::X}, Bad{0, 0x1p52, 0, 1, Axis::Y}}) {
    Paths paths(3, Path{{0, 0}, {10, 0}, {10, 10}, {0, 10}, {5, 5}});
    paths[bad.path][bad.vertex] = {bad.x, bad.y};
    for (int operand = 0; operand < 2; ++operand) {
      try {
        detail::snapRings(paths, operand, grid);
        ADD_FAILURE() << "no error for (" << bad.x << ", " << bad.y << ")";
      } catch (const InvalidInputError& e) {
        EXPECT_EQ(e.location().path, bad.path) << e.what();
        EXPECT_EQ(e.location().vertex, bad.vertex) << e.what();
        EXPECT_EQ(e.location().axis, bad.axis) << e.what();
        EXPECT_EQ(e.location().operand, operand == 0 ? Operand::Subject : Operand::Clip);
      }
    }
  }
  // The range's ends themselves are held, and an origin shifts the range.
  const double m = double(Grid::kMaxUnits);
  const auto rings = detail::snapRings({{{-m, -m}, {m, -m}, {m, m}}}, 0, grid);
  ASSERT_EQ(rings.size(), 1u);
  EXPECT_EQ(rings[0][2], (IPoint{Grid::kMaxUnits, Grid::kMaxUnits}));
  EXPECT_THROW(detail::snapRings({{{0, 0}, {m, 0}, {1, 1}}}, 0, Grid::fixed(1.0, {-1, 0})),
               InvalidInputError);
  const auto shifted =
      detail::snapRings({{{0, 0}, {m + 5, 0}, {1, 1}}}, 0, Grid::fixed(1.0, {5, 0}));
  ASSERT_EQ(shifted.size(), 1u);
  EXPECT_EQ(shifted[0][1], (IPoint{Grid::kMaxUnits, 0}));
}

// orientInGrid() (int64) against the 128-bit orient() on every triple of points built from the
// extreme coordinates of the grid's range, where the products reach 2^62.
TEST(StageInput, Int64OrientationAgreesAtTheRangesEnds) {
  const std::int64_t m = Grid::kMaxUnits;
  const std::int64_t values[] = {-m, -m + 1, -m / 2, -1, 0, 1, m / 2 + 1, m - 1, m};
  std::vector<IPoint> points;
  for (std::int64_t x : values) {
    for (std::int64_t y : values) points.push_back({x, y});
  }
  long long checked = 0, zero = 0;
  for (const IPoint a : points) {
    for (const IPoint b : points) {
      for (const IPoint c : points) {
        const int expected = detail::orient(a, b, c);
        ASSERT_EQ(detail::orientInGrid(a, b, c), expected)
            << a.x << "," << a.y << " " << b.x << "," << b.y << " " << c.x << "," << c.y;
        zero += expected == 0;
        ++checked;
      }
    }
  }
  EXPECT_GT(zero, 0);
  EXPECT_EQ(checked, 81LL * 81 * 81);
  // crossSign() (int64) on the directions of segments between them, up to 2^31 a component.
  long long crossed = 0, parallel = 0;
  for (const IPoint a : points) {
    for (const IPoint b : points) {
      const IPoint d{b.x - a.x, b.y - a.y};
      for (const IPoint e : {IPoint{2 * m, 2 * m}, IPoint{-2 * m, 2 * m - 1}, IPoint{2 * m, -1},
                             IPoint{m, -2 * m}, IPoint{-1, 0}, d}) {
        const __int128 cross = __int128(d.x) * e.y - __int128(d.y) * e.x;
        ASSERT_EQ(detail::crossSign(d, e), (cross > 0) - (cross < 0))
            << d.x << "," << d.y << " x " << e.x << "," << e.y;
        ++crossed;
        parallel += cross == 0;
      }
    }
  }
  EXPECT_GT(parallel, 81);
  EXPECT_EQ(crossed, 81LL * 81 * 6);
}

// Straight runs and spikes are merged with the int64 test at the range's ends too: a ring along
// the range's border keeps only its corners, and a spike along the border goes.
TEST(StageInput, MergesStraightRunsAtTheRangesEnds) {
  const double m = double(Grid::kMaxUnits);
  const auto rings = detail::snapRings(
      {{{-m, -m}, {0, -m}, {m, -m}, {m, 0}, {m, m}, {0, m}, {-m, m}, {-m, 0}}}, 0, Grid::fixed(1));
  ASSERT_EQ(rings.size(), 1u);
  EXPECT_EQ(rings[0].size(), 4u);
  const auto spike =
      detail::snapRings({{{-m, -m}, {m, -m}, {m, m}, {m, -m + 1}, {m, m - 1}}}, 0, Grid::fixed(1));
  const std::int64_t u = Grid::kMaxUnits;
  EXPECT_EQ(spike, detail::Rings({ring({{-u, -u}, {u, -u}, {u, u - 1}})}));
}

// The inline snapping of snapRings() against the rule it repeats, Grid::toUnits(), where it
// decides by its range test alone: origins up to and past 2^50 units, coordinates whose units
// reach 2^51 and 2^52 (where the short rounding is no longer exact), and the range's ends. A
// point is snapped to toUnits()' units, or the call throws when toUnits() rejects it.
TEST(StageInput, InlineSnappingAgreesWithToUnitsAtItsLimits) {
  const double m = double(Grid::kMaxUnits);
  int snapped = 0, rejected = 0;
  for (const double scale : {1.0, 0.5, 4.0, 0x1p-20, 1000.0}) {
    for (const double originUnits :
         {0.0, 0x1p50, -0x1p50, 0x1p50 + 1, -0x1p50 - 1, 0x1p51, 0x1p51 - 0x1p30, 0x1p60}) {
      const Point origin{originUnits / scale, -originUnits / scale};
      const Grid grid = Grid::fixed(scale, origin);
      std::vector<double> units;
      for (const double base : {originUnits, 0x1p51, -0x1p51, 0x1p52, -0x1p52, 0.0}) {
        for (const double d : {-m - 1, -m, -m + 0.5, -1.5, -0.5, 0.0, 0.5, 2.5, m - 0.5, m, m + 0.5,
                               m + 1, 0x1p51 - originUnits}) {
          units.push_back(base + d);
        }
      }
      for (const double u : units) {
        for (const double v : {u / scale, std::nextafter(u / scale, 0.0)}) {
          const std::optional<std::int64_t> x = grid.toUnits(v, origin.x);
          const std::optional<std::int64_t> y = grid.toUnits(-v, origin.y);
          // The probe, the origin's grid point and a point about 2^30 units above it: a triangle
          // (the probe first) unless the probe lies on x = 0.
          const Point above{origin.x, origin.y + (m - 1) / scale};
          const Paths paths{{{v, -v}, origin, above, above}};
          if (!x || !y) {
            EXPECT_THROW((void)detail::snapRings(paths, 0, grid), InvalidInputError)
                << "scale " << scale << " origin " << originUnits << " v " << v;
            ++rejected;
            continue;
          }
          const auto rings = detail::snapRings(paths, 0, grid);
          const IPoint expected{*x, *y};
          if (expected.x == 0) continue;  // the ring collapses to a segment
          ASSERT_EQ(rings.size(), 1u) << "scale " << scale << " origin " << originUnits;
          ASSERT_EQ(rings[0].size(), 3u);
          EXPECT_EQ(rings[0][2], (IPoint{0, *grid.toUnits(above.y, origin.y)}));
          EXPECT_EQ(rings[0][0], expected)
              << "scale " << scale << " origin " << originUnits << " v " << v;
          ++snapped;
        }
      }
    }
  }
  EXPECT_GT(snapped, 200);
  EXPECT_GT(rejected, 200);
}

}  // namespace
}  // namespace roiclip
