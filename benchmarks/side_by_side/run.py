#!/usr/bin/env python3
"""Side-by-side runs of genmesh_benchmarks rows, one process per row and repetition.

The machines these benchmarks run on are shared and noisy, so a comparison is only
meaningful between rows measured in the same run, interleaved. This script does
exactly that for any family of rows that genmesh_benchmarks registers (for example
Simplification/armadillo832k_to10pc or Remeshing/armadillo):

  python3 benchmarks/side_by_side/run.py build-bench/benchmarks/genmesh_benchmarks \\
      Simplification/armadillo832k_to10pc \\
      --rows genmesh_Halfedge_mesh,CGAL_GH_plane,meshoptimizer \\
      --reference CGAL_GH_plane --reps 3
  python3 benchmarks/side_by_side/run.py build-bench/benchmarks/genmesh_benchmarks \\
      Remeshing/armadillo --rows genmesh_Halfedge_mesh,CGAL_Surface_mesh --time cpu

Every repetition runs each row in its own process (so one row's heap never
inflates another's peak), rotating the row order from one repetition to the next
(so no row always runs first or last). The quality counters (Hausdorff distance,
self-intersections, angles; slow on large meshes) are computed in the first
repetition only: the others run with GENMESH_BENCH_QUALITY=0.

It prints a Markdown table: per row, the median time over the repetitions (the
benchmark's real_time, or with --time cpu its cpu_time), every repetition's time,
the reference row's median over the row's median (how many times faster the row is
than the reference), and the counters of the first repetition. The load average is
printed before and after, since these figures depend on it.
"""

import argparse
import json
import os
import statistics
import subprocess
import sys


def load_average():
    with open("/proc/loadavg") as f:
        return " ".join(f.read().split()[:3])


def run_row(bench, family, row, quality, clock):
    name = f"{family}/{row}"
    env = dict(os.environ, GENMESH_BENCH_QUALITY="1" if quality else "0")
    out = subprocess.run(
        [bench, f"--benchmark_filter=^{name}(/|$)", "--benchmark_format=json"],
        env=env, check=True, capture_output=True, text=True).stdout
    found = [b for b in json.loads(out)["benchmarks"] if b["name"].startswith(name)] if out.strip() else []
    if not found:
        sys.exit(f"side_by_side: no benchmark named {name} (check the family and row names)")
    b = found[0]
    scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b.get("time_unit", "ns")]
    skip = {"name", "run_name", "run_type", "repetitions", "repetition_index", "threads",
            "iterations", "real_time", "cpu_time", "time_unit", "family_index",
            "per_family_instance_index", "aggregate_name", "aggregate_unit"}
    counters = {k: v for k, v in b.items() if k not in skip and isinstance(v, (int, float))}
    return b[clock + "_time"] * scale, counters


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("bench", help="path to genmesh_benchmarks")
    p.add_argument("family", help="row family, e.g. Simplification/armadillo832k_to10pc")
    p.add_argument("--rows", required=True, help="comma-separated row names of the family")
    p.add_argument("--reference", help="row the others are compared with (default: the last)")
    p.add_argument("--reps", type=int, default=3, help="repetitions (default 3)")
    p.add_argument("--time", choices=["real", "cpu"], default="real",
                   help="the benchmark's real_time (default; the simplification rows' manual "
                        "time is already the algorithm's CPU time) or its cpu_time (the process's)")
    args = p.parse_args()

    rows = args.rows.split(",")
    reference = args.reference or rows[-1]
    if reference not in rows:
        sys.exit(f"side_by_side: the reference {reference} is not among --rows")
    times = {r: [] for r in rows}
    counters = {}
    print(f"load average before: {load_average()}", file=sys.stderr)
    for rep in range(args.reps):
        order = rows[rep % len(rows):] + rows[:rep % len(rows)]
        for row in order:
            seconds, c = run_row(args.bench, args.family, row, quality=(rep == 0), clock=args.time)
            times[row].append(seconds)
            if rep == 0:
                counters[row] = c
            print(f"rep {rep + 1} {row}: {seconds:.3f} s (load {load_average()})", file=sys.stderr)
    print(f"load average after: {load_average()}", file=sys.stderr)

    keys = sorted({k for c in counters.values() for k in c})
    ref = statistics.median(times[reference])
    print(f"{args.family}, median of {args.reps}, reference {reference}\n")
    print("| row | median s | runs s | " + reference + " / row | " + " | ".join(keys) + " |")
    print("|---" * (4 + len(keys)) + "|")
    for row in rows:
        med = statistics.median(times[row])
        runs = ", ".join(f"{t:.3f}" for t in times[row])
        cells = [f"{counters[row][k]:.4g}" if k in counters[row] else "" for k in keys]
        print(f"| {row} | {med:.3f} | {runs} | {ref / med:.2f}x | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
