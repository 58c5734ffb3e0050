#!/usr/bin/env python3
"""fuzz/filter_sensitivity_keep.py [--inc FILE] LOG... — from the logs of
fuzz/filter_sensitivity.sh (or of the test binary run with
FLIPFLOP_SENSITIVITY_SEED), each bound and shape's closest input among the
lines "closer than the fixed set", as entries for
proptests/filter_sensitivity_kept.inc, with the ratio that run measured and the
factor kCaught can then list (the smallest power of two F with ratio * F > 1).

    python3 fuzz/filter_sensitivity_keep.py --inc proptests/filter_sensitivity_kept.inc \
        build/sensitivity-runs/*.log > /tmp/kept.inc && mv /tmp/kept.inc proptests/filter_sensitivity_kept.inc

With --inc, the file's own entries (their ratios read from the comment line
above each) compete too, and the whole merged file is printed, header
included: one entry per shape, the largest ratio. Then rerun the test and set
kCaught from the ratios it prints."""
import math
import re
import sys

ENUM = {"static": "static_bound", "semi-static": "semi_static", "permanent": "permanent", "dynamic": "dynamic",
        "dd a-priori": "dd_apriori", "dd running": "dd_running", "plane form": "plane_form", "dd wide": "dd_wide"}
SHAPE = re.compile(r"^sensitivity (.+?)\s+k=(\d) (plain|lifted)\s+(.*)$")
RATIO = re.compile(r"max \|det\|/bound among wrong signs ([0-9.eE+-]+)")
SEED = re.compile(r"seed (0x[0-9a-f]+)")


HEADER = """// proptests/filter_sensitivity_kept.inc — kKept of filter_sensitivity_test.cpp: inputs
// from longer runs with other seeds (fuzz/filter_sensitivity.sh), chosen by
// fuzz/filter_sensitivity_keep.py: per bound and shape the closest to the bound's
// edge, with the ratio and seed of the run that found it."""
KEPT = re.compile(r"^\s*// (.+?) k=(\d) (plain|lifted): ratio ([0-9.eE+-]+), caught at .* \(seed (\S+)\)$")
ENTRY = re.compile(r'^\s*\{Bound::\w+, \d, (?:true|false), "(.*)"\},$')


def read_inc(path, best):
    pending = None
    with open(path) as f:
        for line in f:
            m = KEPT.match(line.rstrip("\n"))
            if m:
                pending = ((m.group(1), int(m.group(2)), m.group(3) == "lifted"), float(m.group(4)), m.group(5))
                continue
            m = ENTRY.match(line.rstrip("\n"))
            if m and pending:
                key, r, seed = pending
                if key not in best or r > best[key][0]:
                    best[key] = (r, m.group(1), seed)
                pending = None


def main(paths):
    best = {}  # (bound, k, lifted) -> (ratio, text, seed)
    inc = None
    if paths and paths[0] == "--inc":
        inc, paths = paths[1], paths[2:]
        read_inc(inc, best)
        print(HEADER)
    for path in paths:
        seed, ratio = "?", {}
        with open(path) as f:
            for line in f:
                m = SEED.search(line)
                if m and line.startswith("filter sensitivity"):
                    seed = m.group(1)
                m = SHAPE.match(line.rstrip("\n"))
                if not m:
                    continue
                key = (m.group(1).strip(), int(m.group(2)), m.group(3) == "lifted")
                rest = m.group(4)
                r = RATIO.search(rest)
                if r:
                    ratio[key] = float(r.group(1))
                elif "closer than the fixed set" in rest and key in ratio:
                    text = rest.split("): ", 1)[1].strip()
                    if key not in best or ratio[key] > best[key][0]:
                        best[key] = (ratio[key], text, seed)
    for (name, k, lifted), (r, text, seed) in sorted(best.items()):
        f = 2.0 ** math.ceil(-math.log2(r))
        if r * f <= 1.0:
            f *= 2
        print(f"    // {name} k={k} {'lifted' if lifted else 'plain'}: ratio {r:.9g}, caught at {f:g}x (seed {seed})")
        print(f'    {{Bound::{ENUM[name]}, {k}, {"true" if lifted else "false"}, "{text}"}},')


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
