// SPDX-License-Identifier: MIT
// Benchmark rows for open polylines (lines_bench.cpp).
#pragma once

namespace roiclip::bench {

/// Registers the Lines/* rows: roiclip::clipLines vs Clipper 1, Boost.Geometry and GEOS.
void registerLines();

}  // namespace roiclip::bench
