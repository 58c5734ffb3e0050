"""Every call of issue 39's list against scipy.spatial on integer grids, the same grids with
20 % of the points moved by 2 ulp (+1.0), and uniform random points, 2D..5D, in one process,
medians of 3 (docs/performance/python_scipy.md, stop 71; `Voronoi` in 4D and 5D too since stop 74):

    build/python-venv/bin/python docs/bench/measure_scipy_matrix.py [DIMS]   # e.g. 45 for 4D and 5D

scipy's incremental add on the 4D and 5D grids ends the process (exit status 7), so those rows
time flipflop alone."""
import sys, time

import numpy as np, scipy.spatial as ss, flipflop
from lattices import grid, perturbed

K = {2: 60, 3: 15, 4: 6, 5: 3}
def med(f, r=3):
    ts = []
    for _ in range(r):
        s = time.perf_counter(); f(); ts.append(time.perf_counter() - s)
    return float(np.median(ts))
for d in (int(x) for x in (sys.argv[1] if len(sys.argv) > 1 else '2345')):
    g = grid(K[d], d)
    inputs = {"grid": g, "grid+2ulp+1": perturbed(g) + 1.0, "random": np.random.default_rng(1).random((len(g), d))}
    q = np.random.default_rng(2).random((2000, d)) * (K[d] - 1)
    for name, p in inputs.items():
        if name == "random": qq = q / (K[d] - 1)
        else: qq = q + (1.0 if "+1" in name else 0.0)
        calls = {
            "ConvexHull": (lambda: flipflop.ConvexHull(p), lambda: ss.ConvexHull(p)),
            "Delaunay": (lambda: flipflop.Delaunay(p), lambda: ss.Delaunay(p)),
        }
        calls["Voronoi"] = (lambda: flipflop.Voronoi(p), lambda: ss.Voronoi(p))
        fd, sd = flipflop.Delaunay(p), ss.Delaunay(p)
        calls["find_simplex"] = (lambda: fd.find_simplex(qq), lambda: sd.find_simplex(qq))
        def tr(cls):
            ts = []
            for _ in range(3):
                o = cls(p); s0 = time.perf_counter(); o.transform; ts.append(time.perf_counter() - s0)
            return float(np.median(ts))
        a, b = tr(flipflop.Delaunay), tr(ss.Delaunay)
        print(f"{d}D {name:12s} n={len(p):5d} {'transform':12s} flipflop {a:.4f} scipy {b:.4f} ratio {a/b:.2f}{'  <-- slower' if a > b else ''}", flush=True)
        n0 = len(p) - len(p) // 10
        def ff_add():
            t = flipflop.Delaunay(p[:n0], incremental=True); s = time.perf_counter(); t.add_points(p[n0:]); return time.perf_counter() - s
        def sp_add():
            t = ss.Delaunay(p[:n0], incremental=True); s = time.perf_counter(); t.add_points(p[n0:]); return time.perf_counter() - s
        for c, (ff, sp) in calls.items():
            try:
                a, b = med(ff), med(sp)
            except Exception as e:
                print(d, name, c, "error", type(e).__name__, str(e)[:80]); continue
            flag = "  <-- slower" if a > b else ""
            print(f"{d}D {name:12s} n={len(p):5d} {c:12s} flipflop {a:.4f} scipy {b:.4f} ratio {a/b:.2f}{flag}", flush=True)
        a = float(np.median([ff_add() for _ in range(3)]))
        if d >= 4 and name != "random":  # scipy's incremental add ends the process (exit 7) on these
            print(f"{d}D {name:12s} n={len(p):5d} {'add_points':12s} flipflop {a:.4f} scipy (exits the process)", flush=True)
            continue
        b = float(np.median([sp_add() for _ in range(3)]))
        flag = "  <-- slower" if a > b else ""
        print(f"{d}D {name:12s} n={len(p):5d} {'add_points':12s} flipflop {a:.4f} scipy {b:.4f} ratio {a/b:.2f}{flag}", flush=True)
