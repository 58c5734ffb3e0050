#!/usr/bin/python3
"""Measure the multithreaded 3D hull against its peers and write the tables the
docs/benchmarks.md's "multithreaded 3D hull" section and docs/bench/hull3.png are drawn from.

usage: /usr/bin/python3 docs/bench/measure_hull3.py FLIPFLOP [--quick]

Each table comes from `flipflop bench hull3 ... --csv` (one process per line,
all rows of a line from one run, median of --reps runs, generation not timed)
and keeps the bench's `identical` verdict; a line whose outputs differ stops
the script. --quick: small sizes, one run (to check the script, not to
report). Writes hull3_1e6.csv, hull3_thickness.csv, hull3_growth.csv and
hull3_stages.csv next to this file.
"""
import sys

from benchrun import Runner

quick = "--quick" in sys.argv
M = 1000 if quick else 1
R = Runner(sys.argv[1], "measure_hull3.py", "1" if quick else "3")
bench = lambda args, run: R.bench("hull3", args, run)
write = R.write


peers = "flipflop:cpu,flipflop:reference:ffhull,qhull,cgal"
cols = ["flipflop:cpu", "flipflop:reference:ffhull", "qhull", "cgal:convex_hull_3"]
lines = []
for dist in (["cube"], ["ball"], ["box", "--thickness", "0.01"], ["sphere", "--thickness", "0.01"]):
    rows = bench(["--dist"] + dist + ["--n", str(10**6 // M)], peers)
    t = {r["name"]: r["median_s"] for r in rows}
    lines.append([" ".join(dist).replace(" --thickness ", " ")] + [t[c] for c in cols] + [rows[0]["size"]])
write("hull3_1e6.csv", ["dist"] + cols + ["triangles"], lines,
      "flipflop bench hull3 --dist D --n 1000000 --reps 3, seed 1, median seconds, compute only")

lines = []
for th in ["0.5", "0.1", "0.01", "0.001", "0.0001"]:
    rows = bench(["--dist", "sphere", "--thickness", th, "--n", str(10**6 // M)], "flipflop:cpu,qhull,cgal")
    t = {r["name"]: r["median_s"] for r in rows}
    lines.append([th, t["flipflop:cpu"], t["qhull"], t["cgal:convex_hull_3"], rows[0]["size"]])
write("hull3_thickness.csv", ["thickness", "flipflop:cpu", "qhull", "cgal:convex_hull_3", "triangles"], lines,
      "sphere-thickness sweep (thesis §6.5), n = 10^6, median seconds of 3")

lines = []
for n in [10**5, 10**6, 10**7]:
    rows = bench(["--dist", "ball", "--n", str(n // M)], "flipflop:cpu,qhull")
    t = {r["name"]: r["median_s"] for r in rows}
    lines.append([n // M, t["flipflop:cpu"], t["qhull"], rows[0]["size"]])
write("hull3_growth.csv", ["n", "flipflop:cpu", "qhull", "triangles"], lines, "ball, median seconds of 3")

lines = []
for n in [10**6, 10**7]:
    for r in R.stages("hull3", ["--dist", "ball", "--n", str(n // M)]):
        lines.append([n // M, r["stage"], r["median_s"]])
write("hull3_stages.csv", ["n", "stage", "median_s"], lines,
      "flipflop bench hull3 --stages --dist ball: a whole run by stage (read, kernel stages, certify, write)")
print("wrote hull3_1e6.csv hull3_thickness.csv hull3_growth.csv hull3_stages.csv")
