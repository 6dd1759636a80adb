#!/usr/bin/env bash
# resources/scripts/plot_run.py on a real run: `grainlab run` of a small experiment (the tiny
# one: 150 ovals, two pressures, shear to 2 %), then the script, then its images checked: both
# PNG files exist at the size the script promises, the series figure shows its curves, and the
# checkpoint figure (the peak of q/p) shows void cells, a large share of the pixels of its right
# panel being the colours of at least three valences, and grains and force chains on the left.
# Skipped (exit 77) only when no python3 with h5py, numpy and matplotlib is found.
# Usage: plot_run_test.sh <grainlab executable> <plot_run.py> <experiment file>
set -uo pipefail

grainlab="$1"
script="$2"
experiment="$3"

# shellcheck source=find_python.sh
source "$(dirname "${BASH_SOURCE[0]}")/find_python.sh"
find_python h5py numpy matplotlib

make_work

must_run "$work/run.log" "grainlab run $experiment" \
  "$grainlab" run "$experiment" --out "$work/run"
must_run "$work/plot.log" "$script" "$python" "$script" "$work/run/run.h5" --out "$work/png"

PLOT_SCRIPT="$script" "$python" - "$work/png" "$work/run/run.h5" << 'CHECK'
import glob
import importlib.util
import os
import sys

import h5py
import matplotlib.image
import numpy as np

spec = importlib.util.spec_from_file_location("plot_run", os.environ["PLOT_SCRIPT"])
plot_run = importlib.util.module_from_spec(spec)
spec.loader.exec_module(plot_run)

folder, run_file = sys.argv[1], sys.argv[2]
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def rgb(colour):
    return np.array([int(colour[i:i + 2], 16) for i in (1, 3, 5)]) / 255.0


def share_of(pixels, colour, tolerance=0.02):
    """Share of the pixels within `tolerance` of `colour` in every channel."""
    return float(np.all(np.abs(pixels[..., :3] - rgb(colour)) <= tolerance, axis=-1).mean())


series = os.path.join(folder, "q_over_p.png")
check(os.path.exists(series), "q_over_p.png not written")
with h5py.File(run_file, "r") as f:
    peaks = [n for n in plot_run.checkpoints_in_write_order(f)
             if f["checkpoints"][n].attrs.get("peak", 0)]
check(len(peaks) == 2, f"{len(peaks)} peak checkpoints in the run file, expected 2 (one per test)")
pictures = glob.glob(os.path.join(folder, "checkpoint-*.png"))
check(len(pictures) == 1, f"{len(pictures)} checkpoint pictures written, expected 1")
if peaks and pictures:
    check(os.path.basename(pictures[0]) == f"checkpoint-{peaks[0]}.png",
          f"the picture is {pictures[0]}, not of the first peak checkpoint {peaks[0]}")

if os.path.exists(series):
    image = matplotlib.image.imread(series)
    w, h = plot_run.SERIES_SIZE
    check(image.shape[:2] == (int(h * 100), int(w * 100)),
          f"q_over_p.png is {image.shape[1]} x {image.shape[0]} px, expected {w * 100:g} x {h * 100:g}")
    # The first two curves, in matplotlib's first two default colours.
    for colour in ("#1f77b4", "#ff7f0e"):
        check(share_of(image, colour, 0.05) > 0.001, f"q_over_p.png: no curve of colour {colour}")

if pictures:
    image = matplotlib.image.imread(pictures[0])
    w, h = plot_run.FIGURE_SIZE
    check(image.shape[:2] == (int(h * 100), int(w * 100)),
          f"checkpoint picture is {image.shape[1]} x {image.shape[0]} px, expected "
          f"{w * 100:g} x {h * 100:g}")
    half = image.shape[1] // 2
    cells, grains = image[:, half:], image[:, :half]
    shares = {n: share_of(cells, c) for n, c in plot_run.VALENCE_COLOURS.items()}
    total = sum(shares.values())
    print("void-cell colours in the right panel:",
          ", ".join(f"{n}: {100 * s:.1f} %" for n, s in shares.items()), f"(total {100 * total:.1f} %)")
    check(total > 0.15, f"only {100 * total:.1f} % of the void-cell panel has void-cell colours")
    check(sum(s > 0.005 for s in shares.values()) >= 3, "fewer than three valences drawn")
    check(sum(share_of(grains, c) for c in plot_run.VALENCE_COLOURS.values()) < 0.01,
          "void-cell colours in the grains panel")
    grain_fill = share_of(grains, "#d9d9d9")
    strong = share_of(grains, "#990000", 0.05)
    print(f"grains panel: grain fill {100 * grain_fill:.1f} %, strong chains {100 * strong:.2f} %")
    check(grain_fill > 0.15, f"only {100 * grain_fill:.1f} % of the grains panel is grain fill")
    check(strong > 0.002, "no strong force chains drawn")

for f in failures:
    print("FAILED:", f, file=sys.stderr)
sys.exit(1 if failures else 0)
CHECK
