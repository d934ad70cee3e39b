// SPDX-License-Identifier: MIT
// Open polylines clipped to a perspective quad: roiclip::clipLines against Clipper 1 (open
// subject paths), Boost.Geometry (linestring / polygon intersection, one call per line) and
// GEOS (one MultiLineString / polygon intersection), in the same run as the polygon rows.
// The first iteration of each is checked: the total clipped length must match roiclip's.
#include "lines_bench.hpp"

#include <cmath>
#include <cstdio>
#include <deque>
#include <random>
#include <stdexcept>
#include <string>
#include <unordered_set>

#include <benchmark/benchmark.h>
#include <geos_c.h>
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/linestring.hpp>
#include <boost/geometry/geometries/multi_linestring.hpp>
#include <clipper.hpp>

#include <roiclip/roiclip.hpp>

#include "adapters.hpp"
#include "alloc_counter.hpp"
#include "workloads.hpp"

namespace roiclip::bench {
namespace {

namespace bg = boost::geometry;
using BoostLine = bg::model::linestring<BoostPoint>;
using BoostLines = bg::model::multi_linestring<BoostLine>;

struct LinesCase {
  std::string name;
  Paths lines;
  Path quad;
  double length = -1;  // roiclip's clipped length, from its first run
  [[nodiscard]] std::size_t vertices() const {
    std::size_t n = quad.size();
    for (const Path& l : lines) n += l.size();
    return n;
  }
};

double pathLength(const Path& line) {
  double total = 0;
  for (std::size_t i = 1; i < line.size(); ++i) {
    total += std::hypot(line[i].x - line[i - 1].x, line[i].y - line[i - 1].y);
  }
  return total;
}

/// Canny-like edges: `count` 8-connected pixel chains of up to `steps` steps that keep a
/// heading with small turns, spread over a 1000 x 1000 image. Like traced Canny edges, no pixel
/// belongs to two chains or twice to one (a chain ends early when it is boxed in), so no two
/// segments overlap and every library sees the same linework.
Paths edgeWalks(std::size_t count, std::size_t steps, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> start(0, 999);
  std::uniform_int_distribution<int> turn(-1, 1);
  constexpr int kDx[8] = {1, 1, 0, -1, -1, -1, 0, 1};
  constexpr int kDy[8] = {0, 1, 1, 1, 0, -1, -1, -1};
  std::unordered_set<std::int64_t> used;
  const auto key = [](int x, int y) { return std::int64_t(x) * 1000003 + y; };
  Paths lines;
  while (lines.size() < count) {
    int x = start(rng), y = start(rng), heading = int(rng() % 8);
    if (!used.insert(key(x, y)).second) continue;
    Path line{{double(x), double(y)}};
    for (std::size_t s = 0; s < steps; ++s) {
      if (rng() % 3 == 0) heading = (heading + 8 + turn(rng)) % 8;
      bool moved = false;
      for (const int change : {0, 1, -1, 2, -2}) {
        const int h = (heading + 8 + change) % 8;
        if (used.insert(key(x + kDx[h], y + kDy[h])).second) {
          heading = h;
          x += kDx[h];
          y += kDy[h];
          moved = true;
          break;
        }
      }
      if (!moved) break;
      line.emplace_back(double(x), double(y));
    }
    if (line.size() >= 2) lines.push_back(std::move(line));
  }
  return lines;
}

template <class Run, class Length>
void measureLines(benchmark::State& state, LinesCase& c, bool reference, double tolerance, Run run,
                  Length length) {
  bool first = true;
  for (auto _ : state) {
    if (!first) {
      auto result = run();
      benchmark::DoNotOptimize(result);
      continue;
    }
    first = false;
    releaseThreadBuffers();  // as in core_bench.cpp: the figures include roiclip's kept arrays
    resetAllocStats();
    auto result = run();
    const AllocStats heap = allocStats();
    state.PauseTiming();
    const double total = length(result);
    if (reference) c.length = total;
    state.counters["vertices"] = double(c.vertices());
    state.counters["length"] = total;
    state.counters["allocs"] = double(heap.allocations);
    state.counters["peak_MB"] = double(heap.peakLive) / 1e6;
    if (c.length < 0) {
      state.SkipWithError("roiclip's row did not run first");
      break;
    }
    const double relDiff = std::fabs(total - c.length) / std::max(c.length, 1.0);
    state.counters["rel_diff"] = relDiff;
    if (!(relDiff <= tolerance)) {
      char message[200];
      std::snprintf(message, sizeof message, "length %.10g disagrees with roiclip %.10g", total,
                    c.length);
      std::fprintf(stderr, "WARNING: %s: %s\n", c.name.c_str(), message);
      state.SkipWithError(message);
      break;
    }
    state.ResumeTiming();
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(c.vertices()));
}

void benchRoiclipLines(benchmark::State& state, LinesCase& c) {
  const Paths region{c.quad};
  measureLines(
      state, c, true, 0.0, [&] { return clipLines(c.lines, region, FillRule::EvenOdd); },
      [](const Paths& r) {
        double total = 0;
        for (const Path& l : r) total += pathLength(l);
        return total;
      });
}

void benchClipperLines(benchmark::State& state, LinesCase& c) {
  const ClipperLib::Paths lines = toClipper(c.lines);
  const ClipperLib::Paths quad = toClipper(Paths{c.quad});
  // Clipper rounds the crossings with the quad's sides to integer units (up to 0.006 px of
  // length each), and on open paths whose first edge is horizontal it can swap the first two
  // points: the chain 277,306 278,306 279,305 came back as 278,306 277,306 279,305, which adds
  // length (measured: +0.02% on Edges10k, +0.04% on Edges100k). Its row is kept for the timing
  // and reports rel_diff.
  measureLines(
      state, c, false, 1e-3,
      [&] {
        ClipperLib::Clipper clipper;
        clipper.AddPaths(lines, ClipperLib::ptSubject, false);
        clipper.AddPaths(quad, ClipperLib::ptClip, true);
        ClipperLib::PolyTree tree;
        if (!clipper.Execute(ClipperLib::ctIntersection, tree, ClipperLib::pftEvenOdd,
                             ClipperLib::pftEvenOdd)) {
          throw std::runtime_error("Clipper::Execute failed");
        }
        ClipperLib::Paths open;
        ClipperLib::OpenPathsFromPolyTree(tree, open);
        return open;
      },
      [](const ClipperLib::Paths& r) {
        double total = 0;
        for (const ClipperLib::Path& l : r) {
          for (std::size_t i = 1; i < l.size(); ++i) {
            total += std::hypot(double(l[i].X - l[i - 1].X), double(l[i].Y - l[i - 1].Y));
          }
        }
        return total / testing::kClipperUnits;
      });
}

void benchBoostLines(benchmark::State& state, LinesCase& c) {
  std::vector<BoostLine> lines;
  for (const Path& l : c.lines) {
    BoostLine line;
    for (const Point& p : l) line.emplace_back(p.x, p.y);
    lines.push_back(std::move(line));
  }
  const BoostPolygon quad = toBoost({c.quad});
  measureLines(
      state, c, false, 1e-9,
      [&] {
        BoostLines out;
        for (const BoostLine& line : lines) bg::intersection(line, quad, out);
        return out;
      },
      [](const BoostLines& r) { return double(bg::length(r)); });
}

// One intersection per line: GEOS nodes and dissolves the linework of one MultiLineString,
// which would merge overlapping edges (a different result).
void benchGeosLines(benchmark::State& state, LinesCase& c) {
  GEOSContextHandle_t ctx = geosContext();
  std::vector<GeosGeometry> lines;
  for (const Path& l : c.lines) {
    GEOSCoordSequence* seq = GEOSCoordSeq_create_r(ctx, unsigned(l.size()), 2);
    for (std::size_t i = 0; i < l.size(); ++i) {
      GEOSCoordSeq_setXY_r(ctx, seq, unsigned(i), l[i].x, l[i].y);
    }
    lines.emplace_back(GEOSGeom_createLineString_r(ctx, seq));
  }
  const GeosGeometry quad = toGeos({c.quad});
  measureLines(
      state, c, false, 1e-9,
      [&] {
        std::vector<GeosGeometry> out;
        for (const GeosGeometry& line : lines) {
          out.emplace_back(GEOSIntersection_r(ctx, line.get(), quad.get()));
          if (!out.back()) throw std::runtime_error("GEOSIntersection_r failed");
        }
        return out;
      },
      [ctx](const std::vector<GeosGeometry>& r) {
        double total = 0;
        for (const GeosGeometry& g : r) {
          double length = 0;
          GEOSLength_r(ctx, g.get(), &length);
          total += length;
        }
        return total;
      });
}

std::deque<LinesCase>& linesCases() {
  static std::deque<LinesCase> all;
  return all;
}

}  // namespace

void registerLines() {
  for (const std::size_t count : {100, 1000}) {
    LinesCase& c = linesCases().emplace_back();
    c.lines = edgeWalks(count, 100, std::uint32_t(70 + count));
    Path box;
    for (const Path& l : c.lines) box.insert(box.end(), l.begin(), l.end());
    c.quad = perspectiveQuad(box, std::uint32_t(80 + count));
    c.name = "Lines/Edges" + std::to_string(count * 100 / 1000) + "k_x_quad";
    const auto add = [&c](const char* lib, void (*fn)(benchmark::State&, LinesCase&)) {
      benchmark::RegisterBenchmark((c.name + "/" + lib).c_str(), [&c, fn](benchmark::State& s) {
        fn(s, c);
      })->Unit(benchmark::kMillisecond);
    };
    add("roiclip", benchRoiclipLines);
    add("clipper", benchClipperLines);
    add("boost", benchBoostLines);
    add("geos", benchGeosLines);
  }
}

}  // namespace roiclip::bench
