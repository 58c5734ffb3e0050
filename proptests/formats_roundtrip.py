#!/usr/bin/python3
"""Every output format of `flipflop -o FILE` read back by an independent
reader (meshio for .off .obj .ply .stl .vtu, numpy for .npy, the standard
library's XML parser for .svg) and compared with the canonical index text of
the same run and the input coordinates: identical geometry (bit for bit where
the format holds doubles; binary STL holds float32 by its specification) and
identical connectivity, orientation included. Also: unknown extensions,
formats that cannot hold a result and unwritable paths are refused with one
line and exit 2.

usage: formats_roundtrip.py FLIPFLOP WORKDIR   (exit 0 when every check holds)
"""
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

import meshio
import numpy as np

FLIPFLOP, WORK = sys.argv[1], sys.argv[2]
os.makedirs(WORK, exist_ok=True)
failures = []
checks = 0


def check(cond, what):
    global checks
    checks += 1
    if not cond:
        failures.append(what)
        print("FAIL:", what)


def run(*args, ok=True):
    r = subprocess.run([FLIPFLOP, *args], capture_output=True, text=True)
    if ok and r.returncode != 0:
        raise SystemExit(f"flipflop {' '.join(args)} failed ({r.returncode}): {r.stderr}")
    return r


def path(name):
    return os.path.join(WORK, name)


def read_points(p):
    rows = []
    with open(p) as f:
        for line in f:
            line = line.split("#")[0].split()
            if line:
                rows.append([float(x) for x in line])
    return np.array(rows)


def read_index_text(p):
    with open(p) as f:
        return [tuple(int(x) for x in line.split()) for line in f if line.strip()]


def rotate_min(t):
    i = t.index(min(t))
    return tuple(t[i:] + t[:i])


def mesh_cells(m):
    out = []
    for block in m.cells:
        out += [tuple(int(x) for x in c) for c in block.data]
    return out


def compare_mesh(fmt, m, xyz, cells, dim, exact=True, input_index=False):
    """m: meshio mesh; cells: canonical tuples of input indices (oriented)."""
    used = sorted({i for c in cells for i in c})
    check(len(m.points) == len(used), f"{fmt}: {len(m.points)} vertices, {len(used)} used points")
    expect = np.zeros((len(used), 3))
    expect[:, :dim] = xyz[used, :dim]
    if exact:
        check(np.array_equal(np.asarray(m.points, dtype=np.float64), expect), f"{fmt}: coordinates differ from the input")
    else:  # binary STL: float32 by its specification
        check(np.array_equal(np.asarray(m.points, dtype=np.float32), expect.astype(np.float32)),
              f"{fmt}: coordinates differ from the input rounded to float32")
    got = sorted(rotate_min([used[i] for i in c]) for c in mesh_cells(m))
    want = sorted(rotate_min(list(c)) for c in cells)
    check(got == want, f"{fmt}: connectivity differs ({len(got)} cells read, {len(want)} expected)")
    if input_index:
        idx = [int(x) for x in np.asarray(m.point_data["input_index"]).ravel()]
        check(idx == used, f"{fmt}: input_index differs from the used input indices")


def stl_by_coordinates(p, xyz, tris, binary):
    """meshio's STL reader merges equal coordinates; compare triangles by the
    input points at their coordinates (inputs with distinct points)."""
    m = meshio.read(p, file_format="stl")
    key = (lambda a: tuple(np.float32(a))) if binary else (lambda a: tuple(a))
    where = {key(np.array([*xyz[i, :3], 0][:3] if xyz.shape[1] == 2 else xyz[i, :3])): i for i in range(len(xyz))}
    got = []
    for c in mesh_cells(m):
        got.append(rotate_min([where.get(key(np.asarray(m.points[j], dtype=np.float64)), -1) for j in c]))
    check(sorted(got) == sorted(rotate_min(list(t)) for t in tris),
          f"stl({'binary' if binary else 'ascii'}): triangles differ")


# ---- 3D hull (general position) ---------------------------------------------
run("gen", "ball", "300", "--seed", "5", "-o", path("ball.xyz"))
ball = read_points(path("ball.xyz"))
run("hull3", path("ball.xyz"), "-o", path("ball.txt"))
tris = read_index_text(path("ball.txt"))
for ext, reader_fmt, extra in [("off", "off", []), ("obj", "obj", []), ("ply", "ply", []),
                               ("ascii.ply", "ply", ["--ascii"]), ("vtu", "vtu", [])]:
    run("hull3", path("ball.xyz"), "-o", path("ball." + ext), *extra)
    m = meshio.read(path("ball." + ext), file_format=reader_fmt)
    compare_mesh("hull3 ." + ext, m, ball, tris, 3, input_index=reader_fmt in ("ply", "vtu"))
run("hull3", path("ball.xyz"), "-o", path("ball.stl"))
stl_by_coordinates(path("ball.stl"), ball, tris, binary=True)
run("hull3", path("ball.xyz"), "--ascii", "-o", path("ballascii.stl"))
stl_by_coordinates(path("ballascii.stl"), ball, tris, binary=False)
run("hull3", path("ball.xyz"), "-o", path("ball.npy"))
a = np.load(path("ball.npy"))
check(a.dtype == np.int64 and a.shape == (len(tris), 3), f"hull3 .npy: dtype {a.dtype} shape {a.shape}")
check([tuple(int(x) for x in r) for r in a] == tris, "hull3 .npy: rows differ from the index text")

# ---- strict view, triangulated (a cube: merged facets) ------------------------
run("gen", "cube", "400", "--seed", "3", "-o", path("cube.xyz"))
cube = read_points(path("cube.xyz"))
strict = run("hull3", path("cube.xyz"), "--strict", "--triangulate").stdout.split("\n")
e, t = (int(x) for x in strict[0].split())
stris = [tuple(int(x) for x in l.split()) for l in strict[1 + e:1 + e + t]]
check(len(stris) == t and all(len(x) == 3 for x in stris), "strict --triangulate: triangles expected")
areas = [np.linalg.norm(np.cross(cube[j, :3] - cube[i, :3], cube[k, :3] - cube[i, :3])) / 2 for i, j, k in stris]
check(min(areas) > 0, "strict --triangulate: a zero-area triangle")
for ext in ("off", "ply", "vtu"):
    run("hull3", path("cube.xyz"), "--strict", "--triangulate", "-o", path("cube." + ext))
    compare_mesh("strict triangulated ." + ext, meshio.read(path("cube." + ext)), cube, stris, 3,
                 input_index=ext in ("ply", "vtu"))
run("hull3", path("cube.xyz"), "--strict", "-o", path("cubepoly.ply"))
poly = run("hull3", path("cube.xyz"), "--strict").stdout.split("\n")
e2, f2 = (int(x) for x in poly[0].split())
polys = [tuple(int(x) for x in l.split()) for l in poly[1 + e2:1 + e2 + f2]]
compare_mesh("strict polygons .ply", meshio.read(path("cubepoly.ply")), cube, polys, 3, input_index=True)

# ---- 2D Delaunay on a grid (degenerate), 2D hull, weighted 2D --------------------
grid = "\n".join(f"{x} {y}" for x in range(8) for y in range(8)) + "\n"
with open(path("grid.xyz"), "w") as f:
    f.write(grid)
gxy = read_points(path("grid.xyz"))
run("dt2", path("grid.xyz"), "-o", path("grid.txt"))
gtris = read_index_text(path("grid.txt"))
for ext in ("off", "obj", "ply", "vtu"):
    run("dt2", path("grid.xyz"), "-o", path("grid." + ext))
    compare_mesh("dt2 ." + ext, meshio.read(path("grid." + ext)), gxy, gtris, 2, input_index=ext in ("ply", "vtu"))
run("hull2", path("grid.xyz"), "-o", path("h2.txt"))
cyc = [c[0] for c in read_index_text(path("h2.txt"))]
run("hull2", path("grid.xyz"), "-o", path("h2.npy"))
h = np.load(path("h2.npy"))
check(h.shape == (len(cyc),) and [int(x) for x in h] == cyc, "hull2 .npy: differs from the index text")
for ext in ("ply", "obj"):  # meshio's OFF reader takes triangles only
    run("hull2", path("grid.xyz"), "-o", path("h2." + ext))
    compare_mesh("hull2 ." + ext, meshio.read(path("h2." + ext)), gxy, [tuple(cyc)], 2, input_index=ext == "ply")
run("hull2", path("grid.xyz"), "-o", path("h2.stl"), "--ascii")
m = meshio.read(path("h2.stl"))
area = sum(abs(np.cross(m.points[c[1]] - m.points[c[0]], m.points[c[2]] - m.points[c[0]])[2]) / 2
           for c in m.cells[0].data)
check(area == 49.0 and min(abs(np.cross(m.points[c[1]] - m.points[c[0]], m.points[c[2]] - m.points[c[0]])[2])
                           for c in m.cells[0].data) > 0, f"hull2 .stl: fan area {area}, expected 49 without zero-area triangles")

run("gen", "disk", "150", "--seed", "2", "--weights", "0,0.02", "-o", path("w.xyz"))
wxy = read_points(path("w.xyz"))
run("rt2", path("w.xyz"), "-o", path("w.txt"))
wtris = read_index_text(path("w.txt"))
run("rt2", path("w.xyz"), "-o", path("w.svg"))
svg = ET.parse(path("w.svg")).getroot()
ns = "{http://www.w3.org/2000/svg}"
polys_svg = [p.get("points") for p in svg.iter(ns + "polygon")]
check(len(polys_svg) == len(wtris), f"rt2 .svg: {len(polys_svg)} polygons, {len(wtris)} triangles")
coords = {(float(x), float(y)) for p in polys_svg for xy in p.split() for x, y in [xy.split(",")]}
check(coords == {(wxy[i, 0], -wxy[i, 1]) for t in wtris for i in t}, "rt2 .svg: polygon corners are not the vertices")
circles = list(svg.iter(ns + "circle"))
check(len(circles) == len(wxy), f"rt2 .svg: {len(circles)} points drawn, {len(wxy)} in the input")
redundant = sorted(set(range(len(wxy))) - {i for t in wtris for i in t})
marks = [int(p.find(ns + "title").text.split()[0]) for p in svg.iter(ns + "path")]
check(marks == redundant, f"rt2 .svg: marked {marks[:10]}, redundant {redundant[:10]}")

# ---- rtd, d = 3 (tetrahedra in VTU, positive volume) ----------------------------
rng = np.random.default_rng(7)
pts = rng.random((60, 3))
w = rng.random(60) * 0.01
with open(path("r3.xyz"), "w") as f:
    for p, wi in zip(pts, w):
        f.write(" ".join(repr(float(x)) for x in (*p, wi)) + "\n")
r3 = read_points(path("r3.xyz"))
run("rtd", path("r3.xyz"), "--dim", "3", "-o", path("r3.txt"))
tets = read_index_text(path("r3.txt"))
run("rtd", path("r3.xyz"), "--dim", "3", "-o", path("r3.vtu"))
m = meshio.read(path("r3.vtu"))
check([b.type for b in m.cells] == ["tetra"], f"rtd .vtu: cell types {[b.type for b in m.cells]}")
used = sorted({i for t in tets for i in t})
check(np.array_equal(m.points, r3[used, :3]), "rtd .vtu: coordinates differ")
got = [tuple(used[i] for i in c) for c in m.cells[0].data]
check(got == tets, "rtd .vtu: tetrahedra differ from the simplex list (order and orientation)")
vols = [np.linalg.det(np.array([m.points[c[k]] - m.points[c[0]] for k in (1, 2, 3)])) for c in m.cells[0].data]
check(min(vols) > 0, "rtd .vtu: a tetrahedron with non-positive volume det[p1-p0, p2-p0, p3-p0]")
run("rtd", path("r3.xyz"), "--dim", "3", "-o", path("r3.npy"))
check([tuple(int(x) for x in r) for r in np.load(path("r3.npy"))] == tets, "rtd .npy: differs")

# ---- refusals: one line, exit 2, nothing written ----------------------------------
for args, what in [(["hull3", path("ball.xyz"), "-o", path("x.foo")], "unknown extension"),
                   (["hull3", path("ball.xyz"), "-o", path("x.svg")], "3D result as SVG"),
                   (["rtd", path("r3.xyz"), "--dim", "3", "-o", path("x.off")], "tetrahedra as OFF"),
                   (["hull3", path("ball.xyz"), "-o", "/nonexistent-dir/x.off"], "unwritable path"),
                   (["hull3", path("ball.xyz"), "--triangulate"], "--triangulate without --strict")]:
    r = run(*args, ok=False)
    lines = r.stderr.strip().split("\n")
    check(r.returncode == 2 and len(lines) == 1 and lines[0].startswith("flipflop: error:"),
          f"{what}: exit {r.returncode}, stderr {r.stderr!r}")
check(not os.path.exists(path("x.foo")) and not os.path.exists(path("x.svg")) and not os.path.exists(path("x.off")),
      "a refused output file was created")

print(f"{checks} checks, {len(failures)} failed")
sys.exit(1 if failures else 0)
