// SPDX-License-Identifier: MIT
// roiclip_limits_bench: the core at the sizes tests/core/limits_test runs scaled down. Each case
// runs in its own child process, so the peak resident memory (getrusage ru_maxrss) is that of
// the case alone, input included. Prints one line per case: vertices, crossings, wall and CPU
// time, resident memory after building the input and at the peak, output rings, and the area
// against its closed form (tests/core/limit_shapes.hpp).
//   roiclip_limits_bench            every case
//   roiclip_limits_bench NAME...    the cases whose name starts with one of the arguments
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include <roiclip/roiclip.hpp>

#include "limit_shapes.hpp"

namespace {

using roiclip::ClipOp;
using roiclip::FillRule;
using roiclip::Path;
using roiclip::Paths;
using roiclip::PolygonSet;

struct Case {
  std::string name;
  std::size_t vertices = 0;
  std::int64_t crossings = 0;
  double expectedArea = 0;
  std::function<Paths()> input;
  std::function<PolygonSet(const Paths&)> run;
};

Path box(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

std::vector<Case> cases() {
  std::vector<Case> all;
  // Pixel contours: 10 million vertices, no crossing.
  for (const std::int64_t m : {62'500LL, 625'000LL}) {
    const roiclip::testing::Crenellated shape{m};
    const std::string size = std::to_string(shape.vertices() / 1000) + "k";
    const auto input = [shape] { return Paths{shape.path()}; };
    all.push_back({"contour-" + size + "-simplify-nonzero", shape.vertices(), 0, shape.area(),
                   input, [](const Paths& p) { return simplify(p, FillRule::NonZero); }});
    // A box cutting the teeth of three sides and the body.
    const double w = static_cast<double>(shape.side());
    const double x0 = -0.5, y0 = -0.75, x1 = w + 0.5, y1 = 0.75 * w + 0.25;
    all.push_back({"contour-" + size + "-clip-quad", shape.vertices(), 0,
                   shape.areaInBox(x0, y0, x1, y1), input,
                   [=](const Paths& p) { return roiclip::intersect(p, {box(x0, y0, x1, y1)}); }});
  }
  // Combs: 4 n^2 crossings.
  for (const std::int64_t n : {500LL, 1000LL, 1581LL}) {
    const roiclip::testing::Combs combs{n};
    const auto input = [combs] { return Paths{combs.path()}; };
    const std::size_t vertices = combs.path().size();
    const std::string k = std::to_string(combs.crossings() / 1000) + "k";
    all.push_back({"combs-" + k + "-crossings-simplify-nonzero", vertices, combs.crossings(),
                   combs.nonZeroArea(), input,
                   [](const Paths& p) { return simplify(p, FillRule::NonZero); }});
    all.push_back({"combs-" + k + "-crossings-simplify-evenodd", vertices, combs.crossings(),
                   combs.evenOddArea(), input,
                   [](const Paths& p) { return simplify(p, FillRule::EvenOdd); }});
  }
  // Deep nesting: every other annulus a hole.
  for (const int k : {1000, 10000, 100000}) {
    const auto input = [k] { return roiclip::testing::alternatingNestedSquares(k); };
    all.push_back({"nested-" + std::to_string(k) + "-simplify-nonzero",
                   static_cast<std::size_t>(4 * k), 0,
                   roiclip::testing::nestedSquaresAreaInBox(k, k), input,
                   [](const Paths& p) { return simplify(p, FillRule::NonZero); }});
    const double h = k / 2 + 0.5;
    all.push_back({"nested-" + std::to_string(k) + "-clip-quad", static_cast<std::size_t>(4 * k), 0,
                   roiclip::testing::nestedSquaresAreaInBox(k, h), input, [h](const Paths& p) {
                     return clip(ClipOp::Intersection, p, {box(-h, -h, h, h)}, FillRule::NonZero,
                                 FillRule::EvenOdd);
                   }});
  }
  return all;
}

double peakMegabytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

// User + system CPU seconds of this process: on a shared machine a fairer figure than wall time.
double cpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6;
  };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

void runCase(const Case& c) {
  const Paths input = c.input();
  const double inputPeak = peakMegabytes();
  const double cpuStart = cpuSeconds();
  const auto start = std::chrono::steady_clock::now();
  const PolygonSet out = c.run(input);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu = cpuSeconds() - cpuStart;
  const double area = out.area();
  const double relError = std::abs(area - c.expectedArea) / c.expectedArea;
  std::printf("%-40s %10zu %10lld %9.2f %9.2f %9.0f %9.0f %9zu %20.1f %20.1f %9.1e %s\n",
              c.name.c_str(), c.vertices, static_cast<long long>(c.crossings), seconds, cpu,
              inputPeak, peakMegabytes(), out.ringCount(), area, c.expectedArea, relError,
              relError < 1e-9 ? "ok" : "WRONG");
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  std::printf("%-40s %10s %10s %9s %9s %9s %9s %9s %20s %20s %9s\n", "case", "vertices",
              "crossings", "wall_s", "cpu_s", "input_MB", "peak_MB", "rings", "area", "closed_form",
              "rel_err");
  int failures = 0;
  for (const Case& c : cases()) {
    bool wanted = argc < 2;
    for (int i = 1; i < argc; ++i) wanted = wanted || c.name.rfind(argv[i], 0) == 0;
    if (!wanted) continue;
    std::fflush(stdout);
    const pid_t pid = fork();
    if (pid == 0) {
      runCase(c);
      _exit(0);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
      std::printf("%-40s failed: %s %d\n", c.name.c_str(),
                  WIFSIGNALED(status) ? "signal" : "exit code",
                  WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status));
      ++failures;
    }
  }
  return failures == 0 ? 0 : 1;
}
