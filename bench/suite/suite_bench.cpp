// SPDX-License-Identifier: MIT
// roiclip_suite: the W1-W5 rows of issue 13, roiclip against Clipper 1, Boost.Geometry, GEOS
// and the raster route (cv::fillPoly of subject and ROI, bitwise_and, findContours) in one run.
//
// For every row: one cold call per library (roiclip's kept buffers released first) records the
// peak heap and checks the area against roiclip's; a library whose area is off by more than its
// stated tolerance, or that throws or refuses the input, is left out of the row ("–"). Then the
// libraries are timed interleaved, A B C A B C: each repetition takes one sample of every
// library in turn; a sample repeats the row (all its calls) until --min_time seconds of thread
// CPU time have passed. The timed region of a call is the conversion from std::vector<cv::Point>
// to the library's types, the operation and the freeing of the result. The tables (minimum and
// median of the samples, ratio peer / roiclip, peak heap) are printed as Markdown at the end.
//
// Flags:
//   --filter=REGEX      rows whose name matches (std::regex_search); --list prints the names
//   --libs=a,b          libraries: roiclip,clipper,boost,geos,raster (roiclip always runs)
//   --reps=N            repetitions (samples per library), default 7
//   --min_time=S        seconds per sample, default 0.02 (--benchmark_min_time=S is the same)
//   --json=FILE         also write every sample as JSON
//   --dump_dir=DIR      write the first call of a row on which a library disagrees to DIR
//   --images=DIR        the scene_NN.png / .json pairs of W5 (default: the repo's images/)
//   --instr=ROW/LIB     callgrind mode: one cold call, then one warm call of the row with
//                       collection toggled on (run under valgrind --collect-atstart=no)
#include <benchmark/benchmark.h>
#include <valgrind/callgrind.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>
#include <roiclip/opencv/convert.hpp>
#include <roiclip/roiclip.hpp>

#include "adapters.hpp"
#include "alloc_counter.hpp"
#include "suite_workloads.hpp"
#include "workloads.hpp"

namespace roiclip::bench::suite {
namespace {

enum class Library { Roiclip, Clipper, Boost, Geos, Raster };
constexpr Library kLibraries[] = {Library::Roiclip, Library::Clipper, Library::Boost, Library::Geos,
                                  Library::Raster};

const char* libraryKey(Library lib) {
  switch (lib) {
    case Library::Roiclip:
      return "roiclip";
    case Library::Clipper:
      return "clipper";
    case Library::Boost:
      return "boost";
    case Library::Geos:
      return "geos";
    case Library::Raster:
      return "raster";
  }
  return "?";
}

const char* libraryLabel(Library lib) {
  switch (lib) {
    case Library::Roiclip:
      return "roiclip";
    case Library::Clipper:
      return "Clipper 1";
    case Library::Boost:
      return "Boost.Geometry";
    case Library::Geos:
      return "GEOS";
    case Library::Raster:
      return "raster";
  }
  return "?";
}

// Area tolerances. Boost.Geometry and GEOS compute crossings in doubles: relative 1e-6 (Boost
// 1.74 rescales overlay input to an integer grid). Clipper rounds every crossing to its integer
// units (1/256 px here): testing::roundingTolerance of its output. The raster route moves every
// boundary point by up to about a pixel: 1 px times its output perimeter plus 2 px^2 per call,
// and at most 1% of the area (on W3's checkerboard of tiny cells the pixel bound allows anything).
constexpr double kDoubleTolerance = 1e-6;
constexpr double kRasterPixels = 1.0;
constexpr double kRasterPerCall = 2.0;
constexpr double kRasterRelative = 0.01;

/// What an untimed call reports: the output area and how far from the exact area it may be.
struct Outcome {
  double area = 0.0;
  double tolerance = 0.0;
};

/// One library's calls: `timed` is the measured unit, `checked` the same call plus inspection.
struct Ops {
  std::function<void(const Job&, FillRule)> timed;
  std::function<Outcome(const Job&, FillRule)> checked;
};

template <class Run, class Inspect>
Ops makeOps(Run run, Inspect inspect) {
  return Ops{[run](const Job& job, FillRule rule) {
               auto result = run(job, rule);
               benchmark::DoNotOptimize(result);
             },
             [run, inspect](const Job& job, FillRule rule) { return inspect(run(job, rule)); }};
}

// ---- conversions from cv::Point (inside the timed region) ----------------------------------

ClipperLib::Paths clipperPaths(const Contours& contours) {
  ClipperLib::Paths paths(contours.size());
  for (std::size_t i = 0; i < contours.size(); ++i) {
    paths[i].reserve(contours[i].size());
    for (const cv::Point& p : contours[i]) {
      paths[i].emplace_back(ClipperLib::cInt(p.x) * 256, ClipperLib::cInt(p.y) * 256);
    }
  }
  return paths;
}

void assignBoostRing(const Contour& contour, std::vector<BoostPoint>& ring) {
  ring.reserve(contour.size() + 1);
  for (const cv::Point& p : contour) ring.emplace_back(p.x, p.y);
  ring.push_back(ring.front());
}

BoostMultiPolygon boostPolygons(const Contours& contours,
                                const std::vector<std::vector<int>>& groups) {
  BoostMultiPolygon polygons;
  polygons.resize(groups.size());
  for (std::size_t g = 0; g < groups.size(); ++g) {
    BoostPolygon& polygon = polygons[g];
    assignBoostRing(contours[std::size_t(groups[g][0])], polygon.outer());
    polygon.inners().resize(groups[g].size() - 1);
    for (std::size_t h = 1; h < groups[g].size(); ++h) {
      assignBoostRing(contours[std::size_t(groups[g][h])], polygon.inners()[h - 1]);
    }
  }
  boost::geometry::correct(polygons);
  return polygons;
}

BoostPolygon boostPolygon(const Contour& contour) {
  BoostPolygon polygon;
  assignBoostRing(contour, polygon.outer());
  boost::geometry::correct(polygon);
  return polygon;
}

GEOSGeometry* geosRing(const Contour& contour) {
  GEOSContextHandle_t ctx = geosContext();
  const auto n = unsigned(contour.size());
  GEOSCoordSequence* seq = GEOSCoordSeq_create_r(ctx, n + 1, 2);
  for (unsigned i = 0; i <= n; ++i) {
    const cv::Point& p = contour[i % n];
    GEOSCoordSeq_setXY_r(ctx, seq, i, p.x, p.y);
  }
  return GEOSGeom_createLinearRing_r(ctx, seq);
}

GEOSGeometry* geosPolygon(const Contours& contours, const std::vector<int>& group) {
  std::vector<GEOSGeometry*> holes;
  for (std::size_t h = 1; h < group.size(); ++h) {
    holes.push_back(geosRing(contours[std::size_t(group[h])]));
  }
  return GEOSGeom_createPolygon_r(geosContext(), geosRing(contours[std::size_t(group[0])]),
                                  holes.data(), unsigned(holes.size()));
}

GeosGeometry geosPolygons(const Contours& contours, const std::vector<std::vector<int>>& groups) {
  if (groups.size() == 1) return GeosGeometry(geosPolygon(contours, groups[0]));
  std::vector<GEOSGeometry*> parts;
  for (const std::vector<int>& group : groups) parts.push_back(geosPolygon(contours, group));
  return GeosGeometry(GEOSGeom_createCollection_r(geosContext(), GEOS_MULTIPOLYGON, parts.data(),
                                                  unsigned(parts.size())));
}

// ---- the libraries --------------------------------------------------------------------------

Ops roiclipOps() {
  return makeOps(
      [](const Job& job, FillRule rule) {
        return clip(ClipOp::Intersection, opencv::fromContours(job.subject),
                    opencv::fromContours(job.clip), rule, rule);
      },
      [](const PolygonSet& r) {
        return Outcome{r.area(), 0.0};
      });
}

Ops clipperOps() {
  return makeOps(
      [](const Job& job, FillRule rule) {
        ClipperLib::Clipper clipper;
        clipper.AddPaths(clipperPaths(job.subject), ClipperLib::ptSubject, true);
        clipper.AddPaths(clipperPaths(job.clip), ClipperLib::ptClip, true);
        ClipperLib::Paths out;
        const ClipperLib::PolyFillType fill = testing::toClipper(rule);
        if (!clipper.Execute(ClipperLib::ctIntersection, out, fill, fill)) {
          throw std::runtime_error("Clipper::Execute failed");
        }
        return out;
      },
      [](const ClipperLib::Paths& r) {
        return Outcome{testing::clipperArea(r), testing::roundingTolerance(testing::measure(r))};
      });
}

Ops boostOps() {
  return makeOps(
      [](const Job& job, FillRule) {
        const BoostMultiPolygon subject = boostPolygons(job.subject, job.groups);
        const BoostPolygon region = boostPolygon(job.clip.front());
        BoostMultiPolygon out;
        boost::geometry::intersection(subject, region, out);
        return out;
      },
      [](const BoostMultiPolygon& r) {
        const double area = boost::geometry::area(r);
        return Outcome{area, kDoubleTolerance * std::fabs(area) + 1e-9};
      });
}

Ops geosOps() {
  return makeOps(
      [](const Job& job, FillRule) {
        const GeosGeometry subject = geosPolygons(job.subject, job.groups);
        const GeosGeometry region(geosPolygon(job.clip, {0}));
        GeosGeometry out(GEOSIntersection_r(geosContext(), subject.get(), region.get()));
        if (!out) throw std::runtime_error("GEOSIntersection_r failed");
        return out;
      },
      [](const GeosGeometry& r) {
        const double area = geosArea(r.get());
        return Outcome{area, kDoubleTolerance * std::fabs(area) + 1e-9};
      });
}

/// The raster route's output: the contours of the part of the subject's mask inside the ROI's.
struct RasterResult {
  Contours contours;
  std::vector<cv::Vec4i> hierarchy;
};

cv::Rect boundingBox(const Contours& contours) {
  cv::Point lo(INT32_MAX, INT32_MAX), hi(INT32_MIN, INT32_MIN);
  for (const Contour& c : contours) {
    for (const cv::Point& p : c) {
      lo = cv::Point(std::min(lo.x, p.x), std::min(lo.y, p.y));
      hi = cv::Point(std::max(hi.x, p.x), std::max(hi.y, p.y));
    }
  }
  return {lo, hi + cv::Point(1, 1)};
}

// cv::fillPoly of the subject and of the ROI in the box both cover (what a careful OpenCV user
// allocates), bitwise_and, findContours(RETR_CCOMP, CHAIN_APPROX_SIMPLE). fillPoly fills
// even-odd, so this route only runs on even-odd rows.
Ops rasterOps() {
  return makeOps(
      [](const Job& job, FillRule) {
        RasterResult out;
        const cv::Rect box = boundingBox(job.subject) & boundingBox(job.clip);
        if (box.empty()) return out;
        cv::Mat subject = cv::Mat::zeros(box.size(), CV_8UC1);
        cv::Mat region = cv::Mat::zeros(box.size(), CV_8UC1);
        cv::fillPoly(subject, job.subject, cv::Scalar(255), cv::LINE_8, 0, -box.tl());
        cv::fillPoly(region, job.clip, cv::Scalar(255), cv::LINE_8, 0, -box.tl());
        cv::bitwise_and(subject, region, subject);
        cv::findContours(subject, out.contours, out.hierarchy, cv::RETR_CCOMP,
                         cv::CHAIN_APPROX_SIMPLE, box.tl());
        return out;
      },
      [](const RasterResult& r) {
        Outcome o;
        for (std::size_t i = 0; i < r.contours.size(); ++i) {
          const double a = std::fabs(cv::contourArea(r.contours[i]));
          o.area += r.hierarchy[i][3] < 0 ? a : -a;
          o.tolerance += kRasterPixels * cv::arcLength(r.contours[i], true);
        }
        o.tolerance += kRasterPerCall;
        return o;
      });
}

Ops opsFor(Library lib) {
  switch (lib) {
    case Library::Roiclip:
      return roiclipOps();
    case Library::Clipper:
      return clipperOps();
    case Library::Boost:
      return boostOps();
    case Library::Geos:
      return geosOps();
    case Library::Raster:
      return rasterOps();
  }
  throw std::logic_error("unknown library");
}

/// Why `lib` cannot take this row ("" when it can): Boost.Geometry and GEOS need valid
/// polygons, the raster route has only fillPoly's even-odd rule.
std::string unsupported(Library lib, const Row& row) {
  if (lib == Library::Raster && row.rule != FillRule::EvenOdd) {
    return "cv::fillPoly has no non-zero rule";
  }
  if (lib == Library::Boost || lib == Library::Geos) {
    for (const Job& job : row.jobs) {
      for (const Contour& c : job.subject) {
        if (c.size() < 3) return "invalid input: contours of 1 or 2 points";
      }
    }
  }
  if (lib == Library::Boost) {
    for (const Job& job : row.jobs) {
      std::string why;
      if (!boost::geometry::is_valid(boostPolygons(job.subject, job.groups), why) ||
          !boost::geometry::is_valid(boostPolygon(job.clip.front()), why)) {
        return "invalid input: " + why.substr(0, why.find(" at "));
      }
    }
  }
  if (lib == Library::Geos) {
    for (const Job& job : row.jobs) {
      const GeosGeometry subject = geosPolygons(job.subject, job.groups);
      const GeosGeometry region(geosPolygon(job.clip, {0}));
      if (GEOSisValid_r(geosContext(), subject.get()) != 1 ||
          GEOSisValid_r(geosContext(), region.get()) != 1) {
        char* reason = GEOSisValidReason_r(geosContext(), subject.get());
        std::string why = std::string("invalid input: ") + reason;
        GEOSFree_r(geosContext(), reason);
        return why.substr(0, why.find('['));
      }
    }
  }
  return "";
}

// ---- running ----------------------------------------------------------------------------------

/// roiclip keeps working arrays per thread between calls; a cold call starts without them.
void coldStart() { releaseThreadBuffers(); }

double threadSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

struct Options {
  std::string filter = ".";
  std::vector<Library> libraries{std::begin(kLibraries), std::end(kLibraries)};
  int reps = 7;
  double minTime = 0.02;
  std::string jsonFile;
  std::string dumpDir;
  std::string imagesDir = ROICLIP_IMAGES;
  std::string instr;
  bool list = false;
};

struct LibraryResult {
  Library lib = Library::Roiclip;
  std::string skipped;  ///< why the library has no figures in this row ("" = it ran)
  Ops ops;
  std::vector<double> samplesMs;
  AllocStats heap;
  Outcome outcome;
  [[nodiscard]] double minMs() const {
    return *std::min_element(samplesMs.begin(), samplesMs.end());
  }
  [[nodiscard]] double medianMs() const {
    std::vector<double> s = samplesMs;
    std::sort(s.begin(), s.end());
    const std::size_t n = s.size();
    return n % 2 == 1 ? s[n / 2] : 0.5 * (s[n / 2 - 1] + s[n / 2]);
  }
};

struct RowResult {
  std::string name;
  std::size_t vertices = 0;
  std::size_t calls = 0;
  std::vector<LibraryResult> libs;
};

void dumpRow(const Options& options, const Row& row, Library lib) {
  if (options.dumpDir.empty()) return;
  const std::string file = options.dumpDir + "/" + row.name + "_" + libraryKey(lib) + ".json";
  const Job& job = row.jobs.front();
  writeCaseJson(file, opencv::fromContours(job.subject), opencv::fromContours(job.clip),
                ClipOp::Intersection, row.rule, row.rule);
  std::fprintf(stderr, "  input saved to %s\n", file.c_str());
}

/// The cold call: heap peak and the area check against roiclip's (`reference`).
void coldCall(const Options& options, const Row& row, LibraryResult& r, const Outcome* reference) {
  try {
    coldStart();
    resetAllocStats();
    for (const Job& job : row.jobs) {
      const Outcome o = r.ops.checked(job, row.rule);
      r.outcome.area += o.area;
      r.outcome.tolerance += o.tolerance;
    }
    r.heap = allocStats();
  } catch (const std::exception& e) {
    r.skipped = std::string("threw: ") + e.what();
    std::fprintf(stderr, "WARNING: %s/%s %s\n", row.name.c_str(), libraryKey(r.lib),
                 r.skipped.c_str());
    dumpRow(options, row, r.lib);
    return;
  }
  if (reference == nullptr) return;
  const double diff = std::fabs(r.outcome.area - reference->area);
  if (r.lib == Library::Raster) {
    r.outcome.tolerance =
        std::min(r.outcome.tolerance, kRasterRelative * std::max(std::fabs(reference->area), 1.0));
  }
  if (!(diff <= r.outcome.tolerance)) {
    char message[200];
    std::snprintf(message, sizeof message, "area %.10g, roiclip %.10g: off by %.3g > %.3g",
                  r.outcome.area, reference->area, diff, r.outcome.tolerance);
    r.skipped = message;
    std::fprintf(stderr, "WARNING: %s/%s %s\n", row.name.c_str(), libraryKey(r.lib), message);
    dumpRow(options, row, r.lib);
  }
}

double sampleMs(const Row& row, const Ops& ops, double minTime) {
  const double start = threadSeconds();
  double elapsed = 0.0;
  std::size_t calls = 0;
  do {
    for (const Job& job : row.jobs) ops.timed(job, row.rule);
    ++calls;
    elapsed = threadSeconds() - start;
  } while (elapsed < minTime);
  return 1e3 * elapsed / double(calls);
}

RowResult runRow(const Options& options, const Row& row) {
  RowResult result{row.name, row.vertices(), row.jobs.size(), {}};
  for (const Library lib : options.libraries) {
    LibraryResult r;
    r.lib = lib;
    r.ops = opsFor(lib);
    r.skipped = unsupported(lib, row);
    result.libs.push_back(std::move(r));
  }
  LibraryResult& reference = result.libs.front();
  coldCall(options, row, reference, nullptr);
  for (std::size_t i = 1; i < result.libs.size(); ++i) {
    LibraryResult& r = result.libs[i];
    if (!reference.skipped.empty()) r.skipped = "roiclip failed";
    if (r.skipped.empty()) coldCall(options, row, r, &reference.outcome);
  }
  for (int rep = 0; rep < options.reps; ++rep) {
    for (LibraryResult& r : result.libs) {
      if (r.skipped.empty()) r.samplesMs.push_back(sampleMs(row, r.ops, options.minTime));
    }
  }
  std::fprintf(stderr, "%-22s", row.name.c_str());
  for (const LibraryResult& r : result.libs) {
    if (r.skipped.empty()) std::fprintf(stderr, " %s %.4g ms", libraryKey(r.lib), r.minMs());
  }
  std::fputc('\n', stderr);
  return result;
}

// ---- the tables -------------------------------------------------------------------------------

std::string formatMs(double ms) {
  char text[32];
  std::snprintf(text, sizeof text, ms >= 100 ? "%.0f" : ms >= 10 ? "%.1f" : "%.3g", ms);
  return text;
}

void printTimeTable(const Options& options, const std::vector<RowResult>& rows, bool median) {
  std::printf("\n%s of %d samples, ms per row (all its calls); in brackets peer / roiclip:\n\n",
              median ? "Median" : "Minimum", options.reps);
  std::printf("| row | vertices | calls |");
  for (const Library lib : options.libraries) std::printf(" %s |", libraryLabel(lib));
  std::printf("\n|---|--:|--:|");
  for (std::size_t i = 0; i < options.libraries.size(); ++i) std::printf("--:|");
  std::printf("\n");
  for (const RowResult& row : rows) {
    std::printf("| %s | %zu | %zu |", row.name.c_str(), row.vertices, row.calls);
    const LibraryResult& base = row.libs.front();
    const auto pick = [&](const LibraryResult& r) { return median ? r.medianMs() : r.minMs(); };
    for (const LibraryResult& r : row.libs) {
      if (!r.skipped.empty()) {
        std::printf(" – |");
      } else if (&r == &base) {
        std::printf(" %s |", formatMs(pick(r)).c_str());
      } else {
        std::printf(" %s (%.2f) |", formatMs(pick(r)).c_str(), pick(r) / pick(base));
      }
    }
    std::printf("\n");
  }
}

void printHeapTable(const Options& options, const std::vector<RowResult>& rows) {
  std::printf(
      "\nPeak heap of one cold call (MB, operator new), and the largest area difference "
      "from roiclip relative to its area:\n\n| row |");
  for (const Library lib : options.libraries) std::printf(" %s |", libraryLabel(lib));
  std::printf(" max rel. area diff |\n|---|");
  for (std::size_t i = 0; i <= options.libraries.size(); ++i) std::printf("--:|");
  std::printf("\n");
  for (const RowResult& row : rows) {
    std::printf("| %s |", row.name.c_str());
    double worst = -1.0;
    const double area = row.libs.front().outcome.area;
    for (const LibraryResult& r : row.libs) {
      if (!r.skipped.empty()) {
        std::printf(" – |");
        continue;
      }
      std::printf(" %.3g |", double(r.heap.peakLive) / 1e6);
      if (&r != &row.libs.front()) {
        worst = std::max(worst, std::fabs(r.outcome.area - area) / std::max(area, 1.0));
      }
    }
    if (worst < 0) {
      std::printf(" – |\n");
    } else {
      std::printf(" %.1e |\n", worst);
    }
  }
}

void printSkipped(const std::vector<RowResult>& rows) {
  // reason -> rows, per library
  std::map<std::pair<int, std::string>, std::vector<std::string>> reasons;
  for (const RowResult& row : rows) {
    for (const LibraryResult& r : row.libs) {
      if (!r.skipped.empty()) reasons[{int(r.lib), r.skipped}].push_back(row.name);
    }
  }
  if (reasons.empty()) return;
  std::printf("\n– (not run):\n");
  for (const auto& [key, names] : reasons) {
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    std::printf("- %s: %s (%s)\n", libraryLabel(Library(key.first)), key.second.c_str(),
                list.c_str());
  }
}

void writeJson(const Options& options, const std::vector<RowResult>& rows) {
  nlohmann::json doc = nlohmann::json::array();
  for (const RowResult& row : rows) {
    nlohmann::json libs = nlohmann::json::object();
    for (const LibraryResult& r : row.libs) {
      libs[libraryKey(r.lib)] = {
          {"skipped", r.skipped},          {"samples_ms", r.samplesMs},
          {"peak_bytes", r.heap.peakLive}, {"allocations", r.heap.allocations},
          {"area", r.outcome.area},        {"tolerance", r.outcome.tolerance}};
    }
    doc.push_back(
        {{"row", row.name}, {"vertices", row.vertices}, {"calls", row.calls}, {"libs", libs}});
  }
  std::ofstream(options.jsonFile) << doc.dump(1) << '\n';
}

std::string loadAverage() {
  std::ifstream in("/proc/loadavg");
  double a = 0, b = 0, c = 0;
  in >> a >> b >> c;
  char text[64];
  std::snprintf(text, sizeof text, "%.2f %.2f %.2f", a, b, c);
  return text;
}

Library parseLibrary(const std::string& key) {
  for (const Library lib : kLibraries) {
    if (key == libraryKey(lib)) return lib;
  }
  throw std::invalid_argument("unknown library " + key);
}

Options parseOptions(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&](const char* flag) -> const char* {
      const std::size_t n = std::strlen(flag);
      return arg.compare(0, n, flag) == 0 ? argv[i] + n : nullptr;
    };
    const char* v = nullptr;
    if ((v = value("--filter="))) {
      o.filter = v;
    } else if ((v = value("--libs="))) {
      o.libraries = {Library::Roiclip};
      std::string list = v;
      for (std::size_t at = 0; at <= list.size();) {
        const std::size_t end = std::min(list.find(',', at), list.size());
        const Library lib = parseLibrary(list.substr(at, end - at));
        if (lib != Library::Roiclip) o.libraries.push_back(lib);
        at = end + 1;
      }
    } else if ((v = value("--reps="))) {
      o.reps = std::max(1, std::atoi(v));
    } else if ((v = value("--min_time="))) {
      o.minTime = std::atof(v);
    } else if ((v = value("--benchmark_min_time="))) {
      o.minTime = std::atof(v);
    } else if ((v = value("--json="))) {
      o.jsonFile = v;
    } else if ((v = value("--dump_dir="))) {
      o.dumpDir = v;
    } else if ((v = value("--images="))) {
      o.imagesDir = v;
    } else if ((v = value("--instr="))) {
      o.instr = v;
    } else if (arg == "--list") {
      o.list = true;
    } else {
      throw std::invalid_argument("unknown argument " + arg + " (see bench/suite/suite_bench.cpp)");
    }
  }
  return o;
}

/// callgrind mode: a cold call, then one warm call with collection on.
int countInstructions(const Options& options, const std::vector<RowRecipe>& recipes) {
  const std::size_t slash = options.instr.rfind('/');
  const std::string rowName = options.instr.substr(0, slash);
  const Library lib = parseLibrary(options.instr.substr(slash + 1));
  const auto recipe = std::find_if(recipes.begin(), recipes.end(),
                                   [&](const RowRecipe& r) { return r.name == rowName; });
  if (slash == std::string::npos || recipe == recipes.end()) {
    std::fprintf(stderr, "--instr=ROW/LIB: no row %s\n", rowName.c_str());
    return 2;
  }
  const Row row = recipe->make();
  const std::string why = unsupported(lib, row);
  if (!why.empty()) {
    std::fprintf(stderr, "%s/%s: %s\n", row.name.c_str(), libraryKey(lib), why.c_str());
    return 3;
  }
  const Ops ops = opsFor(lib);
  coldStart();
  for (const Job& job : row.jobs) ops.timed(job, row.rule);
  CALLGRIND_TOGGLE_COLLECT;
  for (const Job& job : row.jobs) ops.timed(job, row.rule);
  CALLGRIND_TOGGLE_COLLECT;
  return 0;
}

int run(int argc, char** argv) {
  const Options options = parseOptions(argc, argv);
  const std::vector<RowRecipe> recipes = rowRecipes(options.imagesDir);
  if (!options.instr.empty()) return countInstructions(options, recipes);
  const std::regex filter(options.filter);
  if (options.list) {
    for (const RowRecipe& r : recipes) {
      if (std::regex_search(r.name, filter)) std::printf("%s\n", r.name.c_str());
    }
    return 0;
  }
  const std::string loadBefore = loadAverage();
  std::vector<RowResult> results;
  for (const RowRecipe& recipe : recipes) {
    if (std::regex_search(recipe.name, filter)) results.push_back(runRow(options, recipe.make()));
  }
  std::printf("Load average (1, 5, 15 min) before %s, after %s; %d samples of >= %g s each.\n",
              loadBefore.c_str(), loadAverage().c_str(), options.reps, options.minTime);
  printTimeTable(options, results, false);
  printTimeTable(options, results, true);
  printHeapTable(options, results);
  printSkipped(results);
  if (!options.jsonFile.empty()) writeJson(options, results);
  return 0;
}

}  // namespace
}  // namespace roiclip::bench::suite

int main(int argc, char** argv) {
  try {
    return roiclip::bench::suite::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "roiclip_suite: %s\n", e.what());
    return 1;
  }
}
