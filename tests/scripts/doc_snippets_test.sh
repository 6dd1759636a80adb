#!/usr/bin/env bash
# The Python snippets of the user docs, run as a reader would: each ```python block of
# docs/formats.md on its own, and the blocks of docs/h5py.md and of docs/python.md each in order as
# one script (they build on each other; python.md's with the grainlab module of the build), in a folder whose out/ is a real run of a small experiment (two pressures,
# 15 and 100 kPa, as the snippets' p100kPa expects). A snippet that raises fails the test.
# Skipped (exit 77) only when no python3 with h5py, numpy, pandas and matplotlib is found
# (resources/scripts/grainlab-setup.sh installs them).
# Usage: doc_snippets_test.sh <grainlab executable> <docs folder> <experiment file> [<module dir>]
# Without a module folder (a build without the Python module) python.md's blocks are not run.
set -uo pipefail

grainlab="$1"
docs="$2"
experiment="$3"
module_dir="${4:-}"

# shellcheck source=find_python.sh
source "$(dirname "${BASH_SOURCE[0]}")/find_python.sh"
find_python h5py numpy pandas matplotlib

make_work
cd "$work" || exit 1
must_run run.log "grainlab run $experiment" "$grainlab" run "$experiment" --out out --quiet

# Writes block k of a markdown file's ```python blocks to snippet-<name>-<k>.py; prints the count.
extract() {
  awk -v prefix="$2" '
    /^```python$/ { n++; inside = 1; file = sprintf("%s-%d.py", prefix, n); next }
    /^```$/ && inside { inside = 0; close(file); next }
    inside { print > file }
    END { print n + 0 }' "$1"
}

status=0
run_snippet() {
  if ! MPLBACKEND=Agg "$python" "$1" > "$1.log" 2>&1; then
    echo "FAILED: $2" >&2
    cat "$1" >&2
    cat "$1.log" >&2
    status=1
  else
    echo "ok: $2"
  fi
}

count=$(extract "$docs/formats.md" formats)
[[ "$count" -ge 2 ]] || { echo "FAILED: $count python blocks in formats.md, expected 2 or more" >&2; exit 1; }
for ((k = 1; k <= count; k++)); do
  run_snippet "formats-$k.py" "docs/formats.md, python block $k"
done

# Blocks of a page in order, as one script: run_page PAGE PREFIX [PYTHONPATH].
run_page() {
  local page="$1" prefix="$2" count k
  count=$(extract "$docs/$page" "$prefix")
  [[ "$count" -ge 1 ]] || { echo "FAILED: no python blocks in $page" >&2; status=1; return; }
  for ((k = 1; k <= count; k++)); do
    cat "$prefix-$k.py" >> "$prefix-all.py"
  done
  PYTHONPATH="${3:-}" run_snippet "$prefix-all.py" "docs/$page, its $count python blocks in order"
}
run_page h5py.md h5py
if [[ -n "$module_dir" ]]; then
  run_page python.md python "$module_dir"
fi
exit $status
