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
"""
from __future__ import annotations

from typing import Optional, Sequence

import numpy as np

from . import _flipflop

__version__: str = _flipflop.__version__

__all__ = ["ConvexHull", "Delaunay", "Certificate", "certify", "instant_flip", "generate", "distributions",
           "gpu_backends", "__version__"]

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
_HULL_BACKENDS = {2: ("cpu", "reference") + _GPU, 3: ("cpu", "reference") + _GPU}
# per dimension, the default first: the multithreaded kernels exist for d = 2
# and 3 (kernels_cpu/rt2, kernels_cpu/rt3), the GPU kernels for d = 2
# (kernels_cuda/rt2)
_DELAUNAY_BACKENDS = {2: ("cpu", "reference") + _GPU, 3: ("cpu", "reference"), 4: ("reference",),
                      5: ("reference",)}


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


class ConvexHull:
    """The convex hull of points in 2D or 3D, exact and certified.

    Attributes (as scipy.spatial.ConvexHull):
      points     (n, d) float64, the input
      simplices  3D: (m, 3) triangles, counter-clockwise seen from outside;
                 2D: (k, 2) edges (i, next) of the counter-clockwise hull
      neighbors  (m, d) the facet opposite each vertex of each simplex
      vertices   2D: the hull vertices counter-clockwise from the smallest
                 index; 3D: sorted
      equations  (m, d+1) [unit outward normal, offset]: normal.x + offset
                 <= 0 inside (floating point, from the exact facets; NaN
                 normals for the zero-area facets of degenerate input)
      volume, area  (2D: area and perimeter; 3D: volume and surface area;
                 inf or 0 only where the true value is not a double)
    All are computed once, in the compiled call, from the certified facets.

    The canonical answer (default) is flipflop's unique answer under
    Simulation of Simplicity: on degenerate input it may keep points inside
    hull edges or facets as vertices and split coplanar facets as the
    perturbation decides. strict=True (3D) returns the strict view instead:
    strictly extreme vertices only, each exact facet fan-triangulated from
    its smallest vertex (no zero-area triangle); `polygons` then holds the
    merged facets.

    backend: 'cpu' (the default: the multithreaded kernels), 'reference'
    (the exact sequential reference) or one of `gpu_backends` ('cuda-omp':
    the GPU kernels on thrust's OpenMP backend); every backend returns the
    same answer. strict=True uses the 'cpu' kernel whatever the backend.

    threads: worker threads (0: the runtime's default, every core the
    process may use) of the 'cpu' kernels and of the certifier; the answer
    is the same at any count. The GIL is released while computing.
    """

    def __init__(self, points, strict: bool = False, backend: Optional[str] = None, threads: int = 0):
        a = _points(points, (2, 3), "ConvexHull", finite=False)
        d = a.shape[1]
        self.points = a
        self.ndim = d
        self.polygons = None
        # every attribute comes from the compiled call, computed there in one
        # pass over the certified facets (python/src/module.cpp: HullMeasures)
        if d == 2:
            if strict:
                raise ValueError("ConvexHull: strict=True applies to 3D hulls")
            attributes = _native("ConvexHull", _flipflop.hull2, a, _backend(backend, _HULL_BACKENDS[2], "ConvexHull"),
                                 _threads(threads, "ConvexHull"))
        elif strict:
            if backend is not None:
                _backend(backend, _HULL_BACKENDS[3], "ConvexHull")
            attributes, polys = _native("ConvexHull", _flipflop.hull3_strict, a, _threads(threads, "ConvexHull"))
            self.polygons = [np.asarray(p, dtype=np.int64) for p in polys]
        else:
            attributes = _native("ConvexHull", _flipflop.hull3, a, _backend(backend, _HULL_BACKENDS[3], "ConvexHull"),
                                 _threads(threads, "ConvexHull"))
        self.simplices, self.vertices, self.neighbors, self.equations, self.volume, self.area = attributes


class Delaunay:
    """The regular (weighted Delaunay) triangulation of points in 2D..5D,
    exact and certified; with weights=None the Delaunay triangulation.

    Attributes (as scipy.spatial.Delaunay):
      points       (n, d) float64
      simplices    (m, d+1) positively oriented (det[p1-p0, ..., pd-p0] > 0),
                   canonical order
      neighbors    (m, d+1) the simplex opposite each vertex, -1 outside
      convex_hull  (h, d) the boundary facets
      redundant    the points that are not vertices (weighted input: hidden
                   by their neighbours' weights; unweighted: duplicates)
    find_simplex(xi) locates points exactly (-1: outside the hull).

    The canonical answer may hold simplices of zero volume on degenerate
    input (collinear or cospherical points): it is the unique answer under
    Simulation of Simplicity, the one every backend reproduces. strict=True
    returns the strict view instead: a regular triangulation of the exact
    input without zero-volume simplices (the 2D grid's 2(k-1)^2 triangles, d!
    simplices per cube of a grid in d >= 3), certified (`dt2 --strict`,
    `rtd --strict` on the command line).

    backend: 'cpu' (2D and 3D, the default there: the multithreaded kernels
    of kernels_cpu/rt2 and kernels_cpu/rt3, certified from their witnesses),
    'reference' (the exact sequential reference: ffRT in 2D, RT+1 in 3D..5D,
    the default in 4D and 5D) or, in 2D, one of `gpu_backends` ('cuda-omp':
    the GPU ffRT on thrust's OpenMP backend); every backend returns the same
    simplices. strict=True derives the strict view from the backend's
    certified answer by the reference's (sequential) rule.
    threads: worker threads of the 'cpu' backend and of its certifier
    (0: all cores); the answer is the same at any count.
    """

    def __init__(self, points, weights=None, strict: bool = False, backend: Optional[str] = None,
                 threads: int = 0):
        a = _points(points, (2, 3, 4, 5), "Delaunay", finite=False)
        w = _weights(weights, a.shape[0], "Delaunay")
        self.points = a
        self.weights = w
        self.ndim = a.shape[1]
        self.simplices, self.redundant = _native(
            "Delaunay", _flipflop.triangulate, a, w, _backend(backend, _DELAUNAY_BACKENDS[a.shape[1]], "Delaunay"),
            bool(strict), _threads(threads, "Delaunay"))
        self.neighbors = _flipflop.neighbors(self.simplices)
        # the boundary facets: each simplex side without a neighbour, its
        # vertices in order with the opposite one left out
        i, j = np.nonzero(self.neighbors < 0)
        keep = np.ones((len(i), self.ndim + 1), dtype=bool)
        keep[np.arange(len(i)), j] = False
        self.convex_hull = self.simplices[i][keep].reshape(-1, self.ndim)

    def find_simplex(self, xi) -> np.ndarray:
        """For each point of xi (shape (..., d)), the index of a simplex that
        contains it (closed; decided exactly), -1 outside the hull. Simplices
        of zero volume (the canonical answer's on degenerate input) are never
        returned: a point on one lies in a neighbour of positive volume."""
        q = np.asarray(xi, dtype=np.float64)
        shape = q.shape[:-1]
        if q.shape[-1:] != (self.ndim,):
            raise ValueError(f"find_simplex: points must have shape (..., {self.ndim}), got {q.shape}")
        q = np.ascontiguousarray(q.reshape(-1, self.ndim))
        return _flipflop.find_simplex(self.points, self.simplices, self.neighbors, q).reshape(shape)


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
    dims = {"hull2": (2,), "hull3": (3,), "delaunay": (2, 3, 4, 5)}
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
