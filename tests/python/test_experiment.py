"""Experiments from files and dicts: the same validation as the command line."""

import json
import subprocess

import pytest

import grainlab
from conftest import EXE


def test_load_reads_the_file(tiny, tiny_path):
    assert tiny.name == "tiny"
    assert tiny.grain_count == 150
    assert tiny.seed == 2026
    assert tiny.compaction_pressures == [15000.0, 100000.0]
    assert tiny.tests == ["drained"]
    assert json.loads(tiny.text) == json.loads(tiny_path.read_text())


def test_dict_round_trip_and_changes(tiny):
    d = tiny.to_dict()
    again = grainlab.Experiment.from_dict(d)
    assert again.to_dict() == d
    changed = tiny.with_changes({"shear": {"friction": 0.3}, "seed": 7})
    assert changed.seed == 7
    assert changed.to_dict()["shear"]["friction"] == 0.3
    assert changed.to_dict()["shear"]["target_axial_strain"] == 0.02  # the rest kept
    assert tiny.to_dict()["shear"]["friction"] == 0.5  # the original unchanged


def test_save_refuses_to_overwrite(tiny, tmp_path):
    path = tmp_path / "e.json"
    tiny.save(str(path))
    assert grainlab.Experiment.load(str(path)).to_dict() == tiny.to_dict()
    path.write_text("keep")
    with pytest.raises(grainlab.GrainLabError, match="exists"):
        tiny.save(str(path))
    assert path.read_text() == "keep"
    tiny.save(str(path), overwrite=True)
    assert grainlab.Experiment.load(str(path)).seed == tiny.seed


# Each wrong experiment and the key its error must name.
BAD = [
    ({"grains": {"count": -5}}, "grains.count"),
    ({"grains": {"aspect_ratio": 1.5}}, "grains.aspect_ratio"),
    ({"time_step": -1e-6}, "time_step"),
    ({"shear": {"friction": "high"}}, "shear.friction"),
    ({"compaction": {"pressures": []}}, "compaction.pressures"),
    ({"damping": {"kind": "magic"}}, "damping.kind"),
    ({"shear": {"axial_strain_per_step": 1.0}}, "shear.axial_strain_per_step"),
    ({"no_such_key": 1}, "no_such_key"),
    ({"record": {"strain_interval": 0}}, "record.strain_interval"),
    ({"test": {"kind": "sideways"}}, "test.kind"),
]


@pytest.mark.parametrize("change,key", BAD)
def test_bad_experiments_name_their_key(tiny, change, key):
    with pytest.raises(grainlab.ExperimentError) as caught:
        tiny.with_changes(change)
    assert key in str(caught.value)
    assert isinstance(caught.value, ValueError)


def test_bad_files_and_types(tmp_path):
    with pytest.raises(grainlab.ExperimentError, match="missing.json"):
        grainlab.Experiment.load(str(tmp_path / "missing.json"))
    (tmp_path / "broken.json").write_text("{ not json")
    with pytest.raises(grainlab.ExperimentError, match="broken.json"):
        grainlab.Experiment.load(str(tmp_path / "broken.json"))
    with pytest.raises(grainlab.ExperimentError):
        grainlab.Experiment.from_dict([1, 2, 3])
    with pytest.raises(grainlab.ExperimentError):
        grainlab.Experiment.from_dict({"time_step": float("nan")})
    with pytest.raises(TypeError):
        grainlab.Experiment.load(42)


def test_version_and_commit_are_the_executables():
    assert grainlab.__version__ and grainlab.__commit__
    if not EXE:
        pytest.skip("GRAINLAB_EXE is not set (ctest sets it)")
    printed = subprocess.run([EXE, "--version"], check=True, capture_output=True,
                             text=True).stdout.strip()
    assert printed == f"GrainLab {grainlab.__version__} (commit {grainlab.__commit__})"
