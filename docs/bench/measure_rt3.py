#!/usr/bin/python3
"""Measure the multithreaded 3D regular / Delaunay triangulation against its
peers and write the tables the docs/benchmarks.md's "multithreaded 3D triangulation"
section and docs/bench/rt3.png are drawn from.

usage: /usr/bin/python3 docs/bench/measure_rt3.py FLIPFLOP [--quick]

Each table comes from `flipflop bench rt3|dt3 ... --csv` (one process per
line, all rows of a line from one run, median of --reps runs, generation not
timed). On the random families the bench's `identical` verdict must hold for
every row (the script stops otherwise); on the degenerate ones (grid3,
sphere-lattice, planes3) the peers break ties their own way and only
flipflop's rows are compared. --quick: small sizes, one run (to check the
script, not to report). Writes rt3_1e6.csv, dt3_growth.csv and rt3_stages.csv
next to this file.
"""
import sys

from benchrun import Runner

quick = "--quick" in sys.argv
M = 1000 if quick else 1
R = Runner(sys.argv[1], "measure_rt3.py", "1" if quick else "3")
bench = R.bench
write = R.write
n6 = 10**6 // M

CGAL_D = "cgal:delaunay_triangulation_3"
CGAL_R = "cgal:regular_triangulation_3"


def med(rows, name):
    return next((r["median_s"] for r in rows if r["name"] == name), "")


# 10^6 points: dt3 on the random families (with Qhull), rt3 in three weight
# ranges, dt3 on the degenerate families (one run each)
lines = []
for dist in ["cube", "ball"]:
    rows = bench("dt3", ["--dist", dist, "--n", str(n6)], "flipflop:cpu,%s,qhull" % CGAL_D)
    lines.append(["dt3 " + dist, med(rows, "flipflop:cpu"), med(rows, CGAL_D), med(rows, CGAL_D + ":parallel"),
                  med(rows, "qhull"), rows[0]["size"]])
for whi in ["1e-4", "1e-3", "1e-2"]:
    rows = bench("rt3", ["--dist", "cube", "--n", str(n6), "--weights", "0," + whi], "flipflop:cpu," + CGAL_R)
    lines.append(["rt3 cube w<=" + whi, med(rows, "flipflop:cpu"), med(rows, CGAL_R), med(rows, CGAL_R + ":parallel"),
                  "", rows[0]["size"]])
for dist in ["grid3", "sphere-lattice", "planes3"]:
    rows = bench("dt3", ["--dist", dist, "--n", str(n6)], "flipflop:cpu,%s" % CGAL_D, "1", identical=False)
    lines.append(["dt3 " + dist, med(rows, "flipflop:cpu"), med(rows, CGAL_D), med(rows, CGAL_D + ":parallel"), "",
                  rows[0]["size"]])
write("rt3_1e6.csv", ["job", "flipflop:cpu", "cgal", "cgal:parallel", "qhull", "tetrahedra"], lines,
      "flipflop bench dt3|rt3 --n 1000000 --reps 3 (degenerate families: 1 run), median seconds, compute only; "
      "cgal: Delaunay_triangulation_3 (dt3) or Regular_triangulation_3 (rt3), :parallel with Parallel_tag on 2 threads")

# dt3 growth 10^5..10^7, median of 3 at every size: the first run of a row
# in a process touches its memory for the first time, which on the
# development VM costs the host's page backing (0.5-0.7 GB/s against 3 GB/s
# for memory the process touched before; at 10^7 flipflop's first run took
# 39.5 s, the next two 23.9 and 25.0 s), so one run measures the row order
lines = []
for n in [10**5, 10**6, 10**7]:
    rows = bench("dt3", ["--dist", "cube", "--n", str(n // M)], "flipflop:cpu," + CGAL_D)
    lines.append([n // M, med(rows, "flipflop:cpu"), med(rows, CGAL_D), med(rows, CGAL_D + ":parallel"),
                  rows[0]["size"]])
write("dt3_growth.csv", ["n", "flipflop:cpu", CGAL_D, CGAL_D + ":parallel", "tetrahedra"], lines,
      "dt3 cube, median seconds of 3")

lines = []
for kind, n, extra in [("dt3", 10**6, ["--dist", "ball"]), ("rt3", 10**6, ["--dist", "cube", "--weights", "0,1e-3"])]:
    for r in R.stages(kind, ["--n", str(n // M)] + extra):
        lines.append([kind, n // M, r["stage"], r["median_s"]])
write("rt3_stages.csv", ["kind", "n", "stage", "median_s"], lines,
      "flipflop bench dt3|rt3 --stages: a whole run by stage (read, kernel stages, certify, write)")
