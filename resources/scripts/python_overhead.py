#!/usr/bin/env python3
"""What driving a run from Python costs: the same experiment run by `grainlab run` and by
grainlab.run() in chunks of 1000 steps, interleaved round by round, wall times and their ratio.

    PYTHONPATH=build/python python3 resources/scripts/python_overhead.py \
        resources/experiments/quick.json --grainlab build/app/grainlab --rounds 3

Both runs write a run folder (in a temporary folder, removed at the end) and must give the
same series bits, which the script checks. Prints one line per round and the median ratio.
"""

import argparse
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np

import grainlab


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("experiment")
    parser.add_argument("--grainlab", default="build/app/grainlab", help="the executable")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--chunk", type=int, default=1000, help="steps per Python call")
    args = parser.parse_args()
    exp = grainlab.Experiment.load(args.experiment)
    ratios = []
    with tempfile.TemporaryDirectory() as tmp:
        for k in range(args.rounds):
            cli, py = Path(tmp, f"cli{k}"), Path(tmp, f"py{k}")
            # Alternate which goes first, so that a drift of the machine's speed cancels.
            order = ("cli", "py") if k % 2 == 0 else ("py", "cli")
            seconds = {}
            for which in order:
                start = time.perf_counter()
                if which == "cli":
                    subprocess.run([args.grainlab, "run", args.experiment, "--out", str(cli),
                                    "--quiet"], check=True, stdout=subprocess.DEVNULL)
                else:
                    grainlab.run(exp, py, chunk=args.chunk)
                seconds[which] = time.perf_counter() - start
            a, b = grainlab.RunFolder(str(cli)), grainlab.RunFolder(str(py))
            for test in a.tests:
                sa, sb = a.series(test), b.series(test)
                if not all(np.array_equal(sa[n], sb[n]) for n in sa.dtype.names):
                    raise SystemExit(f"round {k}: the series of {test} differ")
            ratio = seconds["py"] / seconds["cli"]
            ratios.append(ratio)
            print(f"round {k + 1}: grainlab run {seconds['cli']:.2f} s, Python "
                  f"{seconds['py']:.2f} s (chunks of {args.chunk}), ratio {ratio:.4f}",
                  flush=True)
    print(f"median ratio Python / grainlab run: {statistics.median(ratios):.4f} over "
          f"{args.rounds} rounds; series bit-identical")


if __name__ == "__main__":
    main()
