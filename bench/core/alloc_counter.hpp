// SPDX-License-Identifier: MIT
// Heap accounting for the benchmark binary: alloc_counter.cpp replaces the global operator
// new/delete (so it also sees allocations made inside Clipper, GEOS and Boost.Geometry) and
// keeps running totals. Memory that a library takes with malloc() directly is not seen.
#pragma once

#include <cstdint>

namespace roiclip::bench {

/// Heap use between resetAllocStats() and allocStats().
struct AllocStats {
  std::uint64_t allocations = 0;  ///< calls to operator new
  std::uint64_t bytes = 0;        ///< bytes requested from operator new, in total
  std::uint64_t peakLive = 0;     ///< highest live heap (bytes) above the level at the reset
};

/// Start a new measurement: zero the totals and take the current live heap as the baseline.
void resetAllocStats();
/// Totals since the last resetAllocStats().
AllocStats allocStats();

}  // namespace roiclip::bench
