"""flipflop.spatial: import it in place of scipy.spatial.

    import flipflop.spatial as spatial     # instead of: import scipy.spatial as spatial
    hull = spatial.ConvexHull(points)      # flipflop's, exact and certified
    tri = spatial.Delaunay(points)         # flipflop's
    vor = spatial.Voronoi(points)          # flipflop's (flipflop/voronoi.py)
    tree = spatial.cKDTree(points)         # scipy's: every other name is scipy.spatial's

ConvexHull, Delaunay and Voronoi are flipflop's classes, with scipy's
attributes (their docstrings and docs/scipy_porting.md say where the exact
answer differs from Qhull's); QhullError is flipflop's QhullOptionError (a
RuntimeError, as scipy's, and a ValueError), the one error the classes
raise for qhull_options. Every other name (cKDTree, distance, voronoi_plot_2d,
HalfspaceIntersection, ...) is forwarded to scipy.spatial when scipy is
installed; without scipy, using one raises ImportError.
"""
from __future__ import annotations

from . import ConvexHull, Delaunay, Voronoi
from . import QhullOptionError as QhullError

__all__ = ["ConvexHull", "Delaunay", "Voronoi", "QhullError"]

_OWN = frozenset(__all__)


def _scipy_spatial():
    try:
        import scipy.spatial
    except ImportError as e:
        raise ImportError("flipflop.spatial forwards every name but ConvexHull, Delaunay and Voronoi to "
                          f"scipy.spatial, and scipy is not installed ({e})") from None
    return scipy.spatial


def __getattr__(name: str):
    # dunder names (__path__, __wrapped__, ...) are this module's own: forwarding
    # them would make the module look like a package or a wrapper
    if name.startswith("__") and name.endswith("__"):
        raise AttributeError(f"module 'flipflop.spatial' has no attribute {name!r}")
    sp = _scipy_spatial()
    try:
        return getattr(sp, name)
    except AttributeError:
        raise AttributeError(f"module 'flipflop.spatial' has no attribute {name!r} (nor has scipy.spatial)") from None


def __dir__():
    names = set(globals()) | _OWN
    try:
        names |= set(dir(_scipy_spatial()))
    except ImportError:
        pass
    return sorted(names)
