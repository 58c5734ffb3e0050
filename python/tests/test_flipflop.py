"""pytest suite of the Python package (make test runs it through ctest,
`python.pytest`, with FLIPFLOP_BINARY naming the command-line tool of the same
build).

  * equal to scipy.spatial (Qhull) on random input, as sets of simplices with
    orientation normalised, with the same volumes and point location;
  * certified and byte-identical to the command line on every generator
    family, degenerate ones included, and on random degenerate integer input
    (hypothesis);
  * certify() rejects flipped, missing and non-regular outputs and accepts
    scipy's correct ones;
  * the attributes (ConvexHull's neighbors, vertices, equations, volume, area;
    Delaunay's neighbors and convex_hull), computed in C++, equal to
    dictionaries and numpy recomputing them from points and simplices, and to
    scipy's;
  * bad input raises ValueError, never crashes;
  * 3D: the cpu kernel (the default) returns the reference's simplices and
    redundant points on random, degenerate and weighted input, equals scipy
    on general-position input (oracle), and find_simplex agrees with an
    exact integer brute force, also on degenerate and strict triangulations.
"""
import os
import subprocess

import numpy as np
import pytest
import scipy.spatial as ss
from hypothesis import given, settings, strategies as st

import flipflop

FLIPFLOP = os.environ.get("FLIPFLOP_BINARY")
needs_cli = pytest.mark.skipif(not FLIPFLOP, reason="FLIPFLOP_BINARY (the command-line tool) not given")


def rows(a):
    return [tuple(int(x) for x in r) for r in a]


def as_text(simplices):
    return "".join(" ".join(str(int(x)) for x in r) + "\n" for r in simplices)


def cli(*args):
    r = subprocess.run([FLIPFLOP, *map(str, args)], capture_output=True, text=True)
    return r.returncode, r.stdout, r.stderr


def write_xyz(path, pts, w=None):
    with open(path, "w") as f:
        for i, p in enumerate(pts):
            vals = [*p] + ([] if w is None else [w[i]])
            f.write(" ".join(repr(float(x)) for x in vals) + "\n")


# ---- equal to scipy on random input ---------------------------------------------

@pytest.mark.parametrize("seed", range(5))
def test_hull3_equals_scipy(seed):
    p = np.random.default_rng(seed).random((400 + 100 * seed, 3))
    h, s = flipflop.ConvexHull(p), ss.ConvexHull(p)
    assert {tuple(sorted(t)) for t in rows(h.simplices)} == {tuple(sorted(t)) for t in rows(s.simplices)}
    assert list(h.vertices) == sorted(s.vertices)
    assert h.volume == pytest.approx(s.volume, rel=1e-12)
    assert h.area == pytest.approx(s.area, rel=1e-12)
    # equations: unit outward normals, every point inside
    assert np.allclose(np.linalg.norm(h.equations[:, :3], axis=1), 1)
    assert (p @ h.equations[:, :3].T + h.equations[:, 3] <= 1e-12).all()
    assert flipflop.certify("hull3", p, h.simplices, canonical=True)


@pytest.mark.parametrize("seed", range(5))
def test_hull2_equals_scipy(seed):
    p = np.random.default_rng(10 + seed).random((1000, 2))
    h, s = flipflop.ConvexHull(p), ss.ConvexHull(p)
    v, sv = list(h.vertices), list(s.vertices)  # both counter-clockwise
    k = sv.index(v[0])
    assert v == sv[k:] + sv[:k]
    assert h.volume == pytest.approx(s.volume, rel=1e-12)
    assert h.area == pytest.approx(s.area, rel=1e-12)
    assert flipflop.certify("hull2", p, h.simplices, canonical=True)
    assert flipflop.certify("hull2", p, h.vertices, canonical=True)
    for backend, threads in (("reference", 0), ("cpu", 1), ("cpu", 2)):  # every backend, the same answer
        assert list(flipflop.ConvexHull(p, backend=backend, threads=threads).vertices) == v


@pytest.mark.parametrize("d,n", [(2, 2000), (3, 600), (4, 150)])
def test_delaunay_equals_scipy(d, n):
    rng = np.random.default_rng(d)
    p = rng.random((n, d))
    t, s = flipflop.Delaunay(p), ss.Delaunay(p)
    assert {tuple(sorted(x)) for x in rows(t.simplices)} == {tuple(sorted(x)) for x in rows(s.simplices)}
    assert len(t.redundant) == 0
    # positive volume in the volume convention, every simplex
    v = np.array([np.linalg.det(p[x[1:]] - p[x[0]]) for x in t.simplices])
    assert (v > 0).all()
    # point location: the same simplex (as a vertex set) as scipy's
    q = rng.random((500, d)) * 1.2 - 0.1
    mine, theirs = t.find_simplex(q), s.find_simplex(q)
    assert ((mine >= 0) == (theirs >= 0)).all()
    for a, b in zip(mine, theirs):
        if a >= 0:
            assert sorted(t.simplices[a]) == sorted(s.simplices[b])
    # neighbours: across the facet opposite vertex j
    for i, x in enumerate(t.simplices[:50]):
        for j in range(d + 1):
            k = t.neighbors[i, j]
            if k >= 0:
                assert set(x) - {x[j]} <= set(t.simplices[k])
    assert len(t.convex_hull) == len(s.convex_hull)
    assert flipflop.certify("delaunay", p, t.simplices, canonical=True)
    assert flipflop.certify("delaunay", p, s.simplices, orient=True)  # scipy's, at the exact level
    # every backend, the same answer (cpu: the default; in 4D and 5D the
    # cavity-insertion kernel, against RT+1)
    for backend, threads in (("reference", 0), ("cpu", 1), ("cpu", 2)):
        assert (flipflop.Delaunay(p, backend=backend, threads=threads).simplices == t.simplices).all()
    if d > 3:
        with pytest.raises(ValueError, match="backend"):
            flipflop.Delaunay(p, backend="cuda-omp")  # the GPU kernels are 2D and 3D


def test_gpu_backends_return_the_reference_answer():
    # The GPU kernels of this build (flipflop.gpu_backends): "cuda-omp", their
    # thrust/OpenMP build, and "cuda" where nvcc built them (RuntimeError, one
    # line, without a device). ctest sets FLIPFLOP_EXPECT_GPU_BACKENDS where
    # the build has them, so that they are tested there, not skipped.
    expected = os.environ.get("FLIPFLOP_EXPECT_GPU_BACKENDS", "")
    for b in filter(None, expected.split(",")):
        assert b in flipflop.gpu_backends, f"this build should have the {b!r} backend: {flipflop.gpu_backends}"
    if not flipflop.gpu_backends:
        pytest.skip("this build of the package has no GPU kernels (no CUDA toolkit headers or OpenMP)")
    rng = np.random.default_rng(7)
    grid2 = np.array([(x, y) for x in range(9) for y in range(9)], dtype=np.float64)
    grid3 = np.array([(x, y, z) for x in range(5) for y in range(5) for z in range(5)], dtype=np.float64)
    inputs2 = [rng.random((3000, 2)), np.vstack([grid2, grid2[::7]])]  # random; cocircular, collinear, duplicated
    inputs3 = [rng.standard_normal((2000, 3)), np.vstack([grid3, grid3[::9]])]  # random; coplanar, duplicated
    for backend in ("cuda-omp", "cuda"):  # "cuda" outside gpu_backends: the RuntimeError below
        try:
            for p in inputs2:
                assert list(flipflop.ConvexHull(p, backend=backend).vertices) == list(
                    flipflop.ConvexHull(p, backend="cpu").vertices)
                w = (np.arange(len(p)) % 3).astype(np.float64) * (0.25 if len(p) < 100 else 1e-5)
                for weights in (None, w):
                    a = flipflop.Delaunay(p, weights=weights, backend=backend)
                    b = flipflop.Delaunay(p, weights=weights, backend="cpu")
                    assert (a.simplices == b.simplices).all()
                    assert list(a.redundant) == list(b.redundant)
            for p in inputs3:
                assert (flipflop.ConvexHull(p, backend=backend).simplices ==
                        flipflop.ConvexHull(p, backend="cpu").simplices).all()
                w = (np.arange(len(p)) % 3).astype(np.float64) * (0.25 if len(p) < 200 else 1e-3)
                for weights in (None, w):  # kernels_cuda/rt3
                    a = flipflop.Delaunay(p, weights=weights, backend=backend)
                    b = flipflop.Delaunay(p, weights=weights, backend="cpu")
                    assert (a.simplices == b.simplices).all()
                    assert (a.neighbors == b.neighbors).all()
                    assert list(a.redundant) == list(b.redundant)
            with pytest.raises(ValueError, match="backend"):
                flipflop.Delaunay(np.random.default_rng(1).random((40, 4)), backend=backend)  # 2D and 3D only
        except RuntimeError as e:  # "cuda" not built with nvcc, or without a usable device: one line
            assert backend == "cuda" and "cuda" in str(e) and "\n" not in str(e), str(e)


def test_weighted_delaunay_backends_agree_on_degenerate_input():
    # a 9x9 grid (cocircular quadruples, collinear boundary points) with
    # duplicated points and integer weights: the cpu kernel and the reference
    # give the same canonical simplices and the same redundant points
    g = np.array([(x, y) for x in range(9) for y in range(9)], dtype=np.float64)
    p = np.vstack([g, g[::7]])
    w = (np.arange(len(p)) % 3).astype(np.float64) * 0.25
    for weights in (None, w):
        a = flipflop.Delaunay(p, weights=weights, backend="cpu", threads=2)
        b = flipflop.Delaunay(p, weights=weights, backend="reference")
        assert (a.simplices == b.simplices).all()
        assert list(a.redundant) == list(b.redundant)
        assert flipflop.certify("delaunay", p, a.simplices, weights=weights, canonical=True)


def test_weighted_delaunay_reports_redundant_points():
    rng = np.random.default_rng(3)
    p = rng.random((400, 2))
    w = rng.random(400) * 0.01
    t = flipflop.Delaunay(p, weights=w)
    assert len(t.redundant) > 0
    assert set(t.redundant) == set(range(400)) - set(np.unique(t.simplices))
    assert flipflop.certify("delaunay", p, t.simplices, weights=w, canonical=True)
    assert not flipflop.certify("delaunay", p, t.simplices, canonical=True)  # the weights matter


# ---- certify ---------------------------------------------------------------------

def test_certify_accepts_scipy_and_rejects_broken_outputs():
    rng = np.random.default_rng(7)
    p = rng.random((300, 3))
    s = ss.ConvexHull(p)
    assert flipflop.certify("hull3", p, s.simplices, orient=True)  # scipy does not orient its facets
    h = flipflop.ConvexHull(p)
    flipped = h.simplices.copy()
    flipped[0] = flipped[0][::-1]
    r = flipflop.certify("hull3", p, flipped)
    assert not r and r.condition
    assert not flipflop.certify("hull3", p, h.simplices[1:])  # a missing facet

    p2 = rng.random((300, 2))
    sd = ss.Delaunay(p2)
    assert flipflop.certify("delaunay", p2, sd.simplices, orient=True)
    t = flipflop.Delaunay(p2)
    # a non-regular triangulation: flip one interior edge
    tri = [list(x) for x in t.simplices]
    i = next(i for i in range(len(tri)) if (t.neighbors[i] >= 0).all())
    j = 0
    k = int(t.neighbors[i, j])
    a = tri[i][j]
    b = next(x for x in tri[k] if x not in tri[i])
    e1, e2 = [x for x in tri[i] if x != a]
    new = [[a, e1, b], [a, b, e2]]
    rest = [x for n, x in enumerate(tri) if n not in (i, k)]
    bad = np.array(rest + new)
    r = flipflop.certify("delaunay", p2, bad, orient=True)
    assert not r
    assert "regular" in r.condition or "orientation" in r.condition or "manifold" in r.condition, r


# ---- the attributes against independent computations -------------------------------
# ConvexHull's neighbors, vertices, equations, volume and area are computed in
# C++ in one pass over the certified facets (module.cpp), Delaunay's neighbors
# by bucketing facets under their smallest vertex: here they are recomputed
# from points and simplices alone, with dictionaries and numpy.

def facet_neighbors(simplices):
    """neighbors by a dictionary from sorted facets to (simplex, slot)."""
    k = simplices.shape[1]
    seen, out = {}, -np.ones_like(simplices)
    for i, x in enumerate(rows(simplices)):
        for j in range(k):
            f = tuple(sorted(x[:j] + x[j + 1:]))
            if f in seen:
                a, b = seen.pop(f)
                out[i, j], out[a, b] = a, i
            else:
                seen[f] = (i, j)
    return out


def hull_measures(p, simplices):
    """(equations, volume, area) in numpy: unit normal of (b - a) x (c - a)
    (3D) or the edge turned clockwise (2D), offset -n.a, volume and area from
    the divergence theorem about the first vertex; from the points scaled by
    2^k (exact) with max |p| in [1/2, 1), each normal scaled by 2^j with its
    largest component in [1/2, 1) before its length is taken (no overflow or
    underflow short of the result's)."""
    k = -np.frexp(np.abs(p[np.unique(simplices)]).max())[1]
    q = np.ldexp(p, k)
    o = q[simplices[0, 0]]
    a, b = (q[simplices[:, j]] for j in range(2))
    if p.shape[1] == 3:
        c = q[simplices[:, 2]]
        n = np.cross(b - a, c - a)
        area_power, volume_power = 2, 3
        volume = np.einsum("ij,ij->i", a - o, np.cross(b - o, c - o)).sum() / 6
    else:
        e = b - a
        n = np.stack([e[:, 1], -e[:, 0]], axis=1)
        area_power, volume_power = 1, 2
        volume = 0.5 * ((a - o)[:, 0] * (b - o)[:, 1] - (b - o)[:, 0] * (a - o)[:, 1]).sum()
    m = np.abs(n).max(axis=1)
    j = np.frexp(m)[1]
    w = np.ldexp(n, -j[:, None])
    length = np.linalg.norm(w, axis=1)
    with np.errstate(invalid="ignore"):  # zero-area facets: NaN normals
        u = w / length[:, None]
    with np.errstate(over="ignore", under="ignore"):  # inf or 0 where the true value is not a double
        area = np.ldexp(np.ldexp(length, j).sum() * (0.5 if p.shape[1] == 3 else 1.0), -area_power * k)
        volume = np.ldexp(volume, -volume_power * k)
    offset = -np.einsum("ij,ij->i", u, p[simplices[:, 0]])
    return np.hstack([u, offset[:, None]]), volume, area


def check_hull_attributes(p, h):
    assert np.array_equal(h.neighbors, facet_neighbors(h.simplices))
    assert (h.neighbors >= 0).all()  # a closed surface / cycle
    if p.shape[1] == 3:
        assert np.array_equal(h.vertices, np.unique(h.simplices))
    else:  # the cycle: simplices are its consecutive pairs
        assert np.array_equal(h.simplices[:, 0], h.vertices)
        assert np.array_equal(h.simplices[:, 1], np.roll(h.vertices, -1))
    eq, volume, area = hull_measures(p, h.simplices)
    assert h.equations.shape == eq.shape
    assert np.allclose(h.equations, eq, rtol=1e-12, atol=1e-12 * np.abs(p).max(), equal_nan=True)
    assert h.volume == pytest.approx(volume, rel=1e-12)
    assert h.area == pytest.approx(area, rel=1e-12)


@pytest.mark.parametrize("seed", range(3))
def test_hull_attributes_match_numpy_and_scipy(seed):
    rng = np.random.default_rng(20 + seed)
    for p in (rng.random((3000, 3)), rng.normal(size=(2000, 3)) * 1e3 + 5e3, rng.random((2000, 2))):
        h, s = flipflop.ConvexHull(p), ss.ConvexHull(p)
        check_hull_attributes(p, h)
        for threads in (1, 2):  # 0, the default: the runtime's thread count; the same answer at any
            g = flipflop.ConvexHull(p, threads=threads)
            assert np.array_equal(g.simplices, h.simplices) and np.array_equal(g.equations, h.equations)
        # scipy's neighbors and equations, matched by vertex sets
        mine = {frozenset(x): i for i, x in enumerate(rows(h.simplices))}
        assert len(mine) == len(s.simplices)
        for i, x in enumerate(rows(s.simplices)):
            k = mine[frozenset(x)]
            assert np.allclose(h.equations[k], s.equations[i], rtol=1e-9, atol=1e-9 * np.abs(p).max())
            for j, v in enumerate(x):
                jj = rows(h.simplices)[k].index(v)
                assert set(h.simplices[h.neighbors[k, jj]]) == set(s.simplices[s.neighbors[i, j]])


def test_hull_attributes_on_degenerate_and_strict_input():
    # the 5x5x5 grid: the canonical hull's coplanar facets (zero-area
    # triangles among them have NaN normals, as numpy's 0/0) and the strict view
    g = np.array([(x, y, z) for x in range(5) for y in range(5) for z in range(5)], dtype=np.float64)
    h = flipflop.ConvexHull(g)
    assert np.array_equal(h.neighbors, facet_neighbors(h.simplices))
    assert np.array_equal(h.vertices, np.unique(h.simplices))
    assert h.volume == 64 and h.area == 96
    check_hull_attributes(g, h)
    assert 12 <= (~np.isnan(h.equations).any(axis=1)).sum() < len(h.simplices)  # some facets of zero area
    st_ = flipflop.ConvexHull(g, strict=True)
    check_hull_attributes(g, st_)
    assert st_.volume == 64 and st_.area == 96 and len(st_.vertices) == 8


def test_hull_measures_at_extreme_magnitudes():
    # computed from points scaled by a power of two: unit normals at any
    # magnitude; volume and area scaled back, inf or 0 only where the true
    # value is not a double
    p = np.random.default_rng(8).integers(-1000, 1000, (300, 3)).astype(np.float64)
    h = flipflop.ConvexHull(p)
    for scale, k in ((2.0**-300, 2.0**-300), (2.0**300, 2.0**300), (1e300, None), (1e-300, None)):
        q = p * scale
        g = flipflop.ConvexHull(q)
        assert np.array_equal(g.simplices, h.simplices)
        assert np.allclose(g.equations[:, :3], h.equations[:, :3], rtol=1e-12, atol=1e-15)
        if k is not None:  # exact powers of two: the same digits
            assert g.volume == pytest.approx(h.volume * k**3, rel=1e-12)
            assert g.area == pytest.approx(h.area * k**2, rel=1e-12)
        elif scale > 1:
            assert g.volume == np.inf and g.area == np.inf
        else:
            assert g.volume == 0 and g.area == 0


def test_hull_normals_of_tiny_facets():
    # a facet 1e-100 wide beside unit edges: its cross product, 1e-200, would
    # square to 0 (the normal to 0/0); scaled first, it keeps a unit normal
    # (2D: an edge 1e-170 long)
    for d, w in ((2, 1e-170), (3, 1e-100)):
        p = np.vstack([np.zeros(d), w * np.eye(d)[:-1], np.eye(d)[-1:]])
        h = flipflop.ConvexHull(p)
        check_hull_attributes(p, h)
        assert np.isfinite(h.equations).all()
        assert np.allclose(np.linalg.norm(h.equations[:, :d], axis=1), 1)


@pytest.mark.parametrize("dist", flipflop.distributions())
def test_hull_attributes_on_every_family(dist):
    # degenerate families included: duplicates (zero-length hull edges),
    # coplanar and jittered points (facets of zero or tiny area), 1e+-300
    p = flipflop.generate(dist, 300, seed=3)
    try:
        h = flipflop.ConvexHull(p)
    except ValueError:  # lower-dimensional families
        return
    check_hull_attributes(p, h)
    if p.shape[1] == 3:
        check_hull_attributes(p, flipflop.ConvexHull(p, strict=True))


@pytest.mark.parametrize("d,n", [(2, 3000), (3, 500), (4, 120)])
def test_delaunay_neighbors_and_convex_hull_independent(d, n):
    rng = np.random.default_rng(30 + d)
    grid = np.array(np.meshgrid(*[range(4 if d < 4 else 3)] * d)).reshape(d, -1).T.astype(np.float64)
    for p in (rng.random((n, d)), grid):  # random, and cospherical (flat simplices)
        t = flipflop.Delaunay(p)
        assert np.array_equal(t.neighbors, facet_neighbors(t.simplices))
        hull = [[v for l, v in enumerate(t.simplices[i]) if l != j]
                for i in range(len(t.simplices)) for j in range(d + 1) if t.neighbors[i, j] < 0]
        assert np.array_equal(t.convex_hull, np.array(hull, dtype=np.int64).reshape(-1, d))
    s = ss.Delaunay(p := rng.random((n, d)))
    t = flipflop.Delaunay(p)
    assert {frozenset(x) for x in rows(t.convex_hull)} == {frozenset(x) for x in rows(s.convex_hull)}


# ---- the command line, byte for byte, on every generator family ---------------------

@needs_cli
@pytest.mark.parametrize("dist", flipflop.distributions())
def test_identical_to_command_line_on_every_family(dist, tmp_path):
    n = 300
    f = tmp_path / "p.xyz"
    code, _, err = cli("gen", dist, n, "--seed", 4, "-o", f)
    assert code == 0, err
    p = flipflop.generate(dist, n, seed=4)
    assert np.array_equal(p, np.loadtxt(f, ndmin=2)[:, : p.shape[1]])  # the same generator
    kinds = ["hull2", "dt2"] if p.shape[1] == 2 else ["hull3"]
    for kind in kinds:
        code, out, err = cli(kind, f)
        try:
            if kind == "dt2":
                mine = as_text(flipflop.Delaunay(p).simplices)
            elif kind == "hull2":
                mine = "".join(f"{int(v)}\n" for v in flipflop.ConvexHull(p).vertices)
            else:
                mine = as_text(flipflop.ConvexHull(p).simplices)
        except ValueError as e:
            assert code == 2, f"{kind}: Python refused ({e}) but the command line answered"
            continue
        assert code == 0, err
        assert mine == out, kind


@needs_cli
def test_strict_hull_identical_to_command_line(tmp_path):
    # the 5x5x5 grid: its hull is the cube, with 98 boundary points of which
    # 8 are strictly extreme, 6 square facets, 12 triangles
    p = np.array([(x, y, z) for x in range(5) for y in range(5) for z in range(5)], dtype=np.float64)
    f = tmp_path / "c.xyz"
    write_xyz(f, p)
    h = flipflop.ConvexHull(p, strict=True)
    code, out, _ = cli("hull3", f, "--strict", "--triangulate")
    assert code == 0
    lines = out.splitlines()
    e, t = map(int, lines[0].split())
    assert [int(x) for x in lines[1:1 + e]] == list(h.vertices)
    assert as_text(h.simplices) == "".join(l + "\n" for l in lines[1 + e:])
    assert len(h.vertices) == 8 and len(h.polygons) == 6 and len(h.simplices) == 12


@needs_cli
@settings(max_examples=60, deadline=None, database=None)
@given(st.lists(st.tuples(st.integers(-3, 3), st.integers(-3, 3)), min_size=3, max_size=40))
def test_degenerate_integer_input_certified_and_identical(tmp_path_factory, pts):
    p = np.array(pts, dtype=np.float64)
    f = tmp_path_factory.mktemp("h") / "g.xyz"
    write_xyz(f, p)
    code, out, _ = cli("dt2", f)
    try:
        t = flipflop.Delaunay(p)
    except ValueError:
        assert code == 2  # lower-dimensional: refused by both
        return
    assert code == 0 and as_text(t.simplices) == out
    assert flipflop.certify("delaunay", p, t.simplices, canonical=True)
    h = flipflop.ConvexHull(p)
    assert flipflop.certify("hull2", p, h.vertices, canonical=True)


def test_instant_flip_matches_a_fresh_triangulation():
    rng = np.random.default_rng(5)
    p = rng.random((200, 2))
    w = np.zeros(200)
    u = rng.random(200) * 1e-4
    # vertices must stay vertices: start from u's vertices only
    keep = np.unique(flipflop.Delaunay(p, weights=u).simplices)
    p, w, u = p[keep], w[keep], u[keep]
    simplices, flips = flipflop.instant_flip(p, w, u)
    assert flips > 0
    assert rows(simplices) == rows(flipflop.Delaunay(p, weights=u).simplices)


# ---- bad input -----------------------------------------------------------------------

@pytest.mark.parametrize("bad", [
    np.array([[0.0, 0.0], [1.0, np.nan], [0.0, 1.0]]),
    np.array([[0.0, 0.0], [1.0, np.inf], [0.0, 1.0]]),
    np.zeros((5, 7)),
    np.zeros(6),
    [["a", "b"], ["c", "d"], ["e", "f"]],
    np.array([[0.0, 0.0], [1.0, 1.0]]),
    np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 2.0], [3.0, 3.0]]),
    np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, 0.0]]),
])
def test_bad_input_raises_value_error(bad):
    with pytest.raises(ValueError, match="^ConvexHull: "):
        flipflop.ConvexHull(bad)
    with pytest.raises(ValueError, match="^Delaunay: "):
        flipflop.Delaunay(bad)


def test_non_finite_values_found_anywhere():
    # the compiled check sums x * 0 in four lanes and a tail: a NaN or an
    # infinity in every lane and in the tail
    p = np.random.default_rng(6).random((1001, 3))
    for i in range(3 * 1001 - 9, 3 * 1001):
        for bad in (np.nan, np.inf, -np.inf):
            q = p.copy()
            q.flat[i] = bad
            with pytest.raises(ValueError, match="^ConvexHull: the points hold NaN or infinite"):
                flipflop.ConvexHull(q)
    w = np.zeros(1001)
    w[-1] = np.nan
    with pytest.raises(ValueError, match="weights hold NaN"):
        flipflop.Delaunay(p[:, :2].copy(), weights=w)


def test_bad_arguments_raise_value_error():
    p = np.random.default_rng(0).random((20, 2))
    with pytest.raises(ValueError):
        flipflop.Delaunay(p, weights=np.ones(3))
    with pytest.raises(ValueError):
        flipflop.ConvexHull(p, backend="gpu")
    for f in (flipflop.ConvexHull, flipflop.Delaunay):
        with pytest.raises(ValueError, match="threads"):
            f(p, threads=-1)
    with pytest.raises(ValueError):
        flipflop.certify("hull9", p, [[0, 1, 2]])
    with pytest.raises(ValueError):
        flipflop.certify("delaunay", p, [[0, 1, 99]])
    with pytest.raises(ValueError):
        flipflop.generate("no-such-family", 10)
    with pytest.raises(ValueError):
        flipflop.Delaunay(p).find_simplex(np.zeros((3, 3)))


def test_extreme_magnitudes():
    rng = np.random.default_rng(9)
    for scale in (1e-300, 1e300, 5e-324 * 2**20):
        p = rng.integers(-1000, 1000, (200, 3)).astype(np.float64) * scale
        h = flipflop.ConvexHull(p)
        assert flipflop.certify("hull3", p, h.simplices, canonical=True)
        assert np.allclose(np.linalg.norm(h.equations[:, :3], axis=1), 1)  # unit normals at any magnitude


def test_version():
    assert flipflop.__version__ == "0.1.0"


@needs_cli
def test_strict_delaunay_identical_to_command_line(tmp_path):
    p = np.array([(x, y) for x in range(12) for y in range(12)], dtype=np.float64)
    f = tmp_path / "g.xyz"
    write_xyz(f, p)
    t = flipflop.Delaunay(p, strict=True)
    code, out, _ = cli("dt2", f, "--strict")
    assert code == 0 and as_text(t.simplices) == out
    assert len(t.simplices) == len(ss.Delaunay(p).simplices) == 242
    area = [np.cross(p[b] - p[a], p[c] - p[a]) for a, b, c in t.simplices]
    assert min(area) > 0
    assert flipflop.certify("delaunay", p, t.simplices)


@needs_cli
def test_strict_delaunay_3d_identical_to_command_line(tmp_path):
    # a 4x4x4 grid: the canonical answer has zero-volume tetrahedra; the
    # strict view 6 per cube, positive volume, what `rtd --strict` writes
    p = np.array([(x, y, z) for x in range(4) for y in range(4) for z in range(4)], dtype=np.float64)
    f = tmp_path / "g.xyz"
    write_xyz(f, p, np.zeros(len(p)))
    t = flipflop.Delaunay(p, strict=True)
    code, out, _ = cli("rtd", f, "--dim", "3", "--strict")
    assert code == 0 and as_text(t.simplices) == out
    assert len(t.simplices) == 27 * 6
    vol = [np.linalg.det(p[s[1:]] - p[s[0]]) for s in t.simplices]
    assert min(vol) > 0
    assert len(flipflop.Delaunay(p).simplices) > len(t.simplices)
    assert not flipflop.certify("delaunay", p, flipflop.Delaunay(p).simplices)  # zero volume at the exact level
    assert flipflop.certify("delaunay", p, t.simplices)


@needs_cli
def test_npy_input_written_by_numpy(tmp_path):
    """The command line reads numpy's .npy (np.save) exactly like the .xyz of the same points."""
    rng = np.random.default_rng(11)
    p = rng.random((5000, 3))
    np.save(tmp_path / "p.npy", p)
    write_xyz(tmp_path / "p.xyz", p)
    a, b = cli("hull3", tmp_path / "p.npy"), cli("hull3", tmp_path / "p.xyz")
    assert a[0] == 0 and a == b
    assert a[1] == as_text(flipflop.ConvexHull(p).simplices)
    w = rng.random(5000) * 1e-3
    np.save(tmp_path / "w.npy", np.c_[p[:, :2], w])
    code, out, _ = cli("rt2", tmp_path / "w.npy")
    assert code == 0 and out == as_text(flipflop.Delaunay(p[:, :2], weights=w).simplices)
    np.save(tmp_path / "f.npy", p.astype(np.float32))
    code, _, err = cli("hull3", tmp_path / "f.npy")
    assert code == 2 and "float64" in err and len(err.strip().splitlines()) == 1


def test_points_and_weights_read_in_place():
    """C-contiguous float64 input is read without a copy (the library borrows
    the numpy buffer), left unchanged, and gives the answer of a copy; other
    layouts and dtypes are converted once by numpy and give the same answer."""
    from flipflop import _flipflop

    rng = np.random.default_rng(5)
    p = rng.random((3000, 3))
    w = rng.random(3000) * 1e-3
    assert _flipflop._reads_in_place(p, None)
    assert _flipflop._reads_in_place(p[:, :2].copy(), w)
    before = p.copy()
    h = flipflop.ConvexHull(p)
    assert np.array_equal(p, before)
    assert h.points is p or np.shares_memory(h.points, p)
    assert np.array_equal(h.simplices, flipflop.ConvexHull(p.copy()).simplices)
    assert np.array_equal(h.simplices, flipflop.ConvexHull(np.asfortranarray(p)).simplices)
    assert np.array_equal(h.simplices, flipflop.ConvexHull(p.tolist()).simplices)
    q = np.ascontiguousarray(p[:, :2])
    t = flipflop.Delaunay(q, weights=w)
    assert np.array_equal(t.simplices, flipflop.Delaunay(q.copy(), weights=w.copy()).simplices)
    assert np.array_equal(t.simplices, flipflop.Delaunay(np.asfortranarray(q), weights=w.tolist()).simplices)


# ---- 3D: the cpu kernel (kernels_cpu/rt3), the reference, scipy, point location -----
# Delaunay in 3D runs the multithreaded kernel by default, certified from its
# witness (certify_rt3); backend="reference" runs RT+1. Both must return the
# same canonical simplices and redundant points on any input, degenerate or
# weighted; scipy (Qhull, no code shared) must agree on general-position
# input; find_simplex is checked against exact integer arithmetic.

def grid3(k, step=1):
    return np.array([(x, y, z) for x in range(k) for y in range(k) for z in range(k)], dtype=np.float64) * step


def inputs_3d():
    """(name, points, weights): random, degenerate and weighted 3D inputs."""
    rng = np.random.default_rng(41)
    g = grid3(6)
    cube = rng.random((2000, 3))
    ball = rng.standard_normal((1500, 3))
    dup = np.vstack([g, g[::5], g[3::17]])  # cospherical, coplanar, duplicated
    planes = np.vstack([np.c_[rng.integers(0, 9, (300, 2)), np.full(300, z)] for z in (0, 1, 2)]).astype(np.float64)
    return [
        ("cube", cube, None),
        ("ball", ball, None),
        ("grid", g, None),
        ("grid+duplicates", dup, None),
        ("planes+duplicates", planes, None),
        ("cube weighted 1e-4", cube, rng.random(len(cube)) * 1e-4),
        ("cube weighted 1e-2", cube, rng.random(len(cube)) * 1e-2),
        ("grid weighted", dup, (np.arange(len(dup)) % 3).astype(np.float64) * 0.25),
    ]


@pytest.mark.parametrize("case", range(len(inputs_3d())), ids=[c[0] for c in inputs_3d()])
def test_delaunay_3d_cpu_equals_reference(case):
    name, p, w = inputs_3d()[case]
    ref = flipflop.Delaunay(p, weights=w, backend="reference")
    assert flipflop.certify("delaunay", p, ref.simplices, weights=w, canonical=True)
    assert set(ref.redundant) == set(range(len(p))) - set(np.unique(ref.simplices))
    for backend, threads in ((None, 0), ("cpu", 1), ("cpu", 2), ("cpu", 8)):
        t = flipflop.Delaunay(p, weights=w, backend=backend, threads=threads)
        assert t.simplices.dtype == np.intc and t.simplices.shape == ref.simplices.shape, (name, threads)
        assert np.array_equal(t.simplices, ref.simplices), (name, threads)
        assert np.array_equal(t.redundant, ref.redundant), (name, threads)
        assert np.array_equal(t.neighbors, ref.neighbors)
    if "duplicates" in name:
        assert len(ref.redundant) > 0  # one copy of coinciding inner points remains
    if "1e-2" in name:
        assert len(ref.redundant) > 0  # heavy weights hide points


def _grid(k, d, step, start=0.0):
    axes = [start + step * np.arange(k)] if step != 0.1 else [np.mgrid[0:k * 0.1 - 0.05:0.1]]
    return np.stack(np.meshgrid(*(axes * d), indexing="ij"), -1).reshape(-1, d).copy()


@pytest.mark.parametrize("d,k,step", [(2, 9, 0.25), (2, 3, 0.1), (3, 5, 0.5), (3, 3, 0.1), (3, 4, 3000.0),
                                      (4, 3, 0.1), (4, 4, 0.25), (5, 2, 0.1)])
def test_delaunay_on_a_lattice_with_a_step_equals_reference_and_integer_grid(d, k, step):
    # a lattice up to one exact common factor runs as the small-integer
    # lattice (reference/lattice_quotient.hpp): the same answer as the
    # reference on the given values and as the integer grid, certified on the
    # given values; likewise with copies, weights that are multiples of
    # step^2, furthest-site and strict
    p = _grid(k, d, step)
    ints = _grid(k, d, 1.0)
    ref = flipflop.Delaunay(p, backend="reference")
    t = flipflop.Delaunay(p)
    assert np.array_equal(t.simplices, ref.simplices) and np.array_equal(t.neighbors, ref.neighbors)
    assert np.array_equal(t.simplices, flipflop.Delaunay(ints).simplices)
    assert flipflop.certify("delaunay", p, t.simplices, canonical=True)
    dup = np.vstack([p, p[::4]])
    w = (np.arange(len(dup)) % 3 - 1).astype(np.float64) * step * step
    a = flipflop.Delaunay(dup, weights=w)
    b = flipflop.Delaunay(dup, weights=w, backend="reference")
    assert np.array_equal(a.simplices, b.simplices) and np.array_equal(a.redundant, b.redundant)
    assert flipflop.certify("delaunay", dup, a.simplices, weights=w, canonical=True)
    a = flipflop.Delaunay(p, furthest_site=True)
    assert np.array_equal(a.simplices, flipflop.Delaunay(p, furthest_site=True, backend="reference").simplices)
    if d <= 3:
        a = flipflop.Delaunay(dup, strict=True)
        assert np.array_equal(a.simplices, flipflop.Delaunay(dup, strict=True, backend="reference").simplices)


def test_delaunay_on_the_5d_grid_of_step_0_1_equals_integer_grid():
    # np.mgrid's 3^5 grid of step 0.1 (0.2 is 2 x 0.1 exactly): the integer
    # grid's answer, certified on the given values (RT+1 on it takes 10 s)
    p, ints = _grid(3, 5, 0.1), _grid(3, 5, 1.0)
    t = flipflop.Delaunay(p)
    assert np.array_equal(t.simplices, flipflop.Delaunay(ints).simplices)
    assert flipflop.certify("delaunay", p, t.simplices, canonical=True)


@pytest.mark.parametrize("d,k,step", [(2, 9, 0.25), (2, 3, 0.1), (3, 5, 0.25), (3, 3, 0.1), (4, 3, 0.1), (4, 4, 0.5),
                                      (5, 3, 0.1), (6, 2, 0.25)])
def test_convex_hull_on_a_lattice_with_a_step(d, k, step):
    # the hull kernels on the small-integer lattice (reference/lattice_quotient.hpp):
    # the integer grid's facets, in 3D the reference's on the given values and
    # certified there; the measures from the given values
    p = _grid(k, d, step)
    h = flipflop.ConvexHull(p)
    assert np.array_equal(h.simplices, flipflop.ConvexHull(_grid(k, d, 1.0)).simplices)
    if d <= 3:
        ref = flipflop.ConvexHull(p, backend="reference")
        assert np.array_equal(h.simplices, ref.simplices)
        assert flipflop.certify(f"hull{d}", p, h.simplices, canonical=True)
    side = float(p[:, 0].max())
    assert h.volume == pytest.approx(side ** d, rel=1e-12)
    eq = h.equations[np.isfinite(h.equations).all(axis=1)]  # (NaN rows: facets of zero area)
    assert len(eq) > 0 and (eq[:, :d] @ p.T + eq[:, d:] <= 1e-12).all()


def test_delaunay_3d_strict_cpu_equals_reference():
    # the strict view is derived from the certified canonical answer by the
    # reference's rule: the same from either backend, d! = 6 simplices per cube
    g = grid3(4)
    a = flipflop.Delaunay(g, strict=True)
    b = flipflop.Delaunay(g, strict=True, backend="reference")
    assert np.array_equal(a.simplices, b.simplices) and len(a.simplices) == 27 * 6
    assert flipflop.certify("delaunay", g, a.simplices)  # exact level: no zero-volume simplex
    dup = np.vstack([g, g[::3]])
    w = (np.arange(len(dup)) % 2).astype(np.float64) * 0.125
    a = flipflop.Delaunay(dup, weights=w, strict=True, threads=2)
    b = flipflop.Delaunay(dup, weights=w, strict=True, backend="reference")
    assert np.array_equal(a.simplices, b.simplices)
    assert np.array_equal(a.redundant, b.redundant)


@pytest.mark.parametrize("seed", range(4))
def test_oracle_delaunay_3d_equals_scipy(seed):
    # oracle: scipy.spatial.Delaunay (Qhull, no code shared) on general-
    # position input: the same tetrahedra as vertex sets; ours positively
    # oriented (numpy determinant, far from 0 on random input)
    rng = np.random.default_rng(100 + seed)
    n = (300, 1000, 3000, 5000)[seed]
    p = rng.random((n, 3)) if seed % 2 == 0 else rng.standard_normal((n, 3)) * 10.0 ** (seed - 2)
    t, s = flipflop.Delaunay(p, threads=2), ss.Delaunay(p)
    assert {tuple(sorted(x)) for x in rows(t.simplices)} == {tuple(sorted(x)) for x in rows(s.simplices)}
    assert len(t.redundant) == 0 and len(s.coplanar) == 0
    e = p[t.simplices]
    assert (np.linalg.det(e[:, 1:] - e[:, :1]) > 0).all()
    assert {frozenset(x) for x in rows(t.convex_hull)} == {frozenset(x) for x in rows(s.convex_hull)}
    q = rng.random((1000, 3)) * 1.2 - 0.1 if seed % 2 == 0 else rng.standard_normal((1000, 3)) * 10.0 ** (seed - 2)
    mine, theirs = t.find_simplex(q), s.find_simplex(q)
    # scipy counts points within about 1e-8 (barycentric) of a simplex as in
    # it: compare where the query is clear of the hull's boundary and, inside,
    # clear of the facets of scipy's simplex
    eq = ss.ConvexHull(p).equations
    clear = np.abs((q @ eq[:, :3].T + eq[:, 3]).max(axis=1)) > 1e-6 * np.abs(p).max()
    assert clear.sum() > 900
    assert ((mine >= 0) == (theirs >= 0))[clear].all()
    inside = np.nonzero(clear & (theirs >= 0))[0]
    b = np.einsum("ijk,ik->ij", s.transform[theirs[inside], :3], q[inside] - s.transform[theirs[inside], 3])
    bary = np.c_[b, 1 - b.sum(axis=1)]
    inside = inside[bary.min(axis=1) > 1e-9]
    assert len(inside) > 100
    assert all(sorted(a) == sorted(b) for a, b in zip(t.simplices[mine[inside]], s.simplices[theirs[inside]]))


def orient_int(a, b, c, d):
    """sign of det[b-a, c-a, d-a], exactly, for int64 arrays of small integers
    (|coordinate| < 2^15: every product fits in int64)."""
    u, v, w = b - a, c - a, d - a
    det = (u[..., 0] * (v[..., 1] * w[..., 2] - v[..., 2] * w[..., 1])
           - u[..., 1] * (v[..., 0] * w[..., 2] - v[..., 2] * w[..., 0])
           + u[..., 2] * (v[..., 0] * w[..., 1] - v[..., 1] * w[..., 0]))
    return np.sign(det)


def containing_simplices(p, simplices, q):
    """contains[i, s]: query i lies in simplex s (closed), decided exactly by
    barycentric signs in integer arithmetic; simplices of zero volume
    contain nothing (they cover no volume)."""
    v = p[simplices]  # (m, 4, 3)
    own = orient_int(v[:, 0], v[:, 1], v[:, 2], v[:, 3])  # (m,)
    out = np.ones((len(q), len(simplices)), dtype=bool)
    for lo in range(0, len(q), 64):  # 64 queries at a time against all simplices
        qq = q[lo:lo + 64]
        shape = (len(qq), len(simplices), 3)
        for j in range(4):
            corners = [np.broadcast_to(v[None, :, k], shape) for k in range(4)]
            corners[j] = np.broadcast_to(qq[:, None, :], shape)
            out[lo:lo + 64] &= orient_int(*corners) * own[None, :] >= 0
    return out & (own != 0)[None, :]


@pytest.mark.parametrize("kind", ["random", "grid", "grid+duplicates", "weighted", "strict"])
def test_find_simplex_3d_against_brute_force(kind):
    # points with even integer coordinates, queries with integer ones: queries
    # on vertices, edges, facets and outside the hull, all decided exactly
    rng = np.random.default_rng(7)
    w = None
    if kind == "random":
        pi = rng.integers(-40, 41, (250, 3)) * 2
    elif kind == "weighted":
        pi = rng.integers(-40, 41, (250, 3)) * 2
        w = rng.random(250) * 300.0
    else:
        pi = grid3(5, 4).astype(np.int64) - 8
        if kind == "grid+duplicates":
            pi = np.vstack([pi, pi[::4]])
    p = pi.astype(np.float64)
    t = flipflop.Delaunay(p, weights=w, strict=kind == "strict")
    lo, hi = pi.min() - 6, pi.max() + 6
    qi = np.vstack([rng.integers(lo, hi + 1, (600, 3)), pi[:50], (pi[:40] + pi[1:41]) // 2])
    qi = np.vstack([qi, rng.integers(pi.min(), pi.max() + 1, (300, 3))])
    got = t.find_simplex(qi.astype(np.float64))
    contains = containing_simplices(pi, t.simplices, qi)
    for i, s in enumerate(got):
        if s >= 0:
            assert contains[i, s], (kind, qi[i], t.simplices[s])
        else:
            assert not contains[i].any(), (kind, qi[i], np.nonzero(contains[i])[0][:5])
    assert (got >= 0).sum() > 300  # most queries are inside
    # shape (..., 3) in, shape (...) out
    assert t.find_simplex(qi[:12].reshape(3, 4, 3).astype(np.float64)).shape == (3, 4)
    assert np.array_equal(t.find_simplex(qi[:12].reshape(3, 4, 3).astype(np.float64)).ravel(), got[:12])


def det_int(m):
    """Exact det m for an int64 array (..., k, k) of small integers, by
    Laplace expansion along the first row (every product fits int64)."""
    k = m.shape[-1]
    if k == 1:
        return m[..., 0, 0]
    total = np.zeros(m.shape[:-2], dtype=np.int64)
    for j in range(k):
        term = m[..., 0, j] * det_int(np.delete(m[..., 1:, :], j, axis=-1))
        total = total + term if j % 2 == 0 else total - term
    return total


def orient_int_d(v):
    """Exact sign of det [[v_0, 1], ..., [v_d, 1]] for int64 rows v (..., d+1, d):
    (-1)^d det [v_1 - v_0, ..., v_d - v_0] (row 0 subtracted, expanded along the
    1-column)."""
    d = v.shape[-1]
    return (-1) ** d * np.sign(det_int(v[..., 1:, :] - v[..., :1, :]))


@pytest.mark.parametrize("d", [2, 3, 4, 5])
def test_find_simplex_one_choice_on_shared_faces(d):
    # Queries on vertices, edges and facets shared by several simplices of a
    # grid's canonical triangulation (points at even integers, queries at
    # integers): find_simplex returns the one simplex of positive volume that
    # holds the query moved infinitesimally towards the vertices of the first
    # simplex of positive volume (x' = x + e (v0 - x) + e^2 (v1 - x) + ...),
    # decided here by brute force over all simplices in integer arithmetic;
    # the same choice at 1, 2 and 16 threads and query by query (any batch)
    k = {2: 5, 3: 3, 4: 3, 5: 2}[d]
    pi = np.array(list(np.ndindex(*([k] * d))), dtype=np.int64) * 2
    if d == 5:
        pi = np.vstack([pi, [[1, 1, 1, 1, 1]]])  # (the cube and its centre)
    rng = np.random.default_rng(40 + d)
    qi = np.vstack([rng.integers(0, 2 * (k - 1) + 1, (70, d)), pi[:10], rng.integers(-1, 2 * k, (10, d))])
    t = flipflop.Delaunay(pi.astype(np.float64))
    S = t.simplices.astype(np.int64)
    v = pi[S]  # (m, d+1, d)
    own = orient_int_d(v)
    ref = int(np.flatnonzero(own != 0)[0])

    def orient_with(x):  # (len(x), m, d+1): each simplex with vertex j replaced by x
        out = np.empty((len(x),) + S.shape, dtype=np.int64)
        for j in range(d + 1):
            w = np.broadcast_to(v, (len(x),) + v.shape).copy()
            w[:, :, j] = x[:, None, :]
            out[:, :, j] = orient_int_d(w)
        return out

    side = orient_with(qi)
    for l in range(d + 1):  # ties: the first non-zero of x, v0, v1, ...
        side = np.where(side != 0, side, orient_with(pi[S[ref, l]][None, :]))
    inside = (own != 0)[None, :] & (side * own[None, :, None] > 0).all(axis=2)
    assert (inside.sum(axis=1) <= 1).all()
    expected = np.where(inside.any(axis=1), inside.argmax(axis=1), -1)
    q = qi.astype(np.float64)
    for threads in (1, 2, 16):
        got = flipflop.Delaunay(pi.astype(np.float64), threads=threads).find_simplex(q)
        assert np.array_equal(got, expected), (threads, np.flatnonzero(got != expected)[:5])
    assert np.array_equal([t.find_simplex(x) for x in q], expected)
    assert np.array_equal(t.find_simplex(q[::-1]), expected[::-1])
    assert (expected >= 0).sum() > 60


def test_delaunay_3d_extreme_magnitudes_and_bad_input():
    # scaled by a power of two the answer is the same (orient3d scales by s^3,
    # the power test by s^5 with weights scaled by s^2); subnormal coordinates
    # included
    rng = np.random.default_rng(12)
    p = rng.integers(-500, 501, (400, 3)).astype(np.float64)
    w = rng.integers(0, 2000, 400).astype(np.float64)
    plain = flipflop.Delaunay(p)
    weighted = flipflop.Delaunay(p, weights=w)
    backends = ("cpu", "reference") + (("cuda-omp",) if "cuda-omp" in flipflop.gpu_backends else ())
    for e in (-1062, -1000, -500, 500, 988):
        s = 2.0 ** e
        for backend in backends:
            assert np.array_equal(flipflop.Delaunay(p * s, backend=backend).simplices, plain.simplices), (e, backend)
            if -500 <= e <= 500:
                t = flipflop.Delaunay(p * s, weights=w * s * s, backend=backend)
                assert np.array_equal(t.simplices, weighted.simplices), (e, backend)
    for scale in (1e300, 1e-300):
        q = rng.uniform(-1, 1, (300, 3)) * scale
        a, b = flipflop.Delaunay(q), flipflop.Delaunay(q, backend="reference")
        assert np.array_equal(a.simplices, b.simplices)
        assert flipflop.certify("delaunay", q, a.simplices, canonical=True)
    # lower-dimensional and too small: ValueError from either backend
    flat = np.c_[rng.random((50, 2)), np.ones(50)]
    line = np.outer(np.arange(10.0), [1.0, 2.0, 3.0])
    for bad, what in ((flat, "coplanar"), (line, "collinear"), (np.ones((6, 3)), "equal"), (p[:3], "at least 4")):
        for backend in backends:
            with pytest.raises(ValueError, match=what):
                flipflop.Delaunay(bad, backend=backend)
    for backend in backends:
        with pytest.raises(ValueError, match="NaN"):
            flipflop.Delaunay(np.vstack([p, [np.nan, 0, 0]]), backend=backend)
        with pytest.raises(ValueError, match="weights hold NaN"):
            flipflop.Delaunay(p, weights=np.r_[w[:-1], np.inf], backend=backend)
    with pytest.raises(ValueError, match="backend"):
        flipflop.Delaunay(np.c_[p, p, p][:, :4], backend="cuda-omp")  # the GPU kernels are 2D and 3D


@needs_cli
@pytest.mark.parametrize("dist", [d for d in flipflop.distributions() if flipflop._flipflop.dimension_of(d) == 3])
def test_dt3_identical_to_command_line_on_every_3d_family(dist, tmp_path):
    n = 300
    f = tmp_path / "p.xyz"
    code, _, err = cli("gen", dist, n, "--seed", 5, "-o", f)
    assert code == 0, err
    p = flipflop.generate(dist, n, seed=5)
    code, out, err = cli("dt3", f, "--threads", 2)
    try:
        t = flipflop.Delaunay(p)
    except ValueError as e:
        assert code == 2 and len(err.strip().splitlines()) == 1, f"Python refused ({e}) but the command line: {err}"
        return
    assert code == 0, err
    assert as_text(t.simplices) == out
    code, ref_out, _ = cli("dt3", f, "--backend", "reference")
    assert code == 0 and ref_out == out


@needs_cli
def test_rt3_command_line_formats_read_by_numpy_and_meshio(tmp_path):
    meshio = pytest.importorskip("meshio")
    rng = np.random.default_rng(13)
    p, w = rng.random((500, 3)), rng.random(500) * 1e-2
    write_xyz(tmp_path / "w.xyz", p, w)
    t = flipflop.Delaunay(p, weights=w)
    code, out, err = cli("rt3", tmp_path / "w.xyz", "-o", tmp_path / "r.txt")
    assert code == 0
    assert (tmp_path / "r.txt").read_text() == as_text(t.simplices)
    # the redundant points on standard error, as rtd reports them
    if len(t.redundant):
        assert err.startswith(f"rt3: {len(t.redundant)} redundant point")
    assert cli("rt3", tmp_path / "w.xyz", "-o", tmp_path / "r.npy")[0] == 0
    assert np.array_equal(np.load(tmp_path / "r.npy"), t.simplices)
    assert cli("rt3", tmp_path / "w.xyz", "-o", tmp_path / "r.vtu", "--backend", "reference")[0] == 0
    m = meshio.read(tmp_path / "r.vtu")
    assert [b.type for b in m.cells] == ["tetra"]
    used = np.unique(t.simplices)
    assert np.array_equal(m.points, p[used])
    assert np.array_equal(used[m.cells[0].data], t.simplices)
    code, out, _ = cli("certify", "rt3", tmp_path / "w.xyz", tmp_path / "r.txt", "--canonical")
    assert code == 0 and out.startswith("certified (rt3, canonical)")


@pytest.mark.parametrize("d", [4, 5])
def test_hull_kernel_equals_triangulation_boundary(d):
    # ConvexHull in 4D/5D: the hull kernel (backend 'cpu', kernels_cpu/rtd/
    # hull_d) against the boundary of RT+1's Delaunay triangulation
    # ('reference'), attribute by attribute, on random, grid and duplicated
    # input; and against scipy's facets on random input
    rng = np.random.default_rng(40 + d)
    grid = np.array(np.meshgrid(*[np.arange(3.0)] * d)).reshape(d, -1).T
    inputs = [rng.standard_normal((60 if d == 4 else 40, d)), grid,
              np.vstack([grid[: 3 ** (d - 1) + 5], grid[:7]])]
    for p in inputs:
        if np.linalg.matrix_rank(p - p[0]) < d:
            continue
        a = flipflop.ConvexHull(p)
        b = flipflop.ConvexHull(p, backend="reference")
        assert (a.simplices == b.simplices).all()
        assert (a.neighbors == b.neighbors).all()
        assert (a.vertices == b.vertices).all()
        assert a.volume == b.volume and a.area == b.area
    p = inputs[0]
    s = ss.ConvexHull(p)
    assert ({tuple(sorted(x)) for x in flipflop.ConvexHull(p).simplices.tolist()} ==
            {tuple(sorted(x)) for x in s.simplices.tolist()})


def test_find_simplex_signs_cached_and_checked():
    from flipflop import _flipflop
    # a 3^4 grid with a fifth of its points moved by 2 ulp: slivers and
    # zero-volume simplices. The per-simplex signs find_simplex caches are
    # the exact orientations (zero exactly where _flat's independent numpy /
    # integer computation says so); a call with them equals one without; the
    # bounding-box shortcut answers -1 where a scan of every simplex does.
    rng = np.random.default_rng(11)
    g = np.array(np.meshgrid(*[np.arange(3)] * 4, indexing="ij"), dtype=float).reshape(4, -1).T + 1.0
    for i in np.nonzero(rng.random(len(g)) < 0.2)[0]:
        for j in range(4):
            for _ in range(2):
                g[i, j] = np.nextafter(g[i, j], np.inf if rng.random() < 0.5 else -np.inf)
    t = flipflop.Delaunay(g)
    s64, n64 = t.simplices.astype(np.int64), t.neighbors.astype(np.int64)
    signs = _flipflop.simplex_signs(t.points, s64)
    assert signs.dtype == np.int8 and signs.shape == (t.nsimplex,)
    assert np.array_equal(signs == 0, t._flat())
    assert (signs != 0).any() and len(set(signs[signs != 0].tolist())) == 1  # one orientation
    q = rng.random((3000, 4)) * 2.4 + 0.8  # a third outside the box [1, 3]^4
    without = _flipflop.find_simplex(t.points, s64, n64, q)
    assert np.array_equal(_flipflop.find_simplex(t.points, s64, n64, q, signs), without)
    assert np.array_equal(t.find_simplex(q), without)
    assert np.array_equal(t.find_simplex(q), without)  # the cached signs again
    outside = ((q < g.min(axis=0)) | (q > g.max(axis=0))).any(axis=1)
    assert outside.sum() > 500 and (without[outside] == -1).all()
    # a found simplex holds its query (closed): every vertex replaced by the
    # query leaves the orientation's sign or makes it 0 (exact signs)
    found = np.nonzero(without >= 0)[0]
    assert len(found) > 1000
    for i in found[:60]:
        k = without[i]
        v = t.points[t.simplices[k]]
        for j in range(5):
            w = v.copy()
            w[j] = q[i]
            assert _flipflop.simplex_signs(w, np.arange(5, dtype=np.int64)[None, :])[0] * signs[k] >= 0
    with pytest.raises(ValueError):
        _flipflop.find_simplex(t.points, s64, n64, q, signs[:-1])
    with pytest.raises(ValueError):
        _flipflop.find_simplex(t.points, s64, n64, q, np.full(t.nsimplex, 2, dtype=np.int8))


@pytest.mark.parametrize("d", [4, 5, 6])
def test_convex_hull_d_same_answer_at_any_thread_count(d):
    """ConvexHull in 4D..9D runs the hull kernel and its certifier on
    `threads` workers (python/src/module.cpp hull_d): the same canonical
    facets and neighbours at 1, 2 and 3 threads and the default, equal to
    scipy's facets as sets; a negative count is a ValueError."""
    a = np.random.default_rng(40 + d).standard_normal((1500, d))
    base = flipflop.ConvexHull(a)
    for t in (1, 2, 3):
        h = flipflop.ConvexHull(a, threads=t)
        assert np.array_equal(h.simplices, base.simplices)
        assert np.array_equal(h.neighbors, base.neighbors)
    assert {tuple(sorted(s)) for s in base.simplices} == {tuple(sorted(s)) for s in ss.ConvexHull(a).simplices}
    with pytest.raises(ValueError):
        flipflop.ConvexHull(a, threads=-1)
