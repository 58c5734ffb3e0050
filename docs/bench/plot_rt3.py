#!/usr/bin/python3
"""docs/bench/rt3.png from the measured tables next to it (rt3_1e6.csv,
dt3_growth.csv, rt3_stages.csv, written by measure_rt3.py; docs/benchmarks.md's
"multithreaded 3D triangulation" section): 10^6 points per family and weight
range, the growth from 10^5 to 10^7 points with the fitted exponent, and a
whole run by stage.
Run: /usr/bin/python3 docs/bench/plot_rt3.py (python3-matplotlib)."""
from benchplot import growth, plt, rows, save, stages

fig, ax = plt.subplots(1, 3, figsize=(17, 4.8))
data = rows("rt3_1e6.csv")
w = 0.2
for k, p in enumerate(["flipflop:cpu", "cgal", "cgal:parallel", "qhull"]):
    xs = [i + (k - 1.5) * w for i, r in enumerate(data) if r[p]]
    ax[0].bar(xs, [float(r[p]) for r in data if r[p]], w, label=p)
ax[0].set_xticks(range(len(data)), [r["job"].replace(" ", "\n", 1) for r in data], fontsize=7)
ax[0].set_yscale("log")
ax[0].set_ylabel("seconds (median)")
ax[0].set_title("10^6 points, dt3 (rt3 and degenerate families: docs/performance/rt3.md)")
ax[0].legend(fontsize=7)

growth(ax[1], rows("dt3_growth.csv"),
       ["flipflop:cpu", "cgal:delaunay_triangulation_3", "cgal:delaunay_triangulation_3:parallel"], "cube, dt3")
stages(ax[2], rows("rt3_stages.csv"), lambda r: "%s %s" % (r["kind"], r["n"]), "a whole run from .npy by stage")

fig.suptitle("flipflop 3D regular / Delaunay triangulation (kernels_cpu/rt3, 2 cores) against CGAL and Qhull — "
             "identical outputs on random input")
save(fig, "rt3.png")
