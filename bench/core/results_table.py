#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Turn roiclip_bench JSON output (--benchmark_out_format=json) into the Markdown table of
bench/RESULTS.md: CPU time per operation for each library and its ratio to roiclip
(ratio > 1 means roiclip is faster), plus heap peaks. With --benchmark_repetitions the median
aggregate is used. Several JSON files (e.g. a repeated pass and a single heavy pass) are merged;
the machine line comes from the first."""
import argparse
import json
import sys

LIBRARIES = [("roiclip", "roiclip"), ("clipper", "Clipper 1"),
             ("clipper_union", "Clipper 1 union (not strictly simple)"),
             ("boost", "Boost.Geometry"), ("geos", "GEOS")]
TO_MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}


def fmt_ms(ms):
    if ms >= 100:
        return f"{ms:.0f} ms"
    if ms >= 1:
        return f"{ms:.3g} ms"
    return f"{ms * 1000:.3g} µs"


def main(paths, order_file=None):
    docs = []
    for path in paths:
        with open(path) as f:
            docs.append(json.load(f))
    doc = docs[0]
    runs = {}
    for b in (b for d in docs for b in d["benchmarks"]):
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
            continue
        name = b.get("run_name", b["name"])
        # A median aggregate replaces the single runs of the same benchmark.
        if name in runs and b.get("run_type") != "aggregate":
            continue
        runs[name] = b
    rows = {}
    order = []
    for name, b in runs.items():
        workload, lib = name.rsplit("/", 1)
        if workload not in rows:
            rows[workload] = {}
            order.append(workload)
        rows[workload][lib] = b
    if order_file:
        # Rows in registration order (the output of --benchmark_list_tests).
        with open(order_file) as f:
            listed = [line.strip().rsplit("/", 1)[0] for line in f if "/" in line]
        rank = {w: i for i, w in reversed(list(enumerate(listed)))}
        order.sort(key=lambda w: rank.get(w, len(rank)))

    ctx = doc.get("context", {})
    model = "?"
    try:
        with open("/proc/cpuinfo") as f:
            model = next(line.split(":", 1)[1].strip() for line in f
                         if line.startswith("model name"))
    except (OSError, StopIteration):
        pass
    print(f"Machine: {model}, {ctx.get('num_cpus', '?')} CPUs at {ctx.get('mhz_per_cpu', '?')} MHz "
          f"(host {ctx.get('host_name', '?')}), run {ctx.get('date', '?')}, "
          f"load average {', '.join(f'{x:.2f}' for x in ctx.get('load_avg', []))}")
    print()
    header = ["workload", "vertices"] + [label for _, label in LIBRARIES] + [
        "roiclip peak MB", "Clipper peak MB", "max rel. area diff"]
    print("| " + " | ".join(header) + " |")
    print("|" + "|".join(["---"] * 2 + ["--:"] * (len(header) - 2)) + "|")
    errors = []
    for workload in order:
        libs = rows[workload]
        base = libs.get("roiclip")
        base_ms = None
        if base and not base.get("error_occurred"):
            base_ms = base["cpu_time"] * TO_MS[base["time_unit"]]
        vertices = next((b.get("vertices") for b in libs.values() if "vertices" in b), None)
        cells = [workload, f"{vertices:.0f}" if vertices else "?"]
        worst = None
        for key, label in LIBRARIES:
            b = libs.get(key)
            if b is None:
                cells.append("–")
                continue
            if b.get("error_occurred"):
                cells.append("error")
                errors.append(f"{workload}/{key}: {b.get('error_message', '')}")
                continue
            ms = b["cpu_time"] * TO_MS[b["time_unit"]]
            if key != "roiclip":
                worst = max(worst or 0.0, b.get("rel_diff", 0.0))
            if key == "roiclip" or base_ms is None:
                cells.append(fmt_ms(ms))
            else:
                cells.append(f"{fmt_ms(ms)} ({ms / base_ms:.2f}×)")
        for key in ("roiclip", "clipper"):
            b = libs.get(key)
            cells.append(f"{b['peak_MB']:.1f}" if b and "peak_MB" in b else "–")
        cells.append("–" if worst is None else f"{worst:.1e}")
        print("| " + " | ".join(cells) + " |")
    if errors:
        print()
        print("Errors (correctness signals, see the WARNING lines of the run):")
        for e in errors:
            print(f"- {e}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("json", nargs="+", help="roiclip_bench --benchmark_out JSON files")
    parser.add_argument("--order", help="--benchmark_list_tests output: row order")
    args = parser.parse_args()
    main(args.json, args.order)
