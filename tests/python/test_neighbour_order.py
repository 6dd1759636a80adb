"""resources/scripts/neighbour_order.py on a real run file: a generated grid numbers its grains
row by row, so neighbour pairs are about one row apart, and a short run keeps that order."""

import importlib.util
import math

import pytest

from conftest import SOURCE


def load_script():
    spec = importlib.util.spec_from_file_location(
        "neighbour_order", SOURCE / "resources" / "scripts" / "neighbour_order.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_neighbours_stay_about_one_grid_row_apart(small, cli_run):
    pytest.importorskip("h5py")
    rows = load_script().order_by_checkpoint(cli_run.run_file)
    assert len(rows) >= 3  # compaction, equilibration, shear checkpoints with neighbour pairs
    grains = small.grain_count
    # The grid of a square cell has ceil(sqrt(N)) columns (at least 3).
    columns = max(3, math.ceil(math.sqrt(grains)))
    for name, count, median, p90, _ in rows:
        assert count > grains  # every grain has neighbours, each pair counted once
        assert 1 <= median <= columns + 1, (name, median, columns)
        assert median <= p90
