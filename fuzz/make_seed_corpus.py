#!/usr/bin/env python3
"""Writes the seed corpus of fuzz_predicates (fuzz/corpus/predicates/).

Byte layout: see fuzz/predicates_check.cpp. Spec indices: 0 orient2d,
1 orient3d, 2 power2d, 3 power3d, 4..8 orient_d(2..6), 9..12 power_d(2..5).
Encodings: 0 raw binary64, 1 int8, 2 int8 scaled by 2^(8s | 4s), 3 table.
Mostly degenerate configurations: collinear, coplanar, cocircular,
cospherical, lifted points on a plane, duplicates, all points equal.
Run from the repository root: python3 fuzz/make_seed_corpus.py
"""
import math
import os
import struct

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "predicates")


def header(spec, encoding, ids, raw_ids=False, scale=0):
    flags = encoding | (4 if raw_ids else 0)
    return bytes([spec, flags, scale & 0xFF]) + bytes(ids)


def f64(values):
    return b"".join(struct.pack("<d", v) for v in values)


def i8(values):
    return b"".join(struct.pack("<b", v) for v in values)


def flat(points):
    return [c for p in points for c in p]


def next_up(x):
    return math.nextafter(x, math.inf)


SEEDS = {
    # orient2d: collinear (raw doubles), near-collinear decimals, identical points
    "orient2d_collinear": header(0, 0, [0, 1, 2]) + f64(flat([(0, 0), (1, 1), (2, 2)])),
    "orient2d_decimals": header(0, 0, [2, 0, 1]) + f64(flat([(0.1, 0.1), (0.2, 0.2), (0.3, 0.3)])),
    "orient2d_one_ulp": header(0, 0, [0, 1, 2]) + f64(flat([(1, 1), (2, 2), (3, next_up(3.0))])),
    "orient2d_identical": header(0, 1, [5, 3, 9]) + i8(flat([(7, -3)] * 3)),
    "orient2d_repeated_id": header(0, 1, [4, 4, 7], raw_ids=True) + i8(flat([(1, 2), (1, 2), (3, 3)])),
    # orient3d: coplanar square
    "orient3d_coplanar": header(1, 1, [0, 1, 2, 3]) + i8(flat([(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)])),
    # power2d: lattice points on x^2 + y^2 = 25; lifted points on a plane
    "power2d_cocircular": header(2, 1, [3, 1, 0, 2]) + i8(flat([(3, 4), (-3, 4), (5, 0), (0, -5)]) + [0, 0, 0, 0]),
    "power2d_lifted_plane": header(2, 1, [0, 1, 2, 3])
    + i8(flat([(0, 0), (2, 1), (-1, 3), (3, -2)]) + [x * x + y * y - x - 2 * y - 3 for x, y in [(0, 0), (2, 1), (-1, 3), (3, -2)]]),
    # power3d: lattice points on x^2 + y^2 + z^2 = 9, plain and scaled to 2^-512 (weights 2^-1024)
    "power3d_cospherical": header(3, 1, [0, 1, 2, 3, 4])
    + i8(flat([(1, 2, 2), (2, 1, 2), (2, 2, 1), (3, 0, 0), (0, 0, -3)]) + [0] * 5),
    "power3d_cospherical_tiny": header(3, 2, [4, 3, 2, 1, 0], scale=-128)
    + i8(flat([(1, 2, 2), (2, 1, 2), (2, 2, 1), (3, 0, 0), (0, 0, -3)]) + [1] * 5),
    # orient_d(6): a short input, every point at the origin
    "orient_d6_all_zero": bytes([8]),
    # orient_d(4): points on a line, scaled to 2^1016
    "orient_d4_line_huge": header(5 + 1, 2, [0, 1, 2, 3, 4], scale=127)
    + i8(flat([(t, 2 * t, -t, 3) for t in (-2, -1, 0, 1, 2)])),
    # orient_d(5): a hyperplane x5 = 0 in raw doubles, one value nudged by an ulp
    "orient_d5_hyperplane_ulp": header(7, 0, [5, 4, 3, 2, 1, 0])
    + f64(flat([(0.5, 0.25, 1, 2, 0), (1, 0, 0, 0, 0), (0, 1, 0, 0, 0), (0, 0, 1, 0, 0), (0, 0, 0, 1, 0), (1, 1, 1, 1, 5e-324)])),
    # power_d(4): lattice points on |x|^2 = 9 in R^4
    "power_d4_cospherical": header(11, 1, [0, 1, 2, 3, 4, 5])
    + i8(flat([(3, 0, 0, 0), (0, 3, 0, 0), (0, 0, 3, 0), (0, 0, 0, 3), (2, 2, 1, 0), (1, 2, 2, 0)]) + [0] * 6),
    # power_d(5): duplicated points with equal weights
    "power_d5_duplicates": header(12, 1, [6, 5, 4, 3, 2, 1, 0])
    + i8(flat([(1, 2, 3, 4, 5)] * 4 + [(0, 0, 0, 0, 0)] * 3) + [2] * 7),
    # extreme magnitudes from the table (encoding 3)
    "orient3d_extreme": header(1, 3, [0, 1, 2, 3]) + bytes([1, 11, 27, 10, 4, 2, 0, 17, 11, 12, 26, 6]),
    "power_d3_extreme": header(10, 3, [1, 0, 3, 2, 4]) + bytes([11, 1, 10, 27, 4, 2, 3, 19, 0, 6, 7, 8, 9, 10, 11, 0, 0, 1, 1, 11]),
}


def main():
    os.makedirs(OUT, exist_ok=True)
    for name, data in sorted(SEEDS.items()):
        with open(os.path.join(OUT, name + ".bin"), "wb") as f:
            f.write(data)
    print(f"wrote {len(SEEDS)} seeds to {OUT}")


if __name__ == "__main__":
    main()
