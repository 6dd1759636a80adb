#!/usr/bin/env python3
"""Peak stress ratio against friction: a sweep of 5 friction coefficients at 3 seeds each,
run on a pool of processes, drawn as mean peak q/p with the seed-to-seed scatter.

    PYTHONPATH=build/python python3 docs/examples/friction_sweep.py \
        resources/experiments/quick.json --out sweep --processes 2

Each run is a run folder (sweep/mu0.30-seed2/ ...) written as `grainlab run` writes it; a run
already finished there is read, not run again, so a sweep that was stopped continues. Writes
sweep/peak_q_over_p.csv and sweep/peak_q_over_p.png.
"""

import argparse
import csv
import os
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

import grainlab


def peak_ratios(folder):
    """Peak q/p of every shear test of a finished run, by test name."""
    out = {}
    for test in folder.tests:
        s = folder.series(test)
        kind = np.char.startswith(s["stage"], "shear")
        if kind.any():
            out[test] = float(s["q_over_p"][kind].max())
    return out


def one_run(job):
    """Runs (or reads) one friction and seed; returns (mu, seed, {test: peak q/p})."""
    text, mu, seed, out = job
    folder = Path(out)
    if (folder / "run.h5").exists() and grainlab.RunFolder(str(folder)).finished:
        return mu, seed, peak_ratios(grainlab.RunFolder(str(folder)))
    exp = grainlab.Experiment.from_text(text).with_changes(
        {"shear": {"friction": mu}, "seed": seed, "threads": 1})
    return mu, seed, peak_ratios(grainlab.run(exp, str(folder), force=True))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("experiment", help="experiment file (JSON)")
    parser.add_argument("--out", required=True, help="folder of the sweep")
    parser.add_argument("--frictions", default="0.1,0.2,0.3,0.4,0.5",
                        help="friction coefficients, comma-separated")
    parser.add_argument("--seeds", type=int, default=3, help="seeds per friction")
    parser.add_argument("--processes", type=int, default=os.cpu_count() or 1)
    args = parser.parse_args()

    text = grainlab.Experiment.load(args.experiment).text
    frictions = [float(m) for m in args.frictions.split(",")]
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    jobs = [(text, mu, seed, str(out / f"mu{mu:.2f}-seed{seed}"))
            for mu in frictions for seed in range(1, args.seeds + 1)]
    with ProcessPoolExecutor(max_workers=args.processes) as pool:
        results = list(pool.map(one_run, jobs))

    tests = sorted({t for _, _, r in results for t in r})
    rows = []
    for test in tests:
        for mu in frictions:
            values = np.array([r[test] for m, _, r in results if m == mu and test in r])
            sd = values.std(ddof=1) if len(values) > 1 else float("nan")
            rows.append((test, mu, len(values), values.mean(), sd))
    with open(out / "peak_q_over_p.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["test", "friction", "seeds", "peak_q_over_p_mean", "peak_q_over_p_sd"])
        w.writerows(rows)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for test in tests:
        r = [row for row in rows if row[0] == test]
        ax.errorbar([x[1] for x in r], [x[3] for x in r], yerr=[x[4] for x in r], marker="o",
                    capsize=3, label=test)
    ax.set_xlabel("μ")
    ax.set_ylabel("peak q/p")
    ax.set_title(f"mean of {args.seeds} seeds, bars: ± one standard deviation")
    ax.legend()
    fig.tight_layout()
    fig.savefig(out / "peak_q_over_p.png", dpi=100)
    for row in rows:
        print(f"{row[0]}  mu {row[1]:.2f}: peak q/p {row[3]:.4f} ± {row[4]:.4f} ({row[2]} seeds)")


if __name__ == "__main__":
    main()
