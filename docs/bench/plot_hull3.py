#!/usr/bin/python3
"""docs/bench/hull3.png from the measured tables next to it (hull3_*.csv, written by
measure_hull3.py; the docs/benchmarks.md's "multithreaded 3D hull" section): 10^6 points per
distribution, the sphere-thickness sweep, the growth from 10^5 to 10^7 ball points
with its fitted exponent, and a whole run by stage.
Run: /usr/bin/python3 docs/bench/plot_hull3.py (python3-matplotlib)."""
from benchplot import growth, plt, rows, save, stages

fig, ax = plt.subplots(1, 4, figsize=(20, 4.6))
peers = ["flipflop:cpu", "flipflop:reference:ffhull", "qhull", "cgal:convex_hull_3"]
data = rows("hull3_1e6.csv")
w = 0.2
for k, p in enumerate(peers):
    ax[0].bar([i + (k - 1.5) * w for i in range(len(data))], [float(r[p]) for r in data], w, label=p)
ax[0].set_xticks(range(len(data)), [r["dist"] for r in data])
ax[0].set_ylabel("seconds (median of 3)")
ax[0].set_title("3D hull, 10^6 points")
ax[0].legend(fontsize=7)

t = rows("hull3_thickness.csv")
for p in ["flipflop:cpu", "qhull", "cgal:convex_hull_3"]:
    ax[1].plot([float(r["thickness"]) for r in t], [float(r[p]) for r in t], "o-", label=p)
ax[1].set_xscale("log")
ax[1].set_xlabel("sphere thickness")
ax[1].set_ylabel("seconds")
ax[1].set_title("sphere-thickness sweep, 10^6 points")
ax[1].legend(fontsize=7)

growth(ax[2], rows("hull3_growth.csv"), ["flipflop:cpu", "qhull"], "ball")
stages(ax[3], rows("hull3_stages.csv"), lambda r: r["n"], "a whole run from .npy by stage (ball)")

fig.suptitle("flipflop 3D hull (kernels_cpu/hull3, 2 cores) against Qhull and CGAL — identical outputs")
save(fig, "hull3.png")
