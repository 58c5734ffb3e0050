#!/usr/bin/python3
"""docs/bench/hull2.png from the measured tables next to it (hull2_*.csv, the
docs/benchmarks.md's "multithreaded 2D hull" section): 10^7 points per distribution,
the circle-thickness sweep, and the growth from 10^5 to 10^8 disk points.
Run: /usr/bin/python3 docs/bench/plot_hull2.py (python3-matplotlib)."""
from benchplot import plt, rows, save

fig, ax = plt.subplots(1, 3, figsize=(15, 4.5))
peers = ["flipflop:cpu", "flipflop:reference:graham-insert", "qhull", "cgal:ch_akl_toussaint",
         "cgal:ch_graham_andrew"]
data = rows("hull2_1e7.csv")
w = 0.16
for k, p in enumerate(peers):
    ax[0].bar([i + (k - 2) * w for i in range(len(data))], [float(r[p]) for r in data], w, label=p)
ax[0].set_xticks(range(len(data)), [r["dist"] for r in data])
ax[0].set_ylabel("seconds (median of 3)")
ax[0].set_title("2D hull, 10^7 points")
ax[0].legend(fontsize=7)

t = rows("hull2_thickness.csv")
for p in ["flipflop:cpu", "qhull", "cgal:ch_akl_toussaint"]:
    ax[1].plot([float(r["thickness"]) for r in t], [float(r[p]) for r in t], "o-", label=p)
ax[1].set_xscale("log")
ax[1].set_xlabel("circle thickness")
ax[1].set_ylabel("seconds")
ax[1].set_title("circle-thickness sweep, 10^7 points")
ax[1].legend(fontsize=7)

g = rows("hull2_growth.csv")
for p in ["flipflop:cpu", "qhull"]:
    ax[2].loglog([int(r["n"]) for r in g], [float(r[p]) for r in g], "o-", label=p)
ax[2].set_xlabel("points (disk)")
ax[2].set_ylabel("seconds")
ax[2].set_title("growth: flipflop:cpu exponent 0.93 (10^6..10^8)")
ax[2].legend(fontsize=7)

fig.suptitle("flipflop 2D hull (kernels_cpu/hull2, 2 cores) against Qhull and CGAL — identical outputs")
save(fig, "hull2.png")
