#!/usr/bin/env bash
# The engine's pair loops run vectorised in a native build. GCC gives up on a loop silently (a
# bool ?: in the oval kernel once made every oval step run scalar, 2.9x slower, and only the bench
# showed it), so this counts the packed (ymm/zmm) instructions in the compiled pair loops of
# frictional and frictionless ovals (of one form, and through per-grain arc tables) and
# frictional disks: a vectorised loop has hundreds (430 to 920 on an AVX-512 build), a scalar
# one a few dozen (56 on an AVX2-only build).
# Usage: vectorised_loops_test.sh GRAINLAB_EXECUTABLE AVX512_OBJECT
# AVX512_OBJECT: engine/src/simulation.cpp compiled for x86-64-v4 (AVX-512), counted on every
# x86-64 machine. GCC 12 vectorises these loops only with AVX-512's masked operations: with AVX2
# alone (an AMD EPYC of the Zen 3 generation, for one) it reports "control flow in loop" and leaves
# them scalar whatever the tuning, so the native executable is counted only where the processor
# has AVX-512.
set -euo pipefail
exe="$1"
avx512_object="$2"
if ! command -v objdump > /dev/null 2>&1; then
  echo "objdump not found: skipped"
  exit 77
fi
status=0
shape="grainlab::Simulation::PairShape"
count_loops() { # FILE WHAT
  local listing loop packed
  listing="$(objdump -d --no-show-raw-insn -C "$1")"
  # PairShape: 0 disks, 1 ovals of one form, 2 ovals through per-grain tables.
  for loop in "pairForces<($shape)1, true, true>" "pairForces<($shape)1, false, false>" \
    "pairForces<($shape)2, true, true>" "pairForces<($shape)2, false, false>" \
    "pairForces<($shape)0, true, true>"; do
    packed=$(awk -v f="$loop() [clone ._omp_fn.0]>:" 'index($0, f) { on = 1; next }
      on && /^$/ { on = 0 } on' <<< "$listing" | grep -cE '%[yz]mm' || true)
    if ((packed >= 200)); then
      echo "$2: Simulation::$loop: $packed packed instructions: vectorised"
    else
      echo "$2: Simulation::$loop: $packed packed instructions (at least 200 expected): the" \
        "pair loop is not vectorised; see -fopt-info-vec-missed on engine/src/simulation.cpp" >&2
      status=1
    fi
  done
}
count_loops "$avx512_object" "AVX-512 build"
if grep -qw avx512f /proc/cpuinfo; then
  count_loops "$exe" "this build"
else
  echo "this processor has no AVX-512: the native build's pair loops are scalar (GCC 12)," \
    "not counted"
fi
exit "$status"
