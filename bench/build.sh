#!/usr/bin/env bash
# Builds the benchmarks into build/bench/ (./test.sh and CI do not: they are
# off by default, DRAPE_BUILD_BENCHMARKS). Results go in docs/performance.md.
#   bench/build.sh [TARGET…]    (default: everything, benchmarks included)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
source "$root/scripts/setup.sh"
drape_install_packages
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DDRAPE_BUILD_BENCHMARKS=ON
if [ $# -gt 0 ]; then
  cmake --build "$root/build" --parallel "$(nproc 2>/dev/null || echo 2)" --target "$@"
else
  cmake --build "$root/build" --parallel "$(nproc 2>/dev/null || echo 2)"
fi
