# Sourced by the test scripts that run Python: find_python MODULE... sets `python` to the first
# python3 (Debian's /usr/bin/python3 first, then the one on PATH) that imports every MODULE, or
# exits 77 (skipped) naming the Debian packages (resources/scripts/grainlab-setup.sh installs
# them); make_work makes the script's temporary folder; must_run LOG WHAT COMMAND... runs a step
# the test cannot go on without.
find_python() {
  local candidate imports
  imports="$(IFS=,; echo "$*")"
  python=""
  for candidate in /usr/bin/python3 "$(command -v python3 || true)"; do
    if [[ -n "$candidate" && -x "$candidate" ]] &&
      "$candidate" -c "import $imports" > /dev/null 2>&1; then
      python="$candidate"
      return 0
    fi
  done
  echo "SKIPPED: no python3 with $* (Debian: $(printf 'python3-%s ' "$@")which" \
    "resources/scripts/grainlab-setup.sh installs)"
  exit 77
}

# make_work: sets `work` to a new temporary folder, removed when the script exits.
make_work() {
  work="$(mktemp -d)"
  trap 'rm -rf "$work"' EXIT
}

# must_run LOG WHAT COMMAND...: runs COMMAND with its output in LOG; when it fails, says
# "FAILED: WHAT" and the log on stderr and exits 1.
must_run() {
  local log="$1" what="$2"
  shift 2
  if ! "$@" > "$log" 2>&1; then
    echo "FAILED: $what" >&2
    cat "$log" >&2
    exit 1
  fi
}
