#!/usr/bin/env bash
# The engine's pair loops run vectorised in a native build. GCC gives up on a loop silently (a
# bool ?: in the oval kernel once made every oval step run scalar, 2.9x slower, and only the bench
# showed it), so this counts the packed (ymm/zmm) instructions in the compiled pair loops of
# frictional and frictionless ovals (of one form, and through per-grain arc tables) and
# frictional disks: a vectorised loop has hundreds (430 to 920 on an AVX-512 build), a scalar
# one a few dozen.
# Usage: vectorised_loops_test.sh GRAINLAB_EXECUTABLE
set -euo pipefail
exe="$1"
if ! command -v objdump > /dev/null 2>&1; then
  echo "objdump not found: skipped"
  exit 77
fi
if ! grep -qw avx2 /proc/cpuinfo; then
  echo "this processor has no AVX2: a native build has no 256-bit vectors to count; skipped"
  exit 77
fi
listing="$(objdump -d --no-show-raw-insn -C "$exe")"
status=0
shape="grainlab::Simulation::PairShape"
# PairShape: 0 disks, 1 ovals of one form, 2 ovals through per-grain tables.
for loop in "pairForces<($shape)1, true, true>" "pairForces<($shape)1, false, false>" \
  "pairForces<($shape)2, true, true>" "pairForces<($shape)2, false, false>" \
  "pairForces<($shape)0, true, true>"; do
  packed=$(awk -v f="$loop() [clone ._omp_fn.0]>:" 'index($0, f) { on = 1; next }
    on && /^$/ { on = 0 } on' <<< "$listing" | grep -cE '%[yz]mm' || true)
  if ((packed >= 200)); then
    echo "Simulation::$loop: $packed packed instructions: vectorised"
  else
    echo "Simulation::$loop: $packed packed instructions (at least 200 expected): the pair" \
      "loop is not vectorised; see -fopt-info-vec-missed on engine/src/simulation.cpp" >&2
    status=1
  fi
done
exit "$status"
