"""flipflop vs scipy.spatial (Qhull) from Python, whole calls, one process, medians of R runs
(argv[1], default 3): build/python-venv/bin/python docs/bench/python_vs_scipy.py 3 [hull]

Every attribute both compute eagerly is included (flipflop: certification, neighbors,
vertices, equations, volume, area). The two libraries' runs alternate (flipflop, scipy,
flipflop, ...), so that load from other processes, which changes over seconds on a shared
machine, weighs on both alike; the load average is printed before and after. With "hull"
as argv[2] only the ConvexHull rows run."""
import os, sys
import numpy as np, scipy, scipy.spatial as ss, flipflop
from alternate import alternate

R = int(sys.argv[1]) if len(sys.argv) > 1 else 3
only_hull = len(sys.argv) > 2 and sys.argv[2] == "hull"
rng = np.random.default_rng(1)


cube, ball = rng.random((1_000_000, 3)), np.array(flipflop.generate("ball", 1_000_000, seed=1))
one_thread = lambda p: flipflop.ConvexHull(p, threads=1)
# threads=1 rows: core for core against Qhull (single-threaded), which load
# from other processes distorts less than the two-thread runs
cases = [
    ("ConvexHull 3D, 10^6 uniform cube", cube, flipflop.ConvexHull, ss.ConvexHull),
    ("ConvexHull 3D, 10^6 ball", ball, flipflop.ConvexHull, ss.ConvexHull),
    ("ConvexHull 3D, 10^6 uniform cube, threads=1", cube, one_thread, ss.ConvexHull),
    ("ConvexHull 3D, 10^6 ball, threads=1", ball, one_thread, ss.ConvexHull),
]
if not only_hull:
    cases.append(("Delaunay 2D, 10^6 uniform square", rng.random((1_000_000, 2)), flipflop.Delaunay, ss.Delaunay))
load0, load1, timed_rows = alternate(cases, R)
rows = [(name, f, s, s / f, len(a.simplices), len(b.simplices)) for name, f, s, a, b in timed_rows]
print(f"numpy {np.__version__}, scipy {scipy.__version__}, flipflop {flipflop.__version__}, median of {R}, "
      f"alternating; load average (1, 5, 15 min) {load0[0]:.2f} {load0[1]:.2f} {load0[2]:.2f} before, "
      f"{load1[0]:.2f} {load1[1]:.2f} {load1[2]:.2f} after, {os.cpu_count()} cores")
print("| call | flipflop | scipy.spatial | scipy / flipflop | simplices (flipflop, scipy) |")
print("| --- | --- | --- | --- | --- |")
for n, tf, ts, r, ka, kb in rows:
    print(f"| {n} | {tf:.3f} s | {ts:.3f} s | {r:.1f}× | {ka}, {kb} |")
