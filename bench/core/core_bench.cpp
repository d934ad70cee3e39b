// SPDX-License-Identifier: MIT
// roiclip_bench: roiclip against Clipper 1, Boost.Geometry and GEOS on the same inputs in one
// run. The first iteration of each benchmark also (a) counts heap use and (b) checks, with the
// timer paused, that its output area agrees with roiclip's; a large disagreement is a correctness
// signal and marks the benchmark with an error (and saves the input when --dump_dir is given).
//
// Extra flags (taken out before Google Benchmark parses the rest):
//   --dump_dir=DIR   write every input on which roiclip throws or disagrees with another library
//                    to DIR/<case>.json;
//   --include_slow   also run Clipper's SimplifyPolygons on the 10k random polygon under EvenOdd
//                    (it did not finish within 6 minutes: StrictlySimple output on ~6M rings).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <deque>
#include <exception>
#include <optional>
#include <string>
#include <utility>

#include <roiclip/roiclip.hpp>

#include "adapters.hpp"
#include "alloc_counter.hpp"
#include "lines_bench.hpp"
#include "workloads.hpp"

namespace roiclip::bench {
namespace {

enum class Library { Roiclip, Clipper, ClipperUnion, Boost, Geos };

const char* libraryName(Library lib) {
  switch (lib) {
    case Library::Roiclip:
      return "roiclip";
    case Library::Clipper:
      return "clipper";
    case Library::ClipperUnion:
      return "clipper_union";
    case Library::Boost:
      return "boost";
    case Library::Geos:
      return "geos";
  }
  return "?";
}

// Allowed relative area differences from roiclip. Boost.Geometry and GEOS compute crossings in
// double precision. Clipper rounds every crossing to integer units (1/256 px), moving it up to
// half a unit across an edge: against the long sides of an ROI quad that is ~0.1 px^2 per
// crossing (measured 3e-6 on the 1k contour), and self-intersecting inputs have thousands of
// crossings (measured up to 5e-6).
constexpr double kDoubleTolerance = 1e-6;
constexpr double kClipperValidTolerance = 1e-5;
constexpr double kRoundedCrossingTolerance = 1e-4;

/// One input: simplify(subject) when `clip` is empty, else intersection(subject, clip).
struct Case {
  std::string name;
  Paths subject;
  Paths clip;
  FillRule rule = FillRule::EvenOdd;
  /// Subject and clip are simple polygons, so Boost.Geometry and GEOS may run on them.
  bool valid = false;
  /// Allowed relative area difference between Clipper and roiclip (see above).
  double clipperTolerance = kClipperValidTolerance;
  /// Clipper takes minutes here; registered only with --include_slow.
  bool clipperSlow = false;

  // roiclip's output area, computed once (by whichever benchmark needs it first).
  std::optional<double> reference;
  std::string referenceError;

  [[nodiscard]] bool binary() const { return !clip.empty(); }
  [[nodiscard]] std::size_t vertices() const {
    std::size_t n = 0;
    for (const Path& p : subject) n += p.size();
    for (const Path& p : clip) n += p.size();
    return n;
  }
};

std::string gDumpDir;
bool gIncludeSlow = false;

PolygonSet runRoiclip(const Case& c) {
  return c.binary() ? clip(ClipOp::Intersection, c.subject, c.clip, c.rule, c.rule)
                    : simplify(c.subject, c.rule);
}

void dumpCase(const Case& c) {
  if (gDumpDir.empty()) return;
  std::string file = c.name;
  for (char& ch : file) {
    if (ch == '/') ch = '_';
  }
  file = gDumpDir + "/" + file + ".json";
  writeCaseJson(file, c.subject, c.binary() ? c.clip : Paths{}, ClipOp::Intersection, c.rule,
                c.rule);
  std::fprintf(stderr, "  input saved to %s\n", file.c_str());
}

/// roiclip's area for the case, or nullopt (after reporting) when roiclip throws.
std::optional<double> referenceArea(Case& c) {
  if (!c.reference && c.referenceError.empty()) {
    try {
      c.reference = runRoiclip(c).area();
    } catch (const std::exception& e) {
      c.referenceError = std::string("roiclip threw: ") + e.what();
      std::fprintf(stderr, "WARNING: %s: %s\n", c.name.c_str(), c.referenceError.c_str());
      dumpCase(c);
    }
  }
  return c.reference;
}

/// Everything one untimed run of an operation reports.
struct Outcome {
  double area = 0.0;
  std::size_t rings = 0;
};

/// The common skeleton. The first iteration of every run is also the check: its heap use is
/// recorded and (with the timer paused) its output area is compared with roiclip's; the heavy
/// cases run one iteration only, so a separate untimed run would double their cost. `run`
/// returns the library's native result (freed inside the loop, as a caller would); `inspect`
/// turns a result into an Outcome.
template <class Run, class Inspect>
void measure(benchmark::State& state, Case& c, Library lib, double tolerance, Run run,
             Inspect inspect) {
  std::optional<double> expected;
  if (lib != Library::Roiclip) {
    expected = referenceArea(c);
    if (!expected) {
      state.SkipWithError(c.referenceError.c_str());
      return;
    }
  }
  bool first = true;
  for (auto _ : state) {
    if (!first) {
      auto result = run();
      benchmark::DoNotOptimize(result);
      continue;
    }
    first = false;
    std::optional<decltype(run())> result;
    AllocStats heap;
    std::string failure;
    // roiclip keeps its working arrays per thread between calls: freed first, so that this
    // call's figures include them (and its time, the cold start).
    releaseThreadBuffers();
    try {
      resetAllocStats();
      result.emplace(run());
      heap = allocStats();
    } catch (const std::exception& e) {
      failure = std::string(libraryName(lib)) + " threw: " + e.what();
    }
    state.PauseTiming();
    if (!failure.empty()) {
      std::fprintf(stderr, "WARNING: %s: %s\n", c.name.c_str(), failure.c_str());
      if (lib == Library::Roiclip) {
        c.referenceError = failure;
        dumpCase(c);
      }
      state.SkipWithError(failure.c_str());
      break;
    }
    const Outcome outcome = inspect(*result);
    if (lib == Library::Roiclip && !c.reference) c.reference = outcome.area;
    if (!expected) expected = c.reference;
    const double relDiff =
        std::fabs(outcome.area - *expected) / std::max(std::fabs(*expected), 1.0);
    state.counters["vertices"] = double(c.vertices());
    state.counters["area"] = outcome.area;
    state.counters["rings"] = double(outcome.rings);
    state.counters["rel_diff"] = relDiff;
    state.counters["allocs"] = double(heap.allocations);
    state.counters["alloc_MB"] = double(heap.bytes) / 1e6;
    state.counters["peak_MB"] = double(heap.peakLive) / 1e6;
    if (!(relDiff <= tolerance)) {
      char message[256];
      std::snprintf(message, sizeof message,
                    "%s area %.10g disagrees with roiclip %.10g (relative difference %.3g > %.3g)",
                    libraryName(lib), outcome.area, *expected, relDiff, tolerance);
      std::fprintf(stderr, "WARNING: %s: %s\n", c.name.c_str(), message);
      dumpCase(c);
      state.SkipWithError(message);
      break;
    }
    state.ResumeTiming();
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(c.vertices()));
}

void benchRoiclip(benchmark::State& state, Case& c) {
  measure(
      state, c, Library::Roiclip, 0.0, [&] { return runRoiclip(c); },
      [](const PolygonSet& r) {
        return Outcome{r.area(), r.ringCount()};
      });
}

void benchClipper(benchmark::State& state, Case& c) {
  const ClipperLib::Paths subject = toClipper(c.subject);
  const ClipperLib::Paths clipPaths = toClipper(c.clip);
  const ClipperLib::PolyFillType fill = toClipper(c.rule);
  const auto inspect = [](const ClipperLib::Paths& r) { return Outcome{clipperArea(r), r.size()}; };
  if (!c.binary()) {
    measure(
        state, c, Library::Clipper, c.clipperTolerance,
        [&] {
          ClipperLib::Paths out;
          ClipperLib::SimplifyPolygons(subject, out, fill);
          return out;
        },
        inspect);
    return;
  }
  measure(
      state, c, Library::Clipper, c.clipperTolerance,
      [&] {
        ClipperLib::Clipper clipper;
        clipper.AddPaths(subject, ClipperLib::ptSubject, true);
        clipper.AddPaths(clipPaths, ClipperLib::ptClip, true);
        ClipperLib::Paths out;
        if (!clipper.Execute(ClipperLib::ctIntersection, out, fill, fill)) {
          throw std::runtime_error("Clipper::Execute failed");
        }
        return out;
      },
      inspect);
}

// Simplify with Clipper's plain union, without SimplifyPolygons' StrictlySimple pass: faster, but
// regions that touch at a vertex stay in one ring (a weaker contract than roiclip's output).
void benchClipperUnion(benchmark::State& state, Case& c) {
  const ClipperLib::Paths subject = toClipper(c.subject);
  const ClipperLib::PolyFillType fill = toClipper(c.rule);
  measure(
      state, c, Library::ClipperUnion, c.clipperTolerance,
      [&] {
        ClipperLib::Clipper clipper;
        clipper.AddPaths(subject, ClipperLib::ptSubject, true);
        ClipperLib::Paths out;
        if (!clipper.Execute(ClipperLib::ctUnion, out, fill, fill)) {
          throw std::runtime_error("Clipper::Execute failed");
        }
        return out;
      },
      [](const ClipperLib::Paths& r) {
        return Outcome{clipperArea(r), r.size()};
      });
}

void benchBoost(benchmark::State& state, Case& c) {
  const BoostPolygon subject = toBoost(c.subject);
  const BoostPolygon clipPolygon = toBoost(c.clip);
  std::string why;
  if (!boost::geometry::is_valid(subject, why) || !boost::geometry::is_valid(clipPolygon, why)) {
    state.SkipWithError(("Boost.Geometry: invalid input: " + why).c_str());
    return;
  }
  measure(
      state, c, Library::Boost, kDoubleTolerance,
      [&] {
        BoostMultiPolygon out;
        boost::geometry::intersection(subject, clipPolygon, out);
        return out;
      },
      [](const BoostMultiPolygon& r) {
        return Outcome{boost::geometry::area(r), ringCount(r)};
      });
}

void benchGeos(benchmark::State& state, Case& c) {
  GEOSContextHandle_t ctx = geosContext();
  const GeosGeometry subject = toGeos(c.subject);
  const GeosGeometry clipPolygon = toGeos(c.clip);
  if (GEOSisValid_r(ctx, subject.get()) != 1 || GEOSisValid_r(ctx, clipPolygon.get()) != 1) {
    state.SkipWithError("GEOS: invalid input");
    return;
  }
  measure(
      state, c, Library::Geos, kDoubleTolerance,
      [&] {
        GeosGeometry out(GEOSIntersection_r(ctx, subject.get(), clipPolygon.get()));
        if (!out) throw std::runtime_error("GEOSIntersection_r failed");
        return out;
      },
      [](const GeosGeometry& r) {
        return Outcome{geosArea(r.get()), geosRingCount(r.get())};
      });
}

// Cases live for the whole run (benchmarks keep references); a deque never moves its elements.
std::deque<Case>& cases() {
  static std::deque<Case> all;
  return all;
}

Case& addCase(std::string name, Paths subject, Paths clipPaths, FillRule rule, bool valid,
              double clipperTolerance) {
  Case c;
  c.name = std::move(name);
  c.subject = std::move(subject);
  c.clip = std::move(clipPaths);
  c.rule = rule;
  c.valid = valid;
  c.clipperTolerance = clipperTolerance;
  return cases().emplace_back(std::move(c));
}

void registerCase(Case& c) {
  const auto add = [&](Library lib, void (*fn)(benchmark::State&, Case&)) {
    const std::string name = c.name + "/" + libraryName(lib);
    benchmark::RegisterBenchmark(name.c_str(), [&c, fn](benchmark::State& s) {
      fn(s, c);
    })->Unit(benchmark::kMillisecond);
  };
  add(Library::Roiclip, benchRoiclip);
  if (!c.clipperSlow || gIncludeSlow) add(Library::Clipper, benchClipper);
  if (!c.binary()) add(Library::ClipperUnion, benchClipperUnion);
  if (c.binary() && c.valid) {
    add(Library::Boost, benchBoost);
    add(Library::Geos, benchGeos);
  }
}

void registerAll() {
  // Simplify: Boost.Geometry and GEOS do not resolve self-intersections, so roiclip vs Clipper
  // (SimplifyPolygons, and a plain union).
  registerCase(addCase("Simplify/Contour100k_twisted", {twistedContour(100000, 20, 1)}, {},
                       FillRule::NonZero, false, kRoundedCrossingTolerance));
  for (const std::size_t n : {1000, 10000}) {
    const std::string size = std::to_string(n / 1000) + "k";
    const Path random = randomPolygon(n, 1000.0, std::uint32_t(10 + n));
    Case& evenOdd = addCase("Simplify/Random" + size + "_evenodd", {random}, {}, FillRule::EvenOdd,
                            false, kRoundedCrossingTolerance);
    evenOdd.clipperSlow = n >= 10000;
    registerCase(evenOdd);
    registerCase(addCase("Simplify/Random" + size + "_nonzero", {random}, {}, FillRule::NonZero,
                         false, kRoundedCrossingTolerance));
  }
  // Clip: the region-of-interest case, intersection with a perspective quad.
  for (const std::size_t n : {1000, 10000, 100000}) {
    const std::string size = std::to_string(n / 1000) + "k";
    Path contour = blobContour(n, std::uint32_t(20 + n));
    Path quad = perspectiveQuad(contour, std::uint32_t(30 + n));
    registerCase(addCase("Clip/Contour" + size + "_x_quad", {std::move(contour)}, {std::move(quad)},
                         FillRule::EvenOdd, true, kClipperValidTolerance));
  }
  for (const std::size_t n : {1000, 10000}) {
    const std::string size = std::to_string(n / 1000) + "k";
    Path random = randomPolygon(n, 1000.0, std::uint32_t(40 + n));
    Path quad = perspectiveQuad(random, std::uint32_t(50 + n));
    registerCase(addCase("Clip/Random" + size + "_x_quad", {std::move(random)}, {std::move(quad)},
                         FillRule::EvenOdd, false, kRoundedCrossingTolerance));
  }
  registerCase(addCase("Clip/Random1k_x_random1k", {randomPolygon(1000, 1000.0, 61)},
                       {randomPolygon(1000, 1000.0, 62)}, FillRule::EvenOdd, false,
                       kRoundedCrossingTolerance));
}

}  // namespace
}  // namespace roiclip::bench

int main(int argc, char** argv) {
  // Take our own flag out before Google Benchmark sees the arguments.
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    constexpr const char* kDumpFlag = "--dump_dir=";
    if (std::strncmp(argv[i], kDumpFlag, std::strlen(kDumpFlag)) == 0) {
      roiclip::bench::gDumpDir = argv[i] + std::strlen(kDumpFlag);
    } else if (std::strcmp(argv[i], "--include_slow") == 0) {
      roiclip::bench::gIncludeSlow = true;
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  roiclip::bench::registerAll();
  roiclip::bench::registerLines();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
