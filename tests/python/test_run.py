"""Runs driven from Python: the same run folder, bit for bit, as `grainlab run`."""

import numpy as np
import pytest

import grainlab


def same_series(a, b):
    assert a.tests == b.tests
    for test in a.tests:
        sa, sb = a.series(test), b.series(test)
        assert sa.dtype == sb.dtype
        for name in sa.dtype.names:
            assert np.array_equal(sa[name], sb[name]), (test, name)


def final_state(folder):
    last = [c for c in folder.checkpoints if not c["peak"]][-1]
    return folder.simulation(checkpoint=last["name"])


def test_python_run_equals_the_command_line(small, cli_run, tmp_path):
    seen = []
    folder = grainlab.run(small, tmp_path / "py", progress=seen.append, chunk=777)
    assert folder.finished
    same_series(folder, cli_run)
    assert final_state(folder).identical(final_state(cli_run))
    # The progress callback saw every stage, in order, with a fraction that never falls.
    fractions = [p["fraction"] for p in seen]
    assert fractions == sorted(fractions)
    assert seen[-1]["finished"] and seen[-1]["fraction"] == pytest.approx(1.0)
    kinds = [p["kind"] for p in seen]
    assert kinds.index("compaction") < kinds.index("shear")
    assert (tmp_path / "py" / "p015kPa" / "series.csv").read_bytes() == \
        (__import__("pathlib").Path(cli_run.path) / "p015kPa" / "series.csv").read_bytes()


def test_a_stopped_run_resumes_to_the_same_bits(small, cli_run, tmp_path):
    out = tmp_path / "stopped"
    folder = grainlab.run(small, out, progress=lambda p: p["kind"] != "shear", chunk=500)
    assert not folder.finished
    assert folder.checkpoints[-1]["name"].endswith("interrupted")
    folder = grainlab.resume(out)
    assert folder.finished
    same_series(folder, cli_run)
    assert final_state(folder).identical(final_state(cli_run))


def test_run_folders_are_not_overwritten(small, cli_run, tmp_path):
    with pytest.raises(grainlab.RunFolderError, match="already holds a run"):
        grainlab.Runner(small, cli_run.path)
    with pytest.raises(grainlab.RunFolderError, match="no run file"):
        grainlab.Runner.resume(str(tmp_path / "nothing"))
    with pytest.raises(grainlab.GrainLabError, match="not a run folder"):
        grainlab.RunFolder(str(tmp_path))


def test_runner_measures_equal_the_recorded_rows(small):
    """At every record, Runner.measures() holds the row just recorded, bit for bit: the same
    code computes both (DI included, from the record before)."""
    runner = grainlab.Runner(small)
    compared = 0
    counts = {}
    more = True
    while more:
        more = runner.advance(1)
        now = runner.row_counts
        test = runner.progress["test"]
        if now.get(test, 0) > counts.get(test, 0):
            raw = [t for t in runner.tables() if t["test"] == test][0]
            row = raw["values"][-1]
            assert row[raw["columns"].index("step")] == runner.progress["step"]
            measured = runner.measures()
            for k, name in enumerate(raw["columns"]):
                assert measured[name] == row[k], name
            compared += 1
        counts = now
    # Every record but those a stage change leaves in the previous test at the same step.
    assert compared >= 0.9 * sum(counts.values()), (compared, counts)
    shear = runner.series()["p015kPa"]
    assert np.count_nonzero(shear["DI"]) > 2  # the dilatancy index was compared too


def test_in_memory_runner_writes_nothing(small, tmp_path):
    runner = grainlab.Runner(small)
    runner.advance(100)
    assert runner.folder == ""
    # Its time went into stepping (and the first record); no checkpoint was written.
    times = runner.times
    assert set(times) == {"stepping", "records", "checkpoints", "events"}
    assert times["stepping"] > 0 and times["records"] > 0
    assert times["checkpoints"] == 0
    with pytest.raises(grainlab.GrainLabError, match="in memory"):
        runner.checkpoint("x")
    with pytest.raises(ValueError):
        runner.advance(-1)
