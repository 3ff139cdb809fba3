#!/usr/bin/env bash
# The engine, reader and command-line tests (all but the workbench and the
# renderer) built with AddressSanitizer and UndefinedBehaviorSanitizer in
# build-asan/ and run through CTest. Any report fails its test: UBSan
# halts on the first, ASan aborts, LeakSanitizer fails the process at exit.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/setup.sh
drape_install_packages
jobs=$(nproc 2>/dev/null || echo 2)
drape_ccache_for "$PWD"
if [ ! -f build-asan/CMakeCache.txt ]; then
  cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDRAPE_SANITIZE=ON \
    -DDRAPE_WITH_GUI=OFF -DDRAPE_BUILD_BENCHMARKS=OFF
fi
cmake --build build-asan --parallel "$jobs"
export ASAN_OPTIONS="abort_on_error=1:detect_leaks=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizer_leaks.supp:print_suppressions=0"
cd build-asan
# The checks labelled `<label>-slow` (tests/CMakeLists.txt: files *_slow_test.cc, each
# taking tens of seconds here and minutes under the sanitizers) are left to
# ./test.sh, to keep .ci/run within its time; their code paths are those of
# tests that run here.
# The three slowest of the rest under the sanitizers (40-95 s each here) run
# in ./test.sh only: their code paths are those of lighter tests that run
# here (the other gripper drags, the block drape's other meshes).
heavy='GripperDrag.FramesFollowTheHandleNearEquilibrium|GripperDrag.ASettledDragIsTheDraggedSceneSolvedFromTheStart|ShellSolver.PointSupportedBlockDrapeSagGrowsLikeTheLogOfTheMesh'
exec ctest --output-on-failure --parallel "$jobs" -LE slow -E "$heavy" "$@"
