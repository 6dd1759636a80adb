"""GrainLab from Python: experiments, runs, the engine step by step, and run folders.

    import grainlab
    exp = grainlab.Experiment.load("resources/experiments/quick.json")
    folder = grainlab.run(exp, "runs/quick")          # as `grainlab run ... --out runs/quick`
    series = folder.series(folder.tests[1])          # a NumPy structured array
    sim = folder.simulation(checkpoint=folder.checkpoints[-1]["name"])
    sim.step(1000)                                    # the engine, from that checkpoint
    forces = sim.contacts()["normal_force"]

The user's guide to this module is docs/python.md. Everything here is computed by the same
code as `grainlab run`: the same validation, the same bits.
"""

import copy as _copy
import json as _json

import numpy as _np

from ._grainlab import (  # noqa: F401  (re-exported)
    ExperimentError,
    Experiment,
    GrainLabError,
    RunFolder,
    RunFolderError,
    Runner,
    Simulation,
    SimulationError,
    __commit__,
    __version__,
    series_columns,
)

__all__ = [
    "Experiment", "Runner", "RunFolder", "Simulation", "run", "resume", "series_columns",
    "GrainLabError", "ExperimentError", "SimulationError", "RunFolderError", "__version__",
    "__commit__",
]


def _merge(base, changes):
    for key, value in changes.items():
        if isinstance(value, dict) and isinstance(base.get(key), dict):
            _merge(base[key], value)
        else:
            base[key] = _copy.deepcopy(value)
    return base


def _from_dict(d, name="<dict>"):
    """An Experiment from a dict shaped as an experiment file; validated as a file is.

    Raises ExperimentError (also a ValueError) naming the key and the allowed range.
    """
    if not isinstance(d, dict):
        raise ExperimentError(f"{name}: an experiment must be a dict, not {type(d).__name__}")
    try:
        text = _json.dumps(d, indent=2, allow_nan=False)
    except (TypeError, ValueError) as e:
        raise ExperimentError(f"{name}: not expressible as an experiment file: {e}") from None
    return Experiment.from_text(text, name)


def _to_dict(self):
    """The experiment as a dict shaped as its file (keys as written)."""
    return _json.loads(self.text)


def _with_changes(self, changes):
    """A new Experiment: this one with `changes` (a nested dict) merged in, then validated.

    >>> exp.with_changes({"shear": {"friction": 0.3}, "grains": {"seed": 2}})
    """
    return _from_dict(_merge(self.to_dict(), changes), f"{self.name} with changes")


Experiment.from_dict = staticmethod(_from_dict)
Experiment.to_dict = _to_dict
Experiment.with_changes = _with_changes


def _structured(raw):
    names = list(raw["columns"]) + ["stage"]
    stages = list(raw["stages"])
    width = max([1] + [len(s) for s in stages])
    dtype = [(n, "f8") for n in raw["columns"]] + [("stage", f"U{width}")]
    out = _np.zeros(len(stages), dtype=dtype)
    values = raw["values"]
    for k, n in enumerate(raw["columns"]):
        out[n] = values[:, k]
    out["stage"] = stages
    assert list(out.dtype.names) == names
    return out


def _dataframe(raw):
    try:
        import pandas as pd
    except ImportError:
        raise ImportError("dataframe() needs pandas (Debian: python3-pandas); "
                          "series() gives the same as a NumPy structured array") from None
    frame = pd.DataFrame(raw["values"], columns=list(raw["columns"]))
    frame.insert(2 if len(frame.columns) >= 2 else 0, "stage", list(raw["stages"]))
    frame.attrs["units"] = dict(zip(raw["columns"], raw["units"]))
    frame.attrs["test"] = raw["test"]
    return frame


def _folder_series(self, test):
    """The series of `test` as a NumPy structured array: one field per column of series.csv
    (units in docs/formats.md and series_columns()), and the text field 'stage'."""
    return _structured(self.table(test))


def _folder_dataframe(self, test):
    """The series of `test` as a pandas DataFrame (needs pandas); units in .attrs['units']."""
    return _dataframe(self.table(test))


RunFolder.series = _folder_series
RunFolder.dataframe = _folder_dataframe


def _runner_series(self):
    """Every test's series so far: a dict test -> NumPy structured array (as RunFolder.series)."""
    return {raw["test"]: _structured(raw) for raw in self.tables()}


Runner.series = _runner_series


def run(experiment, out, progress=None, *, force=False, threads=0, chunk=1000):
    """Runs `experiment` into the folder `out` exactly as `grainlab run EXPERIMENT --out OUT`.

    experiment: an Experiment, a dict or the path of an experiment file.
    progress: called after every `chunk` steps with a dict (stage, kind, test, pressure, step,
    axial_strain, fraction, finished); returning False stops the run with a checkpoint, to be
    continued with resume(out). Ctrl-C does the same and raises KeyboardInterrupt.
    Returns the RunFolder. A folder that holds a run is refused (RunFolderError) unless force.
    """
    if isinstance(experiment, dict):
        experiment = Experiment.from_dict(experiment)
    elif not isinstance(experiment, Experiment):
        experiment = Experiment.load(str(experiment))
    with Runner(experiment, str(out), force=force, threads=threads) as runner:
        runner.run(progress, chunk=chunk)
    return RunFolder(str(out))


def resume(folder, progress=None, *, threads=0, chunk=1000):
    """Continues the run in `folder` from its last checkpoint, as `grainlab run --resume`.

    A finished run is left as it is. Returns the RunFolder."""
    if RunFolder(str(folder)).finished:
        return RunFolder(str(folder))
    with Runner.resume(str(folder), threads=threads) as runner:
        runner.run(progress, chunk=chunk)
    return RunFolder(str(folder))
