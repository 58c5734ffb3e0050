"""Issue 39's rows against scipy.spatial (Qhull) from Python: whole calls in one process,
flipflop and scipy alternating, medians of R runs (argv[1], default 3):

    build/python-venv/bin/python docs/bench/measure_scipy_rows.py 3 [SUBSTRING]

(with SUBSTRING, only the rows whose name contains it, e.g. ConvexHull).

Rows: Delaunay on integer grids k^d and on the same grids with 20 % of the points moved by
2 ulp per coordinate (each coordinate stepped twice by np.nextafter in a random direction,
seed 7: a moved 0 becomes a subnormal), the perturbed grids plus 1.0 (no subnormals),
Voronoi of the 3^5 and 6^4 grids and of the same grids perturbed, Delaunay of random points in 4D and 5D, ConvexHull of standard normal points in 4D..7D and of
uniform cube points in 4D and 5D,
find_simplex of 18,000 queries on the perturbed 3^5 grid. flipflop's calls include
certification; both libraries' attributes are those computed eagerly."""
import os, sys
import numpy as np, scipy, scipy.spatial as ss, flipflop
from alternate import alternate
from lattices import grid, perturbed

R = int(sys.argv[1]) if len(sys.argv) > 1 else 3
ONLY = sys.argv[2] if len(sys.argv) > 2 else ""


rng = np.random.default_rng(1)
g35p = perturbed(grid(3, 5))
queries = rng.random((18_000, 5)) * 2.0
cases = [
    ("Delaunay, 3^5 grid", grid(3, 5), flipflop.Delaunay, ss.Delaunay),
    ("Delaunay, 3^5 grid, 20 % moved by 2 ulp", g35p, flipflop.Delaunay, ss.Delaunay),
    ("Delaunay, 3^5 grid, 20 % moved by 2 ulp, + 1", g35p + 1.0, flipflop.Delaunay, ss.Delaunay),
    ("Delaunay, 6^4 grid", grid(6, 4), flipflop.Delaunay, ss.Delaunay),
    ("Delaunay, 6^4 grid, 20 % moved by 2 ulp", perturbed(grid(6, 4)), flipflop.Delaunay, ss.Delaunay),
    ("Delaunay, 20^3 grid, 20 % moved by 2 ulp", perturbed(grid(20, 3)), flipflop.Delaunay, ss.Delaunay),
    ("Voronoi, 3^5 grid", grid(3, 5), flipflop.Voronoi, ss.Voronoi),
    ("Voronoi, 6^4 grid", grid(6, 4), flipflop.Voronoi, ss.Voronoi),
    ("Voronoi, 3^5 grid, 20 % moved by 2 ulp", g35p, flipflop.Voronoi, ss.Voronoi),
    ("Voronoi, 3^5 grid, 20 % moved by 2 ulp, + 1", g35p + 1.0, flipflop.Voronoi, ss.Voronoi),
    ("Voronoi, 6^4 grid, 20 % moved by 2 ulp", perturbed(grid(6, 4)), flipflop.Voronoi, ss.Voronoi),
    ("Delaunay, 2x10^4 random 4D", rng.random((20_000, 4)), flipflop.Delaunay, ss.Delaunay),
    ("Delaunay, 5000 random 5D", rng.random((5000, 5)), flipflop.Delaunay, ss.Delaunay),
    ("ConvexHull, 10^5 normal 4D", rng.standard_normal((100_000, 4)), flipflop.ConvexHull, ss.ConvexHull),
    ("ConvexHull, 2x10^4 normal 5D", rng.standard_normal((20_000, 5)), flipflop.ConvexHull, ss.ConvexHull),
    ("ConvexHull, 10^5 uniform cube 4D", rng.random((100_000, 4)), flipflop.ConvexHull, ss.ConvexHull),
    ("ConvexHull, 10^5 uniform cube 5D", rng.random((100_000, 5)), flipflop.ConvexHull, ss.ConvexHull),
    ("ConvexHull, 2000 normal 6D", rng.standard_normal((2000, 6)), flipflop.ConvexHull, ss.ConvexHull),
    ("ConvexHull, 800 normal 7D", rng.standard_normal((800, 7)), flipflop.ConvexHull, ss.ConvexHull),
]
ff_g, sp_g = flipflop.Delaunay(g35p), ss.Delaunay(g35p)
cases.append(("find_simplex, 18,000 queries, perturbed 3^5 grid", None,
              lambda _: ff_g.find_simplex(queries), lambda _: sp_g.find_simplex(queries)))
cases = [c for c in cases if ONLY in c[0]]
load0, load1, timed_rows = alternate(cases, R)
size = lambda x: (len(x.vertices) if hasattr(x, "ridge_points") else len(x.simplices) if hasattr(x, "simplices")
                  else int((np.asarray(x) >= 0).sum()))
rows = [(name, f, s, size(a), size(b)) for name, f, s, a, b in timed_rows]
print(f"numpy {np.__version__}, scipy {scipy.__version__}, flipflop {flipflop.__version__}, median of {R}, "
      f"alternating; load average {load0[0]:.2f} {load0[1]:.2f} {load0[2]:.2f} before, "
      f"{load1[0]:.2f} {load1[1]:.2f} {load1[2]:.2f} after, {os.cpu_count()} cores")
print("| call | flipflop | scipy.spatial | flipflop / scipy | simplices, vertices or found (flipflop, scipy) |")
print("| --- | ---: | ---: | ---: | --- |")
for n, f, s, ka, kb in rows:
    print(f"| {n} | {f:.4f} s | {s:.4f} s | {f / s:.2f} | {ka}, {kb} |")
