#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test through CTest under a
# virtual display. The exit status is CTest's. Arguments go to CTest: e.g.
# `./test.sh -L unit`, `./test.sh -LE slow` (labels: tests/CMakeLists.txt).
set -euo pipefail
cd "$(dirname "$0")"
source scripts/setup.sh
drape_setup
cd build
# Under xvfb-run a display is expected: a render or workbench test that finds
# none fails instead of being skipped (tests/support/display_required.h).
export DRAPE_EXPECT_DISPLAY=1
# -noreset: by default Xvfb resets when its last client leaves and refuses
# connections meanwhile, which failed rendering tests started in that gap.
exec xvfb-run -a -s "-screen 0 1600x1200x24 -noreset" \
  ctest --output-on-failure --parallel "$(nproc 2>/dev/null || echo 2)" "$@"
