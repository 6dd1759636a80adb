#!/usr/bin/env bash
# resources/scripts/grainlab-setup.sh with stand-ins for the system (dpkg-query, id, apt-get,
# sudo, cmake) and for the grainlab executable, on a PATH that holds only them and a few basic
# tools: nothing is installed or built. Checks: with packages missing, a user who is neither
# root nor has sudo is told what to install and the script exits 1; root runs apt-get itself;
# another user goes through sudo; `run` without a display writes the quick run where the
# command was run, and a second `run` continues it instead of starting again.
# Usage: setup_script_test.sh <path of grainlab-setup.sh>
set -uo pipefail

script="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() {
  echo "FAILED: $*" >&2
  failures=$((failures + 1))
}

bin="$work/bin"
mkdir -p "$bin" "$work/build/app" "$work/user"
for tool in bash grep dirname nproc env cat mkdir touch; do
  ln -s "$(command -v "$tool")" "$bin/$tool"
done
# dpkg-query: every package installed unless FAKE_MISSING is set.
cat > "$bin/dpkg-query" << 'STUB'
#!/bin/bash
[[ -z "${FAKE_MISSING:-}" ]] && printf 'install ok installed'
exit 0
STUB
cat > "$bin/id" << 'STUB'
#!/bin/bash
echo "${FAKE_UID:-1000}"
STUB
cat > "$bin/apt-get" << 'STUB'
#!/bin/bash
echo "apt-get $*" >> "$FAKE_LOG"
STUB
cat > "$bin/cmake" << 'STUB'
#!/bin/bash
echo "cmake $*" >> "$FAKE_LOG"
STUB
cat > "$work/sudo" << 'STUB'
#!/bin/bash
echo "sudo $*" >> "$FAKE_LOG"
exec "$@"
STUB
# The grainlab executable: notes where it ran and with what; `run --out X` writes X/run.h5
# (only inside the test's folder).
cat > "$work/build/app/grainlab" << 'STUB'
#!/bin/bash
echo "grainlab in $PWD: $*" >> "$FAKE_LOG"
[[ "$PWD" == "$FAKE_WORK"* ]] || exit 0
args=("$@")
for ((i = 0; i < ${#args[@]}; ++i)); do
  if [[ "${args[i]}" == --out ]]; then
    mkdir -p "${args[i + 1]}" && touch "${args[i + 1]}/run.h5"
  fi
done
STUB
chmod +x "$bin"/* "$work/sudo" "$work/build/app/grainlab"

export FAKE_LOG="$work/log"
setup() { # runs the script from $work/user with the stand-ins; its stderr goes to $work/err
  (cd "$work/user" && env -i PATH="$bin" HOME="$work" FAKE_LOG="$FAKE_LOG" FAKE_WORK="$work" \
    GRAINLAB_BUILD_DIR="$work/build" "$@" "$(command -v bash)" "$script" run 2> "$work/err")
}

# Not root, no sudo, packages missing: told what to install, exit 1, nothing installed or run.
: > "$FAKE_LOG"
setup FAKE_MISSING=1 FAKE_UID=1000
status=$?
[[ $status -eq 1 ]] || fail "no root, no sudo: exit status $status, expected 1"
grep -q "apt-get install -y build-essential" "$work/err" ||
  fail "no root, no sudo: the message does not name the packages: $(cat "$work/err")"
grep -q "not root and has no sudo" "$work/err" || fail "no root, no sudo: no reason given"
[[ ! -s "$FAKE_LOG" ]] || fail "no root, no sudo: something ran: $(cat "$FAKE_LOG")"

# Root: apt-get directly, no sudo.
: > "$FAKE_LOG"
setup FAKE_MISSING=1 FAKE_UID=0 > /dev/null || fail "root: exit status $?"
grep -q "^apt-get install -y build-essential" "$FAKE_LOG" || fail "root: no apt-get install"
grep -q "^sudo" "$FAKE_LOG" && fail "root: sudo was used"
# The Python example's packages (resources/scripts/plot_run.py and its test), and pandas, which
# the snippets of docs/formats.md import (tests/scripts/doc_snippets_test.sh runs them).
grep -q "^apt-get install -y .*python3-h5py python3-matplotlib python3-numpy python3-pandas" \
  "$FAKE_LOG" || fail "root: the Python packages are not installed: $(cat "$FAKE_LOG")"
# The Python module's build and tests (pybind11, pytest, the notebook's nbconvert).
grep -q "^apt-get install -y .*python3-dev pybind11-dev python3-pytest jupyter-nbconvert" \
  "$FAKE_LOG" || fail "root: the Python module's packages are not installed: $(cat "$FAKE_LOG")"
rm -rf "$work/user/grainlab-quick"

# Another user with sudo: through sudo.
cp "$work/sudo" "$bin/sudo"
: > "$FAKE_LOG"
setup FAKE_MISSING=1 FAKE_UID=1000 > /dev/null || fail "sudo: exit status $?"
grep -q "^sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y build-essential" \
  "$FAKE_LOG" || fail "sudo: apt-get install not run through sudo: $(cat "$FAKE_LOG")"
rm -f "$bin/sudo"
rm -rf "$work/user/grainlab-quick"

# run, no display, nothing missing: the quick run is written where the command was run.
: > "$FAKE_LOG"
setup > /dev/null || fail "run: exit status $?"
grep -q "^grainlab in $work/user: run .*/resources/experiments/quick.json --out grainlab-quick$" \
  "$FAKE_LOG" || fail "run: grainlab not run in the user's folder: $(cat "$FAKE_LOG")"
[[ -e "$work/user/grainlab-quick/run.h5" ]] || fail "run: no grainlab-quick in the user's folder"
grep -q "^apt-get\|^sudo" "$FAKE_LOG" && fail "run: installed although nothing was missing"

# run again: continues the run already there.
: > "$FAKE_LOG"
setup > /dev/null || fail "second run: exit status $?"
grep -q "^grainlab in $work/user: run --resume grainlab-quick$" "$FAKE_LOG" ||
  fail "second run: not continued: $(cat "$FAKE_LOG")"

if ((failures)); then
  exit 1
fi
echo "setup script: all checks passed"
