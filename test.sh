#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test through CTest under a
# virtual display. The exit status is CTest's.
set -euo pipefail
cd "$(dirname "$0")"
source scripts/setup.sh
drape_setup
cd build
# -noreset: by default Xvfb resets when its last client leaves and refuses
# connections meanwhile, which failed rendering tests started in that gap.
exec xvfb-run -a -s "-screen 0 1600x1200x24 -noreset" \
  ctest --output-on-failure --parallel "$(nproc 2>/dev/null || echo 2)" "$@"
