"""flipflop vs scipy.spatial (Qhull) from Python, whole calls, one process, medians of R runs
(argv[1], default 3): build/python-venv/bin/python docs/bench/python_vs_scipy.py 3"""
import statistics, sys, time
import numpy as np, scipy, scipy.spatial as ss, flipflop

R = int(sys.argv[1]) if len(sys.argv) > 1 else 3
rng = np.random.default_rng(1)

def med(f):
    ts = []
    for _ in range(R):
        t = time.perf_counter(); out = f(); ts.append(time.perf_counter() - t)
    return statistics.median(ts), out

rows = []
for name, pts, ff, sp in [
    ("ConvexHull 3D, 10^6 uniform cube", rng.random((1_000_000, 3)), flipflop.ConvexHull, ss.ConvexHull),
    ("ConvexHull 3D, 10^6 ball", None, flipflop.ConvexHull, ss.ConvexHull),
    ("Delaunay 2D, 10^6 uniform square", rng.random((1_000_000, 2)), flipflop.Delaunay, ss.Delaunay),
]:
    if pts is None:
        pts = flipflop.generate("ball", 1_000_000, seed=1)
    tf, a = med(lambda: ff(pts))
    ts, b = med(lambda: sp(pts))
    same = len(a.simplices) == len(b.simplices)
    rows.append((name, tf, ts, ts / tf, len(a.simplices), len(b.simplices)))
print(f"numpy {np.__version__}, scipy {scipy.__version__}, flipflop {flipflop.__version__}, median of {R}")
print("| call | flipflop | scipy.spatial | scipy / flipflop | simplices (flipflop, scipy) |")
print("| --- | --- | --- | --- | --- |")
for n, tf, ts, r, ka, kb in rows:
    print(f"| {n} | {tf:.3f} s | {ts:.3f} s | {r:.1f}× | {ka}, {kb} |")
