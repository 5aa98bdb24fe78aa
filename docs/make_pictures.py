#!/usr/bin/env python3
"""Makes the before/after pictures of docs/subdivision.md and docs/remeshing.md.

Runs the genmesh program on real meshes from libcgal-demo and draws each input
and result: for subdivision a flat-shaded SVG (orthographic view, painter's
algorithm); for remeshing, whose meshes have thousands of triangles, a PNG
from a small software rasterizer (z-buffer, flat shading, dark edges) — with
no dependency beyond Python 3:

    python3 docs/make_pictures.py [--remesh] [path/to/genmesh] [data/meshes folder]

--remesh: only the remeshing pictures.

Defaults: build/tools/genmesh and ~/.cache/genmesh/data/meshes.
"""
import json
import math
import os
import struct
import subprocess
import sys
import tempfile
import zlib

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ARGS = [a for a in sys.argv[1:] if not a.startswith("--")]
GENMESH = ARGS[0] if len(ARGS) > 0 else os.path.join(ROOT, "build", "tools", "genmesh")
MESHES = ARGS[1] if len(ARGS) > 1 else os.path.expanduser("~/.cache/genmesh/data/meshes")
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


# (picture name, input mesh, genmesh remesh options; "{l}" is replaced by the
# input's mean edge length)
REMESH_CASES = [
    ("remesh_uniform", "elephant.off", ["--relative", "1"]),
    ("remesh_adaptive", "elephant.off", ["--adaptive", "{0.3l}", "{4l}", "{0.1l}"]),
    ("remesh_features", "fandisk.off", ["--relative", "2", "--features", "40"]),
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


def mean_edge_length(points, faces):
    edges = {(min(a, b), max(a, b)) for f in faces for a, b in zip(f, f[1:] + f[:1])}
    return sum(math.dist(points[a], points[b]) for a, b in edges) / len(edges)


def png(points, faces, path, size=420):
    """Rasterizes the triangles (fans for polygons) with a z-buffer, flat
    shading and dark edges, and writes an 8-bit RGB PNG."""
    pts = [rotate(p) for p in points]
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    scale = 0.92 * size / max(max(xs) - min(xs), max(ys) - min(ys))
    cx, cy = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2
    scr = [(size / 2 + (p[0] - cx) * scale, size / 2 - (p[1] - cy) * scale, p[2]) for p in pts]
    light = (0.3, 0.5, 0.8)
    ll = math.sqrt(sum(c * c for c in light))
    zbuf = [-math.inf] * (size * size)
    img = bytearray(b"\xff" * (3 * size * size))
    for f in faces:
        for k in range(1, len(f) - 1):
            a, b, c = scr[f[0]], scr[f[k]], scr[f[k + 1]]
            pa, pb, pc = pts[f[0]], pts[f[k]], pts[f[k + 1]]
            u = [pb[i] - pa[i] for i in range(3)]
            v = [pc[i] - pa[i] for i in range(3)]
            n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
            nl = math.sqrt(sum(t * t for t in n)) or 1.0
            if n[2] <= 0:
                continue  # turned away from the viewer (+z)
            shade = max(0.0, sum(n[i] * light[i] for i in range(3)) / (nl * ll))
            # Screen-space edge functions; area > 0 after the y flip.
            area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
            if area == 0:
                continue
            x0, x1 = max(0, int(min(a[0], b[0], c[0]))), min(size - 1, int(max(a[0], b[0], c[0])) + 1)
            y0, y1 = max(0, int(min(a[1], b[1], c[1]))), min(size - 1, int(max(a[1], b[1], c[1])) + 1)
            lens = [math.dist(b[:2], c[:2]) or 1.0, math.dist(c[:2], a[:2]) or 1.0, math.dist(a[:2], b[:2]) or 1.0]
            # Which sides are the polygon's own (the fan's inner diagonals are not drawn).
            sides = (True, k + 1 == len(f) - 1, k == 1)
            g = 70 + 160 * shade
            fill = (int(g * 0.55 + 30), int(g * 0.7 + 35), int(g))
            for y in range(y0, y1 + 1):
                py = y + 0.5
                for x in range(x0, x1 + 1):
                    px = x + 0.5
                    w0 = ((b[0] - px) * (c[1] - py) - (b[1] - py) * (c[0] - px)) / area
                    w1 = ((c[0] - px) * (a[1] - py) - (c[1] - py) * (a[0] - px)) / area
                    w2 = 1.0 - w0 - w1
                    if w0 < 0 or w1 < 0 or w2 < 0:
                        continue
                    z = w0 * a[2] + w1 * b[2] + w2 * c[2]
                    i = y * size + x
                    if z <= zbuf[i]:
                        continue
                    zbuf[i] = z
                    # Distance in pixels to the nearest side: w_k · 2·area / |side k|.
                    d = min(w * abs(area) / lens[j] for j, w in enumerate((w0, w1, w2)) if sides[j])
                    col = (25, 30, 45) if d < 0.55 else fill
                    img[3 * i:3 * i + 3] = bytes(col)
    raw = b"".join(b"\x00" + bytes(img[3 * size * y:3 * size * (y + 1)]) for y in range(size))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    with open(path, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", size, size, 8, 2, 0, 0, 0)) +
                  chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def remesh_pictures(tmp):
    for name, mesh, options in REMESH_CASES:
        src = os.path.join(MESHES, mesh)
        points, faces = read_off(src)
        length = mean_edge_length(points, faces)
        args = [str(float(o[1:-2] or 1) * length) if o.startswith("{") else o for o in options]
        dst = os.path.join(tmp, f"{name}.off")
        record = subprocess.run([GENMESH, "remesh", src, dst, "--json"] + args, check=True,
                                capture_output=True, text=True).stdout
        r = json.loads(record.strip().splitlines()[-1])
        png(points, faces, os.path.join(OUT, f"{name}_before.png"))
        png(*read_off(dst), os.path.join(OUT, f"{name}_after.png"))
        print(f"docs/images/{name}_before.png, {name}_after.png: {mesh} {' '.join(args)}: "
              f"{len(faces)} -> {r['faces']} faces, min angle {r['min_angle']:.1f}, "
              f"valence 6 {100 * r['valence6_share']:.1f} %")


def main():
    os.makedirs(OUT, exist_ok=True)
    only_remesh = "--remesh" in sys.argv
    if only_remesh:
        with tempfile.TemporaryDirectory() as tmp:
            remesh_pictures(tmp)
        return
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
        remesh_pictures(tmp)


if __name__ == "__main__":
    main()
