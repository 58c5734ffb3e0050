#!/usr/bin/env python3
"""dask_hull.py — flipflop.dask.ConvexHull on a dask.distributed LocalCluster
against flipflop.ConvexHull on the computed array (issue 37; results in
docs/distributed_dask.md).

The points are generated inside the cluster, one task per chunk with its own
seed (flipflop.generate), and persisted on the workers: they never exist in
one process until the in-memory comparison gathers them. Prints the median
of --repeat runs of each, their ratio, the bytes the reduction and the
certificate broadcast hand between tasks (the result's transfer_bytes) and
the bytes the workers actually sent to each other (distributed's
transfer_outgoing_bytes_total), and checks that both answers are equal on
every attribute.

    PYTHONPATH=<flipflop package> python3 examples/dask_hull.py --n 10000000

--shards DIR: the hull of a directory of .npy shards (rows in shard-name
order, as flipflop-mpi reads them) through flipflop.dask.from_npy_shards,
not persisted: each pass reads every chunk from the files inside the task
that uses it, so the workers never hold more than their chunks at hand (the
input may exceed memory). One timed run (--repeat); prints the time of each
pass, the peak resident memory of every worker and of this process (client
and scheduler), the bytes sent between workers, and, with --compare-file,
whether the facets equal an index-text file written by `flipflop hull3 ...
-o FILE.txt` or `flipflop-mpi` (2D: the vertex cycle, one index a line).

    PYTHONPATH=<flipflop package> python3 examples/dask_hull.py --shards DIR \
        --compare-file FILE.txt
"""
import argparse
import resource
import statistics
import time

import numpy as np

import dask
import dask.array as da
from distributed import Client, LocalCluster, wait

import flipflop
import flipflop.dask as fdask


def generate_block(dist: str, n: int, seed: int) -> np.ndarray:
    return flipflop.generate(dist, n, seed=seed)


def sent_bytes(client) -> int:
    return sum(client.run(lambda dask_worker: dask_worker.transfer_outgoing_bytes_total).values())


def peak_rss_mib(client):
    """The peak resident memory (MiB) of each worker process and of this one."""
    def peak():
        import resource
        return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss  # KiB on Linux
    workers = {w: kib / 1024 for w, kib in client.run(peak).items()}
    return workers, resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def read_index_text(path: str, d: int) -> np.ndarray:
    """An index-text hull (flipflop / flipflop-mpi): "i j k" a line (3D), or
    one vertex a line (2D); '#' comments and blank lines skipped."""
    a = np.loadtxt(path, dtype=np.int64, comments="#", ndmin=2)
    return a if d == 3 else a.ravel()


def run_shards(args, client):
    x = fdask.from_npy_shards(args.shards, chunk_rows=args.chunk_rows)
    print(f"{x.shape[0]} points ({x.nbytes / 1e9:.2f} GB, {x.shape[1]}D) from {args.shards} in {x.numblocks[0]} "
          f"chunks of at most {args.chunk_rows} rows on {args.workers} workers (1 thread each, not persisted); "
          f"flipflop threads per task: {args.threads}")
    before = sent_bytes(client)
    t_dask, h = median_time(lambda: fdask.ConvexHull(x, threads=args.threads, persist=False,
                                                                certify=args.certify), args.repeat)
    sent = (sent_bytes(client) - before) // args.repeat
    print(f"flipflop.dask.ConvexHull   {t_dask:8.3f} s (median of {args.repeat}; last run: hull pass "
          f"{h.pass_seconds[0]:.3f} s, certificate pass {h.pass_seconds[1]:.3f} s)  {len(h.vertices)} vertices, "
          f"{h.nsimplex} facets, all {h.nchunks} chunks certified: {all(h.certificates)}; persisted: {h.persisted}")
    print(f"  transfer_bytes (candidates + hull broadcast): {h.transfer_bytes} B; "
          f"bytes sent between workers per run: {sent} B; the points: {x.nbytes} B")
    workers, here = peak_rss_mib(client)
    print("  peak resident memory: " + ", ".join(f"worker {i} {m:.0f} MiB" for i, m in enumerate(workers.values()))
          + f"; this process (client and scheduler) {here:.0f} MiB")
    if args.compare_file:
        other = read_index_text(args.compare_file, h.ndim)
        mine = h.simplices if h.ndim == 3 else h.vertices
        same = other.shape == mine.shape and np.array_equal(other, mine)
        print(f"equal to {args.compare_file} ({len(other)} {'facets' if h.ndim == 3 else 'vertices'}): {same}")
        if not same:
            raise SystemExit("the answers differ")


def median_time(f, repeat):
    times, out = [], None
    for _ in range(repeat):
        t = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - t)
    return statistics.median(times), out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--n", type=int, default=10_000_000, help="points (default 10^7)")
    ap.add_argument("--dist", default="ball", help="a flipflop.distributions() family (default ball, 3D)")
    ap.add_argument("--chunk", type=int, default=None, help="points per chunk (default n / 16, at most 5e6)")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--threads", type=int, default=1, help="flipflop threads per task (default 1)")
    ap.add_argument("--repeat", type=int, default=None, help="timed runs (default 3; with --shards 1)")
    ap.add_argument("--skip-memory", action="store_true", help="no in-memory comparison")
    ap.add_argument("--shards", metavar="DIR", help="the hull of a directory of .npy shards (not persisted)")
    ap.add_argument("--chunk-rows", type=int, default=2 ** 23, help="with --shards: rows per chunk at most "
                    "(default 2^23)")
    ap.add_argument("--certify", choices=("points", "chain"), default="points",
                    help="pass 2: every chunk's points (default) or its certified hull vertices")
    ap.add_argument("--compare-file", metavar="FILE.txt", help="with --shards: compare with an index-text hull")
    args = ap.parse_args()
    if args.shards:
        args.repeat = args.repeat or 1
        cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True,
                               dashboard_address=None)
        client = Client(cluster)
        try:
            run_shards(args, client)
        finally:
            client.close()
            cluster.close()
        return

    args.repeat = args.repeat or 3
    chunk = args.chunk or max(1, min(5_000_000, -(-args.n // 16)))
    sizes = [chunk] * (args.n // chunk) + ([args.n % chunk] if args.n % chunk else [])
    d = flipflop.generate(args.dist, 4, seed=1).shape[1]

    cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True, dashboard_address=None)
    client = Client(cluster)
    try:
        blocks = [da.from_delayed(dask.delayed(generate_block)(args.dist, s, 1000 + i), shape=(s, d),
                                  dtype=np.float64) for i, s in enumerate(sizes)]
        x = da.concatenate(blocks).persist()
        wait(x)
        print(f"{args.n} {args.dist} points ({x.nbytes / 1e9:.2f} GB) in {len(sizes)} chunks on "
              f"{args.workers} workers; flipflop threads per task: {args.threads}")

        def distributed():
            return fdask.ConvexHull(x, threads=args.threads, certify=args.certify)

        before = sent_bytes(client)
        t_dask, h = median_time(distributed, args.repeat)
        sent = (sent_bytes(client) - before) // args.repeat
        print(f"flipflop.dask.ConvexHull   {t_dask:8.3f} s (median of {args.repeat})  "
              f"{len(h.vertices)} vertices, {h.nsimplex} facets, all {h.nchunks} chunks certified: "
              f"{all(h.certificates)}")
        print(f"  transfer_bytes (candidates + hull broadcast): {h.transfer_bytes} B; "
              f"bytes sent between workers per run: {sent} B; the points: {x.nbytes} B")
        if args.skip_memory:
            return
        a = x.compute()
        t_mem, m = median_time(lambda: flipflop.ConvexHull(a), args.repeat)
        print(f"flipflop.ConvexHull        {t_mem:8.3f} s (median of {args.repeat}, threads=0: every core)")
        same = (all(np.array_equal(getattr(h, k), getattr(m, k), equal_nan=True)
                    for k in ("simplices", "vertices", "neighbors", "equations", "min_bound", "max_bound"))
                and h.volume == m.volume and h.area == m.area)
        print(f"ratio dask / in-memory: {t_dask / t_mem:.2f}; equal on every attribute: {same}")
        if not same:
            raise SystemExit("the answers differ")
    finally:
        client.close()
        cluster.close()


if __name__ == "__main__":
    main()
