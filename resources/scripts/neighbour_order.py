#!/usr/bin/env python3
"""How close in memory each checkpoint's neighbour pairs are: for every checkpoint of a run
file, the number of neighbour pairs and the median and 90th percentile of |i - j| over them
(grain numbers i, j of a pair), and the share of pairs more than 1000 grains apart.

    python3 resources/scripts/neighbour_order.py ref/run.h5

The engine reads a pair's two grains from arrays in grain order: the closer the numbers, the
more of a pair's data is already in the processor's caches. A generated grid numbers grains
row by row, so a grain's neighbours are about one row (the grid's column count) away; the
table shows whether compaction and shear keep that order. Needs python3-h5py and numpy.
"""

import argparse

import h5py
import numpy as np


def order_by_checkpoint(run_file):
    """(checkpoint, pairs, median |i-j|, 90th percentile, share > 1000) per checkpoint with
    neighbour pairs, in the order the run wrote them."""
    rows = []
    with h5py.File(run_file, "r") as f:
        for name in sorted(f["checkpoints"]):
            pairs = f["checkpoints"][name]["pairs"]
            first = pairs["first"][:].astype(np.int64)
            second = pairs["second"][:].astype(np.int64)
            if len(first) == 0:
                continue
            gap = np.abs(second - first)
            rows.append((name, len(first), float(np.median(gap)), float(np.percentile(gap, 90)),
                         float(np.mean(gap > 1000))))
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("run_file")
    args = parser.parse_args()
    print(f"{'checkpoint':<45} {'pairs':>7} {'median':>7} {'p90':>7} {'>1000':>7}")
    for name, count, median, p90, far in order_by_checkpoint(args.run_file):
        print(f"{name:<45} {count:>7} {median:>7.0f} {p90:>7.0f} {far:>7.3f}")


if __name__ == "__main__":
    main()
