#!/usr/bin/env bash
# The examples of docs/examples/ at a tiny size, as a user runs them, with the module of the build:
#   python_examples_test.sh BUILD_PYTHON_DIR GRAINLAB_EXE SOURCE_DIR
# the friction sweep (2 frictions x 2 seeds on 2 processes: its CSV, its figure, and peak q/p
# rising with friction), the stop on the strong fabric's reversal (its checkpoint in the run
# file), and the notebook executed by nbconvert (no error, its three figures drawn).
# Skipped (77) only without python3-numpy, python3-matplotlib, nbconvert or ipykernel.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
source "$here/find_python.sh"
find_python numpy matplotlib nbconvert ipykernel
module_dir="$1" exe="$2" source_dir="$3"
export PYTHONPATH="$module_dir${PYTHONPATH:+:$PYTHONPATH}" MPLBACKEND=Agg OMP_NUM_THREADS=1
examples="$source_dir/docs/examples"
make_work
cd "$work"
fail() { echo "FAILED: $*" >&2; exit 1; }

# A tiny experiment: one pressure, sheared to 1 %.
"$python" - "$source_dir/resources/experiments/tiny.json" <<'PY'
import sys, grainlab
grainlab.Experiment.load(sys.argv[1]).with_changes({
    "compaction": {"pressures": [15000.0]},
    "shear": {"target_axial_strain": 0.01},
    "record": {"strain_interval": 0.0005},
}).save("small.json")
PY

"$python" "$examples/friction_sweep.py" small.json --out sweep --frictions 0.1,0.5 --seeds 2 \
  --processes 2 > sweep.log || { cat sweep.log >&2; fail "friction_sweep.py"; }
cat sweep.log
[[ -s sweep/peak_q_over_p.png ]] || fail "friction_sweep.py drew no figure"
"$python" - <<'PY' || fail "friction_sweep.py: the CSV"
import csv
rows = list(csv.DictReader(open("sweep/peak_q_over_p.csv")))
assert [r["friction"] for r in rows] == ["0.1", "0.5"], rows
assert all(r["seeds"] == "2" for r in rows), rows
low, high = (float(r["peak_q_over_p_mean"]) for r in rows)
assert high > low, f"peak q/p does not rise with friction: {low} at 0.1, {high} at 0.5"
PY
# A second call reads the finished runs instead of running them again.
"$python" "$examples/friction_sweep.py" small.json --out sweep --frictions 0.1,0.5 --seeds 2 \
  --processes 2 | diff - sweep.log || fail "friction_sweep.py: a second call differs"

"$python" "$examples/stop_on_fabric_reversal.py" small.json --out reversal --tolerance 0.01 \
  > reversal.log || { cat reversal.log >&2; fail "stop_on_fabric_reversal.py"; }
cat reversal.log
"$python" - <<'PY' || fail "stop_on_fabric_reversal.py: the stop"
import json, grainlab
result = json.load(open("reversal/reversal.json"))
folder = grainlab.RunFolder("reversal")
assert result.get("axial_strain"), f"no reversal found in the tiny test: {result}"
names = [c["name"] for c in folder.checkpoints]
assert any(n.endswith("fabric-reversal") for n in names), names
assert not folder.finished
assert result["Hsdev_largest"] - result["Hsdev"] > 0.01
PY

cp "$examples/run_walkthrough.ipynb" .
# The kernel draws inline (its own backend), not through Agg.
env -u MPLBACKEND GRAINLAB_RUN="$work/sweep/mu0.50-seed1" "$python" -m nbconvert --to notebook --execute \
  --output executed.ipynb run_walkthrough.ipynb > nb.log 2>&1 || { cat nb.log >&2; fail "the notebook"; }
"$python" - <<'PY' || fail "the notebook's outputs"
import json
nb = json.load(open("executed.ipynb"))
outputs = [o for c in nb["cells"] if c["cell_type"] == "code" for o in c["outputs"]]
assert not [o for o in outputs if o["output_type"] == "error"]
images = [o for o in outputs if "image/png" in o.get("data", {})]
assert len(images) == 3, f"{len(images)} figures drawn, expected 3"
PY
echo "ok: the examples ran"
