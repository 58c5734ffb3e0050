"""The alternating timing both scipy comparisons use (python_vs_scipy.py,
measure_scipy_rows.py): each case's flipflop call and scipy call run in turn,
R times (flipflop, scipy, flipflop, ...), so that load from other processes,
which changes over seconds on a shared machine, weighs on both alike."""
import os, statistics, time


def timed(f):
    t = time.perf_counter(); out = f(); return time.perf_counter() - t, out


def alternate(cases, R):
    """cases: (name, points, flipflop_call, scipy_call). Returns the load
    averages before and after and, per case, (name, flipflop median s, scipy
    median s, flipflop's last result, scipy's last result)."""
    load0 = os.getloadavg()
    rows = []
    for name, pts, ff, sp in cases:
        tf, ts = [], []
        for _ in range(R):
            t, a = timed(lambda: ff(pts)); tf.append(t)
            t, b = timed(lambda: sp(pts)); ts.append(t)
        rows.append((name, statistics.median(tf), statistics.median(ts), a, b))
    return load0, os.getloadavg(), rows
