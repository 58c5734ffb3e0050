"""Instructions per input point of issue 40's five rows (measure_margins.py), counted by valgrind:
    build/python-venv/bin/python docs/bench/count_instructions.py

A count does not depend on the machine's speed, cache sizes or load, so a change in it is visible on
any machine where the times are not comparable. Everything runs on one core (`taskset -c 0`: TBB
then starts no second worker and no instruction is spent waiting; the timed runs use both cores for
the same work). What each row counts — the work its time measures:

1. `bench hull3 --dist ball` 10^6: `cpu::hull3_ffhull` (the bench row's timed call) alone
   (callgrind, --toggle-collect), input generation excluded
2. the same with `--dist sphere`
3. the whole process `flipflop hull3 ball.xyz -o out.txt` (cachegrind --cache-sim=no: every
   instruction of the process, start-up, text reading and writing included)
4. `bench instant-flip --dim 3 --n 100000 --step 0.01`: the first call of
   `DynamicRegularTriangulation::set_weights` (the timed update; the bench's untimed restore after
   it is the second call), between a --dump-before and a --dump-after
5. Python `flipflop.ConvexHull` of 10^6 uniform cube points: the process that makes the points and
   calls it, less the same process without the call (cachegrind, both whole)

Prints one line per row; nothing is asserted. Takes about 7 minutes (valgrind runs about 50x slower)."""
import glob
import os
import re
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(os.path.dirname(here))
FLIPFLOP = os.environ.get("FLIPFLOP_BIN", os.path.join(root, "build", "flipflop"))  # another binary to compare
ONE_CORE = ["taskset", "-c", "0"]


def collected(cmd, tool, extra, tmp):
    """Instructions valgrind counted for cmd: callgrind's first profile part (the whole run, or the
    part a --toggle-collect or a --dump-before/--dump-after cuts), or cachegrind's whole-process
    total"""
    for f in glob.glob(os.path.join(tmp, "vg.*")):
        os.remove(f)
    out = os.path.join(tmp, "vg.%p")
    opt = ["--callgrind-out-file=" + out] if tool == "callgrind" else ["--cachegrind-out-file=" + out, "--cache-sim=no"]
    r = subprocess.run(ONE_CORE + ["valgrind", "--tool=" + tool] + opt + extra + cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("count_instructions.py: %s failed:\n%s" % (" ".join(cmd), r.stderr[-2000:]))
    if tool == "cachegrind":
        m = re.search(r"I\s+refs:\s+([\d,]+)", r.stderr)
        return int(m.group(1).replace(",", ""))
    # vg.PID alone, or with dumps vg.PID.1, vg.PID.2, ... and vg.PID the part after the last dump
    files = glob.glob(os.path.join(tmp, "vg.*"))
    first = [f for f in files if f.endswith(".1")] or files
    with open(first[0]) as f:
        for line in f:
            if line.startswith("summary:") or line.startswith("totals:"):
                return int(line.split()[1])
    sys.exit("count_instructions.py: no total in " + first[0])


def main():
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        n = 1_000_000
        for dist in ("ball", "sphere"):
            ir = collected([FLIPFLOP, "bench", "hull3", "--dist", dist, "--n", str(n), "--reps", "1", "--run",
                            "flipflop:cpu$"], "callgrind", ["--toggle-collect=flipflop::cpu::hull3_ffhull*"], tmp)
            rows.append(("bench hull3 --dist %s 10^6: cpu::hull3_ffhull" % dist, ir, n))
        xyz = os.path.join(tmp, "ball.xyz")
        subprocess.run([FLIPFLOP, "gen", "ball", str(n), "--seed", "1", "-o", xyz], check=True, capture_output=True)
        ir = collected([FLIPFLOP, "hull3", xyz, "-o", os.path.join(tmp, "out.txt")], "cachegrind", [], tmp)
        rows.append(("whole process flipflop hull3 ball.xyz -o out.txt", ir, n))
        # callgrind 3.19 ignores --dump-before/--dump-after while a --toggle-collect is set: the
        # update is the first part of a run dumped after its first call less the first part of a
        # run dumped before it (one-core runs count the same instructions to within a few)
        fn = "flipflop::ref::DynamicRegularTriangulation::set_weights*"
        cmd = [FLIPFLOP, "bench", "instant-flip", "--dim", "3", "--n", "100000", "--step", "0.01", "--reps", "1",
               "--run", "flipflop:instant-flip"]
        ir = collected(cmd, "callgrind", ["--dump-after=" + fn], tmp) - collected(cmd, "callgrind", ["--dump-before=" + fn], tmp)
        rows.append(("bench instant-flip --dim 3 10^5 step 0.01: the update", ir, 100_000))
        script = ("import numpy as np\nimport flipflop\n"
                  "cube = np.random.default_rng(1).random((1_000_000, 3))\n%s")
        with_call = collected([sys.executable, "-c", script % "flipflop.ConvexHull(cube)"], "cachegrind", [], tmp)
        without = collected([sys.executable, "-c", script % "pass"], "cachegrind", [], tmp)
        rows.append(("Python flipflop.ConvexHull 10^6 cube", with_call - without, n))
    for name, ir, pts in rows:
        print("%-58s %14d instructions = %7.1f per point" % (name, ir, ir / pts))


if __name__ == "__main__":
    main()
