"""flipflop.dask: the exact convex hull of a dask array, on any dask
scheduler (the default threaded one, "synchronous", or a dask.distributed
cluster), equal to flipflop.ConvexHull of the computed array bit for bit.

    >>> import dask.array as da, flipflop.dask
    >>> x = da.random.random((10**7, 3), chunks=(10**6, 3))
    >>> hull = flipflop.dask.ConvexHull(x)       # attributes as flipflop.ConvexHull

Only hull vertices travel between tasks; the points stay where their chunks
are (docs/distributed_dask.md). An input larger than memory (a directory of
.npy shards: from_npy_shards) is read chunk by chunk, twice.

How (two dask.compute passes):

Pass 1, one graph:
1. One task per row-chunk: the chunk's hull vertices, as (global row ids
   ascending, their float64 coordinates). A chunk whose points span less
   than the full dimension (or has fewer than d + 1 points) forwards all
   its points.
2. A tree reduction (split_every children per node): concatenate, sort by
   global id, keep the hull vertices of the union (all of it where it is
   lower-dimensional).
3. The root: flipflop.ConvexHull of the remaining candidates, sorted by
   global id, its indices mapped back to global ids.
Pass 2, a second graph with the final hull as a plain argument:
4. One task per chunk certifies its points: flipflop.certify(...,
   canonical=True) on the final hull's vertices outside the chunk, the
   chunk's own points and the final facets, in global order.
Each chunk is needed by one task per pass, so a chunk read from files (or
generated) is dropped after its task: peak memory is about one chunk per
worker thread plus the candidates. On a dask.distributed cluster x is
persisted first when it fits (see ConvexHull's `persist`); then pass 2
reads the chunks from the workers' memory and every chunk's tasks are
pinned to the workers holding it.

Why it is exact: Simulation of Simplicity perturbs point i by powers of
epsilon ordered by i (DESIGN.md, "The perturbation"), so every perturbed
predicate's sign depends only on the relative order of the indices
involved. The hull of a subset, computed with its points in ascending
global order, is therefore the canonical hull of those perturbed points,
and mapping its indices back (a monotone map) keeps the canonical form. The
hull of a union is the hull of the union of its parts' hull vertices; a
lower-dimensional part forwards all its points, a superset of its vertices.
The root's call sees the final vertices' coordinates in the same order as
the in-memory call, so its equations, area and volume (computed from the
facets' vertices alone: python/src/module.cpp, hull2_measures and
hull3_measures) are the same doubles. A chunk's certificate shows that the
final facets are the canonical hull of the chunk's points together with the
hull's vertices; every point lies in some chunk, so all certificates
together show that they are the canonical hull of all points.
"""
from __future__ import annotations

import contextlib
import math
import os
import sys
import time
from typing import List, Optional, Sequence, Union

import numpy as np
import dask
import dask.array as da

from . import Certificate
from . import ConvexHull as _MemoryHull
from . import certify as _certify
from . import _intc

__all__ = ["ConvexHull", "CertificationError", "certify_chunks", "from_npy_shards"]

_WHAT = "flipflop.dask.ConvexHull"


class CertificationError(RuntimeError):
    """A chunk's points are not certified against the hull: `chunk` is the
    chunk's number, `rows` its global rows [start, stop), `certificate` the
    failed flipflop.Certificate (condition and detail)."""

    def __init__(self, chunk: int, rows: Sequence[int], certificate: Certificate):
        self.chunk, self.rows, self.certificate = chunk, tuple(rows), certificate
        super().__init__(f"{_WHAT}: chunk {chunk} (rows {rows[0]}..{rows[1] - 1}) is not certified: "
                         f"{certificate.condition}: {certificate.detail}")


# ---- the input -------------------------------------------------------------------------

def _dask_points(x, what: str) -> da.Array:
    """A dask array (n, d), d in (2, 3), one chunk across the columns, with
    known chunk sizes; ValueError otherwise."""
    if not isinstance(x, da.Array):
        try:
            x = da.asarray(x)
        except (TypeError, ValueError) as e:
            raise ValueError(f"{what}: points must be a dask array or an array-like: {e}") from None
    if x.ndim != 2 or x.shape[1] not in (2, 3):
        raise ValueError(f"{what}: points must have shape (n, d) with d in (2, 3), got {x.shape}")
    if any(math.isnan(c) for c in x.chunks[0]):
        raise ValueError(f"{what}: the chunk sizes along the rows are unknown; call x.compute_chunk_sizes() first")
    if not (np.issubdtype(x.dtype, np.number) or x.dtype == np.bool_) or np.issubdtype(x.dtype, np.complexfloating):
        raise ValueError(f"{what}: points must be real numbers, got dtype {x.dtype}")
    if len(x.chunks[1]) != 1:
        x = x.rechunk({1: -1})
    return x


def _offsets(x: da.Array) -> np.ndarray:
    """Global row of each chunk's first point, and n last."""
    return np.concatenate([[0], np.cumsum(x.chunks[0], dtype=np.int64)])


def _chunk_array(block, start: int, what: str) -> np.ndarray:
    """A chunk as C-contiguous float64 (n, d); ValueError naming the first
    global row with NaN or an infinite coordinate."""
    a = np.ascontiguousarray(np.asarray(block, dtype=np.float64))
    finite = np.isfinite(a).all(axis=1)
    if not finite.all():
        row = start + int(np.argmin(finite))
        raise ValueError(f"{what}: the points hold NaN or infinite coordinates (row {row})")
    return a


# ---- .npy shards ------------------------------------------------------------------------

_SHARDS = "flipflop.dask.from_npy_shards"
_F8 = np.dtype("<f8")


def _shard_paths(path) -> List[str]:
    """As flipflop-mpi (distributed/shards.cpp): a directory's files whose
    names end in ".npy" (longer than that), sorted byte-wise; or one .npy
    file."""
    path = os.fspath(path)
    if os.path.isdir(path):
        try:
            names = os.listdir(path)
        except OSError as e:
            raise ValueError(f"{_SHARDS}: {path}: cannot list the directory: {e.strerror}") from None
        paths = [os.path.join(path, n) for n in names
                 if len(n) > 4 and n.endswith(".npy") and not os.path.isdir(os.path.join(path, n))]
        if not paths:
            raise ValueError(f"{_SHARDS}: {path}: no .npy shards in the directory")
        return sorted(paths, key=os.fsencode)
    if not os.path.exists(path):
        raise ValueError(f"{_SHARDS}: {path}: no such file or directory")
    if os.path.splitext(path)[1] not in (".npy", ".NPY"):
        raise ValueError(f"{_SHARDS}: {path}: expected a .npy file or a directory of .npy shards")
    return [path]


def _npy_header(path: str):
    """(rows, columns, offset of the data) of a .npy shard of little-endian
    float64 in C order, shape (n, 2) or (n, 3), holding all its rows (what
    flipflop-mpi accepts); ValueError naming the file otherwise."""
    fmt = np.lib.format
    try:
        with open(path, "rb") as f:
            version = fmt.read_magic(f)
            if version == (1, 0):
                shape, fortran, dtype = fmt.read_array_header_1_0(f)
            elif version == (2, 0):
                shape, fortran, dtype = fmt.read_array_header_2_0(f)
            else:
                shape, fortran, dtype = fmt._read_array_header(f, version)
            offset = f.tell()
        size = os.path.getsize(path)
    except OSError as e:
        raise ValueError(f"{_SHARDS}: {path}: cannot read: {e.strerror or e}") from None
    except ValueError as e:
        raise ValueError(f"{_SHARDS}: {path}: not a .npy file: {e}") from None
    if dtype != _F8:
        raise ValueError(f"{_SHARDS}: {path}: npy dtype {dtype.str}, expected float64 ('<f8')")
    if len(shape) != 2 or shape[1] not in (2, 3):
        raise ValueError(f"{_SHARDS}: {path}: shape {tuple(shape)}, expected (n, 2) or (n, 3)")
    if fortran:
        raise ValueError(f"{_SHARDS}: {path}: Fortran order, expected C order")
    if size < offset + shape[0] * shape[1] * 8:
        raise ValueError(f"{_SHARDS}: {path}: npy data is truncated ({size - offset} bytes of "
                         f"{shape[0] * shape[1] * 8})")
    return int(shape[0]), int(shape[1]), int(offset)


def _read_rows(path: str, header: tuple, start: int, stop: int) -> np.ndarray:
    """Rows [start, stop) of a shard, read straight into a new array (no
    mapping: the worker's resident memory is the result alone). header:
    what _npy_header found when the array was made; a shard that changed
    since raises ValueError."""
    if _npy_header(path) != header:
        raise ValueError(f"{_SHARDS}: {path}: the shard changed since from_npy_shards read its header")
    rows, width, offset = header
    out = np.empty((stop - start, width), dtype=np.float64)
    if start == stop:
        return out
    with open(path, "rb") as f:
        f.seek(offset + start * width * 8)
        got = f.readinto(memoryview(out).cast("B"))
    if got != out.nbytes:
        raise ValueError(f"{_SHARDS}: {path}: npy data is truncated (rows {start}..{stop - 1})")
    return out


def from_npy_shards(path: Union[str, os.PathLike], chunk_rows: int = 2 ** 23) -> da.Array:
    """A dask array (n, d) of the rows of a directory's .npy shards, in the
    order flipflop-mpi reads them: the files whose names end in ".npy",
    sorted by name (byte-wise), their rows concatenated, so that global row
    g is the row flipflop-mpi (and flipflop hull2|hull3 of the concatenated
    array) numbers g. path may also be one .npy file.

    Each shard must be little-endian float64 in C order of shape (n, 2) or
    (n, 3), all of the same width; every header is checked here (ValueError
    naming the file: dtype, shape, width, order, truncation). The data is
    not read: each chunk is one task that reads its row range from its
    shard when it runs, so nothing but file names and row numbers is
    pickled, and a chunk a task has used can be dropped and read again.

    chunk_rows: at most this many rows per chunk (default 2**23: 192 MiB of
    3D points); a chunk never spans two shards (a shard is cut into equal
    parts; an empty shard gives no chunk)."""
    chunk_rows = int(chunk_rows)
    if chunk_rows < 1:
        raise ValueError(f"{_SHARDS}: chunk_rows must be positive, got {chunk_rows}")
    paths = _shard_paths(path)
    headers = [_npy_header(p) for p in paths]
    width = headers[0][1]
    for p, h in zip(paths, headers):
        if h[1] != width:
            raise ValueError(f"{_SHARDS}: {p}: {h[1]} columns, but {paths[0]} has {width}")
    pieces = []  # (shard, start, stop)
    for k, (rows, _, _) in enumerate(headers):
        parts = -(-rows // chunk_rows)
        cuts = [rows * i // parts for i in range(parts + 1)] if parts else []
        pieces += [(k, lo, hi) for lo, hi in zip(cuts[:-1], cuts[1:])]
    if not pieces:  # every shard is empty: one empty chunk
        pieces = [(0, 0, 0)]
    stats = [(p, os.stat(p).st_mtime_ns, h) for p, h in zip(paths, headers)]
    name = "from-npy-shards-" + dask.base.tokenize(stats, pieces)
    graph = {(name, i, 0): (_read_rows, paths[k], headers[k], lo, hi) for i, (k, lo, hi) in enumerate(pieces)}
    chunks = (tuple(hi - lo for _, lo, hi in pieces), (width,))
    return da.Array(graph, name, chunks=chunks, dtype=np.float64)


# ---- the tasks -------------------------------------------------------------------------
#
# A candidate set is (ids, coords, nbytes): global row ids (int64, ascending),
# their coordinates (float64, (k, d)), and the bytes of candidate sets that
# the tasks below it passed on (ids and coordinates; counted for the
# attribute transfer_bytes).

def _vertices(coords: np.ndarray, threads: int) -> Optional[np.ndarray]:
    """The local indices (ascending) of the hull vertices of coords, or None
    where flipflop.ConvexHull raises for it (fewer than d + 1 points or a
    lower-dimensional set: all of them are candidates). coords is finite."""
    if coords.shape[0] < coords.shape[1] + 1:
        return None
    try:
        v = _MemoryHull(coords, threads=threads).vertices
    except ValueError:
        return None
    return np.sort(v)


def _chunk_candidates(block, start: int, threads: int):
    a = _chunk_array(block, start, _WHAT)
    v = _vertices(a, threads)
    if v is None:
        ids, coords = np.arange(start, start + a.shape[0], dtype=np.int64), a
    else:
        ids, coords = v.astype(np.int64) + start, np.ascontiguousarray(a[v])
    return ids, coords, 0


def _union(parts):
    ids = np.concatenate([p[0] for p in parts])
    coords = np.concatenate([p[1] for p in parts])
    order = np.argsort(ids, kind="stable")  # the parts come in order already: then a no-op
    passed = sum(p[2] + p[0].nbytes + p[1].nbytes for p in parts)
    return ids[order], np.ascontiguousarray(coords[order]), passed


def _merge_candidates(threads: int, *parts):
    ids, coords, passed = _union(parts)
    v = _vertices(coords, threads)
    if v is None:
        return ids, coords, passed
    return ids[v], np.ascontiguousarray(coords[v]), passed


def _final_hull(threads: int, *parts) -> dict:
    """The root: flipflop.ConvexHull of the candidates (its ValueError for a
    lower-dimensional input is the in-memory call's, which sees the same
    points: every part of such an input forwards all its points), indices
    mapped to global ids."""
    ids, coords, passed = _union(parts)
    h = _MemoryHull(coords, threads=threads)
    vertices = np.unique(h.simplices)  # the hull's vertices, ascending (local = rank among the candidates)
    return {"simplices": ids[h.simplices], "vertices": ids[h.vertices], "neighbors": h.neighbors,
            "equations": h.equations, "volume": h.volume, "area": h.area,
            "vertex_ids": ids[vertices], "vertex_coords": np.ascontiguousarray(coords[vertices]),
            "reduction_bytes": passed}


def _certify_chunk(block, start: int, stop: int, hull: dict) -> Certificate:
    """The chunk's certificate: the final facets are the canonical hull of the
    hull's vertices outside [start, stop) with the chunk's points, in global
    order (the hull's vertices inside the range are the chunk's own rows)."""
    a = _chunk_array(block, start, _WHAT)
    ids, coords, simplices = hull["vertex_ids"], hull["vertex_coords"], hull["simplices"]
    lo, hi = np.searchsorted(ids, start), np.searchsorted(ids, stop)
    before, after = coords[:lo], coords[hi:]
    combined = np.concatenate([before, a, after])
    s = simplices.ravel()
    if len(s) and (s.min() < 0 or s.max() >= hull["npoints"]):
        return Certificate(False, "index", f"a facet names a row outside 0..{hull['npoints'] - 1}",
                           "hull%d" % a.shape[1], "canonical")
    local = np.where(s < start, np.searchsorted(ids[:lo], s),
                     np.where(s < stop, s - start + lo, lo + (stop - start) + np.searchsorted(ids[hi:], s)))
    # a facet vertex outside the chunk that is not among the given vertices
    outside = s[(s < start) | (s >= stop)]
    known = np.isin(outside, ids)
    if not known.all():
        return Certificate(False, "index", f"facet vertex {int(outside[np.argmin(known)])} has no coordinates",
                           "hull%d" % a.shape[1], "canonical")
    return _certify("hull%d" % a.shape[1], combined, local.reshape(simplices.shape), canonical=True)


def _certify_candidates(cand, start: int, stop: int, hull: dict) -> Certificate:
    """certify="chain": the chunk's certificate from its candidates (the
    vertices of its flipflop.ConvexHull, certified when pass 1 computed it;
    all its points where that hull is not defined): the final facets are the
    canonical hull of the hull's vertices together with the candidates, the
    final vertices in the chunk's rows are among its candidates, with the
    same coordinates. With pass 1's certificate of the chunk's hull this
    puts every point of the chunk in the final hull, strictly unless a
    vertex (the argument of distributed/partial_hull.hpp)."""
    ids_c, coords_c = cand[0], cand[1]
    vid, vco, simplices = hull["vertex_ids"], hull["vertex_coords"], hull["simplices"]
    kind = "hull%d" % vco.shape[1]
    mine = vid[(vid >= start) & (vid < stop)]
    missing = mine[~np.isin(mine, ids_c)]
    if len(missing):
        return Certificate(False, "vertex-rows", f"row {int(missing[0])} is a vertex of the hull but not of the "
                                                 f"chunk's certified hull", kind, "canonical")
    common, ic, iv = np.intersect1d(ids_c, vid, assume_unique=True, return_indices=True)
    differ = (coords_c[ic] != vco[iv]).any(axis=1)
    if differ.any():
        return Certificate(False, "vertex-rows", f"row {int(common[np.argmax(differ)])}: the hull's coordinates are "
                                                 f"not the chunk's", kind, "canonical")
    ids, first = np.unique(np.concatenate([vid, ids_c]), return_index=True)
    coords = np.ascontiguousarray(np.concatenate([vco, coords_c])[first])
    return _certify(kind, coords, np.searchsorted(ids, simplices), canonical=True)


def _for_certificates(hull: dict, n: int) -> dict:
    """What each certificate task receives: the hull's vertices (ids and
    coordinates) and facets, nothing else."""
    return {"vertex_ids": hull["vertex_ids"], "vertex_coords": hull["vertex_coords"],
            "simplices": hull["simplices"], "npoints": n}


# ---- the graph -------------------------------------------------------------------------
#
# The tasks are impure (dask.delayed's default): every call computes afresh,
# rather than finding a previous call's results still held by a cluster.

def _client(compute_kwargs: dict):
    """The dask.distributed Client that dask.compute(..., **compute_kwargs)
    will use, or None (a local scheduler)."""
    if "distributed" not in sys.modules:  # no Client can exist
        return None
    from distributed import Client
    try:
        get = dask.base.get_scheduler(scheduler=compute_kwargs.get("scheduler"))
    except Exception:  # an unknown scheduler name: dask.compute will say so
        return None
    client = getattr(get, "__self__", None)
    return client if isinstance(client, Client) else None


def _held(x: da.Array) -> bool:
    """Whether x is already persisted on a cluster: every chunk's key maps to
    a distributed Future in x's graph."""
    if "distributed" not in sys.modules:
        return False
    from distributed import Future
    graph = x.__dask_graph__()
    try:
        return all(isinstance(graph[k], Future) for row in x.__dask_keys__() for k in row)
    except KeyError:
        return False


def _cluster_memory(client) -> int:
    """The sum of the workers' memory limits, 0 where a worker has none (or
    there are no workers)."""
    limits = [w.get("memory_limit") or 0 for w in client.scheduler_info()["workers"].values()]
    return 0 if not limits or min(limits) <= 0 else int(sum(limits))


def _should_persist(x: da.Array, client, persist: Optional[bool]) -> bool:
    """persist=None: on a cluster, when x.nbytes is below half the workers'
    memory limits together (never where a worker has no limit); on a local
    scheduler never. True/False: as given."""
    if persist is not None:
        return bool(persist)
    if client is None:
        return False
    memory = _cluster_memory(client)
    return memory > 0 and x.nbytes < memory / 2


def _placement(x: da.Array, compute_kwargs: dict, persist: Optional[bool] = None):
    """(x, the workers of each chunk or None, whether x is held in memory).

    Where x is persisted (already, or now by the persist rule: _should_persist)
    on a distributed cluster, every task that reads a chunk is restricted to
    the workers holding it, so that no chunk of points crosses between
    workers, whatever the scheduler's load balancing would do;
    allow_other_workers keeps a run alive when those workers are lost (the
    chunk is then recomputed elsewhere). Where it is not, no task is pinned:
    a chunk's tasks then depend only on the task that reads (or makes) it,
    and the scheduler runs them on the worker that did. On a local scheduler
    persist=True computes x into this process's memory."""
    client = _client(compute_kwargs)
    held = _held(x)
    if client is None:
        if persist and not held:
            (x,) = dask.persist(x, **compute_kwargs)
        return x, None, bool(persist) or held
    if not held and not _should_persist(x, client, persist):
        return x, None, False
    from distributed import wait
    x = client.persist(x)
    with client.as_current():  # wait() asks for the default client
        wait(x)
    who = {str(k): w for k, w in client.who_has(x).items()}  # keyed by str(key) in distributed 2022.12
    keys = [k for row in x.__dask_keys__() for k in row]
    return x, [list(who.get(str(k), who.get(k, ()))) or None for k in keys], True


def _on(workers, i: int):
    """The annotation context for a task reading chunk i."""
    if workers is None or workers[i] is None:
        return contextlib.nullcontext()
    return dask.annotate(workers=workers[i], allow_other_workers=True)


def _certificate_tasks(x: da.Array, hull: dict, workers=None) -> list:
    """One delayed certificate per chunk of x against hull (a dict with
    vertex_ids, vertex_coords, simplices: one task of the graph holds it,
    every certificate task depends on that one, so a cluster sends it to
    each worker once)."""
    offsets = _offsets(x)
    hull = dask.delayed(_for_certificates)(hull, int(x.shape[0]))
    tasks = []
    for i, b in enumerate(x.to_delayed().ravel()):
        with _on(workers, i):
            tasks.append(dask.delayed(_certify_chunk)(b, int(offsets[i]), int(offsets[i + 1]), hull))
    return tasks


def _reduction(x: da.Array, threads: int, split_every: int, workers=None):
    """The delayed root (_final_hull's dict) of the tree over x's chunks, and
    the chunks' candidate tasks."""
    offsets = _offsets(x)
    level = []
    for i, b in enumerate(x.to_delayed().ravel()):
        with _on(workers, i):
            level.append(dask.delayed(_chunk_candidates)(b, int(offsets[i]), threads))
    chunks = level
    merge = dask.delayed(_merge_candidates)
    while len(level) > split_every:
        level = [merge(threads, *level[i:i + split_every]) for i in range(0, len(level), split_every)]
    return dask.delayed(_final_hull)(threads, *level), chunks


def _compute(tasks: list, x: da.Array, held: bool, compute_kwargs: dict) -> list:
    """dask.compute of the delayed tasks, each of which reads at most one
    chunk of x. Where x is not held in memory, each chunk's task and the
    tasks that only it depends on (the shard reading, the generating) are
    first inlined into the one task of the pass that uses the chunk
    (dask.optimization.inline): no chunk is then ever a result of its own,
    which a cluster's scheduler could move to another worker to balance
    the load (it did, in tests: a chunk read on one worker, its certificate
    computed on the other), and the chunk is dropped when the task ends."""
    if not held:
        from dask.core import reverse_dict
        from dask.delayed import Delayed
        from dask.optimization import cull, inline
        keys = [t.key for t in tasks]
        graph, dependencies = cull(dict(dask.base.collections_to_dsk(tasks)), keys)
        dependents = reverse_dict(dependencies)
        chunks = {k for row in x.__dask_keys__() for k in row}
        exclusive, pending = set(), [k for k in chunks if k in graph]
        while pending:  # the chunks and their ancestors that have one dependent
            k = pending.pop()
            if k not in exclusive and len(dependents[k]) == 1 and k not in keys:
                exclusive.add(k)
                pending.extend(dependencies[k])
        graph = inline(graph, keys=exclusive, inline_constants=False, dependencies=dependencies)
        graph, _ = cull(graph, keys)  # inline leaves the inlined keys in the graph
        tasks = [Delayed(k, graph) for k in keys]
    return list(dask.compute(*tasks, **compute_kwargs))


def certify_chunks(x, simplices, vertex_points=None, *, persist: Optional[bool] = False,
                   compute_kwargs: Optional[dict] = None) -> List[Certificate]:
    """The per-chunk certificates of a claimed hull of the dask array x: one
    task per row-chunk checks (flipflop.certify, canonical=True) that
    `simplices` (global row ids: 3D triangles, 2D the (k, 2) edges or the
    vertex cycle, as flipflop.ConvexHull gives them) are the canonical hull
    of the chunk's points together with the hull's vertices. All are
    truthy exactly when `simplices` is flipflop.ConvexHull(x.compute())'s.
    vertex_points: the coordinates of the hull's vertices (np.unique of
    simplices, in that order); gathered from x where not given. Returns one
    flipflop.Certificate per chunk, in chunk order (the constructor raises
    CertificationError on the first that fails). persist: as ConvexHull's,
    but False by default (one pass over x, or two where vertex_points must
    be gathered)."""
    x = _dask_points(x, "certify_chunks")
    d = x.shape[1]
    s = np.asarray(simplices, dtype=np.int64)
    if d == 2 and s.ndim == 1:
        s = np.stack([s, np.roll(s, -1)], axis=1)
    if s.ndim != 2 or s.shape[1] != d:
        raise ValueError(f"certify_chunks: simplices must have shape (m, {d}), got {s.shape}")
    if len(s) and (s.min() < 0 or s.max() >= x.shape[0]):
        raise ValueError(f"certify_chunks: simplices name rows outside 0..{x.shape[0] - 1}")
    ids = np.unique(s)
    if vertex_points is None:
        vertex_points = x[ids].compute(**(compute_kwargs or {}))
    coords = np.ascontiguousarray(np.asarray(vertex_points, dtype=np.float64))
    if coords.shape != (len(ids), d):
        raise ValueError(f"certify_chunks: vertex_points must have shape ({len(ids)}, {d}), got {coords.shape}")
    hull = {"vertex_ids": ids, "vertex_coords": coords, "simplices": s}
    x, workers, held = _placement(x, compute_kwargs or {}, persist)
    return _compute(_certificate_tasks(x, hull, workers), x, held, compute_kwargs or {})


class ConvexHull:
    """The convex hull of a dask array x of shape (n, 2) or (n, 3), with
    flipflop.ConvexHull's attributes in global row indices, equal to
    flipflop.ConvexHull(x.compute()) exactly (every array and float), on
    any dask scheduler.

    ConvexHull(x, *, threads=0, split_every=8, certify=True, persist=None,
               **compute_kwargs)

    x: a dask array (array-likes are wrapped with dask.array.asarray); any
    row chunking (chunks of one point, empty chunks and chunks of interior
    points included); the columns are brought into one chunk. Real dtypes,
    taken as float64.
    threads: worker threads of each task's compiled call (0: every core of
    the process; on a cluster with several workers per machine, 1).
    split_every: children per node of the reduction tree.
    certify: run one certificate task per chunk (CertificationError, a
    RuntimeError naming the chunk and the failed condition, where one
    fails). True or "points" (default): pass 2 reads every chunk again and
    certifies its points against the final hull. "chain": pass 2 certifies
    only each chunk's candidates (its hull's vertices, from pass 1, where
    flipflop.ConvexHull certified the chunk's hull while it held the chunk)
    against the final hull, as flipflop-mpi does: no second read (out of
    core: a few seconds instead of a pass over the data), but it trusts the
    code between a chunk's certified hull and the vertices its task returns
    (a test shows a task that drops a vertex there is caught by "points" and
    not by "chain"). False: no pass 2; the answer is still each chunk's and
    the root's certified hull, but the final facets are not checked against
    every point.
    persist: whether x is first persisted. Two passes read every chunk (the
    hull pass, then the certificate pass): a persisted x is read once and
    its chunks' tasks run on the workers holding them; an x that is not
    is read (or generated) again in pass 2, one chunk per task, and never
    held whole. None (default): persist on a dask.distributed cluster when
    x.nbytes is below half the sum of the workers' memory limits
    (client.scheduler_info(); never where a worker has no limit), never
    on a local scheduler. True/False force it (True on a local scheduler:
    into this process's memory). An x already persisted on the cluster is
    used where it is, pinned, whatever persist says.
    compute_kwargs: passed to dask.compute (scheduler=..., ...).

    Attributes (as flipflop.ConvexHull; docs/distributed_dask.md):
      points      x itself, the dask array (not computed; where the run
                  persists it, it lets go of it when done)
      persisted   whether the run held x in memory (persisted by it or
                  before it)
      simplices, vertices, neighbors, equations, volume, area
      ndim, npoints, nsimplex, min_bound, max_bound (the bounds of the
                  hull's vertices: those of all points)
      coplanar    (0, 3) int64 (no qhull_options); good None
      certificates  the per-chunk flipflop.Certificates (empty without
                  certify)
      transfer_bytes  bytes of the candidate sets (ids and coordinates)
                  passed between tasks in the reduction, plus the hull's
                  vertices and facets sent to each certificate task (and,
                  with certify="chain", the chunks' candidates gathered
                  and sent back): an upper bound of what crosses between
                  workers, never a chunk of points
      nchunks     x's row-chunks
      pass_seconds  wall seconds of the hull pass and of the certificate
                  pass (0.0 without certify)

    Bad input raises ValueError: NaN or infinity naming its global row; an
    input with fewer than d + 1 points or lower-dimensional the in-memory
    call's message (from the root, which then holds every point).
    """

    def __init__(self, x, *, threads: int = 0, split_every: Optional[int] = 8, certify: bool = True,
                 persist: Optional[bool] = None, **compute_kwargs):
        x = _dask_points(x, _WHAT)
        threads = int(threads)
        if threads < 0:
            raise ValueError(f"{_WHAT}: threads must be 0 (all cores) or positive, got {threads}")
        split_every = 8 if split_every is None else int(split_every)
        if split_every < 2:
            raise ValueError(f"{_WHAT}: split_every must be at least 2, got {split_every}")
        if persist is not None and not isinstance(persist, bool):
            raise ValueError(f"{_WHAT}: persist must be None, True or False, got {persist!r}")
        if certify not in (True, False, "points", "chain"):
            raise ValueError(f"{_WHAT}: certify must be True, False, 'points' or 'chain', got {certify!r}")
        chain = certify == "chain"
        given = x
        x, workers, self.persisted = _placement(x, compute_kwargs, persist)
        # pass 1: the chunks' candidates, the reduction and the root (and,
        # for the chain, the candidates themselves)
        t0 = time.perf_counter()
        root, chunk_tasks = _reduction(x, threads, split_every, workers)
        hull, *candidates = _compute([root] + (chunk_tasks if chain else []), x, self.persisted, compute_kwargs)
        t1 = time.perf_counter()
        # pass 2: every chunk again (or its candidates), against the final
        # hull (a plain argument)
        certificates = []
        if chain:
            off = _offsets(x)
            shared = dask.delayed(_for_certificates)(hull, int(x.shape[0]))
            tasks = [dask.delayed(_certify_candidates)(c, int(off[i]), int(off[i + 1]), shared)
                     for i, c in enumerate(candidates)]
            certificates = list(dask.compute(*tasks, **compute_kwargs))
        elif certify:
            certificates = _compute(_certificate_tasks(x, hull, workers), x, self.persisted, compute_kwargs)
        self.pass_seconds = (t1 - t0, time.perf_counter() - t1)
        for i, c in enumerate(certificates):
            if not c:
                off = _offsets(x)
                raise CertificationError(i, (int(off[i]), int(off[i + 1])), c)
        d = x.shape[1]
        self.points, self.ndim, self.nchunks = given, d, len(x.chunks[0])
        # scipy's (and flipflop.ConvexHull's) index dtype, np.intc
        self.simplices, self.vertices = _intc(hull["simplices"]), _intc(hull["vertices"])
        self.neighbors = _intc(hull["neighbors"])
        self.equations, self.volume, self.area = hull["equations"], hull["volume"], hull["area"]
        self.coplanar, self.good, self.polygons = np.zeros((0, 3), dtype=np.intc), None, None
        self.certificates = certificates
        vc = hull["vertex_coords"]
        self.min_bound, self.max_bound = vc.min(axis=0), vc.max(axis=0)
        broadcast = hull["vertex_ids"].nbytes + vc.nbytes + hull["simplices"].nbytes
        self.transfer_bytes = int(hull["reduction_bytes"]) + broadcast * len(certificates)
        if chain:  # the chunks' candidates to this process and back to the certificate tasks
            self.transfer_bytes += 2 * sum(int(c[0].nbytes + c[1].nbytes) for c in candidates)

    @property
    def npoints(self) -> int:
        return int(self.points.shape[0])

    @property
    def nsimplex(self) -> int:
        return int(self.simplices.shape[0])

    def close(self) -> None:
        """As scipy's: no resources to free (the hull is not incremental)."""
