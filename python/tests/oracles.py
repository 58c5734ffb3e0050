"""Exact oracles shared by the Python tests: plain Fractions, no flipflop code."""
from fractions import Fraction


def exact_centre(pts, w=None):
    """The exact circumcentre (power centre with weights) of d + 1 points, as
    Fractions; None when they span no volume. Gaussian elimination in
    Fractions on 2 (p_k - p_0) . c = |p_k|^2 - |p_0|^2 - w_k + w_0."""
    d = len(pts[0])
    P = [[Fraction(float(x)) for x in p] for p in pts]
    W = [Fraction(0)] * (d + 1) if w is None else [Fraction(float(x)) for x in w]
    A = [[2 * (P[k][l] - P[0][l]) for l in range(d)] + [sum(x * x for x in P[k]) - sum(x * x for x in P[0])
                                                           - W[k] + W[0]] for k in range(1, d + 1)]
    for c in range(d):
        piv = next((r for r in range(c, d) if A[r][c] != 0), None)
        if piv is None:
            return None
        A[c], A[piv] = A[piv], A[c]
        for r in range(d):
            if r != c and A[r][c] != 0:
                f = A[r][c] / A[c][c]
                A[r] = [a - f * b for a, b in zip(A[r], A[c])]
    return [A[c][d] / A[c][c] for c in range(d)]
