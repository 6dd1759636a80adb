#!/usr/bin/env bash
# One entry point for a newcomer and for CI (see README.md):
#   resources/scripts/grainlab-setup.sh run    install what is missing, build, run the main job
#   resources/scripts/grainlab-setup.sh test   install what is missing, build, run every test
# Idempotent: packages already installed are not reinstalled; the build is incremental.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$here"
mode="${1:-run}"
build_dir="${GRAINLAB_BUILD_DIR:-build}"

# Debian 12 packages the project builds and tests with.
packages=(
  build-essential cmake ninja-build pkg-config
  qt6-base-dev libqt6charts6-dev libqt6opengl6-dev libqt6svg6-dev libgl-dev
  libeigen3-dev libhdf5-dev hdf5-tools nlohmann-json3-dev libcli11-dev libfmt-dev
  libgtest-dev libbenchmark-dev
  xvfb xauth libgl1-mesa-dri
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "Installing missing Debian packages: ${missing[*]}"
  sudo_cmd=()
  if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
  "${sudo_cmd[@]}" apt-get update
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y "${missing[@]}"
fi

jobs="$(nproc)"
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build "$build_dir" -j "$jobs"

case "$mode" in
  run)
    if [[ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]]; then
      exec "$build_dir/app/grainlab"
    else
      echo "No display found: running the quick experiment headless into ./grainlab-quick"
      exec "$build_dir/app/grainlab" run resources/experiments/quick.json --out grainlab-quick
    fi
    ;;
  test)
    cd "$build_dir"
    exec ctest --output-on-failure -j "$jobs" --timeout 900
    ;;
  *)
    echo "usage: $0 run|test" >&2
    exit 2
    ;;
esac
