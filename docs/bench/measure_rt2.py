#!/usr/bin/python3
"""Measure the multithreaded 2D regular / Delaunay triangulation against its
peers and write the tables the docs/benchmarks.md's "multithreaded 2D triangulation"
section and docs/bench/rt2.png are drawn from.

usage: /usr/bin/python3 docs/bench/measure_rt2.py FLIPFLOP [--quick]

Each table comes from `flipflop bench rt2|dt2 ... --csv` (one process per
line, all rows of a line from one run, median of --reps runs, generation not
timed) and keeps the bench's `identical` verdict; a line whose outputs differ
stops the script. --quick: small sizes, one run (to check the script, not to
report). Writes rt2_1e6.csv, dt2_growth.csv and rt2_stages.csv next to this
file.
"""
import sys

from benchrun import Runner

quick = "--quick" in sys.argv
M = 1000 if quick else 1
R = Runner(sys.argv[1], "measure_rt2.py", "1" if quick else "3")
bench = R.bench
write = R.write


# rt2, 10^6 square points: the weight ranges of thesis §5.4 (about 99 %, a
# quarter and 1 % of the points non-redundant at this density), and dt2
n6 = 10**6 // M
lines = []
for whi in ["1e-7", "1e-5", "1e-3"]:
    rows = bench("rt2", ["--dist", "square", "--n", str(n6), "--weights", "0," + whi],
                 "flipflop:cpu,cgal:regular")
    t = {r["name"]: r["median_s"] for r in rows}
    lines.append(["rt2 w<=" + whi, t["flipflop:cpu"], t["cgal:regular_triangulation_2"], "", rows[0]["size"]])
rows = bench("dt2", ["--dist", "square", "--n", str(n6)], "flipflop:cpu,cgal,qhull")
t = {r["name"]: r["median_s"] for r in rows}
lines.append(["dt2", t["flipflop:cpu"], t["cgal:delaunay_triangulation_2"], t["qhull"], rows[0]["size"]])
write("rt2_1e6.csv", ["job", "flipflop:cpu", "cgal", "qhull", "triangles"], lines,
      "flipflop bench rt2|dt2 --dist square --n 1000000 --reps 3, seed 1, median seconds, compute only; "
      "cgal: Regular_triangulation_2 (rt2) or Delaunay_triangulation_2 (dt2)")

# dt2 growth 10^5..10^7 (Qhull at 10^7: one run, it takes minutes)
lines = []
for n in [10**5, 10**6, 10**7]:
    rows = bench("dt2", ["--dist", "square", "--n", str(n // M)], "flipflop:cpu,cgal")
    t = {r["name"]: r["median_s"] for r in rows}
    q = bench("dt2", ["--dist", "square", "--n", str(n // M)], "qhull", "1" if n == 10**7 else None)
    lines.append([n // M, t["flipflop:cpu"], t["cgal:delaunay_triangulation_2"], q[0]["median_s"], rows[0]["size"]])
write("dt2_growth.csv", ["n", "flipflop:cpu", "cgal:delaunay_triangulation_2", "qhull", "triangles"], lines,
      "dt2 square, median seconds of 3 (qhull at 10^7: one run)")

lines = []
for kind, n, extra in [("dt2", 10**6, []), ("dt2", 10**7, []), ("rt2", 10**6, ["--weights", "0,1e-5"])]:
    for r in R.stages(kind, ["--dist", "square", "--n", str(n // M)] + extra):
        lines.append([kind, n // M, r["stage"], r["median_s"]])
write("rt2_stages.csv", ["kind", "n", "stage", "median_s"], lines,
      "flipflop bench dt2|rt2 --stages --dist square: a whole run by stage (read, kernel stages, certify, write)")
