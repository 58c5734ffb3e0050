"""flipflop: exact, certified convex hulls and regular (weighted Delaunay)
triangulations, with the attributes of scipy.spatial's ConvexHull and
Delaunay.

Every predicate is decided exactly, with Simulation of Simplicity for
degenerate input, so every input — collinear, cospherical, duplicated,
1e-300 or 1e+300 — has one answer, the same on every machine, certified
before it is returned.

    >>> import numpy as np, flipflop
    >>> pts = np.random.default_rng(1).random((1000, 3))
    >>> hull = flipflop.ConvexHull(pts)          # like scipy.spatial.ConvexHull
    >>> tri = flipflop.Delaunay(pts)             # like scipy.spatial.Delaunay
    >>> bool(flipflop.certify("hull3", pts, hull.simplices))
    True

ConvexHull and Delaunay take scipy.spatial's constructor arguments in
scipy's order (qhull_options, incremental / add_points, close, furthest_site)
and carry every attribute of scipy's classes; docs/scipy_porting.md lists
each name and every difference from Qhull's answers.
"""
from __future__ import annotations

import math
import numbers
import re
import warnings
from fractions import Fraction
from itertools import combinations
from typing import Optional, Sequence

import numpy as np

from . import _flipflop

__version__: str = _flipflop.__version__

__all__ = ["ConvexHull", "Delaunay", "Voronoi", "QhullOptionError", "Certificate", "certify", "instant_flip", "generate",
           "distributions", "gpu_backends", "__version__"]

#: The GPU kernels' backends of this build (kernels_cuda/): "cuda-omp", the
#: GPU algorithms on thrust's OpenMP backend (every multicore CPU), where the
#: CUDA toolkit's headers and OpenMP were found when the package was built;
#: "cuda" only in a build whose kernels nvcc compiled (not this package's
#: own build), and then it needs a CUDA device at run time. Where the kernels
#: are built, backend="cuda" is accepted and raises RuntimeError (the command
#: line's one line) when it cannot run. Every backend returns the reference's
#: answer.
gpu_backends: tuple = tuple(_flipflop.gpu_backends())

_GPU = ("cuda-omp", "cuda") if gpu_backends else ()
# 4D..9D: the hull kernel (kernels_cpu/rtd/hull_d) or, 'reference', the
# boundary of the Delaunay triangulation by RT+1
_HULL_BACKENDS = {2: ("cpu", "reference") + _GPU, 3: ("cpu", "reference") + _GPU,
                  **{d: ("cpu", "reference") for d in range(4, 10)}}
# per dimension, the default first: the multithreaded kernels exist for d = 2
# and 3 (kernels_cpu/rt2, kernels_cpu/rt3), the cavity-insertion kernel for
# d = 4..9 (kernels_cpu/rtd, one thread), the GPU kernels for d = 2 and 3
# (kernels_cuda/rt2, kernels_cuda/rt3)
_DELAUNAY_BACKENDS = {2: ("cpu", "reference") + _GPU, 3: ("cpu", "reference") + _GPU,
                      **{d: ("cpu", "reference") for d in range(4, 10)}}
# the dimensions of Delaunay, Voronoi and ConvexHull (predicates of up to 11
# rows: power tests in 9D)
_DIMS = tuple(range(2, 10))


def _points(points, dims: Sequence[int], what: str, finite: bool = True) -> np.ndarray:
    """float64, C-contiguous (no copy when it already is), shape (n, d) with d
    in dims, finite; ValueError otherwise. finite=False leaves the check for
    NaN and infinity to the compiled call (every _flipflop function makes it,
    in one pass without a temporary array; _native names the caller)."""
    try:
        a = np.asarray(points, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise ValueError(f"{what}: points must be numeric: {e}") from None
    if a.ndim != 2 or a.shape[1] not in dims:
        raise ValueError(f"{what}: points must have shape (n, d) with d in {tuple(dims)}, got {a.shape}")
    if finite and not np.isfinite(a).all():
        raise ValueError(f"{what}: the points hold NaN or infinite coordinates")
    if a.shape[0] < a.shape[1] + 1:
        raise ValueError(f"{what}: {a.shape[0]} points, at least {a.shape[1] + 1} needed in {a.shape[1]}D")
    return np.ascontiguousarray(a)


def _weights(weights, n: int, what: str) -> Optional[np.ndarray]:
    if weights is None:
        return None
    try:
        w = np.ascontiguousarray(np.asarray(weights, dtype=np.float64))
    except (TypeError, ValueError) as e:
        raise ValueError(f"{what}: weights must be numeric: {e}") from None
    if w.shape != (n,):
        raise ValueError(f"{what}: weights must have shape ({n},), got {w.shape}")
    if not np.isfinite(w).all():
        raise ValueError(f"{what}: the weights hold NaN or infinite values")
    return w


def _furthest_site(value, what: str) -> bool:
    """scipy's furthest_site argument as a bool; anything else (old code passing
    weights positionally) is a ValueError naming weights=."""
    if not isinstance(value, (bool, np.bool_)) and not (
            isinstance(value, (int, np.integer)) and value in (0, 1)):
        raise ValueError(f"{what}: furthest_site must be a bool (weights are keyword-only: "
                         f"{what}(points, weights=w))")
    return bool(value)


def _threads(threads, what: str) -> int:
    """0: the runtime's default (oneTBB: every core the process may use)."""
    t = int(threads)
    if t < 0:
        raise ValueError(f"{what}: threads must be 0 (all cores) or positive, got {t}")
    return t


def _native(what: str, f, *args):
    """f(*args), a _flipflop function, with its ValueError (the command
    line's one-line message) prefixed by the caller's name."""
    try:
        return f(*args)
    except ValueError as e:
        raise ValueError(f"{what}: {e}") from None


def _backend(backend: Optional[str], allowed: Sequence[str], what: str) -> str:
    if backend is None:
        return allowed[0]
    if backend not in allowed:
        raise ValueError(f"{what}: backend must be one of {tuple(allowed)}, got {backend!r}")
    return backend



def _intc(a) -> np.ndarray:
    """scipy's index dtype, np.intc (32 bits), for an index array; int64
    where a value does not fit (beyond 2^31 - 1 points or simplices, where
    scipy's own arrays would overflow)."""
    a = np.asarray(a)
    if a.size and int(a.max()) > np.iinfo(np.intc).max:
        return a.astype(np.int64, copy=False)
    return a.astype(np.intc)


# ---- exact signs of small determinants (the scipy attributes' exact parts) ----------
#
# ConvexHull.good / .coplanar, Delaunay.good and the zero-volume test behind
# Delaunay.transform are exact decisions about determinants of small matrices
# whose entries are differences of input doubles (and, for Delaunay.good,
# lifted heights). They are made by a floating-point filter and, for the few
# matrices it cannot decide, by integer arithmetic on the doubles taken as
# exact rationals (fractions.Fraction), sharing no code with the compiled
# predicates.

_FILTER = 1e-6  # the filter's threshold on a row-scaled determinant (below)


def _exact_sign(rows) -> int:
    """The sign of det(rows), rows a square list of lists of Fractions:
    the entries brought to one power-of-two denominator, then Bareiss'
    fraction-free elimination on Python integers (exact)."""
    n = len(rows)
    den = 1
    for r in rows:
        for x in r:
            den = den * x.denominator // math.gcd(den, x.denominator)
    m = [[int(x * den) for x in r] for r in rows]
    sign, prev = 1, 1
    for k in range(n - 1):
        if m[k][k] == 0:
            p = next((i for i in range(k + 1, n) if m[i][k] != 0), None)
            if p is None:
                return 0
            m[k], m[p] = m[p], m[k]
            sign = -sign
        for i in range(k + 1, n):
            for j in range(k + 1, n):
                m[i][j] = (m[i][j] * m[k][k] - m[i][k] * m[k][j]) // prev
        prev = m[k][k]
    last = m[n - 1][n - 1]
    return sign * ((last > 0) - (last < 0))


def _det(m: np.ndarray) -> np.ndarray:
    """Determinants of stacked n x n matrices (..., n, n): written out for
    n <= 3 (numpy's LU costs about a microsecond per small matrix), else
    numpy's."""
    n = m.shape[-1]
    if n == 1:
        return m[..., 0, 0].copy()
    if n == 2:
        return m[..., 0, 0] * m[..., 1, 1] - m[..., 0, 1] * m[..., 1, 0]
    if n == 3:
        a, b, c = m[..., 0, :], m[..., 1, :], m[..., 2, :]
        return (a[..., 0] * (b[..., 1] * c[..., 2] - b[..., 2] * c[..., 1])
                + a[..., 1] * (b[..., 2] * c[..., 0] - b[..., 0] * c[..., 2])
                + a[..., 2] * (b[..., 0] * c[..., 1] - b[..., 1] * c[..., 0]))
    return np.linalg.det(m)


def _det_signs(mats: np.ndarray, exact, mags: Optional[np.ndarray] = None) -> np.ndarray:
    """Exact signs (int8) of det(M_i) for the k matrices of mats (k, n, n),
    each computed in floating point from the exact matrix exact(i) (a list of
    rows of Fractions) with every entry's absolute error at most 16 * 2^-53
    times its row's magnitude: max |entry| of the row, or mags[i, row] where
    given (an upper bound of the terms an entry was computed from).

    The filter: each row scaled by the power of two that brings its magnitude
    into [1/2, 1) (exact), then numpy's LU determinant. The rows of the scaled
    matrix have norm <= sqrt(n) <= sqrt(6), so the input errors move the
    determinant by at most about n * sqrt(n)^n * 16 * 2^-53 < 1e-11, and its
    evaluation (cofactors: n! terms of at most 1; LU with partial pivoting,
    growth factor <= 2^(n-1)) by less than 1e-9; where
    |det| > 1e-6 the sign is certain. The rest (and any matrix with an
    entry that over- or underflowed) is decided by _exact_sign."""
    k = mats.shape[0]
    out = np.zeros(k, dtype=np.int8)
    if k == 0:
        return out
    with np.errstate(all="ignore"):
        mag = np.abs(mats).max(axis=2)
        if mags is not None:
            mag = np.maximum(mag, mags)
        good = np.isfinite(mag).all(axis=1) & (mag > 1e-290).all(axis=1) & (mag < 1e290).all(axis=1)
        _, e = np.frexp(np.where(good[:, None], mag, 1.0))
        scaled = np.ldexp(np.where(good[:, None, None], mats, 0.0), -e[:, :, None])
        det = _det(scaled)
    sure = good & np.isfinite(det) & (np.abs(det) > _FILTER)
    out[sure] = np.sign(det[sure]).astype(np.int8)
    for i in np.flatnonzero(~sure):
        out[i] = _exact_sign(exact(int(i)))
    return out


def _fractions(points: np.ndarray, rows) -> list:
    return [[Fraction(float(x)) for x in points[r]] for r in rows]


def _differences(points: np.ndarray, rows, base) -> list:
    """The exact rows points[r] - points[base] (Fractions)."""
    b = [Fraction(float(x)) for x in points[base]]
    return [[Fraction(float(x)) - y for x, y in zip(points[r], b)] for r in rows]


# ---- qhull_options ---------------------------------------------------------------------

#: The Qhull options flipflop accepts (qhull_options of ConvexHull and
#: Delaunay). Applied: Qc (fill `coplanar`), QGn / QG-n (compute without point
#: n; `good` marks the facets that see it / do not see it). Accepted and
#: ignored, because they only steer Qhull's floating-point computation, which
#: flipflop does not do (its answer is the exact one): Qbb QbB (scale the last
#: coordinate / to the unit cube), Qz (a point at infinity against cospherical
#: input), Qx (exact pre-merges), QJ / QJn (joggle the input), Qt (triangulate
#: merged facets: flipflop's output is always simplicial), Q12 (allow wide
#: facets), Pp (do not print precision warnings).
QHULL_OPTIONS_IGNORED = ("Qbb", "QbB", "Qz", "Qx", "QJ", "Qt", "Q12", "Pp")
QHULL_OPTIONS_APPLIED = ("Qc", "QGn", "QG-n")


class QhullOptionError(ValueError, RuntimeError):
    """A qhull_options string flipflop does not accept. A ValueError (bad
    input, flipflop's rule) and a RuntimeError (what scipy's QhullError is),
    so that code written for either catches it."""


class _Options:
    def __init__(self, text: str, coplanar: bool, good: Optional[int], visible: bool):
        self.text, self.coplanar, self.good, self.visible = text, coplanar, good, visible


def _qhull_options(options, what: str, default: str) -> _Options:
    """One parser for both classes: str or bytes (as scipy), tokens
    separated by white space; QhullOptionError naming any other token. As in
    scipy, a given string replaces the class's default options."""
    if options is None:
        options = default
    if isinstance(options, (bytes, bytearray)):
        try:
            options = bytes(options).decode("ascii")
        except UnicodeDecodeError:
            raise QhullOptionError(f"{what}: qhull_options must be ASCII, got {options!r}") from None
    if not isinstance(options, str):
        raise QhullOptionError(f"{what}: qhull_options must be a str or bytes, got {type(options).__name__}")
    coplanar, good, visible = False, None, True
    for tok in options.split():
        if tok in QHULL_OPTIONS_IGNORED:
            continue
        if tok == "Qc":
            coplanar = True
            continue
        if tok.startswith("QJ"):
            try:
                float(tok[2:])
                continue
            except ValueError:
                pass
        m = re.fullmatch(r"QG(-?)(\d+)", tok)
        if m:
            if good is not None:
                raise QhullOptionError(f"{what}: qhull option {tok!r}: only one QGn or QG-n may be given")
            good, visible = int(m.group(2)), m.group(1) != "-"
            continue
        raise QhullOptionError(
            f"{what}: qhull option {tok!r} is not supported (flipflop applies Qc, QGn and QG-n and accepts "
            f"{' '.join(QHULL_OPTIONS_IGNORED)} as no-ops: its answer is exact)")
    return _Options(options, coplanar, good, visible)


def _good_point(opts: _Options, a: np.ndarray, what: str):
    """(kept indices, the QG point) or (None, None) without QGn."""
    if opts.good is None:
        return None, None
    n = a.shape[0]
    if opts.good >= n:
        raise QhullOptionError(f"{what}: qhull option QG{'' if opts.visible else '-'}{opts.good}: "
                               f"there are {n} points (0..{n - 1})")
    if not np.isfinite(a[opts.good]).all():
        raise ValueError(f"{what}: the points hold NaN or infinite coordinates (point {opts.good})")
    return np.flatnonzero(np.arange(n) != opts.good), opts.good


def _new_points(points, d: int, what: str) -> np.ndarray:
    try:
        a = np.asarray(points, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise ValueError(f"{what}: points must be numeric: {e}") from None
    if a.ndim != 2 or a.shape[1] != d:
        raise ValueError(f"{what}: invalid size for new points array: shape (k, {d}) expected, got {a.shape}")
    return a


class _QhullUser:
    """add_points / close as scipy's _QhullUser: add_points needs
    incremental=True and no close() before it (RuntimeError otherwise, as
    scipy); it recomputes the answer for all points."""

    def close(self) -> None:
        """As scipy: ends incremental mode (add_points raises RuntimeError
        afterwards) and frees the kernel kept for in-place insertion;
        flipflop holds no Qhull resources; the attributes stay."""
        self._closed = True
        self._inc = None

    def _check_incremental(self):
        if not self._incremental or self._closed:
            raise RuntimeError("incremental mode not enabled or already closed")

    @property
    def npoints(self) -> int:
        return self.points.shape[0]

    @property
    def nsimplex(self) -> int:
        return self.simplices.shape[0]

    @property
    def min_bound(self) -> np.ndarray:
        return self.points.min(axis=0)

    @property
    def max_bound(self) -> np.ndarray:
        return self.points.max(axis=0)


class ConvexHull(_QhullUser):
    """The convex hull of points in 2D..9D, exact and certified, with
    scipy.spatial.ConvexHull's constructor and attributes
    (docs/scipy_porting.md lists every name and difference). 4D..9D:
    the hull kernel's facets (beneath-beyond, exact, certified; backend
    'cpu') or the boundary facets
    of the canonical Delaunay triangulation (RT+1, certified; backend
    'reference'), which are the
    canonical hull's facets (_hull_d says why), with the
    attributes below computed in Python; facets outward (det[f1-f0, ...,
    x-f0] > 0 beyond), ascending but for a swap of the last two.

    ConvexHull(points, incremental=False, qhull_options=None, *,
               strict=False, backend=None, threads=0)

    Attributes (as scipy.spatial.ConvexHull):
      points     (n, d) float64, the input
      simplices  3D: (m, 3) triangles, counter-clockwise seen from outside;
                 2D: (k, 2) edges (i, next) of the counter-clockwise hull;
                 4D..9D: (m, d) outward (above)
      neighbors  (m, d) the facet opposite each vertex of each simplex
      vertices   2D: the hull vertices counter-clockwise from the smallest
                 index; 3D..9D: sorted
      equations  (m, d+1) [unit outward normal, offset]: normal.x + offset
                 <= 0 inside (floating point, from the exact facets; NaN
                 normals for the zero-area facets of degenerate input)
      volume, area  (2D: area and perimeter; 3D..9D: volume and surface
                 area; inf or 0 only where the true value is not a double)
      coplanar   (k, 3) intc [point, facet, vertex], filled only when
                 qhull_options holds Qc (else shape (0, 3)): the points
                 that lie exactly on the hull's boundary but are not
                 vertices, each with a facet whose plane holds it exactly
                 (one whose closed facet holds it, where floating point can
                 tell) and that facet's vertex nearest to it
      good       None, or with qhull_options QGn / QG-n a bool array over
                 the facets: those that point n sees (strictly on their
                 outer side, decided exactly) / does not see; as in Qhull,
                 the hull is then the hull of the points without point n
      npoints, nsimplex, ndim, min_bound, max_bound
    In 2D and 3D all but coplanar and good are computed once, in the
    compiled call, from the certified facets.

    The canonical answer (default) is flipflop's unique answer under
    Simulation of Simplicity: on degenerate input it may keep points inside
    hull edges or facets as vertices and split coplanar facets as the
    perturbation decides. strict=True (3D) returns the strict view instead:
    strictly extreme vertices only, each exact facet fan-triangulated from
    its smallest vertex (no zero-area triangle); `polygons` then holds the
    merged facets.

    incremental=True allows add_points(points, restart=False). The
    construction is the one-shot call's. With the 'cpu' backend (and no
    strict view) the first add_points then creates the d-dimensional hull
    kernel (kernels_cpu/rtd/hull_d) on the certified hull's vertices only —
    every other point was certified strictly inside, and a hull only grows
    — and keeps it: each add_points inserts only the new points into it, in
    place, and certifies the result in the canonical form of the one-shot
    call — the same answer byte for byte (the canonical hull does not depend
    on the insertion order; restart changes nothing). With another backend
    or strict=True add_points recomputes. close() ends incremental mode and
    frees the kept kernel.

    qhull_options: Qc and QGn / QG-n are applied; Qbb QbB Qz Qx QJ Qt Q12 Pp
    are accepted and ignored (they steer Qhull's floating point; flipflop's
    answer is exact); anything else raises QhullOptionError (a ValueError
    and a RuntimeError). str or bytes.

    backend: 'cpu' (the default: the multithreaded kernels in 2D and 3D,
    the d-dimensional hull kernel in 4D..9D, one thread),
    'reference' (the exact sequential reference)
    or one of `gpu_backends` ('cuda-omp': the GPU kernels on thrust's OpenMP
    backend); every backend returns the same answer. strict=True (3D only)
    uses the 'cpu' kernel whatever the backend.

    threads: worker threads (0: the runtime's default, every core the
    process may use) of the 'cpu' kernels and of the certifier; the answer
    is the same at any count. The GIL is released while computing.
    """

    def __init__(self, points, incremental: bool = False, qhull_options=None, *, strict: bool = False,
                 backend: Optional[str] = None, threads: int = 0):
        a = _points(points, _DIMS, "ConvexHull", finite=False)
        d = a.shape[1]
        self._options = _qhull_options(qhull_options, "ConvexHull", "Qx" if d > 4 else "")
        if strict and d != 3:
            raise ValueError("ConvexHull: strict=True applies to 3D hulls")
        if backend is not None or not strict:
            _backend(backend, _HULL_BACKENDS[d], "ConvexHull")
        self._strict, self._backend, self._threads = bool(strict), backend, _threads(threads, "ConvexHull")
        self._incremental, self._closed = bool(incremental), False
        self._inc = self._inc_points = None
        self._update(a)

    def add_points(self, points, restart: bool = False) -> None:
        """As scipy's: adds points (shape (k, ndim)); needs incremental=True
        and no close() before (RuntimeError otherwise, as scipy). With the
        'cpu' backend the points are inserted in place into the kept hull
        (see the class docstring); otherwise the hull of all points is
        computed again. Either way the answer is the one-shot answer (restart
        is accepted and changes nothing: the canonical answer does not depend
        on the insertion order). On bad input (ValueError) the hull is left
        as it was."""
        self._check_incremental()
        new = _new_points(points, self.ndim, "ConvexHull.add_points")
        self._update(np.ascontiguousarray(np.concatenate([self.points, new])))

    def _update(self, a: np.ndarray) -> None:
        d = a.shape[1]
        keep, g = _good_point(self._options, a, "ConvexHull")
        sub = a if keep is None else np.ascontiguousarray(a[keep])
        threads = self._threads
        polygons = None
        # every attribute comes from the compiled call, computed there in one
        # pass over the certified facets (python/src/module.cpp: HullMeasures)
        kept = self._incremental and not self._strict and (self._backend or "cpu") == "cpu"
        if kept and getattr(self, "_inc_points", None) is not None:
            attributes = self._kept_hull_add(sub, threads)
        elif d == 2:
            attributes = _native("ConvexHull", _flipflop.hull2, sub, _backend(self._backend, _HULL_BACKENDS[2],
                                                                                "ConvexHull"), threads)
        elif d > 3:
            attributes = _hull_d(sub, _backend(self._backend, _HULL_BACKENDS[d], "ConvexHull"),
                                                  threads)
        elif self._strict:
            attributes, polys = _native("ConvexHull", _flipflop.hull3_strict, sub, threads)
            polygons = [np.asarray(p, dtype=np.int64) for p in polys]
        else:
            attributes = _native("ConvexHull", _flipflop.hull3, sub, _backend(self._backend, _HULL_BACKENDS[3],
                                                                                "ConvexHull"), threads)
        simplices, vertices, neighbors, equations, volume, area = attributes
        if kept:  # the certified hull's facets, indices into sub, for the next add_points
            self._inc_points = (len(sub), simplices, neighbors)
        if keep is not None:  # back to the input's indices (a monotone map: the canonical form is kept)
            simplices, vertices = keep[simplices], keep[vertices]
            if polygons is not None:
                polygons = [keep[p] for p in polygons]
        good = None
        if g is not None:
            sees = _hull_sees(a, simplices, g) if len(simplices) else np.zeros(0, dtype=bool)
            good = sees if self._options.visible else ~sees
        coplanar = np.zeros((0, 3), dtype=np.int64)
        if self._options.coplanar:
            others = np.ones(a.shape[0], dtype=bool)
            others[vertices] = False
            if g is not None:
                others[g] = False
            coplanar = _hull_coplanar(a, simplices, np.flatnonzero(others))
        self.points, self.ndim, self.polygons = a, d, polygons
        # scipy's index dtype (np.intc)
        self.simplices, self.vertices, self.neighbors = _intc(simplices), _intc(vertices), _intc(neighbors)
        self.equations, self.volume, self.area, self.good, self.coplanar = equations, volume, area, good, _intc(coplanar)

    def _kept_hull_add(self, sub: np.ndarray, threads: int):
        """add_points on the kept hull kernel (incremental=True, 'cpu'):
        the attributes of the hull of sub, whose first n points were
        certified before with the facets s and their neighbours
        (self._inc_points: simplices, indices into sub, and neighbors). The kernel (_flipflop.IncrementalHull) holds only
        what can still matter: at the first add it is seeded with that
        certified hull on its vertices v alone (no construction: the facets
        and their links from neighbors), then every add inserts the new points into it in
        place and certifies the result. Its points are sub[self._inc_index],
        an ascending subset of sub, so its answer maps back by a monotone
        renumbering, under which every SoS sign and the canonical form are
        the same (predicates.hpp; python/src/module.cpp, IncrementalHull,
        says why the hull of v and the new points is the hull of all of
        them: every other point was certified strictly inside conv(v), and a
        hull only grows). Bad input (ValueError) is refused before the
        kernel changes; any other failure drops the kernel, and the next add
        seeds it again from the last certified hull."""
        n, s, nb = self._inc_points
        d = sub.shape[1]
        inc = self._inc
        try:
            if inc is None:
                v = np.unique(s)
                # the kernel's convention, orient_d(facet, x) < 0 inside: the
                # public simplices with the last two vertices swapped in 2D
                # ((i, next) counter-clockwise) and in odd d (outward,
                # det[f1-f0, ..., x-f0] > 0 beyond; _hull_d says why), and
                # the neighbours' columns with them
                seed, nb = np.searchsorted(v, s).astype(np.int64), np.array(nb, dtype=np.int64)
                if d == 2 or d % 2 == 1:
                    seed[:, -2:], nb[:, -2:] = seed[:, -1:-3:-1], nb[:, -1:-3:-1]
                inc = _native("ConvexHull", _flipflop.IncrementalHull, np.ascontiguousarray(sub[v]), threads,
                              np.ascontiguousarray(seed), np.ascontiguousarray(nb))
                self._inc, self._inc_index = inc, v
            index = np.concatenate([self._inc_index, np.arange(n, len(sub))])
            _native("ConvexHull.add_points", inc.add, np.ascontiguousarray(sub[index]))
        except ValueError:
            raise
        except BaseException:
            self._inc = None
            raise
        try:
            local = inc.attributes() if d <= 3 else _hull_d(sub[index], "cpu", threads, facets=inc.facets())
        except BaseException:  # the kernel holds the new points: drop it
            self._inc = None
            raise
        self._inc_index = index
        return (index[local[0]], index[local[1]]) + tuple(local[2:])


def _hull_d(a: np.ndarray, backend: str, threads: int, facets: Optional[np.ndarray] = None):
    """The convex hull in 4D..9D: backend 'cpu' the facets of the hull
    kernel (kernels_cpu/rtd/hull_d, beneath-beyond, certified), 'reference'
    the boundary facets of the canonical Delaunay triangulation (RT+1,
    certified) — the same facets —, with the
    attributes the compiled call gives in 2D and 3D, computed in floating
    point by _flipflop.hull_d_attributes. Why it is the canonical hull: an unweighted Delaunay
    triangulation covers the convex hull of all points, so its boundary
    facets triangulate the hull's boundary; under the perturbation the
    points are in general position, the hull is simplicial and its facets
    are those boundary facets. The hull's orientation predicates use only
    the spatial coordinates, whose perturbation is ordered the same whether
    the lifted height is perturbed too or not (DESIGN.md: c(i,j) + eps^(2^(i
    delta - j)) orders the terms by i, then j, for any delta), so they are
    the canonical hull's facets. Tested against the definition (every point
    on the inner side of every facet, exactly) and scipy.

    Facets: outward, det[f1-f0, ..., f_{d-1}-f0, x-f0] > 0 for x beyond
    (the 3D hull's counter-clockwise rule), vertices ascending but for a
    swap of the last two where the orientation needs it; rows sorted.
    facets: the hull kernel's certified facets when already computed (the
    kept kernel of an incremental hull), backend 'cpu'."""
    d = a.shape[1]
    if backend == "cpu":
        # the hull kernel's facets (kernels_cpu/rtd/hull_d, certified there):
        # orient_d(facet, x) < 0 inside, and orient_d = (-1)^d det[f1-f0, ...,
        # x-f0] (the 1-column of the predicates' matrix last): outward in the
        # det convention after a swap in odd d
        if facets is None:
            facets = _native("ConvexHull", _flipflop.hull_d, a, threads)
        if d % 2 == 1:
            facets[:, -2:] = facets[:, -1:-3:-1]
    else:
        simplices, _ = _native("ConvexHull", _flipflop.triangulate, a, None, backend, False, threads)
        nb = _flipflop.neighbors(simplices)
        i, j = np.nonzero(nb < 0)
        keep = np.ones((len(i), d + 1), dtype=bool)
        keep[np.arange(len(i)), j] = False
        facets = simplices[i][keep].reshape(-1, d)
        # the facet opposite vertex j of a positively oriented simplex, with
        # that vertex appended, has the sign (-1)^(d-j); inside must be negative
        flip = (d - j) % 2 == 0
        facets[flip, -2:] = facets[flip, -1:-3:-1]
    # canonical form, vertices, neighbours, equations, area and volume in
    # one compiled pass (python/src/module.cpp: hull_d_attributes)
    return _flipflop.hull_d_attributes(a, np.ascontiguousarray(facets, dtype=np.int64))


def _hull_sides(points: np.ndarray, facets: np.ndarray, queries: np.ndarray, pairs_f: np.ndarray,
                pairs_q: np.ndarray) -> np.ndarray:
    """For the pairs (facet pairs_f[i], point queries[pairs_q[i]], an index
    into points): +1 when the point is strictly outside the facet's
    hyperplane (the side its outward normal points to), -1 strictly inside,
    0 on it; exact. The facets are flipflop's: 3D triangles counter-clockwise
    seen from outside (outward = +det[b-a, c-a, x-a]; 4D..9D:
    +det[f1-f0, ..., x-f0] likewise), 2D edges of the counter-clockwise cycle
    (outward = -det[b-a, x-a]). The signs are the compiled exact orient_d
    (_flipflop.simplex_signs, in parallel) of the facet's vertices and the
    point: det[[p 1]] with the 1-column last = (-1)^d det[f1-f0, ..., x-f0]."""
    d = points.shape[1]
    cells = np.ascontiguousarray(np.concatenate([facets[pairs_f], queries[pairs_q][:, None]], axis=1), dtype=np.int64)
    s = _flipflop.simplex_signs(points, cells).astype(np.int8)
    s = s if d % 2 == 0 else -s
    return s if d >= 3 else -s


def _hull_sees(points: np.ndarray, facets: np.ndarray, g: int) -> np.ndarray:
    """Which facets have point g strictly on their outer side (exact)."""
    m = len(facets)
    return _hull_sides(points, facets, np.array([g], dtype=np.int64), np.arange(m), np.zeros(m, dtype=np.int64)) > 0


def _nondegenerate_facets(points: np.ndarray, facets: np.ndarray) -> np.ndarray:
    """The facets whose vertices span a hyperplane, exactly: the (d-1) x d
    matrix [f1-f0; ...] has a non-zero (d-1)-minor (2D: distinct endpoints;
    3D: one of the three coordinate projections not collinear)."""
    d = points.shape[1]
    U = np.stack([points[facets[:, j]] - points[facets[:, 0]] for j in range(1, d)], axis=1)  # (m, d-1, d)
    ok = np.zeros(len(facets), dtype=bool)
    for cols in combinations(range(d), d - 1):
        undecided = np.flatnonzero(~ok)
        if len(undecided) == 0:
            break
        mats = U[undecided][:, :, list(cols)]

        def exact(k, cols=cols, undecided=undecided):
            rows = _differences(points, list(facets[undecided[k], 1:]), facets[undecided[k], 0])
            return [[r[c] for c in cols] for r in rows]

        ok[undecided] = _det_signs(mats, exact) != 0
    return ok


def _hull_coplanar(points: np.ndarray, facets: np.ndarray, candidates: np.ndarray) -> np.ndarray:
    """scipy's `coplanar` for an exact hull: (k, 3) [point, facet, vertex]
    for the candidates (points that are not hull vertices) that lie exactly
    on the hull's boundary: on the hyperplane of a facet of non-zero size
    (every point is inside or on the hull, so a point on a supporting
    hyperplane is on the boundary, and the facets of non-zero size cover
    the boundary). A float filter picks the (point, facet) pairs that may be
    0; _hull_sides decides them exactly."""
    d = points.shape[1]
    live = np.flatnonzero(_nondegenerate_facets(points, facets))
    out = []
    if len(live) == 0 or len(candidates) == 0:
        return np.zeros((0, 3), dtype=np.int64)
    F = facets[live]
    a = points[F[:, 0]]
    U = np.stack([points[F[:, j]] - a for j in range(1, d)], axis=1)  # (f, d-1, d)
    # n: the cofactors of the last row of det[U; w], so that det = n . w
    n = np.stack([(-1) ** (d - 1 + k) * _det(np.delete(U, k, axis=2)) for k in range(d)], axis=1)
    scale = np.prod(np.abs(U).sum(axis=2), axis=1)
    tolerance = 1e-14 if d <= 3 else 1e-12  # n's error: cofactors (d <= 3), LU (d = 4, 5)
    chunk = max(1, (1 << 20) // len(live))
    for lo in range(0, len(candidates), chunk):
        c = candidates[lo:lo + chunk]
        with np.errstate(all="ignore"):
            w = points[c][:, None, :] - a[None, :, :]  # (c, f, d)
            det = np.einsum("cfd,fd->cf", w, n)
            bound = tolerance * np.abs(w).sum(axis=2) * scale[None, :]
            maybe = ~(np.isfinite(det) & np.isfinite(bound) & (bound > 1e-250) & (np.abs(det) > bound))
        qi, fi = np.nonzero(maybe)
        if len(qi) == 0:
            continue
        zero = _hull_sides(points, F, c, fi, qi) == 0
        qi, fi = qi[zero], fi[zero]
        for q in np.unique(qi):
            p = int(c[q])
            fs = fi[qi == q]
            best = _containing_facet(points, F[fs], points[p])
            facet = F[fs[best]]
            dist = np.abs(points[facet] - points[p]).sum(axis=1)
            out.append((p, int(live[fs[best]]), int(facet[int(np.argmin(dist))])))
    if not out:
        return np.zeros((0, 3), dtype=np.int64)
    return np.array(sorted(out), dtype=np.int64)


def _containing_facet(points: np.ndarray, facets: np.ndarray, x: np.ndarray) -> int:
    """Among facets whose plane holds x exactly, the first whose closed
    facet holds x as far as floating point can tell (barycentric coordinates
    >= -1e-9), else the one where x is least outside; only a choice among
    correct answers."""
    best, worst = 0, -np.inf
    for k, f in enumerate(facets):
        V = points[f]
        A = (V[1:] - V[0]).T  # (d, d-1)
        with np.errstate(all="ignore"):
            lam = np.linalg.lstsq(A, x - V[0], rcond=None)[0]
        bary = np.concatenate([[1 - lam.sum()], lam])
        low = float(bary.min()) if np.isfinite(bary).all() else -np.inf
        if low >= -1e-9:
            return k
        if low > worst:
            best, worst = k, low
    return best


# The sign of the lifted in-sphere determinant (rows (v_j - x, |v_j - x|^2))
# of a positively oriented simplex with x inside its circumsphere, per d:
# computed once, exactly, for the standard simplex and its centroid.
def _insphere_sign(d: int) -> int:
    verts = [[Fraction(0)] * d] + [[Fraction(int(i == j)) for i in range(d)] for j in range(d)]
    x = [Fraction(1, d + 1)] * d
    rows = []
    for v in verts:
        r = [a - b for a, b in zip(v, x)]
        rows.append(r + [sum(c * c for c in r)])
    return _exact_sign(rows)


_INSPHERE = {d: _insphere_sign(d) for d in _DIMS}


def _kept(owner, what: str, create, add):
    """The compiled kernel kept in owner._inc for in-place insertion
    (_flipflop.IncrementalTriangulation or IncrementalHull): create() it on
    the first call, later add(kept) the points after those it holds (the
    caller's array extends the points given before: add_points appends, and
    QGn's kept set only grows at its end). Bad input is refused before
    anything changes (ValueError: the kept kernel stays); any other failure
    drops it, so that the next add_points rebuilds."""
    inc = getattr(owner, "_inc", None)
    try:
        if inc is None:
            inc = _native(what, create)
        else:
            _native(what + ".add_points", add, inc)
    except ValueError:
        raise
    except BaseException:
        owner._inc = None
        raise
    owner._inc = inc
    return inc


def _kept_triangulation(owner, what: str, sub: np.ndarray, sw: Optional[np.ndarray], strict: bool, threads: int,
                        furthest: bool):
    """(simplices, redundant, neighbors or None) of the points sub (weights
    sw) for an incremental Delaunay or Voronoi, with the cavity-insertion
    kernel kept in owner._inc (_flipflop.IncrementalTriangulation, certified
    after every add; _kept) for in-place adds.

    In 2D and 3D (no strict view, no furthest site) the construction is the
    one-shot call's (the multithreaded kernels, 3-5x faster than the cavity
    kernel's build) and the first add seeds the kernel with that certified
    triangulation — its simplices and neighbours, no predicate — kept in
    owner._inc_seed, then inserts the new points into it; elsewhere the
    kernel builds the triangulation and is kept from the construction. A
    kernel dropped by a failure is seeded again from the last certified
    answer."""
    seeded = sub.shape[1] <= 3 and not strict and not furthest
    if seeded and getattr(owner, "_inc", None) is None:
        seed = getattr(owner, "_inc_seed", None)
        if seed is None:  # the construction: the one-shot kernels
            simplices, redundant, neighbors = _native(what, _flipflop.triangulate_with_neighbors, sub, sw, "cpu",
                                                      False, threads, False)
            if neighbors is None:
                neighbors = _flipflop.neighbors(simplices)
            owner._inc_seed = (len(sub), simplices, neighbors)
            return simplices, redundant, neighbors
        n, s, nb = seed
        owner._inc = _native(what, _flipflop.IncrementalTriangulation, np.ascontiguousarray(sub[:n]),
                             None if sw is None else np.ascontiguousarray(sw[:n]), threads, s, nb)
    inc = _kept(owner, what, lambda: _flipflop.IncrementalTriangulation(sub, sw, strict, threads, furthest),
                lambda k: k.add(sub, sw))
    simplices, redundant = inc.result()
    neighbors = inc.neighbors()
    if seeded:
        owner._inc_seed = (len(sub), simplices, neighbors)
    return simplices, redundant, neighbors


class Delaunay(_QhullUser):
    """The regular (weighted Delaunay) triangulation of points in 2D..9D,
    exact and certified; with weights=None the Delaunay triangulation. The
    constructor and attributes are scipy.spatial.Delaunay's
    (docs/scipy_porting.md lists every name and difference):

    Delaunay(points, furthest_site=False, incremental=False,
             qhull_options=None, *, weights=None, strict=False,
             backend=None, threads=0)

    Attributes (as scipy.spatial.Delaunay; index arrays np.intc, as scipy's):
      points       (n, d) float64
      simplices    (m, d+1) positively oriented (det[p1-p0, ..., pd-p0] > 0),
                   canonical order
      neighbors    (m, d+1) the simplex opposite each vertex, -1 outside
      convex_hull  (h, d) the boundary facets
      equations    (m, d+2) [unit normal, offset] of each simplex's lifted
                   hyperplane: the hyperplane through the lifted vertices
                   (v, s * (|v|^2 - w_v)), s = paraboloid_scale (shift 0),
                   normal pointing down (outward of the lower hull); the
                   zero-volume simplices' are vertical (normal[-1] = 0) or
                   NaN (floating point, from the exact simplices)
      paraboloid_scale, paraboloid_shift  the lift: lift_points(x) = (x,
                   s |x|^2 + shift); s a power of two (about 1 / the largest
                   coordinate, Qbb's intent), shift 0.0
      transform    (m, d+1, d) the barycentric transform: [:d] = T^-1,
                   [d] = r = the last vertex, T's columns v_j - r; NaN for
                   the zero-volume simplices (decided exactly) and any a
                   floating-point inverse fails on
      vertex_to_simplex  (n,) a simplex holding each vertex; for the points
                   in `coplanar` their simplex, else -1
      vertex_neighbor_vertices  (indptr, indices): the vertices joined to
                   vertex k by an edge are indices[indptr[k]:indptr[k+1]],
                   ascending
      coplanar     (k, 3) [point, simplex, vertex]: the points that are not
                   vertices (duplicates; weighted: redundant points), a
                   simplex that contains it (exact point location) and that
                   simplex's vertex nearest to it; computed when
                   qhull_options holds Qc, as in scipy (its default does)
      good         (m,) int: 1 for every simplex; with QGn / QG-n, 1 where
                   point n lies strictly inside / not strictly inside the
                   simplex's circumsphere (weighted: power distance < 0;
                   exact), the triangulation then being that of the other
                   points (as Qhull)
      redundant    the points that are not vertices
      nsimplex, npoints, ndim, min_bound, max_bound, furthest_site,
      vertices     scipy's deprecated alias of simplices (DeprecationWarning)
    The floating-point attributes are computed on first use, like scipy's
    transform. find_simplex(xi) locates points exactly (-1: outside the
    hull); plane_distance(xi) and lift_points(x) use the lift above.

    The canonical answer may hold simplices of zero volume on degenerate
    input (collinear or cospherical points): it is the unique answer under
    Simulation of Simplicity, the one every backend reproduces. strict=True
    returns the strict view instead: a regular triangulation of the exact
    input without zero-volume simplices (the 2D grid's 2(k-1)^2 triangles, d!
    simplices per cube of a grid in d >= 3), certified (`dt2 --strict`,
    `rtd --strict` on the command line).

    furthest_site=True: the furthest-site Delaunay triangulation (every
    dimension 2..9, unweighted, the 'cpu' backend — the cavity-insertion
    kernel, every dimension — or 'reference'; no strict view):
    the upper hull of the lifted points projected, its vertices those of
    the convex hull (the other points are in `redundant`; `coplanar` is
    empty, as scipy's), certified exactly. Its canonical answer is the upper
    hull of flipflop's perturbed lifted points (x + ε_x, |x|^2 + ε_h): on
    cospherical input it splits the ties as that perturbation decides
    (Qhull's may differ there). `equations` then point up (outward of the
    upper hull, as scipy's), and QGn / QG-n's `good` marks the simplices
    whose circumsphere point n lies strictly outside of / not.
    incremental=True allows add_points(points,
    restart=False, *, weights=None). With the 'cpu' backend the
    cavity-insertion kernel (kernels_cpu/rtd) is kept: in 2D and 3D (no
    strict view, no furthest site) the construction is the one-shot call's
    and the first add_points seeds the kernel with that certified
    triangulation; elsewhere the kernel builds it. add_points
    inserts only the new points into it, in place, and certifies the result;
    the answer is the one-shot answer for all the points, byte for byte (the
    canonical answer does not depend on the insertion order; restart changes
    nothing). With backend='reference' add_points recomputes. close() ends
    incremental mode and frees the kept kernel.

    qhull_options: Qc and QGn / QG-n are applied; Qbb QbB Qz Qx QJ Qt Q12 Pp
    are accepted and ignored (they steer Qhull's floating point; flipflop's
    answer is exact); anything else raises QhullOptionError (a ValueError
    and a RuntimeError). Default, as scipy: "Qbb Qc Qz Q12" ("Qbb Qc Qz Qx
    Q12" for d > 4). str or bytes.

    backend: 'cpu' (the default: the multithreaded kernels of kernels_cpu/rt2
    and kernels_cpu/rt3, certified from their witnesses, in 2D and 3D; the
    cavity-insertion kernel of kernels_cpu/rtd, one thread, certified by the
    d-dimensional certifier, in 4D..9D), 'reference' (the exact
    sequential reference: ffRT in 2D, RT+1 in 3D..9D) or, in 2D and 3D, one
    of `gpu_backends` ('cuda-omp': the GPU kernels kernels_cuda/rt2 and
    kernels_cuda/rt3 on thrust's OpenMP backend; 'cuda': on the device, where
    nvcc built them); every backend returns the same simplices. strict=True derives the strict view from the backend's
    certified answer by the reference's (sequential) rule.
    threads: worker threads of the 'cpu' backend and of its certifier
    (0: all cores); the answer is the same at any count.
    """

    furthest_site = False

    def __init__(self, points, furthest_site=False, incremental: bool = False, qhull_options=None, *,
                 weights=None, strict: bool = False, backend: Optional[str] = None, threads: int = 0):
        self.furthest_site = _furthest_site(furthest_site, "Delaunay")
        if self.furthest_site and strict:
            raise ValueError("Delaunay: furthest_site=True has no strict view (strict=True)")
        if self.furthest_site and weights is not None:
            raise ValueError("Delaunay: furthest_site=True takes no weights")
        if self.furthest_site and backend not in (None, "cpu", "reference"):
            raise ValueError(f"Delaunay: furthest_site=True is computed by the 'cpu' or the 'reference' backend, "
                             f"got {backend!r}")
        a = _points(points, _DIMS, "Delaunay", finite=False)
        d = a.shape[1]
        if strict and d > 5:
            raise ValueError(f"Delaunay: strict=True is defined for 2D..5D (its second perturbation), got {d}D")
        self._options = _qhull_options(qhull_options, "Delaunay", "Qbb Qc Qz Qx Q12" if d > 4 else "Qbb Qc Qz Q12")
        self._strict, self._threads = bool(strict), _threads(threads, "Delaunay")
        self._backend = ((backend or "cpu") if self.furthest_site
                         else _backend(backend, _DELAUNAY_BACKENDS[d], "Delaunay"))
        self._incremental, self._closed = bool(incremental), False
        self._inc = self._inc_seed = None
        self._update(a, _weights(weights, a.shape[0], "Delaunay"))

    def add_points(self, points, restart: bool = False, *, weights=None) -> None:
        """As scipy's: adds points (shape (k, ndim)); needs incremental=True
        and no close() before (RuntimeError otherwise, as scipy). A weighted
        triangulation needs their weights (shape (k,)), an unweighted one
        none. With the 'cpu' backend the points are inserted in place into
        the kept triangulation (see the class docstring); with 'reference'
        all points are triangulated again. Either way the answer is the
        one-shot answer for all the points (restart is accepted and changes
        nothing: the canonical answer does not depend on the insertion
        order). On bad input (ValueError) nothing changes."""
        self._check_incremental()
        new = _new_points(points, self.ndim, "Delaunay.add_points")
        w = None
        if self.weights is not None:
            if weights is None:
                raise ValueError("Delaunay.add_points: the triangulation is weighted: weights= are needed")
            w = np.concatenate([self.weights, _weights(weights, new.shape[0], "Delaunay.add_points")])
        elif weights is not None:
            raise ValueError("Delaunay.add_points: the triangulation is unweighted: no weights")
        self._update(np.ascontiguousarray(np.concatenate([self.points, new])), w)

    def _update(self, a: np.ndarray, w: Optional[np.ndarray]) -> None:
        keep, g = _good_point(self._options, a, "Delaunay")
        sub, sw = a, w
        if keep is not None:
            sub = np.ascontiguousarray(a[keep])
            sw = None if w is None else np.ascontiguousarray(w[keep])
        neighbors = None  # the certificate's or the 3D cpu kernel's witness's; else matched below
        if self._incremental and self._backend == "cpu":
            simplices, redundant, neighbors = _kept_triangulation(self, "Delaunay", sub, sw, self._strict,
                                                                  self._threads, self.furthest_site)
        else:
            simplices, redundant, neighbors = _native("Delaunay", _flipflop.triangulate_with_neighbors, sub, sw,
                                                      self._backend, self._strict, self._threads, self.furthest_site)
        if keep is not None:  # back to the input's indices (a monotone map: the canonical form is kept)
            simplices, redundant = keep[simplices], keep[redundant]
        d = a.shape[1]
        if neighbors is None:
            neighbors = _flipflop.neighbors(simplices)
        # the boundary facets: each simplex side without a neighbour, its
        # vertices in order with the opposite one left out
        i, j = np.nonzero(neighbors < 0)
        leave = np.ones((len(i), d + 1), dtype=bool)
        leave[np.arange(len(i)), j] = False
        self.points, self.weights, self.ndim = a, w, d
        # scipy's index dtype (np.intc); `redundant` (flipflop's) stays int64
        self.simplices, self.redundant, self.neighbors = _intc(simplices), redundant, _intc(neighbors)
        self.convex_hull = _intc(simplices[i][leave].reshape(-1, d))
        self._good_index = g
        self._cache = {}
        big = float(np.abs(a).max())
        _, e = np.frexp(big if big > 0 else 1.0)
        e = min(max(int(e), -1020), 1020)  # the scale 2^-e a normal double
        self._lift_exponent = e
        self.paraboloid_scale = float(np.ldexp(1.0, -e))
        self.paraboloid_shift = 0.0

    def _cached(self, name, compute):
        if name not in self._cache:
            self._cache[name] = compute()
        return self._cache[name]

    # ---- scipy's attributes ------------------------------------------------------

    @property
    def vertices(self) -> np.ndarray:
        """scipy's deprecated alias of `simplices` (DeprecationWarning, as
        scipy 1.10)."""
        warnings.warn("Delaunay attribute 'vertices' is deprecated in favour of 'simplices' (as in scipy)",
                      DeprecationWarning, stacklevel=2)
        return self.simplices

    @property
    def good(self) -> np.ndarray:
        return self._cached("good", self._compute_good)

    @property
    def coplanar(self) -> np.ndarray:
        return self._cached("coplanar", self._compute_coplanar)

    @property
    def vertex_to_simplex(self) -> np.ndarray:
        return self._cached("vertex_to_simplex", self._compute_vertex_to_simplex)

    @property
    def vertex_neighbor_vertices(self):
        return self._cached("vertex_neighbor_vertices", self._compute_vertex_neighbor_vertices)

    @property
    def transform(self) -> np.ndarray:
        return self._cached("transform", self._compute_transform)

    @property
    def equations(self) -> np.ndarray:
        return self._cached("equations", self._compute_equations)

    def lift_points(self, x) -> np.ndarray:
        """Points x (shape (..., d)) lifted to the paraboloid: (x,
        paraboloid_scale * |x|^2 + paraboloid_shift), as scipy (the power of
        two applied before squaring, so no intermediate over- or
        underflows)."""
        x = np.asarray(x, dtype=np.float64)
        e = self._lift_exponent
        with np.errstate(over="ignore", under="ignore"):
            h = np.ldexp((np.ldexp(x, -e) ** 2).sum(axis=-1), e) + self.paraboloid_shift
        return np.concatenate([x, h[..., None]], axis=-1)

    def plane_distance(self, xi) -> np.ndarray:
        """For points xi (shape (..., d)), the signed distance of each
        lifted point from every simplex's lifted hyperplane, shape (...,
        nsimplex), as scipy: positive where xi lies inside the simplex's
        circumsphere (weighted: its orthogonal sphere)."""
        xi = np.asarray(xi, dtype=np.float64)
        if xi.shape[-1:] != (self.ndim,):
            raise ValueError(f"plane_distance: xi has different dimensionality than triangulation "
                             f"(shape (..., {self.ndim}) expected, got {xi.shape})")
        eq = self.equations
        return self.lift_points(xi) @ eq[:, :-1].T + eq[:, -1]

    def find_simplex(self, xi, bruteforce: bool = False, tol=None) -> np.ndarray:
        """For each point of xi (shape (..., d)), the index of a simplex that
        contains it (closed; decided exactly), -1 outside the hull. Simplices
        of zero volume (the canonical answer's on degenerate input) are never
        returned: a point on one lies in a neighbour of positive volume. A
        point on a face shared by several simplices gets one fixed choice
        among them (the one holding the point moved infinitesimally towards
        the first simplex of positive volume), the same for any batch and at
        any thread count; scipy's choice there depends on Qhull's walk. The
        queries run in parallel pieces on the object's threads.

        bruteforce and tol are scipy's and accepted: the search is exact, so
        the answer is the same with either; tol (a tolerance of scipy's
        floating-point inside test, default 100 eps) is only checked to be a
        real number (TypeError otherwise, as scipy) and has no effect."""
        if tol is not None and not isinstance(tol, numbers.Real):
            raise TypeError(f"find_simplex: tol must be real number, not {type(tol).__name__}")  # as scipy
        q = np.asarray(xi, dtype=np.float64)
        shape = q.shape[:-1]
        if q.shape[-1:] != (self.ndim,):
            raise ValueError(f"find_simplex: wrong dimensionality in xi: points must have shape (..., {self.ndim}), "
                             f"got {q.shape}")
        q = np.ascontiguousarray(q.reshape(-1, self.ndim))
        s64, n64 = self._int64()
        return _intc(_flipflop.find_simplex(self.points, s64, n64, q, self._signs(), self._threads).reshape(shape))

    # ---- their computation -----------------------------------------------------------

    def _int64(self):
        """(simplices, neighbors) as int64, the compiled calls' index type,
        once per triangulation."""
        return self._cached("int64", lambda: (self.simplices.astype(np.int64), self.neighbors.astype(np.int64)))

    def _signs(self) -> np.ndarray:
        """Each simplex's exact orientation sign (no perturbation; int8),
        once per triangulation (_flipflop.simplex_signs: the exact orient_d
        of the compiled predicates, in parallel)."""
        s64 = self._int64()[0]
        return self._cached("signs", lambda: _flipflop.simplex_signs(self.points, s64))

    def _flat(self) -> np.ndarray:
        """The simplices of zero volume, exactly."""
        return self._signs() == 0

    def _compute_transform(self) -> np.ndarray:
        """scipy's barycentric transforms, (m, d+1, d): [T^-1; r] with r the
        last vertex and T's column j = v_j - r, in the compiled call
        (_flipflop.barycentric_transforms: T scaled by a power of two, Gauss-
        Jordan with partial pivoting, in parallel); NaN for the simplices of
        zero volume, decided exactly (_signs), and for those singular in
        floating point."""
        s64 = self._int64()[0]
        return _flipflop.barycentric_transforms(self.points, s64, self._signs())

    def _compute_equations(self) -> np.ndarray:
        """Each simplex's lifted hyperplane [unit normal, offset], the normal
        down (up for the furthest site), in the compiled call
        (_flipflop.lifted_equations: the lifted vertices as lift_points
        gives them, the normal by cofactors of their differences scaled by a
        power of two, in parallel)."""
        s64 = self._int64()[0]
        return _flipflop.lifted_equations(self.points, self.weights, s64, self._lift_exponent, self.furthest_site)

    def _compute_vertex_to_simplex(self) -> np.ndarray:
        S = self.simplices
        out = np.full(self.npoints, -1, dtype=np.int64)
        out[S.ravel()[::-1]] = np.repeat(np.arange(len(S), dtype=np.int64), S.shape[1])[::-1]
        c = self.coplanar
        out[c[:, 0]] = c[:, 1]
        return _intc(out)

    def _compute_vertex_neighbor_vertices(self):
        # each vertex's neighbours ascending (_flipflop.vertex_neighbours)
        s64 = self._int64()[0]
        indptr, indices = _flipflop.vertex_neighbours(s64, self.npoints)
        return _intc(indptr), _intc(indices)

    def _compute_coplanar(self) -> np.ndarray:
        if not self._options.coplanar or len(self.redundant) == 0 or self.furthest_site:
            return np.zeros((0, 3), dtype=np.intc)
        r = self.redundant
        s = self.find_simplex(self.points[r])
        rows = []
        for p, t in zip(r, s):
            if t < 0:  # not reached: a point that is not a vertex lies in the hull of the vertices
                continue
            verts = self.simplices[t]
            dist = ((self.points[verts] - self.points[p]) ** 2).sum(axis=1)
            rows.append((int(p), int(t), int(verts[int(np.argmin(dist))])))
        return _intc(np.array(rows, dtype=np.int64).reshape(-1, 3))

    def _compute_good(self) -> np.ndarray:
        m, g = len(self.simplices), self._good_index
        if g is None:
            return np.ones(m, dtype=np.intc)
        # det Λ of the simplex's lifted vertices and point g's (rows (p,
        # |p|^2 - w, 1), g last; _flipflop.power_signs: the compiled exact
        # power_d, no perturbation) is, subtracting g's row from the others,
        # det [v - x, |v - x|^2 - w_v + w_x]: negative _INSPHERE[d] times
        # that means strictly inside the circumsphere (below the lower hull's
        # facet, visible from the lifted point g); furthest site: strictly
        # outside (above the upper hull's facet)
        cells = np.ascontiguousarray(np.concatenate([self.simplices, np.full((m, 1), g)], axis=1), dtype=np.int64)
        s = _flipflop.power_signs(self.points, self.weights, cells)
        inside = s == (-_INSPHERE[self.ndim] if self.furthest_site else _INSPHERE[self.ndim])
        return (inside if self._options.visible else ~inside).astype(np.intc)


class Certificate:
    """The result of certify(): truthy when certified; otherwise `condition`
    names the first violated condition and `detail` says where."""

    def __init__(self, ok: bool, condition: str, detail: str, kind: str, level: str):
        self.ok, self.condition, self.detail, self.kind, self.level = ok, condition, detail, kind, level

    def __bool__(self) -> bool:
        return self.ok

    def __repr__(self) -> str:
        if self.ok:
            return f"Certificate(certified, {self.kind}, {self.level})"
        return f"Certificate(NOT certified, {self.kind}, {self.level}: {self.condition}: {self.detail})"


def certify(kind: str, points, simplices, weights=None, canonical: bool = False, orient: bool = False) -> Certificate:
    """Checks an output against its input exactly — flipflop's, scipy's or
    any other program's.

    kind: 'hull2' (simplices: the hull's vertex cycle, counter-clockwise, or
    scipy's (k, 2) edges in cycle order), 'hull3' (triangles, counter-
    clockwise seen from outside), 'delaunay' (d-simplices, positively
    oriented; weights for a regular triangulation).
    canonical=False checks that it is *a* correct answer for the exact input
    (any tie-breaking on degenerate input; for d >= 3 triangulations without
    zero-volume simplices); canonical=True that it is flipflop's unique
    answer in canonical form. orient=True first orients every triangle outward /
    simplex positively, exactly (scipy does not orient its hull facets).
    """
    dims = {"hull2": (2,), "hull3": (3,), "delaunay": _DIMS}
    if kind not in dims:
        raise ValueError(f"certify: kind must be one of {tuple(dims)}, got {kind!r}")
    a = _points(points, dims[kind], "certify")
    w = _weights(weights, a.shape[0], "certify")
    try:
        s = np.asarray(simplices, dtype=np.int64)
    except (TypeError, ValueError) as e:
        raise ValueError(f"certify: simplices must be integer indices: {e}") from None
    if kind == "hull2":
        if s.ndim == 2 and s.shape[1] == 2:
            s = s[:, 0]
        s = s.reshape(-1, 1)
    elif s.ndim != 2:
        raise ValueError(f"certify: simplices must be a 2-dimensional index array, got shape {s.shape}")
    s = np.ascontiguousarray(s)
    if orient and kind != "hull2":
        s = _flipflop.orient(kind, a, s)
    ok, (condition, detail) = _flipflop.certify(kind, a, s, w, bool(canonical))
    return Certificate(ok, condition, detail, kind, "canonical" if canonical else "exact")


def instant_flip(points, w_from, w_to):
    """RT(S + w_from) -> RT(S + w_to) by the monotonic instant flip (thesis
    §9.2, Algorithm 14, with insertion events: any w_from and w_to; points
    may enter and leave), exact and certified; the simplices equal
    Delaunay(points, w_to)'s. Returns (simplices, flips)."""
    a = _points(points, (2, 3, 4, 5), "instant_flip")
    w = _weights(w_from, a.shape[0], "instant_flip")
    u = _weights(w_to, a.shape[0], "instant_flip")
    if w is None or u is None:
        raise ValueError("instant_flip: w_from and w_to are required")
    return _flipflop.instant_flip(a, w, u)


def distributions() -> list:
    """The generator families (flipflop gen --list), degenerate ones included."""
    return list(_flipflop.distributions())


def generate(dist: str, n: int, seed: int = 1, thickness: float = 0.01, weights=None):
    """n points of family `dist` (distributions()), as `flipflop gen`:
    returns points (n, d), or (points, weights) when weights=(lo, hi)."""
    if n <= 0:
        raise ValueError("generate: n must be positive")
    rng = None if weights is None else (float(weights[0]), float(weights[1]))
    pts, w = _flipflop.generate(dist, int(n), int(seed), float(thickness), rng)
    return pts if rng is None else (pts, w)


# last: voronoi.py uses the helpers above
from .voronoi import Voronoi  # noqa: E402
