#!/usr/bin/env bash
# Runs the method-study presets of resources/studies/ one after the other, each with the local
# pool (as many runs at once as the cores allow), into OUT/<preset>/, and writes
# OUT/wall-times.csv: each preset's runs, wall seconds, processor seconds and exit status.
#   resources/scripts/run-method-studies.sh OUT [PRESET...]
# Without presets: every preset but the tests' tiny one. Killed, it resumes with the same
# command (each study resumes; a preset already finished is only summarised again).
# GRAINLAB names the executable (default: build/app/grainlab of this repository).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
grainlab="${GRAINLAB:-$here/build/app/grainlab}"
if [[ $# -lt 1 ]]; then
  echo "usage: $0 OUT [PRESET...]" >&2
  exit 2
fi
out="$1"
shift
presets=("$@")
if [[ ${#presets[@]} -eq 0 ]]; then
  presets=(time-step loading-rate damping grain-count shape neighbour-skin threads combined)
fi
for p in "${presets[@]}"; do
  if [[ ! -f "$here/resources/studies/$p.json" ]]; then
    echo "$0: no preset $p (resources/studies/$p.json)" >&2
    exit 2
  fi
done
mkdir -p "$out"
times="$out/wall-times.csv"
[[ -f "$times" ]] || echo "preset,runs,wall_seconds,cpu_seconds,exit_status" > "$times"
failed=0
for p in "${presets[@]}"; do
  echo "== $p"
  start=$(date +%s.%N)
  # A study with failed runs (exit status 1) does not stop the others.
  status=0
  "$grainlab" study "$here/resources/studies/$p.json" --out "$out/$p" || status=$?
  [[ $status -eq 0 ]] || failed=1
  end=$(date +%s.%N)
  runs=$(find "$out/$p/runs" -name cost.json | wc -l)
  cpu=$(cat "$out/$p"/runs/*/cost.json | sed -n 's/.*"cpu_seconds": *\([0-9.e+-]*\).*/\1/p' |
    awk '{s += $1} END {printf "%.1f", s}')
  wall=$(awk -v a="$start" -v b="$end" 'BEGIN {printf "%.1f", b - a}')
  echo "$p,$runs,$wall,$cpu,$status" >> "$times"
  echo "$p: $runs runs, $wall s wall, $cpu s processor, exit status $status"
done
exit $failed
