#!/usr/bin/env bash
# The Python module's tests (tests/python, pytest) against the module in the build folder:
#   python_module_test.sh BUILD_PYTHON_DIR GRAINLAB_EXE SOURCE_DIR [pytest arguments...]
# Skipped (77) only without python3-numpy or python3-pytest.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
source "$here/find_python.sh"
find_python numpy pytest
module_dir="$1" exe="$2" source_dir="$3"
shift 3
export PYTHONPATH="$module_dir${PYTHONPATH:+:$PYTHONPATH}"
export GRAINLAB_EXE="$exe" GRAINLAB_SOURCE_DIR="$source_dir"
# A single engine thread per simulation: ctest runs tests side by side on few cores.
export OMP_NUM_THREADS="${OMP_NUM_THREADS:-1}"
make_work
cd "$work"
exec "$python" -m pytest -q -p no:cacheprovider --basetemp="$work/tmp" \
  "$source_dir/tests/python" "$@"
