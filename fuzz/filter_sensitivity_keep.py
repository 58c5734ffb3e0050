#!/usr/bin/env python3
"""fuzz/filter_sensitivity_keep.py LOG... — from the logs of
fuzz/filter_sensitivity.sh (or of the test binary run with
FLIPFLOP_SENSITIVITY_SEED), each bound and shape's closest input among the
lines "closer than the fixed set", as entries for
proptests/filter_sensitivity_kept.inc, with the ratio that run measured and the
factor kCaught can then list (the smallest power of two F with ratio * F > 1).

    python3 fuzz/filter_sensitivity_keep.py build/sensitivity-runs/*.log

Prints the entries; paste the new ones into the .inc file (one per shape: an
entry for a shape that has one already replaces it when its ratio is larger),
rerun the test, and set kCaught from the ratios it prints."""
import math
import re
import sys

ENUM = {"static": "static_bound", "semi-static": "semi_static", "permanent": "permanent", "dynamic": "dynamic",
        "dd a-priori": "dd_apriori", "dd running": "dd_running", "plane form": "plane_form", "dd wide": "dd_wide"}
SHAPE = re.compile(r"^sensitivity (.+?)\s+k=(\d) (plain|lifted)\s+(.*)$")
RATIO = re.compile(r"max \|det\|/bound among wrong signs ([0-9.eE+-]+)")
SEED = re.compile(r"seed (0x[0-9a-f]+)")


def main(paths):
    best = {}  # (bound, k, lifted) -> (ratio, text, seed)
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
