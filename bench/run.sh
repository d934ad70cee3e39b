#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Build roiclip_bench (Release) and run it, then print the Markdown results table.
#   bench/run.sh                       # full run: cheap rows repeated, heavy rows once
#   bench/run.sh --benchmark_filter=Clip/   # one pass with these Google Benchmark flags
# Environment: BUILD_DIR (default build-bench), MIN_TIME (default 0.5), REPETITIONS for the cheap
# rows (default 3; the table shows medians). JSON output goes to $BUILD_DIR/roiclip_bench*.json.
# Inputs on which roiclip throws or disagrees with another library go to $BUILD_DIR/bench_cases/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build-bench}
reps=${REPETITIONS:-3}
# Rows that take seconds to minutes per operation: run once, not repeated.
heavy='Random10k|Contour100k_twisted/clipper$'
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >&2
fi
cmake --build "$build" -j2 --target roiclip_bench >&2
bench=$build/bench/core/roiclip_bench
mkdir -p "$build/bench_cases"
"$bench" --benchmark_list_tests=true > "$build/roiclip_bench.list"
common=(--dump_dir="$build/bench_cases" --benchmark_min_time="${MIN_TIME:-0.5}"
        --benchmark_out_format=json)
if [ $# -gt 0 ]; then
  "$bench" "${common[@]}" --benchmark_out="$build/roiclip_bench.json" "$@" >&2
  outputs=("$build/roiclip_bench.json")
else
  "$bench" "${common[@]}" --benchmark_out="$build/roiclip_bench_cheap.json" \
    --benchmark_filter="-$heavy" --benchmark_repetitions="$reps" \
    --benchmark_report_aggregates_only="$([ "$reps" -gt 1 ] && echo true || echo false)" >&2
  "$bench" "${common[@]}" --benchmark_out="$build/roiclip_bench_heavy.json" \
    --benchmark_filter="$heavy" >&2
  outputs=("$build/roiclip_bench_cheap.json" "$build/roiclip_bench_heavy.json")
fi
python3 "$root/bench/core/results_table.py" --order "$build/roiclip_bench.list" "${outputs[@]}"
