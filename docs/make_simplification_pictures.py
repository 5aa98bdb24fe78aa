#!/usr/bin/env python3
"""Makes the pictures of docs/simplification.md.

1. Before/after pictures: the genmesh program simplifies elephant.off
   (libcgal-demo) to several ratios; each result is drawn as a flat-shaded SVG
   by make_pictures.svg (no dependency beyond Python 3).
2. The error-versus-face-count plot: runs the SimplificationCurve family of
   genmesh_benchmarks (armadillo.off, 52k faces, simplified to 50% ... 0.5% by
   genmesh, CGAL's Garland-Heckbert plane policies and meshoptimizer; each
   result's symmetric Hausdorff distance to the input, relative to its
   bounding-box diagonal) and draws it as an SVG line chart, log-log.

    python3 docs/make_simplification_pictures.py [genmesh] [genmesh_benchmarks] [data/meshes]

Defaults: build/tools/genmesh, build/benchmarks/genmesh_benchmarks and
~/.cache/genmesh/data/meshes. Without a benchmarks executable (or with "-")
only the pictures are made.
"""
import json
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_pictures import read_off, svg  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GENMESH = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "tools", "genmesh")
BENCH = sys.argv[2] if len(sys.argv) > 2 else os.path.join(ROOT, "build", "benchmarks", "genmesh_benchmarks")
MESHES = sys.argv[3] if len(sys.argv) > 3 else os.path.expanduser("~/.cache/genmesh/data/meshes")
OUT = os.path.join(ROOT, "docs", "images")

RATIOS = [0.2, 0.05, 0.01]


def pictures():
    src = os.path.join(MESHES, "elephant.off")
    svg(*read_off(src), os.path.join(OUT, "simplify_elephant_100.svg"))
    print("docs/images/simplify_elephant_100.svg")
    with tempfile.TemporaryDirectory() as tmp:
        for r in RATIOS:
            dst = os.path.join(tmp, f"elephant_{r}.off")
            subprocess.run([GENMESH, "simplify", src, dst, "--ratio", str(r)], check=True,
                           stdout=subprocess.DEVNULL)
            name = f"simplify_elephant_{r * 100:g}".replace(".", "_") + ".svg"
            svg(*read_off(dst), os.path.join(OUT, name))
            print(f"docs/images/{name}")


def curve_data():
    run = subprocess.run([BENCH, "--benchmark_filter=SimplificationCurve/", "--benchmark_format=json"],
                         check=True, capture_output=True, text=True)
    series = {}
    for b in json.loads(run.stdout)["benchmarks"]:
        _, _, row = b["name"].split("/")[:3]
        series.setdefault(row, []).append((b["faces_out"], b["hausdorff"]))
    for row in series:
        series[row].sort()
    return series


def plot(series, path, width=520, height=340):
    """A log-log line chart: faces left (x) against relative Hausdorff (y)."""
    left, right, top, bottom = 70, 150, 20, 50
    xs = [x for s in series.values() for x, _ in s]
    ys = [y for s in series.values() for _, y in s if y > 0]
    x0, x1 = math.floor(math.log10(min(xs))), math.ceil(math.log10(max(xs)))
    y0, y1 = math.floor(math.log10(min(ys))), math.ceil(math.log10(max(ys)))

    def px(x):
        return left + (math.log10(x) - x0) / (x1 - x0) * (width - left - right)

    def py(y):
        return height - bottom - (math.log10(y) - y0) / (y1 - y0) * (height - top - bottom)

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           f'viewBox="0 0 {width} {height}" font-family="sans-serif" font-size="11">',
           f'<rect width="{width}" height="{height}" fill="white"/>']
    for e in range(x0, x1 + 1):
        x = px(10 ** e)
        out.append(f'<line x1="{x:.1f}" y1="{top}" x2="{x:.1f}" y2="{height - bottom}" stroke="#ddd"/>')
        out.append(f'<text x="{x:.1f}" y="{height - bottom + 15}" text-anchor="middle">1e{e}</text>')
    for e in range(y0, y1 + 1):
        y = py(10 ** e)
        out.append(f'<line x1="{left}" y1="{y:.1f}" x2="{width - right}" y2="{y:.1f}" stroke="#ddd"/>')
        out.append(f'<text x="{left - 6}" y="{y + 4:.1f}" text-anchor="end">1e{e}</text>')
    out.append(f'<text x="{(left + width - right) / 2}" y="{height - 12}" text-anchor="middle">faces left '
               f'(armadillo, 52k faces)</text>')
    out.append(f'<text x="14" y="{(top + height - bottom) / 2}" text-anchor="middle" '
               f'transform="rotate(-90 14 {(top + height - bottom) / 2})">Hausdorff / diagonal</text>')
    colours = {"genmesh": "#c0392b", "CGAL_GH_plane": "#2e86c1", "meshoptimizer": "#27ae60"}
    for i, (row, points) in enumerate(sorted(series.items())):
        c = colours.get(row, "#555")
        d = " ".join(f"{px(x):.1f},{py(y):.1f}" for x, y in points if y > 0)
        out.append(f'<polyline points="{d}" fill="none" stroke="{c}" stroke-width="2"/>')
        for x, y in points:
            if y > 0:
                out.append(f'<circle cx="{px(x):.1f}" cy="{py(y):.1f}" r="3" fill="{c}"/>')
        ly = top + 15 + 18 * i
        out.append(f'<line x1="{width - right + 10}" y1="{ly - 4}" x2="{width - right + 30}" y2="{ly - 4}" '
                   f'stroke="{c}" stroke-width="2"/>')
        out.append(f'<text x="{width - right + 35}" y="{ly}">{row}</text>')
    out.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def main():
    os.makedirs(OUT, exist_ok=True)
    pictures()
    if BENCH != "-" and os.path.exists(BENCH):
        series = curve_data()
        for row, points in sorted(series.items()):
            print(row, " ".join(f"{int(x)}:{y:.3g}" for x, y in points))
        plot(series, os.path.join(OUT, "simplify_error_curve.svg"))
        print("docs/images/simplify_error_curve.svg")


if __name__ == "__main__":
    main()
