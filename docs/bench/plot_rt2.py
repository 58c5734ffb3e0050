#!/usr/bin/python3
"""docs/bench/rt2.png from the measured tables next to it (rt2_1e6.csv,
dt2_growth.csv, rt2_stages.csv, written by measure_rt2.py; docs/benchmarks.md's
"multithreaded 2D triangulation" section): 10^6 points per weight range and
unweighted, the growth from 10^5 to 10^7 points with the fitted exponent, and
a whole run by stage.
Run: /usr/bin/python3 docs/bench/plot_rt2.py (python3-matplotlib)."""
from benchplot import growth, plt, rows, save, stages

fig, ax = plt.subplots(1, 3, figsize=(16, 4.6))
data = rows("rt2_1e6.csv")
w = 0.27
for k, p in enumerate(["flipflop:cpu", "cgal", "qhull"]):
    xs = [i + (k - 1) * w for i, r in enumerate(data) if r[p]]
    ax[0].bar(xs, [float(r[p]) for r in data if r[p]], w, label=p)
ax[0].set_xticks(range(len(data)), [r["job"] for r in data], fontsize=8)
ax[0].set_yscale("log")
ax[0].set_ylabel("seconds (median of 3)")
ax[0].set_title("10^6 square points: rt2 per weight range, dt2")
ax[0].legend(fontsize=7)

growth(ax[1], rows("dt2_growth.csv"), ["flipflop:cpu", "cgal:delaunay_triangulation_2", "qhull"], "square, dt2")
stages(ax[2], rows("rt2_stages.csv"), lambda r: "%s %s" % (r["kind"], r["n"]), "a whole run from .npy by stage")

fig.suptitle("flipflop 2D regular / Delaunay triangulation (kernels_cpu/rt2, 2 cores) against CGAL and Qhull — identical outputs")
save(fig, "rt2.png")
