"""flipflop.Voronoi: the exact Voronoi diagram (with weights, the power or
Laguerre diagram) of points in 2D..9D, with scipy.spatial.Voronoi's
attributes; the dual of flipflop's certified (canonical) regular
triangulation.

    >>> import numpy as np, flipflop
    >>> vor = flipflop.Voronoi(np.random.default_rng(1).random((100, 2)))
    >>> vor.vertices.shape[1], len(vor.regions) == len(vor.points)
    (2, True)
"""
from __future__ import annotations

from typing import Optional

import numpy as np

from . import (QhullOptionError, _QhullUser, _flipflop, _furthest_site, _kept_triangulation, _new_points, _points,
               _qhull_options, _threads, _weights)

__all__ = ["Voronoi"]

# the backend of `_flipflop.triangulate` per dimension: the multithreaded
# kernels in 2D and 3D, the cavity-insertion kernel in 4D..9D (every backend
# returns the same certified triangulation)
_BACKENDS = {d: "cpu" for d in range(2, 10)}


def _lists(offsets: np.ndarray, values: np.ndarray) -> list:
    v = values.tolist()
    o = offsets.tolist()
    return [v[o[i]:o[i + 1]] for i in range(len(o) - 1)]


class Voronoi(_QhullUser):
    """Voronoi(points, furthest_site=False, incremental=False,
    qhull_options=None, *, weights=None, threads=0)

    The exact Voronoi diagram of points in 2D..9D; with `weights` the power
    (Laguerre) diagram, whose cell of point p is where |x - p|^2 - w_p is
    least. It is the dual of flipflop's certified regular triangulation
    (flipflop.Delaunay), with the exact diagram's topology on any input.

    Attributes (as scipy.spatial.Voronoi):
      points          (n, d) float64, the input
      vertices        (V, d) float64: the Voronoi vertices, each the correctly
                      rounded double of an exact circumcentre (weighted: power
                      centre) of a cell of the exact Delaunay (regular)
                      subdivision; in order of their first simplex
      ridge_points    (R, 2) int: the pairs of points whose cells share a
                      (d-1)-dimensional face, sorted (i < j, rows in order)
      ridge_vertices  list of R lists: the Voronoi vertices of each ridge, -1
                      for the vertex at infinity (unbounded ridges); 2D:
                      [a, b] ([-1, b] when unbounded); 3D: in cyclic order
                      around the ridge; 4D..9D: sorted
      regions         list of n lists: the Voronoi vertices of each point's
                      cell, -1 when the cell is unbounded (2D: in cyclic order)
      point_region    (n,) int: the region of each point (here the identity:
                      regions[i] is point i's cell)
      furthest_site, ndim, npoints, min_bound, max_bound
      weights         the weights, or None
      simplices       the triangulation it is the dual of (flipflop.Delaunay's)
      simplex_vertex  (m,) int: the Voronoi vertex of each simplex, -1 for
                      simplices of zero volume (degenerate input)

    Where the exact answer differs from Qhull's: degenerate input
    (cospherical or collinear points, grids) gets the exact diagram, where
    Qhull's (with its default 'Qbb Qc Qz') may split one exact vertex into
    several nearby ones and report ridges of zero length; points that have no
    cell of their own (duplicates, and with weights the points hidden by
    their neighbours) have an empty region and no ridges; and the vertices
    are the correctly rounded exact centres (Qhull's carry rounding errors).
    The rules on degenerate input: every simplex of positive volume of the
    canonical triangulation lies in one cell of the exact Delaunay
    subdivision and has that cell's centre, so the distinct exact centres
    (compared exactly, never as floats) are the Voronoi vertices, and
    simplices of zero volume (cospherical or coplanar points in 3D and up,
    collinear points on the hull) have no centre and add no vertex. A point
    has a cell of its own (a non-empty region) iff its lifted point
    (p, |p|^2 - w) is a vertex of the lower hull of the lifted points; with
    weights a point whose lifted point lies exactly on a face of that hull
    without being one of its vertices (an exact tie among the weights) has a
    cell with no interior: its region is empty and it has no ridges, as a
    hidden point. Points i and j share a ridge iff both have cells, some
    cell of the exact subdivision holds both, and no third point that has a
    cell lies in every cell and hull facet holding both (then the smallest
    face of the lifted hull holding them is the edge between them); this
    holds also when the triangulation has no edge ij because a tied point
    lies on that edge. A ridge is unbounded iff some exact hull facet holds i
    and j; its vertices are the centres of the cells holding both.

    furthest_site=True: the furthest-site Voronoi diagram, whose cell of
    point p is where p is the furthest point (no weights): the dual of the
    furthest-site Delaunay triangulation (flipflop.Delaunay(furthest_site=
    True), the upper hull of the lifted points), by the same rules with the
    upper hull in place of the lower one. Only the vertices of the convex hull
    have cells (every one unbounded: its region holds -1); the other points'
    regions are empty, as Qhull's. qhull_options accepts
    Qhull's 'Qbb Qc Qz Qx QJ Qt Q12', which change nothing here; any other
    option raises ValueError.

    incremental=True allows add_points(points, restart=False): the
    cavity-insertion kernel is kept (in 2D and 3D seeded at the first
    add_points with the one-shot triangulation, as Delaunay's), and
    add_points inserts the new points into it in place; the
    diagram is derived again from its certified result (the exact answer
    does not depend on the order of insertion); close() ends it and frees
    the kept kernel.

    threads: worker threads (0: all cores) of the triangulation, of its
    certifier and of the centres; the answer is the same at any count. The
    GIL is released while computing.
    """

    def __init__(self, points, furthest_site: bool = False, incremental: bool = False, qhull_options=None, *,
                 weights=None, threads: int = 0):
        furthest_site = _furthest_site(furthest_site, "Voronoi")
        if furthest_site and weights is not None:
            raise ValueError("Voronoi: furthest_site=True takes no weights")
        # scipy's default "Qbb Qc Qz"; QGn / QG-n select facets and
        # simplices, which a diagram has not
        if _qhull_options(qhull_options, "Voronoi", "Qbb Qc Qz").good is not None:
            raise QhullOptionError("Voronoi: qhull options QGn and QG-n apply to ConvexHull and Delaunay")
        self._threads = _threads(threads, "Voronoi")
        self.furthest_site = furthest_site
        self._incremental = bool(incremental)
        self._inc = self._inc_seed = None
        self._closed = False
        a = _points(points, tuple(_BACKENDS), "Voronoi")
        self._compute(a, _weights(weights, a.shape[0], "Voronoi"))

    def _compute(self, a: np.ndarray, w: Optional[np.ndarray]) -> None:
        n, d = a.shape
        if n < d + 1:
            raise ValueError(f"Voronoi: {n} points, at least {d + 1} needed in {d}D")
        try:
            # furthest site: the 'cpu' backend in every d (Delaunay's choice)
            backend = "cpu" if self.furthest_site else _BACKENDS[d]
            if self._incremental:  # the kernel kept for in-place insertion (add_points)
                simplices, _redundant, _neighbors = _kept_triangulation(self, "Voronoi", a, w, False, self._threads,
                                                                        self.furthest_site)
            else:  # with the neighbours the certificate gives (None where it does not)
                simplices, _redundant, _neighbors = _flipflop.triangulate_with_neighbors(
                    a, w, backend, False, self._threads, self.furthest_site)
            (vertices, simplex_vertex, ridge_points, r_off, r_val, g_off,
             g_val) = _flipflop.voronoi(a, w, simplices, self._threads, _neighbors)
        except ValueError as e:
            raise ValueError(f"Voronoi: {e}") from None
        self.points = a
        self.weights = w
        self.ndim = d
        self.simplices = simplices
        self.simplex_vertex = simplex_vertex
        self.vertices = vertices
        self.ridge_points = ridge_points.astype(np.intc)
        self.ridge_vertices = _lists(r_off, r_val)
        self.regions = _lists(g_off, g_val)
        self.point_region = np.arange(n, dtype=np.intp)

    @property
    def ridge_dict(self) -> dict:
        """{(i, j): ridge vertices} as scipy's (i < j here)."""
        return {(int(p[0]), int(p[1])): v for p, v in zip(self.ridge_points, self.ridge_vertices)}

    def add_points(self, points, restart: bool = False, *, weights=None) -> None:
        """Adds points (incremental=True only): they are inserted in place
        into the kept triangulation (the cavity-insertion kernel, as
        Delaunay's add_points), whose certified result the diagram is then
        derived from again; the answer is the one-shot diagram of all the
        points (it does not depend on the order of insertion, so restart
        changes nothing). A weighted diagram needs the new points' weights."""
        self._check_incremental()
        b = _new_points(points, self.ndim, "Voronoi.add_points")
        if not np.isfinite(b).all():
            raise ValueError("Voronoi.add_points: the points hold NaN or infinite coordinates")
        if (weights is None) != (self.weights is None):
            raise ValueError("Voronoi.add_points: weights are needed exactly when the diagram is weighted")
        w = None
        if self.weights is not None:
            w = np.concatenate([self.weights, _weights(weights, b.shape[0], "Voronoi.add_points")])
        self._compute(np.ascontiguousarray(np.concatenate([self.points, b])), w)
