# Sourced by the test scripts that run Python: find_python MODULE... sets `python` to the first
# python3 (Debian's /usr/bin/python3 first, then the one on PATH) that imports every MODULE, or
# exits 77 (skipped) naming the Debian packages (resources/scripts/grainlab-setup.sh installs
# them).
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
