"""flipflop.dask.ConvexHull (issue 37): equal to flipflop.ConvexHull of the
computed array on every attribute, across chunkings and degenerate families,
on the synchronous scheduler, the default threaded one and a two-worker
dask.distributed LocalCluster; the per-chunk certificates reject a hull that
misses a point only one chunk holds."""
import pickle
import subprocess
import sys

import numpy as np
import pytest

import dask
import dask.array as da
from distributed import Client, LocalCluster, get_task_stream

import flipflop
import flipflop.dask as fdask

ARRAYS = ("simplices", "vertices", "neighbors", "equations", "min_bound", "max_bound", "coplanar")


@pytest.fixture(scope="module")
def client():
    # processes=True: the workers are separate processes, so every task and
    # its arguments are pickled as on a real cluster (startup about 1 s)
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    c = Client(cluster, set_as_default=False)
    yield c
    c.close()
    cluster.close()


@pytest.fixture(params=["synchronous", "cluster"])
def scheduler(request):
    if request.param == "cluster":
        return request.getfixturevalue("client")
    return "synchronous"


def assert_same(h, a, scheduler=None):
    """h (flipflop.dask.ConvexHull) equals flipflop.ConvexHull(a) exactly."""
    m = flipflop.ConvexHull(a)
    for k in ARRAYS:
        x, y = getattr(h, k), getattr(m, k)
        assert x.dtype == y.dtype and x.shape == y.shape, k
        assert np.array_equal(x, y, equal_nan=True), k
    assert h.volume == m.volume and h.area == m.area
    assert (h.ndim, h.npoints, h.nsimplex, h.good) == (m.ndim, m.npoints, m.nsimplex, m.good)
    assert np.array_equal(h.points.compute(scheduler=scheduler), a)
    assert len(h.certificates) == h.nchunks and all(h.certificates)


def uniform(n, d, seed):
    return np.random.default_rng(seed).random((n, d))


def chunkings(n):
    """1 chunk, 7 chunks, uneven chunks with empty ones, chunks of one point."""
    cuts = np.sort(np.random.default_rng(n).choice(np.arange(1, n), size=min(5, n - 1), replace=False))
    uneven = tuple(np.diff(np.concatenate([[0], cuts, [n]])).tolist())
    uneven = (0,) + uneven[:2] + (0, 1) + uneven[2:-1] + (uneven[-1] - 1, 0)
    assert sum(uneven) == n
    return [n, -(-n // 7), uneven, 1]


@pytest.mark.parametrize("d", [2, 3])
def test_random_across_chunkings(d, scheduler):
    a = uniform(3000, d, seed=d)
    for c in chunkings(len(a))[:3]:
        x = da.from_array(a, chunks=(c, d))
        h = fdask.ConvexHull(x, scheduler=scheduler)
        assert h.nchunks == len(x.chunks[0])
        assert_same(h, a)


@pytest.mark.parametrize("d", [2, 3])
def test_chunks_of_one_point(d, scheduler):
    a = np.round(uniform(300, d, seed=10 + d) * 4) / 4  # repeated coordinates: a degenerate lattice
    x = da.from_array(a, chunks=(1, d))
    h = fdask.ConvexHull(x, split_every=5, scheduler=scheduler)
    assert h.nchunks == 300
    assert_same(h, a)


# the generator's degenerate families: lattices, cospherical integer points,
# duplicates, jitter, coplanar planes
FAMILIES = ["grid2", "circle-lattice", "duplicates2", "jitter2", "grid3", "sphere-lattice", "duplicates3",
            "planes3", "box", "frame"]


@pytest.mark.parametrize("dist", FAMILIES)
def test_degenerate_families(dist):
    a = flipflop.generate(dist, 2000, seed=3)
    d = a.shape[1]
    for c in chunkings(len(a)):
        if c == 1:
            continue  # test_chunks_of_one_point; 2000 tasks would only cost time
        h = fdask.ConvexHull(da.from_array(a, chunks=(c, d)), scheduler="synchronous")
        assert_same(h, a)


def test_degenerate_families_on_the_cluster(client):
    for dist in ("grid3", "sphere-lattice", "duplicates2"):
        a = flipflop.generate(dist, 1500, seed=5)
        h = fdask.ConvexHull(da.from_array(a, chunks=(211, a.shape[1])), scheduler=client)
        assert_same(h, a)


def test_duplicates_across_chunks(scheduler):
    # every point twice, the copies in other chunks: the perturbation (keyed
    # by the global row) decides which copy is a vertex
    base = flipflop.generate("sphere-lattice", 400, seed=2)
    a = np.concatenate([base, base[::-1], base[:50]])
    h = fdask.ConvexHull(da.from_array(a, chunks=(123, 3)), scheduler=scheduler)
    assert_same(h, a)


def interior_chunks(d):
    """The first chunk holds the cube's corners, chunks 1..4 only points
    strictly inside, chunk 5 one point, chunk 6 a lower-dimensional set on
    a face of the cube (collinear in 2D, coplanar in 3D)."""
    rng = np.random.default_rng(7)
    corners = np.array(np.meshgrid(*[[0.0, 1.0]] * d)).reshape(d, -1).T
    inside = 0.1 + 0.8 * rng.random((4 * 250, d))
    one = np.full((1, d), 0.5)
    face = rng.random((60, d))
    face[:, 0] = 1.0  # on the face x = 1: lower-dimensional, on the hull's boundary
    a = np.concatenate([corners, inside, one, face])
    chunks = (len(corners),) + (250,) * 4 + (1, 60)
    return a, chunks


@pytest.mark.parametrize("d", [2, 3])
def test_interior_one_point_and_flat_chunks(d, scheduler):
    a, chunks = interior_chunks(d)
    x = da.from_array(a, chunks=(chunks, d))
    h = fdask.ConvexHull(x, scheduler=scheduler)
    assert_same(h, a)
    # the interior chunks' rows are not vertices; the flat chunk on the
    # face x = 1 holds vertices (the perturbation keeps some of them)
    start = np.cumsum((0,) + chunks)
    assert not np.any((h.vertices >= start[1]) & (h.vertices < start[5]))


def test_default_scheduler_and_config():
    a = uniform(5000, 3, seed=4)
    x = da.from_array(a, chunks=(700, 3))
    assert_same(fdask.ConvexHull(x), a)  # dask's default: the threaded scheduler
    with dask.config.set(scheduler="synchronous"):
        assert_same(fdask.ConvexHull(x, threads=1), a)


def test_client_as_the_configured_scheduler(client):
    # no scheduler argument: dask's configuration names the cluster; its
    # task stream shows that the chunk and certificate tasks ran there
    a = uniform(4000, 2, seed=9)
    with dask.config.set(scheduler=client.get), get_task_stream(client) as ts:
        h = fdask.ConvexHull(da.from_array(a, chunks=(333, 2)))
    assert_same(h, a)
    names = [t["key"][0] if isinstance(t["key"], tuple) else t["key"] for t in ts.data]
    assert sum("_certify_chunk" in k for k in names) == 13
    assert sum("_chunk_candidates" in k for k in names) == 13


def test_transfer_is_hull_vertices_only(scheduler):
    a = uniform(100_000, 3, seed=1)
    h = fdask.ConvexHull(da.from_array(a, chunks=(12_500, 3)), scheduler=scheduler)
    assert_same(h, a)
    # 8 chunks of 12,500 points (300 kB each) hand on their hull vertices
    # (some hundred each); each certificate task receives the final hull
    k = len(h.vertices)
    assert h.transfer_bytes > 8 * (k * 32 + h.nsimplex * 24)  # the broadcast alone
    assert h.transfer_bytes < a.nbytes // 10


@pytest.mark.parametrize("persist", [None, False])
def test_lazy_array_generated_in_tasks(client, persist):
    # data that never exists in the client: each chunk made by its own task
    # (persist=False: made again for the certificates, inside their tasks)
    def block(seed, n):
        return np.random.default_rng(seed).normal(size=(n, 3))

    parts = [da.from_delayed(dask.delayed(block)(s, 3000), shape=(3000, 3), dtype=np.float64) for s in range(6)]
    x = da.concatenate(parts)
    h = fdask.ConvexHull(x, persist=persist, scheduler=client)
    assert h.persisted == (persist is None)
    assert_same(h, x.compute(scheduler="synchronous"))


def test_integer_dtype_and_numpy_input():
    a = np.random.default_rng(3).integers(-50, 50, size=(2000, 3))
    h = fdask.ConvexHull(da.from_array(a, chunks=(300, 3)), scheduler="synchronous")
    assert_same(h, a.astype(np.float64))
    h = fdask.ConvexHull(a.astype(np.float64), scheduler="synchronous")  # an array-like is wrapped
    assert_same(h, a.astype(np.float64))


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_nan_names_the_global_row(bad, scheduler):
    a = uniform(5000, 3, seed=2)
    a[3456, 1] = bad
    x = da.from_array(a, chunks=(1000, 3))
    with pytest.raises(ValueError, match=r"NaN or infinite coordinates \(row 3456\)"):
        fdask.ConvexHull(x, scheduler=scheduler)


@pytest.mark.parametrize("pts", [
    np.column_stack([np.arange(50.0), 2 * np.arange(50.0)]),  # collinear 2D
    np.column_stack([np.arange(60.0), np.arange(60.0) % 7, np.zeros(60)]),  # coplanar 3D
    np.column_stack([np.arange(40.0)] * 3),  # collinear 3D
    np.ones((30, 3)),  # all equal
    np.ones((3, 3)),  # too few points
    np.zeros((2, 2)),
])
def test_degenerate_input_raises_as_in_memory(pts, scheduler):
    with pytest.raises(ValueError) as mem:
        flipflop.ConvexHull(pts)
    d = pts.shape[1]
    for c in (1, 7, len(pts)):
        with pytest.raises(ValueError) as dist:
            fdask.ConvexHull(da.from_array(pts, chunks=(c, d)), scheduler=scheduler)
        assert str(dist.value) == str(mem.value)


def test_bad_shapes():
    with pytest.raises(ValueError, match="shape"):
        fdask.ConvexHull(da.zeros((10, 4)))
    with pytest.raises(ValueError, match="shape"):
        fdask.ConvexHull(da.zeros(10))
    with pytest.raises(ValueError, match="unknown"):
        x = da.from_array(uniform(100, 2, 0), chunks=(10, 2))
        fdask.ConvexHull(x[x[:, 0] > 0.5])
    with pytest.raises(ValueError, match="split_every"):
        fdask.ConvexHull(da.from_array(uniform(100, 2, 0)), split_every=1)
    with pytest.raises(ValueError, match="threads"):
        fdask.ConvexHull(da.from_array(uniform(100, 2, 0)), threads=-1)


def outlier_input(d):
    """Random points in 6 chunks of 500 and one point far outside, row 1717
    (chunk 3), held by no other chunk."""
    a = uniform(3000, d, seed=20 + d)
    a[1717] = 3.0
    return a, 500, 3, 1717


def hull_without(a, row):
    keep = np.flatnonzero(np.arange(len(a)) != row)
    return keep[flipflop.ConvexHull(a[keep]).simplices]


def drop_from_chunk_task(monkeypatch, row):
    """Make every chunk task lose `row` from the candidates it returns (as a
    faulty task would, after its chunk's hull was certified)."""
    real = fdask._chunk_candidates

    def lossy(block, start, threads):
        ids, coords, passed = real(block, start, threads)
        keep = ids != row
        return ids[keep], coords[keep], passed

    monkeypatch.setattr(fdask, "_chunk_candidates", lossy)


@pytest.mark.parametrize("d", [2, 3])
def test_certificates_reject_a_hull_missing_one_chunks_point(d, scheduler):
    a, c, chunk, row = outlier_input(d)
    x = da.from_array(a, chunks=(c, d))
    good = fdask.ConvexHull(x, scheduler=scheduler)
    assert row in good.vertices
    certs = fdask.certify_chunks(x, good.simplices, compute_kwargs={"scheduler": scheduler})
    assert len(certs) == 6 and all(certs)
    # the hull of every point but the outlier: right for every chunk but its own
    tampered = hull_without(a, row)
    certs = fdask.certify_chunks(x, tampered, compute_kwargs={"scheduler": scheduler})
    assert [bool(z) for z in certs] == [i != chunk for i in range(6)]
    assert certs[chunk].condition  # the failed condition is named
    # a facet naming a row that is not a point is rejected before any task runs
    with pytest.raises(ValueError, match="outside"):
        fdask.certify_chunks(x, good.simplices + len(a))


@pytest.mark.parametrize("d", [2, 3])
def test_constructor_raises_when_a_chunk_fails(d, monkeypatch):
    # a chunk task that loses the outlier (as a faulty task would): the
    # root's hull misses it, and the outlier's chunk's certificate fails
    a, c, chunk, row = outlier_input(d)
    drop_from_chunk_task(monkeypatch, row)
    x = da.from_array(a, chunks=(c, d))
    with pytest.raises(fdask.CertificationError) as e:
        fdask.ConvexHull(x, scheduler="synchronous")
    assert e.value.chunk == chunk and e.value.rows == (1500, 2000)
    assert "chunk 3 (rows 1500..1999)" in str(e.value)
    assert not e.value.certificate
    # without certification the wrong hull is returned: the check is what catches it
    h = fdask.ConvexHull(x, scheduler="synchronous", certify=False)
    assert row not in h.vertices and h.certificates == []


@pytest.mark.parametrize("d", [2, 3])
def test_chain_certificate_equals_and_rejects(d, scheduler, monkeypatch):
    # certify="chain": the chunks' certified hull vertices against the final
    # hull, no second pass over the points
    a = uniform(3000, d, 40 + d)
    x = da.from_array(a, chunks=(700, d))
    h = fdask.ConvexHull(x, certify="chain", scheduler=scheduler)
    assert_same(h, a, scheduler)
    # a root that loses a vertex only one chunk holds: that chunk's chain
    # certificate fails, naming it
    b, c, chunk, row = outlier_input(d)
    real = fdask._final_hull

    def lossy_root(threads, *parts):
        parts = [(i[i != row], co[i != row], n) for i, co, n in parts]
        return real(threads, *parts)

    monkeypatch.setattr(fdask, "_final_hull", lossy_root)
    y = da.from_array(b, chunks=(c, d))
    with pytest.raises(fdask.CertificationError) as e:
        fdask.ConvexHull(y, certify="chain", scheduler="synchronous")
    assert e.value.chunk == chunk and not e.value.certificate
    with pytest.raises(fdask.CertificationError):  # the per-point pass catches it as well
        fdask.ConvexHull(y, scheduler="synchronous")


@pytest.mark.parametrize("d", [2, 3])
def test_chain_trusts_the_chunk_task_points_does_not(d, monkeypatch):
    # the trust boundary of "chain", shown: a chunk task that drops one of
    # its certified hull's vertices before returning them is caught by the
    # per-point pass only
    a, c, chunk, row = outlier_input(d)
    drop_from_chunk_task(monkeypatch, row)
    x = da.from_array(a, chunks=(c, d))
    h = fdask.ConvexHull(x, certify="chain", scheduler="synchronous")
    assert row not in h.vertices and all(h.certificates)
    with pytest.raises(fdask.CertificationError):
        fdask.ConvexHull(x, certify="points", scheduler="synchronous")
    with pytest.raises(ValueError, match="certify"):
        fdask.ConvexHull(x, certify="sometimes")


def test_import_flipflop_does_not_import_dask():
    code = "import sys, flipflop; assert 'dask' not in sys.modules; import flipflop.dask; print(flipflop.dask.__name__)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "flipflop.dask"


# ---- out of core: two passes, the persist rule, .npy shards ------------------------------

def task_names(ts):
    return [t["key"][0] if isinstance(t["key"], tuple) else t["key"] for t in ts.data]


def write_shards(directory, sizes, d, seed):
    """Shards of the given sizes (in name order), and their concatenation."""
    rng = np.random.default_rng(seed)
    parts = [rng.normal(size=(n, d)) for n in sizes]
    for i, p in enumerate(parts):
        np.save(directory / f"part{i:03d}.npy", p)
    return np.concatenate(parts)


@pytest.mark.parametrize("d", [2, 3])
def test_npy_shards_uneven_with_an_empty_shard(d, tmp_path, scheduler):
    sizes = (700, 0, 1300, 5, 2000, 1)
    a = write_shards(tmp_path, sizes, d, seed=d)
    (tmp_path / "notes.txt").write_text("not a shard")
    x = fdask.from_npy_shards(tmp_path, chunk_rows=600)
    # every shard cut into equal parts of at most 600 rows, no chunk across
    # two shards, the empty shard none
    assert x.chunks == ((350, 350, 433, 433, 434, 5, 500, 500, 500, 500, 1), (d,))
    assert x.dtype == np.float64
    # only file names and row numbers in the graph, not the points
    assert len(pickle.dumps(dict(x.__dask_graph__()))) < 10_000
    h = fdask.ConvexHull(x, scheduler=scheduler)
    assert_same(h, a)


def test_npy_shards_in_name_order_as_flipflop_mpi(tmp_path):
    # byte-wise order of the names (upper case first), other files and
    # directories ending in .npy ignored; one .npy file works too
    rng = np.random.default_rng(5)
    named = {"b.npy": rng.random((30, 3)), "B.npy": rng.random((20, 3)), "a10.npy": rng.random((10, 3)),
             "a9.npy": rng.random((9, 3)), ".hidden.npy": rng.random((4, 3))}
    for k, v in named.items():
        np.save(tmp_path / k, v)
    (tmp_path / "dir.npy").mkdir()
    with open(tmp_path / "c.NPY", "wb") as f:  # not ".npy": ignored in a directory
        np.save(f, rng.random((5, 3)))
    order = [".hidden.npy", "B.npy", "a10.npy", "a9.npy", "b.npy"]
    x = fdask.from_npy_shards(str(tmp_path), chunk_rows=8)
    assert np.array_equal(x.compute(scheduler="synchronous"), np.concatenate([named[k] for k in order]))
    one = fdask.from_npy_shards(tmp_path / "b.npy")
    assert one.chunks == ((30,), (3,)) and np.array_equal(one.compute(), named["b.npy"])


def test_npy_shards_bad_shard_names_the_file(tmp_path):
    good = np.random.default_rng(1).random((50, 3))
    np.save(tmp_path / "s0.npy", good)
    cases = [("s1.npy", good[:, :2], r"s1\.npy: 2 columns, but .*s0\.npy has 3"),
             ("s1.npy", good.astype(np.float32), r"s1\.npy: npy dtype <f4, expected float64"),
             ("s1.npy", good.astype(">f8"), r"s1\.npy: npy dtype >f8"),
             ("s1.npy", good[:, 0], r"s1\.npy: shape \(50,\), expected \(n, 2\) or \(n, 3\)"),
             ("s1.npy", good[:, :1], r"s1\.npy: shape \(50, 1\)"),
             ("s1.npy", np.asfortranarray(good), r"s1\.npy: Fortran order"),
             ("s1.npy", np.zeros((3, 4)), r"s1\.npy: shape \(3, 4\)")]
    for name, arr, message in cases:
        np.save(tmp_path / name, arr)
        with pytest.raises(ValueError, match=message):
            fdask.from_npy_shards(tmp_path)
    (tmp_path / "s1.npy").write_bytes(b"not numpy at all")
    with pytest.raises(ValueError, match=r"s1\.npy: not a \.npy file"):
        fdask.from_npy_shards(tmp_path)
    np.save(tmp_path / "s1.npy", good)
    data = (tmp_path / "s1.npy").read_bytes()
    (tmp_path / "s1.npy").write_bytes(data[:-8])
    with pytest.raises(ValueError, match=r"s1\.npy: npy data is truncated"):
        fdask.from_npy_shards(tmp_path)
    empty = tmp_path / "empty"
    empty.mkdir()
    with pytest.raises(ValueError, match="no .npy shards in the directory"):
        fdask.from_npy_shards(empty)
    with pytest.raises(ValueError, match="no such file"):
        fdask.from_npy_shards(tmp_path / "missing")
    with pytest.raises(ValueError, match="chunk_rows"):
        fdask.from_npy_shards(tmp_path / "s0.npy", chunk_rows=0)


def test_npy_shards_changed_after_reading_the_headers(tmp_path):
    a = write_shards(tmp_path, (100, 200), 3, seed=3)
    x = fdask.from_npy_shards(tmp_path)
    np.save(tmp_path / "part001.npy", a[:150])  # fewer rows than the header said
    with pytest.raises(ValueError, match=r"part001\.npy: the shard changed"):
        x.compute(scheduler="synchronous")


def test_all_shards_empty(tmp_path):
    np.save(tmp_path / "a.npy", np.zeros((0, 3)))
    x = fdask.from_npy_shards(tmp_path)
    assert x.shape == (0, 3)
    with pytest.raises(ValueError) as mem:
        flipflop.ConvexHull(np.zeros((0, 3)))
    with pytest.raises(ValueError) as dist:
        fdask.ConvexHull(x, scheduler="synchronous")
    assert str(dist.value) == str(mem.value)


def test_unpersisted_shards_are_read_once_per_pass_and_never_move(tmp_path, client):
    # persist=False: the hull pass and the certificate pass each read every
    # chunk once; the tasks are not pinned, yet no chunk crosses between the
    # workers (each chunk's task runs where the chunk was read)
    a = write_shards(tmp_path, (30_000,) * 4, 3, seed=11)
    x = fdask.from_npy_shards(tmp_path, chunk_rows=15_000)  # 8 chunks of 360 kB
    sent = lambda: sum(client.run(lambda dask_worker: dask_worker.transfer_outgoing_bytes_total).values())
    before = sent()
    with get_task_stream(client) as ts:
        h = fdask.ConvexHull(x, persist=False, scheduler=client)
    moved = sent() - before
    assert not h.persisted
    assert_same(h, a)
    names = task_names(ts)
    assert sum("from-npy-shards" in k for k in names) == 0  # read inside them
    assert sum("_certify_chunk" in k for k in names) == 8
    assert moved < 15_000 * 24 // 2, moved  # hull vertices, not a chunk
    # persisted (the rule's choice for an array this small): read once
    with get_task_stream(client) as ts:
        h = fdask.ConvexHull(x, scheduler=client)
    assert h.persisted
    assert_same(h, a)
    assert sum("from-npy-shards" in k for k in task_names(ts)) == 8


def test_persist_rule(client):
    memory = fdask._cluster_memory(client)
    assert memory > 0  # LocalCluster's workers have limits
    small = da.zeros((1000, 3), chunks=(100, 3))
    huge = da.zeros((memory // 48 + 1, 3), chunks=(10**8, 3))  # just over half the memory; never computed
    assert fdask._should_persist(small, client, None)
    assert not fdask._should_persist(huge, client, None)
    assert fdask._should_persist(huge, client, True) and not fdask._should_persist(small, client, False)
    assert not fdask._should_persist(small, None, None)  # a local scheduler: never by default
    # already persisted: used where it is, pinned, whatever persist says
    a = uniform(2000, 3, seed=6)
    held = client.persist(da.from_array(a, chunks=(500, 3)))
    assert fdask._held(held) and not fdask._held(small)
    h = fdask.ConvexHull(held, persist=False, scheduler=client)
    assert h.persisted
    assert_same(h, a, scheduler=client)
    with pytest.raises(ValueError, match="persist"):
        fdask.ConvexHull(small, persist="yes")


def test_persist_on_a_local_scheduler():
    a = uniform(3000, 3, seed=8)
    calls = []

    def block(i):
        calls.append(i)
        return a[i * 1000:(i + 1) * 1000]

    x = da.concatenate([da.from_delayed(dask.delayed(block)(i), shape=(1000, 3), dtype=np.float64)
                        for i in range(3)])
    h = fdask.ConvexHull(x, scheduler="synchronous")
    assert not h.persisted and sorted(calls) == [0, 0, 1, 1, 2, 2]  # made once per pass
    calls.clear()
    h = fdask.ConvexHull(x, persist=True, scheduler="synchronous")
    assert h.persisted and sorted(calls) == [0, 1, 2]
    assert_same(h, a)
