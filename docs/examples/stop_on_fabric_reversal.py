#!/usr/bin/env python3
"""Stops a shear test when the strong-contact fabric first reverses: when the deviator of the
strong contacts' fabric, Hs11 - Hs22, having grown with the axial load, falls back from its
largest value by more than a tolerance. No experiment key expresses this condition.

    PYTHONPATH=build/python python3 docs/examples/stop_on_fabric_reversal.py \
        resources/experiments/quick.json --out reversal

Plays the experiment into the run folder --out (as `grainlab run` would) and watches the first
shear test record by record (Runner.measures() is the row a record made now holds). When the
fabric reverses it writes a checkpoint "fabric-reversal" and stops; the run folder can be
resumed later (`grainlab run --resume`). Prints where it stopped; writes reversal.json there.
"""

import argparse
import json
from pathlib import Path

import grainlab


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("experiment", help="experiment file (JSON)")
    parser.add_argument("--out", required=True, help="run folder to write")
    parser.add_argument("--tolerance", type=float, default=0.02,
                        help="fall of Hs11 - Hs22 from its largest value that counts [-]")
    args = parser.parse_args()

    exp = grainlab.Experiment.load(args.experiment)
    found = None
    with grainlab.Runner(exp, args.out) as runner:
        # Steps between the shear test's records: one check per record.
        stride = max(1, round(exp.to_dict()["record"]["strain_interval"] /
                              exp.to_dict()["shear"]["axial_strain_per_step"]))
        largest, test = None, None
        while runner.advance(stride):
            p = runner.progress
            if p["kind"] != "shear":
                continue
            if test is None:
                test = p["test"]
            elif p["test"] != test:
                break                      # the first test ended without a reversal
            hs = runner.measures()["Hsdev"]
            largest = hs if largest is None else max(largest, hs)
            if largest - hs > args.tolerance:
                found = {"test": test, "axial_strain": p["axial_strain"], "step": p["step"],
                         "Hsdev": hs, "Hsdev_largest": largest}
                runner.checkpoint("fabric-reversal")
                break
    result = found or {"test": test, "reversal": None}
    Path(args.out, "reversal.json").write_text(json.dumps(result, indent=2) + "\n")
    if found:
        print(f"{test}: the strong fabric reversed at eps1 = {found['axial_strain']:.4f} "
              f"(Hs11 - Hs22 = {found['Hsdev']:.4f}, largest {found['Hsdev_largest']:.4f})")
    else:
        print(f"{test}: no reversal of the strong fabric in the first shear test")


if __name__ == "__main__":
    main()
