#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test through CTest under a
# virtual display. The exit status is CTest's.
set -euo pipefail
cd "$(dirname "$0")"
source scripts/setup.sh
drape_setup
cd build
exec xvfb-run -a ctest --output-on-failure --parallel "$(nproc 2>/dev/null || echo 2)" "$@"
