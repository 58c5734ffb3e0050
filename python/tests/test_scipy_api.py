"""scipy.spatial's constructor and attribute surface of flipflop.ConvexHull
and flipflop.Delaunay (issue 39; docs/scipy_porting.md).

  * on random input (general position) every attribute and keyword equals
    scipy 1.10's (Qhull): simplices as sets, neighbors, convex_hull,
    vertex_neighbor_vertices, transform (as barycentric coordinates, 1e-12),
    plane_distance and lift_points up to the scale convention, equations'
    signs, good (QGn / QG-n), bounds and counts;
  * on degenerate input (grids, duplicates, cocircular points, points a few
    ulps from a facet) the exact attributes (coplanar, good, the NaN rows of
    transform) equal oracles that share no code with the package: small
    cases computed by hand and brute force with fractions.Fraction;
  * add_points in many batches gives the one-shot answer, array for array;
  * bad input raises what scipy raises (checked against scipy in the test
    where scipy raises at all).
"""
import inspect
from fractions import Fraction
import math
import itertools
from itertools import combinations

import numpy as np
import pytest
import scipy.spatial as ss

import flipflop
from oracles import exact_centre


def sets(simplices):
    return {frozenset(int(x) for x in r) for r in simplices}


def index_of(simplices):
    return {frozenset(int(x) for x in r): k for k, r in enumerate(simplices)}


def fdet(rows):
    """Exact determinant of a square matrix of Fractions (or integers),
    written here independently of the package: each row scaled by the least
    common multiple of its denominators to integers, then Bareiss's
    fraction-free elimination in Python's integers (every division exact),
    the result divided by the scales. (Gaussian elimination in Fractions gave
    the same values 5-10x slower: a gcd per operation.)"""
    m, scale = [], 1
    for r in rows:
        r = [Fraction(x) for x in r]
        den = 1
        for x in r:
            den = den * x.denominator // math.gcd(den, x.denominator)
        m.append([int(x * den) for x in r])
        scale *= den
    n, sign, prev = len(m), 1, 1
    for c in range(n - 1):
        if m[c][c] == 0:
            p = next((r for r in range(c + 1, n) if m[r][c] != 0), None)
            if p is None:
                return Fraction(0)
            m[c], m[p] = m[p], m[c]
            sign = -sign
        for r in range(c + 1, n):
            for k in range(c + 1, n):
                m[r][k] = (m[r][k] * m[c][c] - m[r][c] * m[c][k]) // prev
        prev = m[c][c]
    return Fraction(sign * m[n - 1][n - 1], scale)


def test_fdet_is_the_determinant():
    """The helper against Leibniz's formula (sum over permutations), on
    matrices of Fractions with zero pivots, repeated rows and rank drops."""
    import itertools
    import random

    def leibniz(a):
        n, total = len(a), Fraction(0)
        for perm in itertools.permutations(range(n)):
            inv = sum(1 for i in range(n) for j in range(i + 1, n) if perm[i] > perm[j])
            term = Fraction(-1 if inv % 2 else 1)
            for i in range(n):
                term *= a[i][perm[i]]
            total += term
        return total

    rng = random.Random(5)
    for _ in range(300):
        n = rng.randint(1, 5)
        a = [[Fraction(rng.randint(-3, 3), rng.choice([1, 2, 3, 7])) if rng.random() < 0.7 else Fraction(0)
              for _ in range(n)] for _ in range(n)]
        if n > 1 and rng.random() < 0.2:
            a[-1] = list(a[0])  # a repeated row: det 0
        assert fdet(a) == leibniz(a)


def F(v):
    return [Fraction(float(x)) for x in v]


def in_simplex_exact(points, simplex, x):
    """x in the closed simplex, exactly: every barycentric coordinate >= 0."""
    V = [F(points[i]) for i in simplex]
    X = F(x)
    d = len(X)
    base = fdet([[V[j][c] - V[0][c] for c in range(d)] for j in range(1, d + 1)])
    if base == 0:
        return False
    for j in range(d + 1):
        W = [X if k == j else V[k] for k in range(d + 1)]
        if fdet([[W[k][c] - W[0][c] for c in range(d)] for k in range(1, d + 1)]) * base < 0:
            return False
    return True


# ---- signatures ---------------------------------------------------------------------

def test_signatures_follow_scipy():
    for ours, theirs in ((flipflop.Delaunay, ss.Delaunay), (flipflop.ConvexHull, ss.ConvexHull)):
        mine = inspect.signature(ours)
        scipy_names = list(inspect.signature(theirs).parameters)
        positional = [n for n, p in mine.parameters.items()
                      if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)]
        assert positional == scipy_names
        for n in scipy_names:
            assert mine.parameters[n].default == inspect.signature(theirs).parameters[n].default
        keyword_only = {n for n, p in mine.parameters.items() if p.kind == p.KEYWORD_ONLY}
        assert keyword_only >= {"strict", "backend", "threads"}
    assert "weights" in inspect.signature(flipflop.Delaunay).parameters
    assert inspect.signature(flipflop.Delaunay).parameters["weights"].kind == inspect.Parameter.KEYWORD_ONLY
    for cls in (flipflop.Delaunay, flipflop.ConvexHull):
        for method in ("add_points", "close"):
            assert callable(getattr(cls, method))
    assert list(inspect.signature(flipflop.Delaunay.find_simplex).parameters) == ["self", "xi", "bruteforce", "tol"]
    assert list(inspect.signature(flipflop.Delaunay.add_points).parameters)[:3] == ["self", "points", "restart"]


def test_positional_weights_are_refused_with_a_pointer():
    p = np.random.default_rng(0).random((20, 2))
    with pytest.raises(ValueError, match="keyword-only"):
        flipflop.Delaunay(p, np.ones(20))


# ---- Delaunay against scipy on random input ------------------------------------------

CASES = [(2, 300), (3, 150), (4, 40), (5, 22)]


@pytest.fixture(scope="module", params=CASES, ids=lambda c: f"{c[0]}d")
def pair(request):
    d, n = request.param
    p = np.random.default_rng(100 + d).random((n, d))
    return p, flipflop.Delaunay(p), ss.Delaunay(p)


def test_counts_bounds_and_simplices(pair):
    p, t, s = pair
    assert sets(t.simplices) == sets(s.simplices)
    assert (t.nsimplex, t.npoints, t.ndim) == (s.nsimplex, s.npoints, s.ndim)
    assert np.array_equal(t.min_bound, s.min_bound) and np.array_equal(t.max_bound, s.max_bound)
    assert t.furthest_site is False and s.furthest_site is False
    assert sets(t.convex_hull) == sets(s.convex_hull)
    assert t.coplanar.shape == s.coplanar.shape == (0, 3)
    assert np.array_equal(t.good, np.ones(t.nsimplex)) and np.array_equal(s.good, np.ones(s.nsimplex))


def _neighbors_by_global_sort(simplices):
    """scipy's neighbors by the definition _flipflop.neighbors documents: the
    (sorted facet, slot) records sorted globally, equal neighbours paired."""
    m, k = simplices.shape
    rec = sorted((tuple(sorted(np.delete(simplices[i], j).tolist())), i * k + j) for i in range(m) for j in range(k))
    out = -np.ones(m * k, dtype=np.int64)
    x = 0
    while x + 1 < len(rec):
        if rec[x][0] == rec[x + 1][0]:
            out[rec[x][1]], out[rec[x + 1][1]] = rec[x + 1][1] // k, rec[x][1] // k
            x += 2
        else:
            x += 1
    return out.reshape(m, k)


def test_neighbors_in_parallel_pieces_equal_the_global_sort():
    """_flipflop.neighbors files facets in parallel pieces and coarse buckets;
    its answer must be the global sort's, on triangulations (2D, 3D via the
    reference backend, 4D) large enough for several pieces and buckets, and on
    arbitrary index lists where a facet lies in one, two or three simplices."""
    from flipflop import _flipflop
    rng = np.random.default_rng(12)
    cases = [flipflop.Delaunay(rng.random((6000, 2))).simplices,
             flipflop.Delaunay(rng.random((1500, 3)), backend="reference").simplices,
             flipflop.Delaunay(rng.random((700, 4))).simplices,
             # several pieces of 4096 simplices, facets in three or more of them
             rng.integers(0, 40, size=(3000, 3)), rng.integers(0, 60, size=(10000, 3)),
             rng.integers(0, 5000, size=(9000, 3)), rng.integers(0, 25, size=(9000, 4))]
    for s in cases:
        s = np.ascontiguousarray(s, dtype=np.int64)
        assert np.array_equal(_flipflop.neighbors(s), _neighbors_by_global_sort(s))


def test_3d_neighbors_from_the_kernel_witness_equal_facet_matching():
    """In 3D the cpu backend's neighbors are read off the kernel's certified
    witness (cpu::rt3_neighbors); they must equal the facet matching every
    other path uses (_flipflop.neighbors), on degenerate input too: a grid
    (flat tetrahedra), exact duplicates, weights with redundant points."""
    from flipflop import _flipflop
    rng = np.random.default_rng(11)
    g = np.array([[i, j, k] for i in range(6) for j in range(6) for k in range(6)], dtype=float)
    dup = np.concatenate([g, g[::3]])
    inputs = [(rng.random((2000, 3)), None), (g, None), (dup, None),
              (rng.random((1500, 3)), rng.random(1500) * 0.05)]
    for pts, w in inputs:
        for threads in (1, 2):
            t = flipflop.Delaunay(pts, weights=w, threads=threads)
            assert np.array_equal(t.neighbors, _flipflop.neighbors(t.simplices.astype(np.int64)))
            assert t.neighbors.dtype == np.intc and t.neighbors.shape == t.simplices.shape


def test_neighbors_from_the_d_dimensional_certificate_equal_facet_matching():
    """From 4D on, and for the furthest-site triangulation in every d, the
    neighbors are the facet table that certify::rtd's certificate matched
    (returned by triangulate_with_neighbors); they must equal the facet
    matching of _flipflop.neighbors and the global sort's, on grids (most
    simplices of zero volume), exact duplicates, weights with redundant
    points, random points, at 1 and 2 threads; the strict view (no table)
    still gets them by matching."""
    from flipflop import _flipflop
    rng = np.random.default_rng(13)
    g5 = np.array(list(itertools.product(range(3), repeat=5)), dtype=float)
    g4 = np.array(list(itertools.product(range(4), repeat=4)), dtype=float)
    cases = [(g5, None, {}), (g4, None, {}), (np.concatenate([g4, g4[::5]]), None, {}),
             (rng.random((300, 4)), rng.random(300) * 0.05, {}), (rng.random((120, 5)), None, {}),
             (rng.random((400, 2)), None, {"furthest_site": True}),
             (rng.random((300, 3)), None, {"furthest_site": True}),
             (rng.random((200, 4)), None, {"furthest_site": True}),
             (g4, None, {"strict": True})]
    for pts, w, kw in cases:
        raw = _flipflop.triangulate_with_neighbors(pts, w, "cpu", kw.get("strict", False), 0,
                                                   kw.get("furthest_site", False))
        assert (raw[2] is None) == kw.get("strict", False)
        for threads in (1, 2):
            t = flipflop.Delaunay(pts, weights=w, threads=threads, **kw)
            s = t.simplices.astype(np.int64)
            assert np.array_equal(t.neighbors, _flipflop.neighbors(s))
            if len(s) < 3000:
                assert np.array_equal(t.neighbors, _neighbors_by_global_sort(s))
            assert t.neighbors.dtype == np.intc and t.neighbors.shape == t.simplices.shape


def test_neighbors_vertex_to_simplex_and_vertex_neighbor_vertices(pair):
    p, t, s = pair
    where = index_of(s.simplices)
    to_scipy = np.array([where[frozenset(r)] for r in t.simplices.tolist()])
    for i, r in enumerate(t.simplices):
        k = to_scipy[i]
        for j, v in enumerate(r):
            jj = list(s.simplices[k]).index(v)  # the same vertex in scipy's row
            a, b = t.neighbors[i, j], s.neighbors[k, jj]
            assert (a < 0) == (b < 0)
            if a >= 0:
                assert to_scipy[a] == b
    v2s = t.vertex_to_simplex
    assert v2s.shape == (t.npoints,)
    for v in range(t.npoints):
        assert v in t.simplices[v2s[v]]
    (ip, ix), (jp, jx) = t.vertex_neighbor_vertices, s.vertex_neighbor_vertices
    assert ip.shape == jp.shape == (t.npoints + 1,)
    for v in range(t.npoints):
        assert set(ix[ip[v]:ip[v + 1]]) == set(jx[jp[v]:jp[v + 1]])
        # the definition: joined by an edge of some simplex; ascending
        assert set(ix[ip[v]:ip[v + 1]]) == {int(x) for r in t.simplices if v in r for x in r} - {v}
        assert (np.diff(ix[ip[v]:ip[v + 1]]) > 0).all()


@pytest.mark.parametrize("d", [2, 3, 4])
def test_vertex_neighbor_vertices_with_duplicates_and_redundant_points(d):
    # copies and weighted points that are vertices of no simplex have no
    # neighbours; the others those of the definition, ascending
    rng = np.random.default_rng(90 + d)
    p = rng.random((30, d))
    p = np.concatenate([p, p[:5]])
    for w in (None, rng.random(len(p)) * 0.05):
        t = flipflop.Delaunay(p, weights=w)
        ip, ix = t.vertex_neighbor_vertices
        assert ip.shape == (len(p) + 1,) and ip[0] == 0 and ip[-1] == len(ix)
        for v in range(len(p)):
            run = ix[ip[v]:ip[v + 1]]
            assert set(run.tolist()) == {int(x) for r in t.simplices if v in r for x in r} - {v}
            assert (np.diff(run) > 0).all()
        assert (np.diff(ip)[np.setdiff1d(np.arange(len(p)), t.simplices)] == 0).all()


def test_transform_gives_scipys_barycentric_coordinates(pair):
    p, t, s = pair
    d = p.shape[1]
    assert t.transform.shape == (t.nsimplex, d + 1, d) and t.transform.dtype == np.float64
    where = index_of(s.simplices)
    q = np.random.default_rng(7).random((40, d))
    for i, r in enumerate(t.simplices):
        k = where[frozenset(r.tolist())]
        T, U = t.transform[i], s.transform[k]
        for x in np.vstack([q[:3], p[r].mean(axis=0)]):
            b = T[:d] @ (x - T[d])
            c = U[:d] @ (x - U[d])
            ours = dict(zip(r.tolist(), np.r_[b, 1 - b.sum()]))
            theirs = dict(zip(s.simplices[k].tolist(), np.r_[c, 1 - c.sum()]))
            scale = max(1.0, np.abs(list(theirs.values())).max())
            assert all(abs(ours[v] - theirs[v]) <= 1e-12 * scale * 10 ** (d - 2) for v in ours), (i, x)
        # the definition: vertex j has coordinate e_j
        for j in range(d):
            e = T[:d] @ (p[r[j]] - T[d])
            assert np.allclose(e, np.eye(d)[j], atol=1e-9)


def test_lift_points_and_plane_distance_agree_with_scipy_up_to_scale(pair):
    p, t, s = pair
    d = p.shape[1]
    x = np.random.default_rng(3).random((25, d)) * 1.4 - 0.2
    L, M = t.lift_points(x), s.lift_points(x)
    assert np.array_equal(L[:, :d], x) and np.array_equal(M[:, :d], x)
    # both are scale * |x|^2 + shift, each with its own scale and shift
    assert np.allclose((L[:, d] - t.paraboloid_shift) / t.paraboloid_scale,
                       (M[:, d] - s.paraboloid_shift) / s.paraboloid_scale, rtol=1e-13)
    assert t.lift_points(x[0]).shape == (d + 1,)
    assert t.equations.shape == (t.nsimplex, d + 2)
    assert np.allclose(np.linalg.norm(t.equations[:, :-1], axis=1), 1)
    assert (t.equations[:, d] < 0).all() and (s.equations[:, d] < 0).all()  # lower hull: normal down
    # plane_distance is, per simplex, a positive multiple of scipy's (both
    # are positive multiples of the power function |x - c|^2 - r^2, negated)
    D, E = t.plane_distance(x), s.plane_distance(x)
    assert D.shape == E.shape == (len(x), t.nsimplex)
    where = index_of(s.simplices)
    k = [where[frozenset(r)] for r in t.simplices.tolist()]
    ratio = D / E[:, k]
    assert (ratio > 0).all()
    assert np.allclose(ratio, ratio[0], rtol=1e-8)
    assert t.plane_distance(x[0]).shape == (t.nsimplex,)
    # the vertices lie on their simplices' planes, the other points above them
    own = t.plane_distance(p)
    scale = np.abs(own).max()
    for i, r in enumerate(t.simplices):
        assert np.abs(own[r, i]).max() <= 1e-12 * scale
    assert (own <= 1e-12 * scale).all()


def test_find_simplex_accepts_scipys_keywords(pair):
    p, t, s = pair
    d = p.shape[1]
    x = np.random.default_rng(4).random((50, d))
    a = t.find_simplex(x)
    assert np.array_equal(a, t.find_simplex(x, bruteforce=True))
    assert np.array_equal(a, t.find_simplex(x, tol=1e-3))
    assert np.array_equal(a, t.find_simplex(x, True, 0.0))
    b = s.find_simplex(x)
    assert [frozenset(t.simplices[i].tolist()) if i >= 0 else None for i in a] == \
           [frozenset(s.simplices[i].tolist()) if i >= 0 else None for i in b]
    for bad in ("a", [1, 2]):
        with pytest.raises(TypeError):
            s.find_simplex(x, tol=bad)
        with pytest.raises(TypeError):
            t.find_simplex(x, tol=bad)
    assert t.find_simplex(x[0]).shape == s.find_simplex(x[0]).shape == ()
    with pytest.raises(ValueError):
        s.find_simplex(x[:, :1])
    with pytest.raises(ValueError):
        t.find_simplex(x[:, :1])


def test_vertices_is_the_deprecated_alias():
    p = np.random.default_rng(0).random((30, 2))
    t = flipflop.Delaunay(p)
    with pytest.warns(DeprecationWarning):
        v = t.vertices
    assert v is t.simplices
    with pytest.warns(DeprecationWarning):
        ss.Delaunay(p).vertices


# ---- Delaunay: exact attributes on degenerate input ---------------------------------

def grid(k, d):
    return np.array(np.meshgrid(*[np.arange(float(k))] * d, indexing="ij")).reshape(d, -1).T.copy()


@pytest.mark.parametrize("d,k", [(2, 5), (3, 3), (4, 3)])
def test_transform_is_nan_exactly_on_zero_volume_simplices(d, k):
    p = grid(k, d) * 0.1  # not integers: 0.1 is not exact, the flat ones are still flat
    t = flipflop.Delaunay(p)
    T = t.transform
    flat = []
    for r in t.simplices:
        V = [F(p[i]) for i in r]
        flat.append(fdet([[V[j][c] - V[0][c] for c in range(d)] for j in range(1, d + 1)]) == 0)
    flat = np.array(flat)
    assert flat.any() and not flat.all()  # the canonical answer keeps some (README)
    assert np.isnan(T[flat]).all()
    assert np.isfinite(T[~flat]).all()
    for i in np.flatnonzero(~flat):
        r = t.simplices[i]
        Tm = (p[r[:d]] - p[r[d]]).T
        assert np.allclose(T[i, :d] @ Tm, np.eye(d), atol=1e-10)
        assert np.array_equal(T[i, d], p[r[d]])
    # the strict view has no flat simplex, so no NaN
    assert np.isfinite(flipflop.Delaunay(p, strict=True).transform).all()


def test_transform_on_a_grid_moved_by_ulps():
    # simplices a few ulps from flat: exactly not flat, so not NaN unless
    # singular in floating point; every finite row inverts its T
    rng = np.random.default_rng(3)
    p = grid(4, 3) + 1.0
    for i in rng.choice(len(p), len(p) // 5, replace=False):
        p[i] = np.nextafter(np.nextafter(p[i], np.inf), np.inf)
    t = flipflop.Delaunay(p)
    T = t.transform
    flat = np.array([fdet([[a - b for a, b in zip(F(p[r[j]]), F(p[r[0]]))] for j in range(1, 4)]) == 0
                     for r in t.simplices])
    assert flat.any() and not flat.all()
    assert np.isnan(T[flat]).all()
    fin = np.isfinite(T).all(axis=(1, 2))
    assert fin[~flat].mean() > 0.5
    for i in np.flatnonzero(fin):
        r = t.simplices[i]
        Tm = (p[r[:3]] - p[r[3]]).T
        assert np.allclose(T[i, :3] @ Tm, np.eye(3), atol=1e-6 * max(1.0, np.abs(T[i, :3]).max()))
        assert np.array_equal(T[i, 3], p[r[3]])


@pytest.mark.parametrize("d", [2, 3])
def test_coplanar_and_vertex_to_simplex_on_duplicates(d):
    rng = np.random.default_rng(11 + d)
    base = rng.random((25, d))
    dup = [3, 7, 7, 20]  # point 7 three times
    p = np.vstack([base, base[dup]])
    t = flipflop.Delaunay(p)
    s = ss.Delaunay(p)
    c = t.coplanar
    # exactly the points that are not vertices; the copies of a point are
    # joined by zero-volume simplices or left out as the perturbation decides
    # (README: the canonical answer on duplicates), so which copies these are
    # is flipflop's choice, not scipy's
    vertices = set(t.simplices.ravel().tolist())
    assert set(range(25)) - {3, 7, 20} <= vertices
    assert c.dtype == np.intc and c.shape[1] == 3 and len(c) >= 1
    assert c[:, 0].tolist() == sorted(set(range(len(p))) - vertices)
    groups = [{3, 25}, {7, 26, 27}, {20, 28}]
    for pt, simplex, vertex in c:
        group = next(g for g in groups if pt in g)
        assert vertex in group and vertex in vertices and vertex != pt  # a copy: at distance 0
        assert vertex in t.simplices[simplex]
        assert in_simplex_exact(p, t.simplices[simplex], p[pt])
        assert t.vertex_to_simplex[pt] == simplex
    assert set(c[:, 0].tolist()) == set(t.redundant.tolist())
    assert len(s.coplanar) == len(dup)  # scipy drops every copy but one
    # without Qc (a given qhull_options replaces scipy's default), as scipy:
    # no coplanar points, -1 for the points that are not vertices
    for opts in ("Qbb Qz", b"Qbb Qz"):
        u = flipflop.Delaunay(p, qhull_options=opts)
        assert u.coplanar.shape == (0, 3)
        assert np.flatnonzero(u.vertex_to_simplex < 0).tolist() == c[:, 0].tolist()
        assert (ss.Delaunay(p, qhull_options="Qbb Qz").vertex_to_simplex < 0).sum() == len(dup)  # scipy: the same rule


def test_weighted_lift_equations_and_redundant_points():
    rng = np.random.default_rng(5)
    p = rng.random((60, 2))
    w = rng.random(60) * 0.02
    w[:5] = -1.0  # hidden: 0..4 are redundant unless on the hull
    t = flipflop.Delaunay(p, weights=w)
    red = set(t.redundant.tolist())
    assert red and red == set(range(60)) - set(t.simplices.ravel().tolist())
    assert set(t.coplanar[:, 0].tolist()) == red
    for pt, simplex, vertex in t.coplanar:
        assert in_simplex_exact(p, t.simplices[simplex], p[pt])
        assert vertex in t.simplices[simplex]
    # the lift is s * (|x|^2 - w): the lifted vertices lie on their simplex's
    # hyperplane, every lifted point on or above every hyperplane
    z = np.c_[p, t.paraboloid_scale * ((p ** 2).sum(axis=1) - w) + t.paraboloid_shift]
    dist = z @ t.equations[:, :-1].T + t.equations[:, -1]
    for i, r in enumerate(t.simplices):
        assert np.abs(dist[r, i]).max() < 1e-13
    assert (dist < 1e-13).all()
    # plane_distance lifts an unweighted query: |x|^2
    assert np.allclose(t.plane_distance(p), (t.lift_points(p) @ t.equations[:, :-1].T + t.equations[:, -1]))


def test_delaunay_good_against_scipy_and_by_hand():
    rng = np.random.default_rng(8)
    for d, n in ((2, 60), (3, 40)):
        p = rng.random((n, d))
        for g in (0, 5, n - 1):
            for sign in ("", "-"):
                t = flipflop.Delaunay(p, qhull_options=f"Qbb Qc Qz QG{sign}{g}")
                s = ss.Delaunay(p, qhull_options=f"Qbb Qc Qz QG{sign}{g}")
                assert g not in t.simplices
                assert sets(t.simplices) == sets(s.simplices)
                assert sets(t.simplices[t.good == 1]) == sets(s.simplices[s.good == 1])
    # by hand: the rectangle (+-3, +-4) lies on the circle of radius 5;
    # (5, 0) and (0, -5) lie on it exactly (not seen), (0, 4.5) inside, (6, 0) outside
    rect = np.array([[3.0, 4.0], [-3.0, 4.0], [-3.0, -4.0], [3.0, -4.0]])
    for x, inside in (([5.0, 0.0], False), ([0.0, -5.0], False), ([0.0, 4.5], True), ([6.0, 0.0], False),
                      ([5.0, np.nextafter(0.0, 1.0)], False), ([np.nextafter(5.0, 0.0), 0.0], True)):
        p = np.vstack([rect, [x]])
        t = flipflop.Delaunay(p, qhull_options="QG4")
        assert len(t.simplices) == 2 and t.good.tolist() == [int(inside)] * 2, x
        assert flipflop.Delaunay(p, qhull_options="QG-4").good.tolist() == [int(not inside)] * 2


def _power_inside(pts, w, x, wx):
    """Oracle (Fractions): x strictly inside the orthosphere of the simplex
    pts (weights w, floats): its centre c (oracles.exact_centre), r^2 =
    |p_0 - c|^2 - w_0, inside iff |x - c|^2 - w_x < r^2; None for a flat
    simplex (no orthosphere)."""
    c = exact_centre(pts, w)
    if c is None:
        return None
    P0, W0 = [Fraction(float(v)) for v in pts[0]], Fraction(0) if w is None else Fraction(float(w[0]))
    X = [Fraction(float(v)) for v in x]
    r2 = sum((a - b) ** 2 for a, b in zip(P0, c)) - W0
    return sum((a - b) ** 2 for a, b in zip(X, c)) - Fraction(float(wx)) < r2


@pytest.mark.parametrize("d", [2, 3, 4])
def test_delaunay_good_exact_on_grids_and_weights(d):
    # QGn on lattices, where the point is cospherical with many simplices
    # (on the sphere: not inside), weighted or not, against the orthosphere
    # in Fractions; the flat simplices against the lifted determinant
    k = {2: 4, 3: 3, 4: 3}[d]
    p = grid(k, d)
    rng = np.random.default_rng(40 + d)
    for weights in (None, rng.choice([0.0, 0.25, 1.0], size=len(p))):
        for g in (0, len(p) // 2, len(p) - 1):
            for sign in ("", "-"):
                t = flipflop.Delaunay(p, weights=weights, qhull_options=f"QG{sign}{g}")
                P = [F(v) for v in p]
                Wf = [Fraction(0)] * len(p) if weights is None else [Fraction(float(w)) for w in weights]
                flat_seen = 0
                for simplex, good in zip(t.simplices, t.good):
                    V, W = [P[i] for i in simplex], [Wf[i] for i in simplex]
                    inside = _power_inside(p[simplex], None if weights is None else weights[simplex], p[g],
                                           0.0 if weights is None else weights[g])
                    if inside is None:  # flat: the sign of the lifted determinant, exactly
                        flat_seen += 1
                        rows = [[a - b for a, b in zip(v, P[g])] + [sum((a - b) ** 2 for a, b in zip(v, P[g])) - w + Wf[g]]
                                for v, w in zip(V, W)]
                        det = fdet(rows)
                        inside = det != 0 and (det > 0) == (d % 2 == 0)  # the sign inside has, below
                    assert bool(good) == (inside if sign == "" else not inside), (weights is None, g, sign, simplex)
                assert flat_seen or weights is not None or d == 2
    # the lifted determinant of a positive simplex and a point inside has the
    # sign (-1)^d: the standard simplex and its centroid
    std = [[Fraction(0)] * d] + [[Fraction(int(i == j)) for i in range(d)] for j in range(d)]
    x = [Fraction(1, d + 1)] * d
    rows = [[a - b for a, b in zip(v, x)] + [sum((a - b) ** 2 for a, b in zip(v, x))] for v in std]
    assert (fdet(rows) > 0) == (d % 2 == 0)
    assert _power_inside(np.vstack([np.zeros(d), np.eye(d)]), None, np.full(d, 0.25), 0.0)


# ---- ConvexHull ----------------------------------------------------------------------

@pytest.mark.parametrize("d", [2, 3])
def test_hull_counts_bounds_and_good_equal_scipy(d):
    rng = np.random.default_rng(20 + d)
    p = rng.random((80, d))
    h, s = flipflop.ConvexHull(p), ss.ConvexHull(p)
    assert (h.npoints, h.nsimplex, h.ndim) == (s.npoints, s.nsimplex, s.ndim)
    assert np.array_equal(h.min_bound, s.min_bound) and np.array_equal(h.max_bound, s.max_bound)
    assert h.good is None and s.good is None
    assert h.coplanar.shape == s.coplanar.shape == (0, 3)
    vertices = [int(v) for v in s.vertices]
    inner = [i for i in range(80) if i not in vertices][:2]
    for g in vertices[:3] + inner:
        for sign in ("", "-"):
            hg = flipflop.ConvexHull(p, qhull_options=f"QG{sign}{g}")
            sg = ss.ConvexHull(p, qhull_options=f"QG{sign}{g}")
            assert hg.good.dtype == bool and hg.good.shape == (hg.nsimplex,)
            assert sets(hg.simplices) == sets(sg.simplices)
            assert sets(hg.simplices[hg.good]) == sets(sg.simplices[sg.good])
            assert g not in hg.vertices


def test_hull_good_exact_by_hand():
    sq = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    tiny = np.nextafter(1.0, 2.0)
    for x, seen in (([0.5, tiny], {(2, 3)}), ([2.0, 1.0], {(1, 2)}), ([0.5, 1.0], set()),
                    ([2.0, 2.0], {(1, 2), (2, 3)}), ([0.5, 0.5], set())):
        h = flipflop.ConvexHull(np.vstack([sq, [x]]), qhull_options="QG4")
        assert {frozenset(e) for e in h.simplices[h.good].tolist()} == {frozenset(e) for e in seen}, x
    cube = grid(2, 3)
    for x, n in (([0.5, 0.5, np.nextafter(1.0, 2.0)], 2), ([0.5, 0.5, 1.0], 0), ([2.0, 2.0, 0.5], 4),
                 ([0.5, 0.5, 0.5], 0)):
        h = flipflop.ConvexHull(np.vstack([cube, [x]]), qhull_options="QG8")
        assert h.good.sum() == n, x  # two triangles per square face seen
        assert (~flipflop.ConvexHull(np.vstack([cube, [x]]), qhull_options="QG-8").good).sum() == n


def boundary_oracle(p, lo, hi):
    """On the boundary of the box [lo, hi]^d exactly."""
    return {i for i, x in enumerate(p.tolist()) if any(c in (lo, hi) for c in x)}


@pytest.mark.parametrize("d,k", [(2, 5), (3, 4)])
def test_hull_coplanar_on_grids(d, k):
    p = grid(k, d)
    for strict in ((False, True) if d == 3 else (False,)):
        h = flipflop.ConvexHull(p, qhull_options="Qc", strict=strict)
        want = boundary_oracle(p, 0.0, k - 1.0) - set(h.vertices.tolist())
        assert set(h.coplanar[:, 0].tolist()) == want
        assert h.coplanar.dtype == np.intc and h.coplanar.shape[1] == 3
        for pt, facet, vertex in h.coplanar:
            V = [F(p[i]) for i in h.simplices[facet]]
            X = F(p[pt])
            assert fdet([[v[c] - V[0][c] for c in range(d)] for v in V[1:] + [X]]) == 0
            assert vertex in h.simplices[facet]
        if strict:
            assert len(h.vertices) == 2 ** d and len(h.coplanar) == len(boundary_oracle(p, 0, k - 1)) - 2 ** d
    assert flipflop.ConvexHull(p).coplanar.shape == (0, 3)  # only with Qc, as scipy


def test_hull_coplanar_is_exact():
    # a tetrahedron's slanted facet x + y + z = 1: (0.25, 0.25, 0.5) lies on
    # it exactly, the same point an ulp lower does not
    tet = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]])
    on = [0.25, 0.25, 0.5]
    below = [0.25, 0.25, np.nextafter(0.5, 0.0)]
    p = np.vstack([tet, [on], [below], [[0.1, 0.1, 0.1]]])
    h = flipflop.ConvexHull(p, qhull_options="Qc")
    assert h.coplanar[:, 0].tolist() == [4]
    facet = h.simplices[h.coplanar[0, 1]]
    assert set(facet.tolist()) == {1, 2, 3}
    assert h.coplanar[0, 2] == 3  # (0, 0, 1) is the nearest of the facet's vertices
    sq = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.5, 0.0], [0.5, 5e-324], [0.5, 1e-300]])
    h = flipflop.ConvexHull(sq, qhull_options=b"Qc")
    assert set(h.coplanar[:, 0].tolist()) == {4} - set(h.vertices.tolist())
    assert 5 not in h.coplanar[:, 0] and 6 not in h.coplanar[:, 0]


# ---- add_points ------------------------------------------------------------------------

@pytest.mark.parametrize("d", [2, 3, 4, 5, 6])
def test_delaunay_add_points_in_batches_equals_one_shot(d):
    rng = np.random.default_rng(30 + d)
    n = {2: 60, 3: 60, 4: 30, 5: 24, 6: 16}[d]
    p = rng.random((n, d))
    p[-5:] = p[:5]  # duplicates arrive late
    p[n // 2:n // 2 + 4] = np.round(p[n // 2:n // 2 + 4])  # cube corners: cospherical ties
    one = flipflop.Delaunay(p)
    t = flipflop.Delaunay(p[:d + 3], incremental=True)
    kept = t._inc  # the kernel kept for in-place insertion (_flipflop.IncrementalTriangulation)
    if d <= 3:  # built by the one-shot kernels; the first add seeds the kernel with that answer
        assert kept is None and t._inc_seed is not None
    else:
        assert kept is not None and len(kept) == d + 3
    for lo in range(d + 3, len(p), 7):
        t.add_points(p[lo:lo + 7], restart=lo % 2 == 0)
        kept = t._inc if kept is None else kept
        assert t._inc is kept and len(kept) == min(lo + 7, len(p))  # inserted in place, not rebuilt
        assert np.array_equal(t.simplices, flipflop.Delaunay(p[:lo + 7]).simplices)
    assert np.array_equal(t.points, p)
    for name in ("simplices", "neighbors", "convex_hull", "redundant", "coplanar", "vertex_to_simplex",
                 "transform", "equations"):
        assert np.array_equal(getattr(t, name), getattr(one, name), equal_nan=name in ("transform", "equations")), name
    assert np.array_equal(t.vertex_neighbor_vertices[1], one.vertex_neighbor_vertices[1])
    assert t.npoints == len(p)
    t.close()
    assert t._inc is None and np.array_equal(t.simplices, one.simplices)


def test_delaunay_add_points_in_place_on_grids_strict_and_good():
    # a 2D and a 3D integer grid added row by row (every predicate exactly
    # degenerate), with the strict view and with QG0 (point 0 left out:
    # the kept kernel triangulates the others)
    for d, side in ((2, 6), (3, 4)):
        g = np.array(np.meshgrid(*[np.arange(side)] * d, indexing="ij"), dtype=float).reshape(d, -1).T
        g = g[np.random.default_rng(d).permutation(len(g))]
        for kw in ({}, {"strict": True}, {"qhull_options": "QG0"}):
            one = flipflop.Delaunay(g, **kw)
            t = flipflop.Delaunay(g[:side ** (d - 1)], incremental=True, **kw)
            kept = t._inc  # None where the first add seeds it (not strict)
            assert (kept is None) == (not kw.get("strict")), kw
            for lo in range(side ** (d - 1), len(g), side):
                t.add_points(g[lo:lo + side])
                kept = t._inc if kept is None else kept
                assert t._inc is kept, kw
            assert np.array_equal(t.simplices, one.simplices), kw
            assert np.array_equal(t.good, one.good), kw


@pytest.mark.parametrize("d", [2, 3, 4, 5, 6])
def test_hull_add_points_in_place_equals_one_shot(d):
    # random points, then a grid's points (ties on every facet) and
    # duplicates in batches; the kept kernel is the same object throughout
    rng = np.random.default_rng(50 + d)
    side = {2: 5, 3: 4, 4: 3, 5: 2, 6: 2}[d]
    grid = np.array(np.meshgrid(*[np.arange(side)] * d, indexing="ij"), dtype=float).reshape(d, -1).T / (side - 1)
    p = np.concatenate([rng.random((d + 4, d)) * 0.5 + 0.25, grid[rng.permutation(len(grid))],
                        rng.random((20, d))])
    p = np.concatenate([p, p[:6]])
    qc = "Qc" if d <= 4 else None  # Qc's coplanar points: Python-side, seconds on the 6D cube's 4440 facets
    one = flipflop.ConvexHull(p, qhull_options=qc)
    h = flipflop.ConvexHull(p[:d + 4], incremental=True, qhull_options=qc)
    assert h._inc is None  # the construction is the one-shot call's; the first add seeds the kernel
    kept, held = None, 0
    step = 9 if d <= 4 else 31
    for lo in range(d + 4, len(p), step):
        vertices, new = len(h.vertices), min(lo + step, len(p)) - lo
        h.add_points(p[lo:lo + step])
        if kept is None:  # seeded with the certified hull's vertices only, then the new points inserted
            kept = h._inc
            assert kept is not None and len(kept) == vertices + new
        else:
            assert h._inc is kept and len(kept) == held + new  # inserted in place, not rebuilt
        held = len(kept)
        assert np.array_equal(h._inc_index, np.unique(h._inc_index))  # an ascending subset: a monotone map
        assert np.array_equal(h.simplices, flipflop.ConvexHull(p[:lo + step]).simplices)
    for name in ("simplices", "vertices", "neighbors", "equations", "coplanar"):  # NaN: zero-area facets
        assert np.array_equal(getattr(h, name), getattr(one, name), equal_nan=name == "equations"), name
    assert (h.volume, h.area, h.npoints) == (one.volume, one.area, len(p))
    h.close()
    assert h._inc is None


@pytest.mark.parametrize("d", [2, 3, 4, 5])
def test_hull_add_points_in_place_with_good_and_inside_points(d):
    # QGn's hull leaves point n out (the kept kernel's points are a subset of
    # the others); batches wholly inside the hull (no vertex changes) and
    # batches that replace every vertex; one-shot answer, good included
    rng = np.random.default_rng(70 + d)
    p = np.concatenate([rng.random((30, d)), 0.4 + 0.2 * rng.random((25, d)), 3 * rng.random((25, d)) - 1])
    for opts in ("QG3", "QG-3", None):
        h = flipflop.ConvexHull(p[:30], incremental=True, qhull_options=opts)
        for lo in (30, 42, 55, 70):
            hi = {30: 42, 42: 55, 55: 70, 70: 80}[lo]
            before = h.simplices.copy()
            h.add_points(p[lo:hi])
            one = flipflop.ConvexHull(p[:hi], qhull_options=opts)
            for name in ("simplices", "vertices", "neighbors", "equations", "good"):
                assert np.array_equal(getattr(h, name), getattr(one, name)), (opts, lo, name)
            if hi <= 55:  # points inside the unit cube's hull: the hull is unchanged
                assert np.array_equal(h.simplices, before), (opts, lo)
        h.close()
        assert h._inc is None


def test_hull_seeded_kernel_refuses_what_is_not_a_closed_surface():
    # the seed is the caller's certified hull, checked only to be glued along
    # its ridges; a broken one is refused (ValueError), never used
    from flipflop import _flipflop
    p = np.random.default_rng(5).random((40, 3))
    h = flipflop.ConvexHull(p)
    v = np.unique(h.simplices)
    seed = np.searchsorted(v, h.simplices).astype(np.int64)
    seed[:, -2:] = seed[:, -1:-3:-1]
    nb = np.array(h.neighbors, dtype=np.int64)
    nb[:, -2:] = nb[:, -1:-3:-1]
    pv = np.ascontiguousarray(p[v])
    k = _flipflop.IncrementalHull(pv, 0, seed, nb)
    with pytest.raises(RuntimeError):  # nothing certified before an add
        k.attributes()
    k.add(np.concatenate([pv, [[0.5, 0.5, 0.5], [2.0, 2.0, 2.0]]]))
    full = flipflop.ConvexHull(np.concatenate([pv, [[0.5, 0.5, 0.5], [2.0, 2.0, 2.0]]]))
    assert np.array_equal(k.attributes()[0], full.simplices)
    bad_nb = nb.copy()
    bad_nb[0, 0], bad_nb[0, 1] = bad_nb[0, 1], bad_nb[0, 0]
    bad_seed = seed.copy()
    bad_seed[1, 0] = seed[0, 0] if seed[1, 0] != seed[0, 0] else seed[0, 1]
    for s_, n_ in ((seed, bad_nb), (bad_seed, nb), (seed[:-1], nb[:-1]), (seed + len(v), nb)):
        with pytest.raises(ValueError):
            _flipflop.IncrementalHull(pv, 0, np.ascontiguousarray(s_), np.ascontiguousarray(n_))


@pytest.mark.parametrize("cls, recomputing", [(flipflop.Delaunay, ({"backend": "reference"},)),
                                               (flipflop.ConvexHull, ({"backend": "reference"}, {"strict": True}))])
def test_add_points_bad_input_keeps_the_kept_kernel(cls, recomputing):
    p = np.random.default_rng(9).random((40, 3))
    h = cls(p[:10], incremental=True)
    assert h._inc is None  # 3D: built by the one-shot kernels, the kernel seeded at the first add
    h.add_points(p[10:10])  # an empty one
    assert h._inc is not None
    kept, before = h._inc, h.simplices.copy()
    held = len(kept)
    for bad_value in (np.nan, np.inf):
        bad = p[10:20].copy()
        bad[4, 0] = bad_value
        with pytest.raises(ValueError):
            h.add_points(bad)
        assert h._inc is kept and len(kept) == held and np.array_equal(h.simplices, before) and h.npoints == 10
    h.add_points(p[10:])
    assert h._inc is kept and np.array_equal(h.simplices, cls(p).simplices)
    for kw in recomputing:  # these recompute: the same answer
        r = cls(p[:10], incremental=True, **kw)
        r.add_points(p[10:])
        assert getattr(r, "_inc", None) is None
        assert np.array_equal(r.simplices, cls(p, **kw).simplices)


# ---- bad input: what scipy raises -----------------------------------------------------

def test_add_points_without_incremental_or_after_close():
    p = np.random.default_rng(0).random((20, 3))
    for ours, theirs in ((flipflop.Delaunay, ss.Delaunay), (flipflop.ConvexHull, ss.ConvexHull)):
        for obj in (ours(p), theirs(p)):
            with pytest.raises(RuntimeError, match="incremental"):
                obj.add_points(p[:2])
        for obj in (ours(p, incremental=True), theirs(p, incremental=True)):
            obj.close()
            obj.close()  # twice is fine
            with pytest.raises(RuntimeError, match="incremental"):
                obj.add_points(p[:2])
        for obj in (ours(p, incremental=True), theirs(p, incremental=True)):
            with pytest.raises(ValueError):
                obj.add_points(p[:2, :2])
        t = ours(p, incremental=True)
        before = t.simplices.copy()
        with pytest.raises(ValueError):
            t.add_points(np.array([[np.nan, 0.5, 0.5]]))  # scipy's hull takes NaN here; flipflop refuses it
        assert np.array_equal(t.simplices, before) and t.npoints == 20


def test_qhull_options_accepted_applied_and_refused():
    p = np.random.default_rng(1).random((30, 3))
    plain = flipflop.Delaunay(p).simplices
    for opts in ("Qbb Qc Qz Qx QJ Qt Q12", "Qbb Qc Qz Q12", "Qbb Qc Qz Qx Q12", "QJ1e-10 Pp", "QbB", "", b"Qt Qbb",
                 "Qbb Qc Qz Qx QJ Qt Q12 QG3 Pp"):
        t = flipflop.Delaunay(p, qhull_options=opts)
        if "QG" not in str(opts):
            assert np.array_equal(t.simplices, plain)
        else:  # the triangulation of the other points, as scipy
            assert sets(t.simplices) == sets(ss.Delaunay(np.delete(p, 3, 0)).simplices + (np.arange(29) >= 3)[
                ss.Delaunay(np.delete(p, 3, 0)).simplices])
        h = flipflop.ConvexHull(p, qhull_options=opts)
        if "QG" not in str(opts):
            assert np.array_equal(h.simplices, flipflop.ConvexHull(p).simplices)
    for bad in ("Foo", "Qbb Zz", "QGx", "Qu", "QG3 QG4", "QJx", "Qbb Qc Qv"):
        for cls in (flipflop.Delaunay, flipflop.ConvexHull):
            with pytest.raises(ValueError, match="qhull option"):
                cls(p, qhull_options=bad)
            with pytest.raises(RuntimeError):  # as scipy's QhullError
                cls(p, qhull_options=bad)
    for bad in ("Zz", "QGx", "QG40"):  # scipy refuses these too, with QhullError (a RuntimeError)
        with pytest.raises(RuntimeError):
            ss.ConvexHull(p, qhull_options=bad)
    for cls in (flipflop.Delaunay, flipflop.ConvexHull):
        with pytest.raises(ValueError, match="30 points"):
            cls(p, qhull_options="QG30")
        with pytest.raises(ValueError):
            cls(p, qhull_options=5)


def test_bad_input_raises_like_scipy():
    p = np.random.default_rng(2).random((20, 3))
    nan = p.copy()
    nan[3, 1] = np.nan
    for ours, theirs in ((flipflop.Delaunay, ss.Delaunay), (flipflop.ConvexHull, ss.ConvexHull)):
        for bad in (nan, np.zeros((10, 1)), [["a", "b"], ["c", "d"], ["e", "f"]]):
            with pytest.raises(ValueError):
                theirs(bad)
            with pytest.raises(ValueError):
                ours(bad)
        with pytest.raises(ValueError):
            ours(p[:, 0])  # scipy: IndexError
        with pytest.raises(ValueError):
            ours(p[None])  # scipy crashes (segmentation fault) on this one
    with pytest.raises(ValueError, match="furthest_site"):
        flipflop.Delaunay(p, furthest_site="yes")
    with pytest.raises(ValueError, match="furthest_site"):
        flipflop.Delaunay(p, furthest_site=True, strict=True)
    with pytest.raises(ValueError, match="furthest_site"):
        flipflop.Delaunay(p, furthest_site=True, weights=np.zeros(len(p)))
    with pytest.raises(ValueError, match="furthest_site"):
        flipflop.Delaunay(p, furthest_site=True, backend="cuda-omp")
    t = flipflop.Delaunay(p)
    with pytest.raises(ValueError):
        t.plane_distance(p[:, :2])
    with pytest.raises(ValueError):
        ss.Delaunay(p).plane_distance(p[:, :2])


# ---- the exact sign helper behind good, coplanar and transform's NaN rows -------------

@pytest.mark.parametrize("n", [2, 3, 4, 5, 6])
def test_det_signs_equal_a_fraction_oracle(n):
    """flipflop._det_signs (float filter, then Bareiss on integers) against
    fdet above on matrices that are singular, a few ulps from singular, or
    at extreme magnitudes."""
    rng = np.random.default_rng(50 + n)
    mats = []
    for k in range(60):
        m = rng.integers(-3, 4, size=(n, n)).astype(float)
        if k % 3 == 0:
            m[-1] = m[0] + m[1]  # singular
        elif k % 3 == 1:
            m[-1] = m[0] + m[1]
            m[-1, k % n] = np.nextafter(m[-1, k % n], np.inf)  # an ulp from singular
        m *= [1e-300, 1e300, 1.0, 0.1][k % 4] if k % 5 == 0 else 1.0
        mats.append(m)
    mats = np.array(mats)
    want = [int(np.sign(fdet([F(r) for r in m]))) for m in mats]
    got = flipflop._det_signs(mats, lambda i: [F(r) for r in mats[i]])
    assert got.tolist() == want
    assert 0 in want and 1 in want and -1 in want


# ---- ConvexHull in 4D and 5D (the canonical Delaunay triangulation's boundary) --------

@pytest.mark.parametrize("d,n", [(4, 60), (5, 30)])
def test_hull_4d_5d_equals_scipy(d, n):
    p = np.random.default_rng(60 + d).random((n, d))
    h, s = flipflop.ConvexHull(p), ss.ConvexHull(p)
    assert sets(h.simplices) == sets(s.simplices)
    assert h.vertices.tolist() == sorted(s.vertices.tolist())
    assert np.isclose(h.volume, s.volume, rtol=1e-12) and np.isclose(h.area, s.area, rtol=1e-12)
    where = index_of(s.simplices)
    k = [where[frozenset(r)] for r in h.simplices.tolist()]
    assert np.allclose(h.equations, s.equations[k], atol=1e-12)  # both outward
    for i, r in enumerate(h.simplices):
        for j in range(d):
            a, b = h.neighbors[i, j], s.neighbors[k[i], list(s.simplices[k[i]]).index(r[j])]
            assert k[a] == b
    g = int(s.vertices[0])
    hg, sg = flipflop.ConvexHull(p, qhull_options=f"QG{g}"), ss.ConvexHull(p, qhull_options=f"QG{g}")
    assert sets(hg.simplices[hg.good]) == sets(sg.simplices[sg.good]) and hg.good.any()
    with pytest.raises(ValueError, match="strict"):
        flipflop.ConvexHull(p, strict=True)


@pytest.mark.parametrize("d", [4, 5])
def test_hull_4d_5d_on_a_grid_is_the_hull_by_definition(d):
    """Every point on the inner side of, or on, every facet (exactly, in
    integers), every facet of non-zero size, each ridge in two facets, the
    outward orientation; and with Qc the boundary points that are not
    vertices."""
    k = 3 if d == 4 else 2
    p = grid(k, d)
    if d == 5:
        p = np.vstack([p, [[0.5, 0.5, 0.5, 0.5, 0.0], [0.5, 0.5, 0.5, 0.5, 0.5]]])  # on a face, inside
    h = flipflop.ConvexHull(p, qhull_options="Qc")
    P = [[Fraction(x) for x in r] for r in p.tolist()]
    for f in h.simplices.tolist():
        rows = [[P[v][c] - P[f[0]][c] for c in range(d)] for v in f[1:]]
        signs = {int(np.sign(fdet(rows + [[P[x][c] - P[f[0]][c] for c in range(d)]]))) for x in range(len(p))}
        assert signs <= {0, -1}  # outward: the points are inside or on the plane
        # {0}: a facet of zero size (the canonical answer's on degenerate input;
        # a hyperplane holding every point is impossible, the input spans R^d)
    ridges = {}
    for f in h.simplices.tolist():
        for r in combinations(sorted(f), d - 1):
            ridges[r] = ridges.get(r, 0) + 1
    assert set(ridges.values()) == {2}
    corners = {i for i, x in enumerate(p.tolist()) if all(c in (0.0, k - 1.0) for c in x)}
    assert len(corners) == 2 ** d and set(h.vertices.tolist()) >= corners
    assert np.isclose(h.volume, (k - 1.0) ** d, rtol=1e-13)
    assert np.isclose(h.area, 2 * d * (k - 1.0) ** (d - 1), rtol=1e-13)
    want = boundary_oracle(p, 0.0, k - 1.0) - set(h.vertices.tolist())
    assert set(h.coplanar[:, 0].tolist()) == want
    assert len(want) > 0 if d == 4 else 33 not in want and 33 not in h.vertices


@pytest.mark.parametrize("p", [grid(4, 3), grid(3, 3), grid(5, 2), np.vstack([grid(3, 3), grid(3, 3)]),
                               np.random.default_rng(9).integers(0, 3, (40, 3)).astype(float),
                               np.random.default_rng(9).integers(0, 3, (30, 2)).astype(float)],
                         ids=["grid4^3", "grid3^3", "grid5^2", "grid3^3x2", "int3d", "int2d"])
def test_the_4d_derivation_holds_where_both_exist(p):
    """The premise of the 4D/5D hull (the canonical Delaunay triangulation's
    boundary facets are the canonical hull's facets, degenerate input
    included), checked in 2D and 3D, where the hull kernels share no code
    with the triangulation."""
    assert sets(flipflop.ConvexHull(p).simplices) == sets(flipflop.Delaunay(p).convex_hull)


def test_hull_coplanar_where_floating_point_cannot_tell():
    """Points on the plane z = 3x/8 + 5y/8 + 1/4 with 42-bit coordinates
    (exactly on it: checked with Fractions) whose float orientation tests
    round (products of 80 bits; most are not 0 in floating point), inside a
    triangle of such points (the strict hull's base: one facet), and the same
    points an ulp lower: only the first are coplanar."""
    rng = np.random.default_rng(70)
    u = 2.0 ** -42
    corners = np.array([[0.01, 0.01], [0.48, 0.01], [0.01, 0.48]]) + rng.integers(1, 2 ** 20, (3, 2)) * u
    xy = np.vstack([corners, 0.05 + rng.integers(1, 2 ** 40, size=(40, 2)) * (0.17 * u)])
    xy = np.round(xy / u) * u
    on = np.c_[xy, 0.375 * xy[:, 0] + 0.625 * xy[:, 1] + 0.25]
    assert all(Fraction(z) == Fraction(3, 8) * Fraction(x) + Fraction(5, 8) * Fraction(y) + Fraction(1, 4)
               for x, y, z in on.tolist())
    below = on[3:].copy()
    below[:, 2] = np.nextafter(below[:, 2], -np.inf)
    apex = np.array([[0.2, 0.2, -5.0]])
    p = np.vstack([apex, on, below])
    for strict in (False, True):
        h = flipflop.ConvexHull(p, qhull_options="Qc", strict=strict)
        assert set(h.coplanar[:, 0].tolist()) == set(range(1, 44)) - set(h.vertices.tolist())
        if strict:
            assert h.vertices.tolist() == [0, 1, 2, 3] and len(h.coplanar) == 40


# ---- furthest_site=True ------------------------------------------------------------------
# Random points (general position: one furthest-site triangulation, Qhull's
# and flipflop's alike); the defining property checked exactly: every
# simplex's circumsphere holds every input point (closed), i.e. every lifted
# point lies on or below the simplex's lifted hyperplane. (Degenerate sets:
# test_oracle_degenerate.py, against the independent brute force.)

def _circumsphere_holds_all(points, simplex):
    """Exact: every point p has |p - c|^2 <= r^2 for the circumsphere
    (c, r) of the simplex, decided as the sign of the lifted determinant."""
    P = [[Fraction(float(c)) for c in row] for row in points]
    S = [P[i] for i in simplex]
    d = len(P[0])

    def lifted(p, o):
        r = [a - b for a, b in zip(p, o)]
        return r + [sum(x * x for x in r)]

    o = S[0]
    assert fdet([lifted(v, o)[:d] for v in S[1:]]) != 0

    def side(p):  # zero on the circumsphere, one sign inside, the other outside
        return fdet([lifted(v, o) for v in S[1:]] + [lifted(p, o)])

    centroid = [sum(v[j] for v in S) / (d + 1) for j in range(d)]  # strictly inside the sphere
    inside = side(centroid)
    assert inside != 0
    return all(side(p) * inside >= 0 for p in P)


@pytest.mark.parametrize("d,n", [(2, 60), (3, 40), (4, 25)])
def test_furthest_site_random_equals_scipy_and_holds_every_point(d, n):
    rng = np.random.default_rng(100 + d)
    p = rng.standard_normal((n, d))
    ours, theirs = flipflop.Delaunay(p, furthest_site=True), ss.Delaunay(p, furthest_site=True)
    assert ours.furthest_site is True and theirs.furthest_site
    assert {tuple(sorted(s)) for s in ours.simplices.tolist()} == {tuple(sorted(s)) for s in theirs.simplices.tolist()}
    hull = ss.ConvexHull(p)
    assert sorted(np.unique(ours.simplices).tolist()) == sorted(hull.vertices.tolist())
    assert sorted(ours.redundant.tolist()) == sorted(set(range(n)) - set(hull.vertices.tolist()))
    for s in ours.simplices[:12]:
        assert _circumsphere_holds_all(p, s)
    # (the check can fail: a Delaunay simplex's circumsphere is empty instead)
    assert not any(_circumsphere_holds_all(p, s) for s in flipflop.Delaunay(p).simplices[:5])
    # equations: outward of the upper hull (up), every lifted point on or below
    assert (ours.equations[:, d] > 0).all() and (theirs.equations[:, d] > 0).all()
    dist = ours.plane_distance(p)
    assert (dist <= 1e-9 * np.abs(ours.lift_points(p)).max()).all()
    # the simplices tile the hull: find_simplex locates points inside it
    q = p[hull.vertices].mean(axis=0) + 0.01 * rng.standard_normal((50, d))
    found = ours.find_simplex(q)
    assert (found >= 0).all()
    bary = np.einsum("ijk,ik->ij", ours.transform[found, :d], q - ours.transform[found, d])
    assert (bary >= -1e-9).all() and (bary.sum(axis=1) <= 1 + 1e-9).all()
    assert (ours.find_simplex(p.max(axis=0) + 1.0) == -1).all()
    assert ours.coplanar.shape == (0, 3) == theirs.coplanar.shape


def test_furthest_site_add_points_and_good():
    rng = np.random.default_rng(7)
    p = rng.random((30, 2))
    t = flipflop.Delaunay(p[:20], furthest_site=True, incremental=True)
    t.add_points(p[20:])
    whole = flipflop.Delaunay(p, furthest_site=True)
    assert np.array_equal(t.simplices, whole.simplices) and t.furthest_site
    # QG0: the simplices whose circumsphere point 0 lies strictly outside of
    # (visible from its lifted point), the triangulation that of the others
    g = flipflop.Delaunay(p, furthest_site=True, qhull_options="QG0")
    others = np.arange(1, 30)
    for s, good in zip(g.simplices, g.good):
        assert 0 not in s
        centre_ok = _circumsphere_holds_all(np.concatenate([p[others], p[:1]]), [list(others).index(v) for v in s])
        assert bool(good) == (not centre_ok)


@pytest.mark.parametrize("d", [2, 3, 4])
def test_index_dtypes_are_scipys(d):
    # every index array has scipy's dtype (np.intc; Voronoi.point_region np.intp)
    p = np.random.default_rng(70 + d).random((40, d))
    pairs = [(flipflop.Delaunay(p), ss.Delaunay(p)), (flipflop.ConvexHull(p), ss.ConvexHull(p))]
    for ours, theirs in pairs:
        for name in ("simplices", "neighbors", "coplanar", "vertices", "convex_hull", "vertex_to_simplex"):
            if not hasattr(theirs, name) or name == "vertices" and isinstance(theirs, ss.Delaunay):
                continue
            assert getattr(ours, name).dtype == getattr(theirs, name).dtype, name
    t, s = pairs[0]
    assert t.find_simplex(p[:5]).dtype == s.find_simplex(p[:5]).dtype
    assert all(a.dtype == b.dtype for a, b in zip(t.vertex_neighbor_vertices, s.vertex_neighbor_vertices))
    assert t.good.dtype == s.good.dtype
    if d > 2:
        v, w = flipflop.Voronoi(p), ss.Voronoi(p)
        assert v.ridge_points.dtype == w.ridge_points.dtype and v.point_region.dtype == w.point_region.dtype


@pytest.mark.parametrize("d,n", [(6, 300), (7, 120), (8, 50), (9, 35)])
def test_convex_hull_6d_to_9d_equals_scipy(d, n):
    # 6D..9D hulls (kernels_cpu/rtd/hull_d; 8D, 9D: orientations of 9 and 10
    # rows, the predicates' run-time filters and GMP): scipy's facets, measures and
    # equations on random input; the definition exactly on a lattice (every
    # point on the inner side of every facet, Fraction arithmetic)
    p = np.random.default_rng(d).standard_normal((n, d))
    ours, theirs = flipflop.ConvexHull(p), ss.ConvexHull(p)
    assert {tuple(sorted(x)) for x in ours.simplices.tolist()} == {tuple(sorted(x)) for x in theirs.simplices.tolist()}
    assert ours.volume == pytest.approx(theirs.volume, rel=1e-12)
    assert ours.area == pytest.approx(theirs.area, rel=1e-12)
    assert sorted(ours.vertices.tolist()) == sorted(theirs.vertices.tolist())
    order = np.lexsort(ours.equations.T[::-1])
    order_s = np.lexsort(theirs.equations.T[::-1])
    assert np.allclose(ours.equations[order], theirs.equations[order_s], atol=1e-12)
    if d == 6:  # the 6-cube's corners: every facet's plane holds 32 points (exact ties)
        g = np.array(np.meshgrid(*[np.arange(2.0)] * d)).reshape(d, -1).T
        want_volume = 1.0
    else:  # 7D: the cross-polytope and its centre (8-point orientations tie only at the centre's planes)
        g = np.vstack([np.zeros(d), np.eye(d), -np.eye(d)])
        want_volume = 2.0 ** d / math.factorial(d)
    h = flipflop.ConvexHull(g)
    assert h.volume == pytest.approx(want_volume, rel=1e-14)
    # backend 'reference' (the boundary of RT+1's canonical triangulation,
    # another algorithm): the same canonical facets, on the tied lattice
    # (7D..9D: 15..19 points) and on a few random points
    if d >= 7:
        assert np.array_equal(flipflop.ConvexHull(g, backend="reference").simplices, h.simplices)
    q = p[:d + 6]
    assert np.array_equal(flipflop.ConvexHull(q, backend="reference").simplices, flipflop.ConvexHull(q).simplices)
    F = Fraction
    for f in h.simplices[:: max(1, len(h.simplices) // 40)]:
        base = [F(x) for x in g[f[0]]]
        rows = [[F(x) - b for x, b in zip(g[v], base)] for v in f[1:]]
        for x in range(len(g)):
            if x in f:
                continue
            m = rows + [[F(c) - b for c, b in zip(g[x], base)]]
            assert fdet(m) <= 0  # outward facets: every point inside or on



# ---- Delaunay in 6D..9D (the cavity kernel; power tests of 8..11 rows) -------------------------

@pytest.mark.parametrize("d,n", [(6, 120), (7, 60), (8, 35), (9, 25)])
def test_delaunay_6d_to_9d_equals_scipy(d, n):
    """scipy's simplices, neighbours (after the map between the simplices),
    barycentric coordinates from `transform`, find_simplex and the convex
    hull's facets on random input; the 'reference' backend (RT+1) gives the
    same bytes; a strict view is refused there."""
    rng = np.random.default_rng(900 + d)
    p = rng.random((n, d))
    t, s = flipflop.Delaunay(p), ss.Delaunay(p)
    assert sets(t.simplices) == sets(s.simplices)
    r = flipflop.Delaunay(p, backend="reference")
    assert np.array_equal(r.simplices, t.simplices)
    where = index_of(s.simplices)
    k = [where[frozenset(x)] for x in t.simplices.tolist()]
    for i, x in enumerate(t.simplices.tolist()):
        for j in range(d + 1):
            a = t.neighbors[i, j]
            b = s.neighbors[k[i], list(s.simplices[k[i]]).index(x[j])]
            assert (a == -1 and b == -1) or k[a] == b
    x = rng.random(d)
    for i in range(0, len(t.simplices), max(1, len(t.simplices) // 50)):
        def bary(T, simp):
            c = T[:d] @ (x - T[d])
            return dict(zip(simp.tolist(), np.append(c, 1 - c.sum())))
        ours, theirs = bary(t.transform[i], t.simplices[i]), bary(s.transform[k[i]], s.simplices[k[i]])
        for v in ours:
            assert ours[v] == pytest.approx(theirs[v], rel=1e-8, abs=1e-8)
    q = rng.random((400, d))
    fs, gs = t.find_simplex(q), s.find_simplex(q)
    assert np.array_equal(fs >= 0, gs >= 0)
    inside = fs >= 0
    assert all(k[a] == b or frozenset(t.simplices[a]) == frozenset(s.simplices[b])
               for a, b in zip(fs[inside], gs[inside]))
    assert sets(t.convex_hull) == sets(s.convex_hull)
    with pytest.raises(ValueError, match="strict"):
        flipflop.Delaunay(p, strict=True)


@pytest.mark.parametrize("d", [6, 7, 8, 9])
def test_delaunay_6d_to_9d_is_delaunay_by_definition_on_degenerate_input(d):
    """The canonical answer on a degenerate set (the cross-polytope, its
    centre, a duplicate of a corner): every simplex has non-negative volume
    and no point strictly inside its circumsphere, exactly in Fractions; the
    simplices cover the hull's volume; every point is a vertex or redundant
    (the perturbation separates the two copies, so both may be vertices of
    zero-volume simplices: the canonical answer's)."""
    p = np.vstack([np.eye(d), -np.eye(d), np.zeros((1, d)), np.eye(d)[:1]])
    t = flipflop.Delaunay(p)
    assert sorted(set(t.simplices.ravel().tolist()) | set(t.redundant.tolist())) == list(range(len(p)))
    F = Fraction
    P = [[F(c) for c in row] for row in p.tolist()]
    total = F(0)
    for simp in t.simplices.tolist():
        base = P[simp[0]]
        rows = [[a - b for a, b in zip(P[v], base)] for v in simp[1:]]
        vol = fdet(rows)
        assert vol >= 0
        total += vol
        if vol == 0:
            continue
        for x in range(len(p)):
            if x in simp:
                continue
            # in-sphere: det of (v - x, |v - x|^2) rows, of the sign _INSPHERE[d] when x is inside
            m = [[a - b for a, b in zip(P[v], P[x])] for v in simp]
            m = [r + [sum(c * c for c in r)] for r in m]
            assert fdet(m) * flipflop._INSPHERE[d] <= 0, (simp, x)
    assert total == F(2 ** d)  # d! times the cross-polytope's volume 2^d / d!
