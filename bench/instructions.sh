#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Instructions per operation (callgrind) for benchmark rows of roiclip_bench: repeatable on a
# loaded machine, where CPU times move by 1.5x between runs. One iteration per row; only the
# library calls are counted (roiclip::clip / simplify / clipLines; Clipper's AddPath, Execute
# and SimplifyPolygons), not the harness or the correctness check. callgrind toggles collection
# at each entry and exit of a listed function, so no listed function may call another.
#   bench/instructions.sh Clip/Random1k_x_quad          # roiclip and clipper of that row
#   bench/instructions.sh Simplify/Random1k_nonzero Clip/Random1k_x_random1k
# With --suite, the rows of bench/suite (roiclip_suite) for roiclip and every peer: one warm call
# of the timed region (conversion from cv::Point, operation, freeing), after one cold call that
# is not counted (roiclip_suite --instr=ROW/LIB toggles collection around it):
#   bench/instructions.sh --suite                    # W1-100k, W3-1k-evenodd, W3-1k-nonzero
#   bench/instructions.sh --suite W2-10k-nonzero     # other rows (roiclip_suite --list)
# Environment: BUILD_DIR (default build; needs bench/core/roiclip_bench or
# bench/suite/roiclip_suite).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [ "${1:-}" = --suite ]; then
  shift
  suite=${BUILD_DIR:-$root/build}/bench/suite/roiclip_suite
  [ -x "$suite" ] || { echo "no $suite: build the roiclip_suite target first" >&2; exit 1; }
  [ $# -gt 0 ] || set -- W1-100k W3-1k-evenodd W3-1k-nonzero
  libs=(roiclip clipper boost geos raster)
  printf '| row | roiclip (M instr) | Clipper 1 | Boost.Geometry | GEOS | raster |\n'
  printf '|---|--:|--:|--:|--:|--:|\n'
  for row in "$@"; do
    line="| $row |"
    base=
    for lib in "${libs[@]}"; do
      # Exit code 3: the library cannot take the row (invalid polygons, no non-zero rule).
      rc=0
      valgrind --tool=callgrind --collect-atstart=no --callgrind-out-file="$work/out" \
        "$suite" --instr="$row/$lib" >/dev/null 2>"$work/log" || rc=$?
      if [ "$rc" -eq 3 ]; then
        line+=" – |"
        continue
      fi
      [ "$rc" -eq 0 ] || { cat "$work/log" >&2; exit 1; }
      n=$(grep -oE 'Collected : [0-9]+' "$work/log" | awk '{print $3}')
      if [ -z "$base" ]; then
        base=$n
        line+=$(awk -v n="$n" 'BEGIN { printf " %.1f |", n / 1e6 }')
      else
        line+=$(awk -v n="$n" -v b="$base" 'BEGIN { printf " %.1f (%.2f) |", n / 1e6, n / b }')
      fi
    done
    echo "$line"
  done
  exit 0
fi
bench=${BUILD_DIR:-$root/build}/bench/core/roiclip_bench
[ -x "$bench" ] || { echo "no $bench: build the release preset first" >&2; exit 1; }
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
