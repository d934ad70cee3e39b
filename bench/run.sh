#!/usr/bin/env bash
# Build roiclip_bench (Release) and run it, then print the Markdown results table.
#   bench/run.sh [extra Google Benchmark flags, e.g. --benchmark_filter=Clip/]
# Environment: BUILD_DIR (default build-bench), MIN_TIME (default 0.2), REPETITIONS (default 1),
# OUT (JSON output, default $BUILD_DIR/roiclip_bench.json). Inputs on which roiclip throws or
# disagrees with another library are saved to $BUILD_DIR/bench_cases/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build-bench}
out=${OUT:-$build/roiclip_bench.json}
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >&2
fi
cmake --build "$build" -j2 --target roiclip_bench >&2
mkdir -p "$build/bench_cases"
"$build/bench/core/roiclip_bench" --dump_dir="$build/bench_cases" \
  --benchmark_min_time="${MIN_TIME:-0.2}" --benchmark_repetitions="${REPETITIONS:-1}" \
  --benchmark_report_aggregates_only="$([ "${REPETITIONS:-1}" -gt 1 ] && echo true || echo false)" \
  --benchmark_out="$out" --benchmark_out_format=json "$@" >&2
python3 "$root/bench/core/results_table.py" "$out"
