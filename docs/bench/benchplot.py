"""Shared by plot_hull2.py, plot_hull3.py and plot_rt2.py: the measured CSV
tables next to this file (lines starting with '#' are notes), a matplotlib
without a display, the growth and the time-by-stage panels."""
import csv
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the backend)

here = os.path.dirname(os.path.abspath(__file__))


def rows(name):
    with open(os.path.join(here, name)) as f:
        return list(csv.DictReader(l for l in f if not l.startswith("#")))


def save(fig, name):
    fig.tight_layout()
    fig.savefig(os.path.join(here, name), dpi=90)


def growth(ax, g, peers, what):
    """log-log time against n for each peer; the title gives flipflop:cpu's
    exponent between the two largest sizes."""
    n = [int(r["n"]) for r in g]
    for p in peers:
        ax.loglog(n, [float(r[p]) for r in g], "o-", label=p)
    cpu = [float(r["flipflop:cpu"]) for r in g]
    slope = math.log(cpu[-1] / cpu[-2]) / math.log(n[-1] / n[-2])
    ax.set_xlabel("points (%s)" % what)
    ax.set_ylabel("seconds")
    ax.set_title("growth: flipflop:cpu exponent %.2f (%.0e..%.0e)" % (slope, n[-2], n[-1]))
    ax.legend(fontsize=7)


def stages(ax, s, key, title):
    """one stacked bar per job (key(row) names it) of its stages' medians,
    leaving out the totals, the .xyz reader and what the total leaves out
    (hull3's witness-free certification, timed beside the witnessed one)."""
    s = [r for r in s if r["stage"] not in ("total (.npy)", "read .xyz") and "not in the total" not in r["stage"]]
    jobs = []
    for r in s:
        if key(r) not in jobs:
            jobs.append(key(r))
    names = [r["stage"] for r in s if key(r) == jobs[0]]
    bottom = [0.0] * len(jobs)
    for name in names:
        v = [float(next(r["median_s"] for r in s if key(r) == j and r["stage"] == name)) for j in jobs]
        ax.bar(jobs, v, bottom=bottom, label=name.replace("compute: ", ""))
        bottom = [b + x for b, x in zip(bottom, v)]
    ax.set_ylabel("seconds (median of 3)")
    ax.set_title(title)
    ax.legend(fontsize=7)
