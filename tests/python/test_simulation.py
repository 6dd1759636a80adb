"""The engine stepped from Python: the same bits as the runner, NumPy views of its state, its
measures equal to the recorded rows, and no input that crashes the interpreter."""

import random
import threading
from pathlib import Path

import numpy as np
import pytest

import grainlab

# Columns that do not depend on where the strains count from or on the records before.
HISTORY = {"eps1", "eps2", "epsv", "DI", "Nv_over_Nvi"}


def shear_checkpoint(folder):
    return [c for c in folder.checkpoints if c["kind"] == "shear" and not c["peak"]][-1]


def test_steps_in_chunks_give_the_same_bits(cli_run):
    name = shear_checkpoint(cli_run)["name"]
    one, chunks = cli_run.simulation(checkpoint=name), cli_run.simulation(checkpoint=name)
    one.step(1500)
    for n in (1, 7, 0, 250, 492, 750):
        chunks.step(n)
        chunks.measures()  # reading measures between chunks changes nothing
        chunks.contacts()
    assert chunks.step_count == one.step_count
    assert chunks.identical(one)


def test_views_are_the_checkpoint_and_follow_the_steps(cli_run):
    h5py = pytest.importorskip("h5py")
    info = shear_checkpoint(cli_run)
    sim = cli_run.simulation(checkpoint=info["name"])
    with h5py.File(cli_run.run_file, "r") as f:
        group = f["checkpoints/" + info["name"].replace("/", "_")]
        for name in ("x1", "x2", "theta", "v1", "v2", "omega", "shape"):
            assert np.array_equal(getattr(sim, name), group["grains/" + name][:]), name
    x1 = sim.x1
    assert not x1.flags.writeable
    with pytest.raises(ValueError):
        x1[0] = 1.0
    before = x1.copy()
    sim.step(200)
    assert not np.array_equal(x1, before)             # the view shows the new state ...
    assert np.array_equal(x1, sim.positions[:, 0])    # ... exactly
    del sim                                           # the view keeps the engine alive
    assert np.isfinite(x1).all()


def test_measures_equal_the_row_of_the_checkpoint(cli_run):
    info = shear_checkpoint(cli_run)
    sim = cli_run.simulation(checkpoint=info["name"])
    series = cli_run.series(info["test"])
    row = series[series["step"] == info["step"]]
    assert len(row) == 1
    measured = sim.measures()
    names = [n for n in series.dtype.names if n not in HISTORY and n != "stage"]
    assert len(names) > 40
    for name in names:
        assert measured[name] == row[name][0], name
    # The stored contacts are the engine's, forces to the bit.
    stored, live = cli_run.contacts(info["name"]), sim.contacts()
    assert np.array_equal(stored["first"], live["first"])
    assert np.array_equal(stored["normal_force"], live["normal_force"])
    assert np.array_equal(stored["tangential_force"], live["tangential_force"])
    assert np.array_equal(stored["sliding"].astype(bool), live["sliding"])
    cells = sim.void_cells()
    assert len(cells["valence"]) == measured["Nv"]
    assert cells["valence"].mean() == pytest.approx(measured["valence_mean"], rel=1e-12)


def test_two_threads_give_the_bits_of_one(cli_run):
    name = shear_checkpoint(cli_run)["name"]
    a, b = cli_run.simulation(checkpoint=name), cli_run.simulation(checkpoint=name)
    threads = [threading.Thread(target=s.step, args=(2000,)) for s in (a, b)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    alone = cli_run.simulation(checkpoint=name)
    alone.step(2000)
    assert a.identical(alone) and b.identical(alone)


def test_a_sample_and_the_generated_assembly(cli_run, small):
    sample = cli_run.simulation(sample=15000.0)
    assert sample.grain_count == 150
    generated = grainlab.Simulation.from_experiment(small)
    assert generated.step_count == 0 and len(generated.contacts()["first"]) == 0
    assert generated.widths.min() >= 0.001 - 1e-15 and generated.widths.max() <= 0.002 + 1e-15
    with pytest.raises(ValueError, match="one of"):
        cli_run.simulation()
    with pytest.raises(grainlab.GrainLabError):
        cli_run.simulation(checkpoint="no-such-checkpoint")


def test_bad_input_raises_and_a_failed_simulation_refuses(small):
    sim = grainlab.Simulation.from_experiment(small)
    with pytest.raises(ValueError):
        sim.step(-1)
    with pytest.raises(TypeError):
        sim.step("ten")
    with pytest.raises(ValueError, match="axis"):
        sim.set_axis(3, "strain")
    with pytest.raises(ValueError, match="mode"):
        sim.set_axis(1, "sideways")
    with pytest.raises(ValueError, match="friction"):
        sim.set_friction(-0.1)
    with pytest.raises(ValueError, match="constant_area|axis"):
        sim.set_axis(1, "constant_area", area=1.0)
    # Compressed far faster than any servo allows, the grains overlap: a blow-up.
    sim.set_axis(1, "strain", rate=2e4)
    sim.set_axis(2, "strain", rate=2e4)
    with pytest.raises(grainlab.SimulationError):
        sim.step(200000)
    assert sim.failure
    with pytest.raises(grainlab.GrainLabError, match="failed"):
        sim.step(1)


def test_garbage_calls_do_not_crash_the_interpreter(small):
    sim = grainlab.Simulation.from_experiment(small)
    rng = random.Random(1)
    junk = [None, -1, 0, 1e308, float("nan"), "x", [1, 2], {"a": 1}, object(), -10**30, 3]
    calls = [sim.step, sim.set_friction, sim.axis, sim.set_axis, grainlab.RunFolder,
             grainlab.Experiment.load, grainlab.Experiment.from_dict, grainlab.Runner,
             sim.identical]
    raised = 0
    for _ in range(40):
        call = rng.choice(calls)
        args = [rng.choice(junk) for _ in range(rng.randint(0, 3))]
        try:
            call(*args)
        except (TypeError, ValueError, grainlab.GrainLabError):
            raised += 1
    assert raised >= 30
    assert sim.grain_count == 150  # still usable


def test_velocities_set_from_arrays(cli_run):
    name = shear_checkpoint(cli_run)["name"]
    sim, same = cli_run.simulation(checkpoint=name), cli_run.simulation(checkpoint=name)
    n = sim.grain_count
    v1 = sim.v1                                        # a view, which must follow the change
    sim.set_velocities(sim.velocities, sim.omega.copy())  # the same values: the same bits
    sim.step(300)
    same.step(300)
    assert sim.identical(same)
    sim.set_velocities(np.zeros((n, 2)), np.zeros(n, dtype=np.int64))
    same.clear_velocities()
    assert sim.identical(same)
    assert not v1.any()
    bad = [
        (np.zeros((n, 3)), None, ValueError, r"\(150, 2\)"),
        (np.zeros((n - 1, 2)), None, ValueError, "one row per grain"),
        (np.zeros(2 * n), None, ValueError, "must be"),
        (np.full((n, 2), "x"), None, TypeError, "dtype"),
        (np.zeros((n, 2), dtype=object), None, TypeError, "dtype"),
        (np.zeros((n, 2), dtype=complex), None, TypeError, "dtype"),
        (np.full((n, 2), np.nan), None, ValueError, "finite"),
        (None, np.zeros(n + 1), ValueError, "one value per grain"),
        (None, [[1.0]], ValueError, "must be"),
        (None, "spin", TypeError, "dtype"),
    ]
    before = sim.velocities
    for velocities, omega, error, message in bad:
        with pytest.raises(error, match=message):
            sim.set_velocities(velocities, omega)
    assert np.array_equal(sim.velocities, before)      # a refusal changes nothing
