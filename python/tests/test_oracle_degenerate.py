"""The Python bindings on small DEGENERATE inputs against an independent oracle.

test_flipflop.py compares random input with scipy and degenerate input with
flipflop's own command line (the same library). Here the bindings' answers on
degenerate sets -- integer grids, cocircular and cospherical integer points,
collinear and coplanar subsets, exact duplicates, equal and lattice weights,
weights that put every lifted point on one hyperplane -- are compared with the
brute force of proptests/support/sos_brute.hpp, which decides every answer by
its definition with the Simulation-of-Simplicity oracle of
proptests/support/sos_oracle.hpp alone (GMP on the perturbed determinants
expanded term by term; no code of predicates/, reference/ or the canonical-form
headers). The brute force runs as the test-support program oracle_brute_cli
(proptests/oracle_brute_cli.cpp), whose path comes in the environment variable
FLIPFLOP_ORACLE_BRUTE (set by the ctest entry "oracle: python bindings on
degenerate input vs brute force"). Set but missing: the tests fail. Unset (a
hand-run pytest): they are skipped.

Compared, with the canonical form of DESIGN.md "Canonical output" that both
sides claim: ConvexHull 2D (vertices: the counter-clockwise cycle from the
smallest index; simplices: its edges (i, next)), ConvexHull 3D (simplices:
ccw seen from outside, smallest first, rows sorted; vertices), Delaunay
d = 2..9 unweighted and weighted (6D..9D: five small sets, weighted in 6D) (simplices: positively oriented, smallest
first, the rest ascending with the last two swapped for an odd permutation,
rows sorted; redundant), byte for byte (the same integer arrays), for every
backend the bindings offer in that dimension ('cpu', 'reference', and the
GPU backends this build has, flipflop.gpu_backends). 2D/3D sets are
triangulated with 6 weightings each (none, equal, lattice, |x|^2, |x|^2 +
a.x + b, one point made redundant), 4D/5D sets with fewer. The last tests
plant errors in the brute force's answer and require the comparison to
report them, and show the sets are degenerate where it matters: the brute
force on the same points in another order (the perturbation's order)
gives an answer the comparison tells apart. About 2 s.
"""

import os
import subprocess
import tempfile
from fractions import Fraction

import numpy as np
import pytest

import flipflop

_ENV = "FLIPFLOP_ORACLE_BRUTE"


def _brute_path():
    path = os.environ.get(_ENV)
    if not path:
        pytest.skip(f"{_ENV} is not set (the ctest entry 'oracle: python bindings on degenerate input vs "
                    "brute force' sets it)")
    assert os.path.isfile(path) and os.access(path, os.X_OK), \
        f"{_ENV}={path}: the brute-force program is missing (build the target oracle_brute_cli)"
    return path


def brute(kind, points, weights=None):
    """The brute force's canonical answer: hull2 -> the vertex cycle (list);
    hull3 -> (m, 3) facets; dt/rt -> ((m, d+1) simplices, redundant)."""
    points = np.asarray(points, dtype=np.float64)
    rows = points if weights is None else np.column_stack([points, np.asarray(weights, dtype=np.float64)])
    with tempfile.NamedTemporaryFile("w", suffix=".xyz", delete=False) as f:
        for r in rows:
            f.write(" ".join(float(v).hex() for v in r) + "\n")  # exact
        name = f.name
    try:
        run = subprocess.run([_brute_path(), kind, name], capture_output=True, text=True, timeout=120)
    finally:
        os.unlink(name)
    assert run.returncode == 0, f"oracle_brute_cli {kind}: exit {run.returncode}: {run.stderr.strip()}"
    lines = run.stdout.splitlines()
    if kind == "hull2":
        return [int(x) for x in lines]
    if kind == "hull3":
        return np.array([[int(x) for x in ln.split()] for ln in lines], dtype=np.int64).reshape(-1, 3)
    assert lines and lines[-1].startswith("redundant:"), run.stdout
    d = points.shape[1]
    simplices = np.array([[int(x) for x in ln.split()] for ln in lines[:-1]], dtype=np.int64).reshape(-1, d + 1)
    redundant = np.array([int(x) for x in lines[-1].split()[1:]], dtype=np.int64)
    return simplices, redundant


def differences(got, want):
    """The differences between two integer answers (arrays or lists): [] when
    they are identical, else lines naming what differs (rows only in one)."""
    g = np.asarray(got, dtype=np.int64)
    w = np.asarray(want, dtype=np.int64)
    if g.shape == w.shape and np.array_equal(g, w):
        return []
    out = [f"shape {g.shape} vs {w.shape}"] if g.shape != w.shape else []
    if g.ndim == 2 and w.ndim == 2:
        gs = {tuple(r) for r in g.tolist()}
        ws = {tuple(r) for r in w.tolist()}
        out += [f"only in the bindings' answer: {sorted(gs - ws)}", f"only in the brute force's: {sorted(ws - gs)}"]
        if gs == ws:
            out.append("the same rows in another order")
    else:
        out.append(f"{g.tolist()} vs {w.tolist()}")
    return out


def hull2_differences(hull, cycle):
    edges = [[cycle[i], cycle[(i + 1) % len(cycle)]] for i in range(len(cycle))]
    return (["vertices: " + s for s in differences(hull.vertices, cycle)] +
            ["simplices: " + s for s in differences(hull.simplices, np.array(edges).reshape(-1, 2))])


def hull3_differences(hull, facets):
    return (["simplices: " + s for s in differences(hull.simplices, facets)] +
            ["vertices: " + s for s in differences(hull.vertices, np.unique(facets))])


def rt_differences(tri, answer):
    simplices, redundant = answer
    return (["simplices: " + s for s in differences(tri.simplices, simplices)] +
            ["redundant: " + s for s in differences(np.sort(tri.redundant), redundant)])


# ---- the degenerate sets (at most 12 points) --------------------------------------------

def _grid(*sizes):
    axes = [np.arange(s, dtype=np.float64) for s in sizes]
    return np.array(np.meshgrid(*axes, indexing="ij")).reshape(len(sizes), -1).T.copy()


def _shuffled(a, seed):
    return a[np.random.default_rng(seed).permutation(len(a))]


def _circle25():
    """The 12 integer points of x^2 + y^2 = 25."""
    pts = [(5, 0), (-5, 0), (0, 5), (0, -5)] + [(sx * a, sy * b) for a, b in ((3, 4), (4, 3))
                                                for sx in (1, -1) for sy in (1, -1)]
    return np.array(pts, dtype=np.float64)


def _sphere9():
    """12 integer points of x^2 + y^2 + z^2 = 9: the six axis points, six of (1, 2, 2)."""
    pts = [(3, 0, 0), (-3, 0, 0), (0, 3, 0), (0, -3, 0), (0, 0, 3), (0, 0, -3),
           (1, 2, 2), (-1, 2, -2), (2, -1, 2), (-2, -2, 1), (2, 2, -1), (-2, 1, -2)]
    return np.array(pts, dtype=np.float64)


def _cross_polytope(d):
    e = np.eye(d)
    return np.concatenate([e, -e])


SETS2 = {
    "grid 3x3": _grid(3, 3),
    "grid 4x3 shuffled": _shuffled(_grid(4, 3), 1),
    "grid 3x3 times 2^-40": np.ldexp(_grid(3, 3), -40),
    "grid 3x3 times 2^40, shifted": np.ldexp(_grid(3, 3), 40) + 2.0 ** 41,
    "cocircular 12 (x^2+y^2=25)": _circle25(),
    "cocircular 12 shuffled": _shuffled(_circle25(), 2),
    "square with points on its edges and centre": np.array(
        [[0, 0], [2, 0], [2, 2], [0, 2], [1, 0], [2, 1], [1, 2], [0, 1], [1, 1]], dtype=np.float64),
    "collinear 5 and one off the line": np.array([[0, 0], [1, 1], [2, 2], [3, 3], [4, 4], [0, 4]], dtype=np.float64),
    "duplicates: square, a corner and the centre twice": np.array(
        [[0, 0], [1, 0], [1, 1], [0, 1], [0, 0], [0.5, 0.5], [0.5, 0.5], [1, 1]], dtype=np.float64),
    "the same point three times and a triangle": np.array(
        [[1, 1], [1, 1], [0, 0], [1, 1], [3, 0], [0, 3]], dtype=np.float64),
}

SETS3 = {
    "cube 2x2x2": _grid(2, 2, 2),
    "cube and centre": np.concatenate([_grid(2, 2, 2) * 2, [[1, 1, 1]]]),
    "grid 3x2x2 shuffled": _shuffled(_grid(3, 2, 2), 3),
    "cospherical 12 (x^2+y^2+z^2=9)": _sphere9(),
    "octahedron and centre": np.concatenate([_cross_polytope(3), [[0, 0, 0]]]),
    "coplanar 3x3 grid with two apexes": np.concatenate(
        [np.column_stack([_grid(3, 3), np.zeros(9)]), [[1, 1, 2], [1, 1, -1]]]),
    "cube times 2^-40 with duplicates": np.ldexp(np.concatenate([_grid(2, 2, 2), [[0, 0, 0], [1, 1, 1]]]), -40),
    "collinear 4 on an edge of a tetrahedron": np.array(
        [[0, 0, 0], [3, 0, 0], [0, 3, 0], [0, 0, 3], [1, 0, 0], [2, 0, 0]], dtype=np.float64),
}

SETS4 = {
    "cross-polytope 4D and centre": np.concatenate([_cross_polytope(4), np.zeros((1, 4))]),
    "0/1 points of the 4-cube (10)": np.array(
        [[0, 0, 0, 0], [1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1], [1, 1, 0, 0], [0, 0, 1, 1],
         [1, 0, 1, 0], [0, 1, 0, 1], [1, 1, 1, 1]], dtype=np.float64),
}

SETS5 = {
    "cross-polytope 5D": _cross_polytope(5),
    "simplex corners, centre twice, cube corner": np.concatenate(
        [np.zeros((1, 5)), np.eye(5), [[0.5] * 5, [0.5] * 5, [1, 1, 0, 0, 0]]]),
}


def _weight_variants(points, seed):
    """Degenerate weightings: equal, small-integer lattice, |x|^2 (every lifted
    height 0: all lifted points on one hyperplane), |x|^2 + a.x + b
    (another hyperplane), and a lattice with one point made redundant."""
    n, d = points.shape
    rng = np.random.default_rng(seed)
    sq = (points ** 2).sum(axis=1)
    a = rng.integers(-2, 3, size=d).astype(np.float64)
    lattice = rng.integers(0, 3, size=n).astype(np.float64)
    pulled = lattice.copy()
    pulled[n // 2] = -100.0 * (1.0 + float(np.abs(points).max()) ** 2)  # far below: redundant
    return {
        "equal weights": np.full(n, 0.75),
        "lattice weights 0..2": lattice,
        "weights |x|^2": sq,
        "weights |x|^2 + a.x + b": sq + points @ a + 3.0,
        "lattice weights, one point redundant": pulled,
    }


def _cases(sets, seed):
    for name, pts in sets.items():
        yield name, pts, None
        for wname, w in _weight_variants(pts, seed).items():
            yield f"{name}, {wname}", pts, w


def _ids(cases):
    return [c[0] for c in cases]


CASES2 = list(_cases(SETS2, 10))
CASES3 = list(_cases(SETS3, 11))
CASES45 = list(_cases(SETS4, 12)) + [(n, p, w) for n, p, w in _cases(SETS5, 13) if w is None or "equal" in n
                                     or "lattice weights 0" in n]


def _corners_and_centre(d, twice):
    """The standard simplex's corners, its centre (twice: a duplicate), a
    corner of the unit cube: cospherical subsets and a point on a face."""
    centre = [[0.5] * d] * (2 if twice else 1)
    return np.concatenate([np.zeros((1, d)), np.eye(d), centre, [[1.0, 1.0] + [0.0] * (d - 2)]])


# 6D..9D (predicates of 8..11 rows: the run-time filters and GMP beyond 8):
# kept small, the brute force's term-by-term oracle is slow on 10 and 11
# degenerate rows (the 8D set with a duplicated centre took 20 s)
SETS6789 = {
    "cross-polytope 6D and centre": np.concatenate([_cross_polytope(6), np.zeros((1, 6))]),
    "simplex corners 7D, centre twice, cube corner": _corners_and_centre(7, True),
    "simplex corners 8D, centre, cube corner": _corners_and_centre(8, False),
    "simplex corners 9D, centre, cube corner": _corners_and_centre(9, False),
    "9D: unit vectors and three opposites": np.concatenate([np.eye(9), -np.eye(9)[:3]]),
}
CASES6789 = [(n, p, w) for n, p, w in _cases(SETS6789, 14)
             if w is None or ("6D" in n and ("equal" in n or "lattice weights 0" in n))]


def _available(backends):
    # the CPU ones, and the GPU ones this build has (flipflop.gpu_backends)
    return [b for b in backends if b in ("cpu", "reference") or b in flipflop.gpu_backends]


def _hull_backends(d):
    return _available(flipflop._HULL_BACKENDS[d])


def _delaunay_backends(d):
    return _available(flipflop._DELAUNAY_BACKENDS[d])


def _assert_same(label, diffs):
    assert not diffs, label + ":\n  " + "\n  ".join(diffs)


# ---- the comparisons -----------------------------------------------------------------------

@pytest.mark.parametrize("name,points", list(SETS2.items()), ids=list(SETS2))
def test_convex_hull_2d_equals_brute_force(name, points):
    cycle = brute("hull2", points)
    for backend in _hull_backends(2):
        _assert_same(f"{name}, {backend}", hull2_differences(flipflop.ConvexHull(points, backend=backend), cycle))


@pytest.mark.parametrize("name,points", list(SETS3.items()), ids=list(SETS3))
def test_convex_hull_3d_equals_brute_force(name, points):
    facets = brute("hull3", points)
    for backend in _hull_backends(3):
        _assert_same(f"{name}, {backend}", hull3_differences(flipflop.ConvexHull(points, backend=backend), facets))


@pytest.mark.parametrize("name,points,weights", CASES2 + CASES3 + CASES45 + CASES6789,
                         ids=_ids(CASES2 + CASES3 + CASES45 + CASES6789))
def test_delaunay_equals_brute_force(name, points, weights):
    d = points.shape[1]
    answer = brute("dt" if weights is None else "rt", points, weights)
    for backend in _delaunay_backends(d):
        tri = flipflop.Delaunay(points, weights=weights, backend=backend)
        _assert_same(f"{name}, {backend}", rt_differences(tri, answer))


def test_brute_force_hand_derived_answers():
    """The program itself on answers derived by hand: the unit square's hull
    (ccw from 0) and its Delaunay triangulation under SoS. Cocircular square
    0 (0,0), 1 (1,0), 2 (1,1), 3 (0,1): the lifted points are coplanar, the
    perturbation decides the diagonal; every simplex must be ccw and cover
    the square with one of the two diagonals."""
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=np.float64)
    assert brute("hull2", square) == [0, 1, 2, 3]
    simplices, redundant = brute("dt", square)
    assert redundant.size == 0
    assert simplices.tolist() in ([[0, 1, 2], [0, 2, 3]], [[0, 1, 3], [1, 2, 3]])
    for s in simplices:  # ccw: positive area, computed exactly
        p = [tuple(Fraction(float(v)) for v in square[i]) for i in s]
        assert (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]) > 0
    # a tetrahedron's hull: its four faces, each ccw from outside
    tet = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64)
    assert brute("hull3", tet).tolist() == [[0, 1, 3], [0, 2, 1], [0, 3, 2], [1, 2, 3]]


# ---- the comparison can fail ------------------------------------------------------------------

def test_planted_errors_are_detected():
    """The comparison catches an answer changed in one simplex, the other
    diagonal of a cocircular cell, a point on a hull edge dropped from the
    cycle, a redundant point added, and rows out of order."""
    grid = _grid(3, 3)
    tri = flipflop.Delaunay(grid)
    simplices, redundant = brute("dt", grid)
    assert rt_differences(tri, (simplices, redundant)) == []
    # one simplex replaced by another triangle of the same points
    changed = simplices.copy()
    changed[0] = [0, 1, 5] if changed[0].tolist() != [0, 1, 5] else [0, 1, 4]
    assert rt_differences(tri, (changed, redundant))
    # the other diagonal of the cell whose triangles are the first two rows
    # holding vertex 0 (the cell (0,0)-(1,1): points 0, 1, 3, 4)
    cell = [i for i, s in enumerate(simplices.tolist()) if set(s) <= {0, 1, 3, 4}]
    assert len(cell) == 2
    flipped = simplices.copy()
    diag = {tuple(sorted(set(simplices[cell[0]]) & set(simplices[cell[1]])))}
    # point 3i + j is (i, j): 0 (0,0), 1 (0,1), 3 (1,0), 4 (1,1); the ccw
    # triangles on the diagonal 0-4 are (0, 3, 4), (0, 4, 1), on 1-3
    # (0, 3, 1), (1, 3, 4) (canonical rotations)
    other = [[0, 3, 4], [0, 4, 1]] if diag == {(1, 3)} else [[0, 3, 1], [1, 3, 4]]
    flipped[cell[0]], flipped[cell[1]] = other
    flipped = flipped[np.lexsort(flipped.T[::-1])]
    assert rt_differences(tri, (flipped, redundant))
    # a redundant point that is not, and the rows reversed
    assert rt_differences(tri, (simplices, np.array([4])))
    assert rt_differences(tri, (simplices[::-1], redundant))
    # hull2: the square with edge points: dropping an edge point from the cycle
    pts = SETS2["square with points on its edges and centre"]
    cycle = brute("hull2", pts)
    hull = flipflop.ConvexHull(pts)
    assert hull2_differences(hull, cycle) == []
    inner = [v for v in cycle if v >= 4]
    assert inner, "SoS keeps some edge points of this square on the hull"
    assert hull2_differences(hull, [v for v in cycle if v != inner[0]])
    # hull3: one facet of the cube replaced by its face's other diagonal split
    cube = SETS3["cube 2x2x2"]
    facets = brute("hull3", cube)
    hull3 = flipflop.ConvexHull(cube)
    assert hull3_differences(hull3, facets) == []
    wrong = facets.copy()
    wrong[0] = wrong[0][[0, 2, 1]]  # the same triangle, turned inside out
    assert hull3_differences(hull3, wrong)


def test_missing_program_fails_not_skips(monkeypatch, tmp_path):
    """With the variable set, a missing program is a failure."""
    monkeypatch.setenv(_ENV, str(tmp_path / "no_such_program"))
    with pytest.raises(AssertionError, match="missing"):
        _brute_path()


def _canonical_rows(simplices):
    """Positively oriented tuples -> DESIGN.md's canonical form (smallest
    first, the rest ascending, the last two swapped for an odd permutation),
    rows sorted."""
    out = []
    for t in np.asarray(simplices).tolist():
        odd = sum(1 for i in range(len(t)) for j in range(i + 1, len(t)) if t[j] < t[i]) % 2 == 1
        s = sorted(t)
        if odd:
            s[-1], s[-2] = s[-2], s[-1]
        out.append(s)
    return np.array(sorted(out), dtype=np.int64).reshape(-1, np.asarray(simplices).shape[1])


@pytest.mark.parametrize("name,points,kind", [
    ("grid 3x3", SETS2["grid 3x3"], "dt"),
    ("cocircular 12 (x^2+y^2=25)", SETS2["cocircular 12 (x^2+y^2=25)"], "dt"),
    ("cube 2x2x2", SETS3["cube 2x2x2"], "dt"),
    ("0/1 points of the 4-cube (10)", SETS4["0/1 points of the 4-cube (10)"], "dt"),
    ("cross-polytope 5D", SETS5["cross-polytope 5D"], "dt"),
], ids=["grid 3x3", "cocircular 12", "cube", "4-cube points", "cross-polytope 5D"])
def test_the_sets_are_degenerate_the_perturbation_decides(name, points, kind):
    """Not vacuous: on these sets the answer depends on the perturbation's
    order. The brute force on the points in other orders (fixed permutations;
    not the reversal, which is a symmetry of the grid, the cube and the
    cross-polytope), its indices mapped back, gives other valid
    triangulations of the same points, and the comparison tells at least one
    of them from the bindings' answer."""
    n = len(points)
    tri = flipflop.Delaunay(points)
    told = 0
    for seed in range(4):
        perm = np.random.default_rng(seed).permutation(n)
        simplices, redundant = brute(kind, points[perm].copy())
        mapped = _canonical_rows(perm[simplices])
        told += bool(rt_differences(tri, (mapped, np.sort(perm[redundant]))))
    assert told > 0, name


# ---- the furthest-site triangulation (Delaunay(furthest_site=True)) ------------------------
# The upper hull of the same perturbed lifted points: the brute force keeps
# the simplices with every other lifted point strictly below (sos_brute.hpp
# rt(in, furthest)); the bindings compute it by RT+1 with every power sign
# negated. On these sets (cocircular and cospherical points, grids, points on
# the hull's edges, duplicates) the ties are the perturbation's to break.
FURTHEST = ([(n, p) for n, p in SETS2.items()] + [(n, p) for n, p in SETS3.items()] +
            [(n, p) for n, p in SETS4.items()] + [(n, p) for n, p in SETS5.items()])


@pytest.mark.parametrize("name,points", FURTHEST, ids=[n for n, _ in FURTHEST])
def test_furthest_site_equals_brute_force(name, points):
    answer = brute("dt-furthest", points)
    tri = flipflop.Delaunay(points, furthest_site=True)
    assert tri.furthest_site
    _assert_same(f"{name}, furthest site", rt_differences(tri, answer))
    # (its vertices need not be ConvexHull's on these sets: the hull's
    # perturbation has d coordinates, the lifted one d + 1, so duplicates and
    # points inside hull edges may be decided differently)


def test_furthest_site_differs_from_delaunay_and_planted_errors_are_detected():
    pts = _circle25()
    near, far = brute("dt", pts), brute("dt-furthest", pts)
    assert differences(near[0], far[0])  # the perturbation's two hulls differ on cocircular points
    tri = flipflop.Delaunay(pts, furthest_site=True)
    assert not rt_differences(tri, far)
    assert rt_differences(tri, near)
