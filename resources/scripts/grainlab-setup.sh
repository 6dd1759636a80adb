#!/usr/bin/env bash
# One entry point for a newcomer and for CI (see README.md):
#   resources/scripts/grainlab-setup.sh run    install what is missing, build, run the main job
#   resources/scripts/grainlab-setup.sh test   install what is missing, build, run every test
# Idempotent: packages already installed are not reinstalled; the build is incremental; a quick
# run already written is continued (--resume: at once when it had finished), not redone.
# Installing needs root: as root the script runs apt-get itself, otherwise through sudo; with
# neither it names the packages to install and exits with status 1.
set -euo pipefail

invoked_from="$PWD"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$here"
mode="${1:-run}"
case "$mode" in
  run | test) ;;
  *)
    echo "usage: $0 run|test" >&2
    exit 2
    ;;
esac
# The build folder: relative paths are relative to the repository.
build_dir="${GRAINLAB_BUILD_DIR:-build}"
[[ "$build_dir" == /* ]] || build_dir="$here/$build_dir"

# Debian 12 packages the project builds and tests with.
packages=(
  build-essential cmake ninja-build pkg-config
  qt6-base-dev libqt6charts6-dev libqt6opengl6-dev libqt6svg6-dev libgl-dev
  libeigen3-dev libhdf5-dev hdf5-tools nlohmann-json3-dev libcli11-dev libfmt-dev
  libgtest-dev libbenchmark-dev
  xvfb xauth libgl1-mesa-dri
  python3-h5py python3-matplotlib python3-numpy python3-pandas
  python3-dev pybind11-dev python3-pytest jupyter-nbconvert python3-ipykernel python3-vtk9
  git man-db lintian clang-format
)

if ! command -v dpkg-query > /dev/null 2>&1; then
  echo "dpkg-query not found: not a Debian system, so the packages are not checked. The build" \
    "needs: ${packages[*]} (Debian 12 names)." >&2
else
  missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2> /dev/null | grep -q "install ok installed" ||
      missing+=("$p")
  done
  if ((${#missing[@]})); then
    if [[ $(id -u) -eq 0 ]]; then
      echo "Installing missing Debian packages: ${missing[*]}"
      apt-get update
      DEBIAN_FRONTEND=noninteractive apt-get install -y "${missing[@]}"
    elif command -v sudo > /dev/null 2>&1; then
      echo "Installing missing Debian packages through sudo: ${missing[*]}"
      sudo apt-get update
      sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y "${missing[@]}"
    else
      {
        echo "These Debian packages are missing: ${missing[*]}"
        echo "Installing them needs root, and this user is not root and has no sudo. As root, run:"
        echo "  apt-get update && apt-get install -y ${missing[*]}"
        echo "then run $0 $mode again."
      } >&2
      exit 1
    fi
  fi
fi

jobs="$(nproc)"
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build "$build_dir" -j "$jobs"

case "$mode" in
  run)
    if [[ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]]; then
      exec "$build_dir/app/grainlab"
    fi
    # Headless: the quick experiment, its outputs where the command was run (not in the
    # repository).
    cd "$invoked_from"
    out="grainlab-quick"
    if [[ -e "$out/run.h5" ]]; then
      echo "No display found: continuing the quick experiment in $invoked_from/$out" \
        "(remove that folder to start it afresh)"
      exec "$build_dir/app/grainlab" run --resume "$out"
    fi
    echo "No display found: running the quick experiment headless into $invoked_from/$out"
    exec "$build_dir/app/grainlab" run "$here/resources/experiments/quick.json" --out "$out"
    ;;
  test)
    cd "$build_dir"
    exec ctest --output-on-failure -j "$jobs" --timeout 900
    ;;
esac
