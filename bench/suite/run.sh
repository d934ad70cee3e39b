#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Build roiclip_suite (Release) and run the W1-W5 rows of bench/suite: roiclip, Clipper 1,
# Boost.Geometry, GEOS and the raster route interleaved; prints the Markdown tables of
# bench/RESULTS.md ("W1-W5 suite"). Instruction counts: bench/instructions.sh --suite.
#   bench/suite/run.sh                        # every row, 7 samples of >= 0.02 s per library
#   bench/suite/run.sh --filter=W3 --reps=3   # roiclip_suite flags (see suite_bench.cpp)
# Environment: BUILD_DIR (default build). The samples go to $BUILD_DIR/roiclip_suite.json.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${BUILD_DIR:-$root/build}
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >&2
fi
grep -q '^CMAKE_BUILD_TYPE:STRING=Release$' "$build/CMakeCache.txt" ||
  echo "WARNING: $build is not a Release build" >&2
cmake --build "$build" -j2 --target roiclip_suite >&2
changes=$(git -C "$root" status --porcelain -- src include | head -1)
echo "roiclip at $(git -C "$root" rev-parse --short HEAD) (src/ and include/ last changed in" \
  "$(git -C "$root" log -1 --format=%h -- src include)${changes:+, with uncommitted changes})," \
  "$(date -u +%Y-%m-%dT%H:%MZ), $(nproc) CPUs ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs))"
"$build/bench/suite/roiclip_suite" --json="$build/roiclip_suite.json" "$@"
