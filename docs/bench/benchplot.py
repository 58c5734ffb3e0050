"""Shared by plot_hull2.py and plot_hull3.py: the measured CSV tables next to
this file (lines starting with '#' are notes) and a matplotlib without a display."""
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the backend)

here = os.path.dirname(os.path.abspath(__file__))


def rows(name):
    with open(os.path.join(here, name)) as f:
        return list(csv.DictReader(l for l in f if not l.startswith("#")))


def save(fig, name):
    fig.tight_layout()
    fig.savefig(os.path.join(here, name), dpi=90)
