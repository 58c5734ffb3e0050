"""The lattice inputs of issue 39's Python benchmarks (measure_scipy_rows.py,
measure_scipy_matrix.py)."""
import itertools

import numpy as np


def grid(k, d):
    """The integer grid {0..k-1}^d, float64, in lexicographic order."""
    return np.array(list(itertools.product(range(k), repeat=d)), dtype=float)


def perturbed(p, seed=7):
    """p with 20 % of its points (seeded) moved by 2 ulp per coordinate, each
    coordinate stepped twice by np.nextafter in a random direction (a moved 0
    becomes a subnormal)."""
    p = p.copy()
    rng = np.random.default_rng(seed)
    moved = rng.choice(len(p), len(p) // 5, replace=False)
    for i in moved:
        for j in range(p.shape[1]):
            to = np.inf if rng.random() < 0.5 else -np.inf
            p[i, j] = np.nextafter(np.nextafter(p[i, j], to), to)
    return p
