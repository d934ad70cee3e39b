// SPDX-License-Identifier: MIT
// Shared pieces of the libFuzzer targets in tests/fuzz: failing loudly, the exception policy,
// decoding bytes into small path sets, and the check of a result against the independent
// oracles of tests/support/oracle.hpp.
//
// Every target defines LLVMFuzzerTestOneInput. A bug (wrong region, broken ring structure, an
// InternalError, an exception outside roiclip::Error) ends in std::abort(), which libFuzzer
// records as a crash and the corpus replay (replay_main.cpp) as a failed test.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <sstream>
#include <string>
#include <typeinfo>
#include <vector>

#include <roiclip/roiclip.hpp>

#include "support/geos_validity.hpp"
#include "support/oracle.hpp"

namespace roiclip::fuzz {

[[noreturn]] inline void fail(const std::string& what) {
  std::cerr << "roiclip fuzz: BUG: " << what << std::endl;
  std::abort();
}

/// Runs `body`. roiclip::InvalidInputError and the other documented roiclip::Error types are
/// expected answers to bad input; InternalError, any other exception type, or (when
/// `anyErrorIsBug`) any exception at all is a bug.
template <class Body>
void expectDocumentedErrors(const char* what, Body&& body, bool anyErrorIsBug = false) {
  try {
    body();
  } catch (const InternalError& e) {
    fail(std::string(what) + ": InternalError: " + e.what());
  } catch (const Error& e) {
    if (anyErrorIsBug) fail(std::string(what) + ": unexpected roiclip::Error: " + e.what());
  } catch (const std::exception& e) {
    fail(std::string(what) + ": undocumented exception " + typeid(e).name() + ": " + e.what());
  } catch (...) {
    fail(std::string(what) + ": exception not derived from std::exception");
  }
}

/// Reads the fuzzer's bytes front to back; past the end it gives zeros.
class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  [[nodiscard]] bool empty() const { return pos_ >= size_; }
  std::uint8_t next() { return pos_ < size_ ? data_[pos_++] : 0; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

/// How a vertex byte (x = low nibble, y = high nibble, n in 0..15) becomes a coordinate. Every
/// mode stays on the 1/256 px grid, so the library sees exactly the oracle's numbers. Small
/// ranges make repeated points, collinear runs, touching vertices and overlapping edges common.
inline double decodeCoordinate(int n, int mode) {
  switch (mode & 7) {
    case 0:
      return n;  // 0..15
    case 1:
      return n - 8;  // -8..7
    case 2:
      return n / 2.0;  // half pixels 0..7.5
    case 3:
      return n % 4;  // 0..3: almost everything coincides
    case 4:
      return (n - 8) * 524288.0;  // up to the edge of the supported range (2^30 grid units)
    case 5:
      return n / 256.0;  // one grid step apart
    case 6:
      return (n - 8) / 2.0;  // half pixels around 0
    default:
      return 3 * n;  // 0..45
  }
}

/// Decodes up to `maxPaths` paths: a length byte (0..15 vertices, so degenerate paths occur),
/// then one byte per vertex. At most `maxVertices` vertices in all (the oracles are quadratic).
inline Paths decodePaths(ByteReader& in, int mode, int maxPaths, std::size_t maxVertices) {
  Paths paths;
  std::size_t total = 0;
  while (!in.empty() && static_cast<int>(paths.size()) < maxPaths) {
    const int count = in.next() % 16;
    Path path;
    for (int i = 0; i < count && !in.empty() && total < maxVertices; ++i, ++total) {
      const std::uint8_t b = in.next();
      path.emplace_back(decodeCoordinate(b & 15, mode), decodeCoordinate(b >> 4, mode));
    }
    paths.push_back(std::move(path));
  }
  return paths;
}

/// Checks `result` against the oracles: ring structure, point-in-result against the exact
/// winding numbers of the inputs at sample points, and the slab-integrated area.
/// `expected(w)` gets one winding number per input; `describe()` names the case in a failure.
template <class Expected, class Describe>
void checkAgainstOracle(const PolygonSet& result, const std::vector<const Paths*>& inputs,
                        Expected expected, Describe describe) {
  const std::string problems = testing::structureProblems(result);
  if (!problems.empty()) fail("ring structure: " + problems + describe());
  double lo = INFINITY, hi = -INFINITY;
  for (const Paths* paths : inputs) {
    for (const Path& path : *paths) {
      for (const Point& v : path) {
        lo = std::min({lo, v.x, v.y});
        hi = std::max({hi, v.x, v.y});
      }
    }
  }
  if (!(lo <= hi)) lo = hi = 0;
  // Samples around the inputs' box; a margin shows a result reaching outside the input.
  const double margin = 0.05 * (hi - lo) + 1.0 / 64;
  const auto report =
      testing::sampleRegion(result, inputs, expected, lo - margin, hi + margin, 300, 12345u);
  if (report.mismatches != 0) {
    fail("point-in-result differs from the exact winding (" + std::to_string(report.mismatches) +
         " of " + std::to_string(report.checked) + "): " + report.firstMismatch + "\n" +
         describe());
  }
  // Valid for GEOS as printed, and so is the result snap-rounded to whole pixels and to 1/256 px
  // (the latter where the extent fits 2^29 steps).
  const std::string invalid = testing::geosValidityProblem(result);
  if (!invalid.empty()) fail("GEOS: " + invalid + "\n" + describe());
  for (const double step : {1.0, 1.0 / 256}) {
    if ((hi - lo) / step > 0x1p28) continue;
    PolygonSet rounded;
    expectDocumentedErrors(
        "roundTo", [&] { rounded = roundTo(result, step); }, true);
    const std::string problem = testing::geosValidityProblem(rounded);
    if (!problem.empty()) {
      fail("GEOS, rounded to " + std::to_string(step) + ": " + problem + "\n" + describe());
    }
  }
  const double truth = testing::slabArea(inputs, expected);
  const double area = result.area();
  // The slab integration runs in doubles: its rounding grows with the square of the extent
  // (about 1e-3 px^2 for coordinates near 2^22 px), far below any real defect at that scale.
  const double extent = hi - lo;
  if (!(std::fabs(area - truth) <= 1e-7 * (std::fabs(truth) + 1) + 1e-12 * extent * extent)) {
    std::ostringstream m;
    m.precision(17);
    m << "area " << area << " but slab integration gives " << truth << "\n";
    fail(m.str() + describe());
  }
}

}  // namespace roiclip::fuzz
