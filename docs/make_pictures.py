#!/usr/bin/env python3
"""Makes the before/after pictures of docs/subdivision.md.

Runs the genmesh program on real meshes from libcgal-demo and draws each input
and result as a flat-shaded SVG (orthographic view, painter's algorithm), with
no dependency beyond Python 3:

    python3 docs/make_pictures.py [path/to/genmesh] [data/meshes folder]

Defaults: build/tools/genmesh and ~/.cache/genmesh/data/meshes.
"""
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GENMESH = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "tools", "genmesh")
MESHES = sys.argv[2] if len(sys.argv) > 2 else os.path.expanduser("~/.cache/genmesh/data/meshes")
OUT = os.path.join(ROOT, "docs", "images")

# (scheme, input mesh, levels)
CASES = [
    ("loop", "icosahedron.off", 2),
    ("catmull-clark", "cube_quad.off", 2),
    ("sqrt3", "icosahedron.off", 2),
    ("doo-sabin", "cube_quad.off", 2),
    ("butterfly", "icosahedron.off", 2),
    ("midpoint", "cube_quad.off", 2),
]


def read_off(path):
    """Points and faces of an ASCII OFF file (as genmesh writes it)."""
    with open(path) as f:
        words = [w for line in f for w in line.split("#")[0].split()]
    assert words[0].endswith("OFF"), path
    nv, nf = int(words[1]), int(words[2])
    pos = 4
    points = []
    for _ in range(nv):
        points.append(tuple(float(w) for w in words[pos:pos + 3]))
        pos += 3
    faces = []
    for _ in range(nf):
        n = int(words[pos])
        faces.append([int(w) for w in words[pos + 1:pos + 1 + n]])
        pos += 1 + n
    return points, faces


def rotate(p):
    """A fixed three-quarter view."""
    x, y, z = p
    a, b = math.radians(35), math.radians(-25)
    x, z = x * math.cos(a) + z * math.sin(a), -x * math.sin(a) + z * math.cos(a)
    y, z = y * math.cos(b) - z * math.sin(b), y * math.sin(b) + z * math.cos(b)
    return x, y, z


def svg(points, faces, path, size=240):
    pts = [rotate(p) for p in points]
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    scale = 0.9 * size / max(max(xs) - min(xs), max(ys) - min(ys))
    cx, cy = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2
    light = (0.3, 0.5, 0.8)
    polys = []
    for f in faces:
        q = [pts[i] for i in f]
        # Newell normal; faces turned away from the viewer (+z) are not drawn.
        n = [0.0, 0.0, 0.0]
        for i in range(len(q)):
            a, b = q[i], q[(i + 1) % len(q)]
            n[0] += (a[1] - b[1]) * (a[2] + b[2])
            n[1] += (a[2] - b[2]) * (a[0] + b[0])
            n[2] += (a[0] - b[0]) * (a[1] + b[1])
        length = math.sqrt(sum(c * c for c in n)) or 1.0
        n = [c / length for c in n]
        if n[2] <= 0:
            continue
        shade = max(0.0, sum(n[i] * light[i] for i in range(3)) / math.sqrt(sum(c * c for c in light)))
        depth = sum(p[2] for p in q) / len(q)
        polys.append((depth, q, shade))
    polys.sort(key=lambda t: t[0])
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{size}" height="{size}" viewBox="0 0 {size} {size}">',
           f'<rect width="{size}" height="{size}" fill="white"/>']
    for _, q, shade in polys:
        g = int(90 + 150 * shade)
        coords = " ".join(f"{size / 2 + (p[0] - cx) * scale:.1f},{size / 2 - (p[1] - cy) * scale:.1f}" for p in q)
        out.append(f'<polygon points="{coords}" fill="rgb({g // 2 + 40},{g // 2 + 70},{g})" '
                   f'stroke="#223" stroke-width="0.6" stroke-linejoin="round"/>')
    out.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def main():
    os.makedirs(OUT, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        for scheme, mesh, levels in CASES:
            src = os.path.join(MESHES, mesh)
            dst = os.path.join(tmp, f"{scheme}.off")
            subprocess.run([GENMESH, "subdivide", src, dst, "--scheme", scheme, "--levels", str(levels)],
                           check=True, stdout=subprocess.DEVNULL)
            name = scheme.replace("-", "_")
            svg(*read_off(src), os.path.join(OUT, f"{name}_before.svg"))
            svg(*read_off(dst), os.path.join(OUT, f"{name}_after.svg"))
            print(f"docs/images/{name}_before.svg, {name}_after.svg")


if __name__ == "__main__":
    main()
