#!/usr/bin/env bash
# Set-up shared by ./run.sh and ./test.sh: installs what is missing (Debian
# bookworm, apt), configures and builds into build/. Idempotent.
#
# Every package the project needs is in DRAPE_PACKAGES, here and nowhere else.
set -euo pipefail

DRAPE_PACKAGES=(
  # build
  g++ cmake ninja-build ccache pkg-config
  # engine
  libeigen3-dev libsuitesparse-dev libopenblas-pthread-dev libgmsh-dev libspectra-dev
  nlohmann-json3-dev libcli11-dev
  # measurement: the shadow of a drape is a polygon union (Clipper)
  libpolyclipping-dev
  # pattern pieces from apparel CAD (AAMA DXF), and the independent DXF
  # writer the reader's tests check it against
  libdxflib-dev python3-ezdxf
  # plans: the derivative-free searches for a fold path (NLopt's BOBYQA, COBYLA)
  libnlopt-cxx-dev
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev
  # rendering (ui/render): VTK through X; ffmpeg encodes MP4/GIF (and its
  # ffprobe checks them in the tests)
  libvtk9-dev libx11-dev ffmpeg
  # the workbench (ui/widgets): Qt 6 widgets and OpenGL widgets
  qt6-base-dev libqt6opengl6-dev qt6-charts-dev libgl-dev
  # headless display for render and GUI tests
  xvfb xauth
  # drape study --emit parallel is tested by running its list
  parallel
)

drape_missing_packages() {
  local missing=()
  for p in "${DRAPE_PACKAGES[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$p")
    fi
  done
  echo "${missing[@]:-}"
}

drape_install_packages() {
  local missing
  missing=$(drape_missing_packages)
  if [ -z "$missing" ]; then
    echo "setup: all ${#DRAPE_PACKAGES[@]} packages present"
    return
  fi
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null; then
      sudo="sudo"
    else
      echo "setup: missing packages ($missing) and not root, no sudo: install them and retry" >&2
      exit 1
    fi
  fi
  echo "setup: installing $missing"
  $sudo apt-get update -qq
  # shellcheck disable=SC2086
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends $missing
}

# ccache keys on paths relative to the checkout, so a fresh clone elsewhere
# (CI's) reuses what an earlier build of the same sources compiled; without
# hashing the build folder, the sanitizer build's debug info does not stop it.
drape_ccache_for() {
  export CCACHE_BASEDIR="$1"
  export CCACHE_NOHASHDIR=1
}

drape_build() {
  local root
  root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
  drape_ccache_for "$root"
  local jobs
  jobs=$(nproc 2>/dev/null || echo 2)
  if [ ! -f "$root/build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release
  fi
  cmake --build "$root/build" --parallel "$jobs"
}

drape_setup() {
  drape_install_packages
  drape_build
}
