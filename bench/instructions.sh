#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Instructions per operation (callgrind) for benchmark rows of roiclip_bench: repeatable on a
# loaded machine, where CPU times move by 1.5x between runs. One iteration per row; only the
# library calls are counted (roiclip::clip / simplify / clipLines; Clipper's AddPath, Execute
# and SimplifyPolygons), not the harness or the correctness check. callgrind toggles collection
# at each entry and exit of a listed function, so no listed function may call another.
#   bench/instructions.sh Clip/Random1k_x_quad          # roiclip and clipper of that row
#   bench/instructions.sh Simplify/Random1k_nonzero Clip/Random1k_x_random1k
# Environment: BUILD_DIR (default build; needs bench/core/roiclip_bench).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bench=${BUILD_DIR:-$root/build}/bench/core/roiclip_bench
[ -x "$bench" ] || { echo "no $bench: build the release preset first" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
count() {  # row library toggle-patterns...
  local row=$1 lib=$2
  shift 2
  local toggles=()
  for t in "$@"; do toggles+=("--toggle-collect=$t"); done
  valgrind --tool=callgrind --callgrind-out-file="$work/out" "${toggles[@]}" "$bench" \
    --benchmark_filter="^$row/$lib\$" --benchmark_min_time=0.000001 >/dev/null 2>"$work/log"
  grep -oE 'Collected : [0-9]+' "$work/log" | awk '{print $3}'
}
printf '| row | roiclip (M instr) | Clipper 1 (M instr) | ratio Clipper/roiclip |\n|---|--:|--:|--:|\n'
for row in "$@"; do
  r=$(count "$row" roiclip 'roiclip::clip(*' 'roiclip::simplify(*' 'roiclip::clipLines(*')
  case $row in
    Simplify/*) c=$(count "$row" clipper 'ClipperLib::SimplifyPolygons(*') ;;
    *) c=$(count "$row" clipper 'ClipperLib::ClipperBase::AddPath(*' 'ClipperLib::Clipper::Execute(*') ;;
  esac
  awk -v row="$row" -v r="$r" -v c="$c" \
    'BEGIN { printf "| %s | %.1f | %.1f | %.2fx |\n", row, r / 1e6, c / 1e6, (r > 0 ? c / r : 0) }'
done
