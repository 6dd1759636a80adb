"""Shared fixtures of the Python module's tests: the module from the build folder, the tiny
experiment, and one run of it by the `grainlab` executable to compare against."""

import os
import subprocess
from pathlib import Path

import pytest

import grainlab

SOURCE = Path(os.environ.get("GRAINLAB_SOURCE_DIR", Path(__file__).resolve().parents[2]))
EXE = os.environ.get("GRAINLAB_EXE", "")


@pytest.fixture(scope="session")
def tiny_path():
    return SOURCE / "resources" / "experiments" / "tiny.json"


@pytest.fixture(scope="session")
def tiny(tiny_path):
    return grainlab.Experiment.load(str(tiny_path))


@pytest.fixture(scope="session")
def small(tiny):
    """The tiny experiment cut short: one pressure, sheared to 0.4 %, records every 0.1 %."""
    return tiny.with_changes({
        "compaction": {"pressures": [15000.0]},
        "shear": {"target_axial_strain": 0.004},
        "record": {"strain_interval": 0.001, "snapshot_strain_interval": 0.002},
    })


@pytest.fixture(scope="session")
def cli_run(small, tmp_path_factory):
    """The small experiment run by `grainlab run`, as a user would."""
    if not EXE:
        pytest.skip("GRAINLAB_EXE is not set (ctest sets it)")
    base = tmp_path_factory.mktemp("cli")
    experiment = base / "small.json"
    small.save(str(experiment))
    out = base / "run"
    subprocess.run([EXE, "run", str(experiment), "--out", str(out), "--quiet"], check=True,
                   stdout=subprocess.DEVNULL)
    return grainlab.RunFolder(str(out))
