#!/usr/bin/env bash
# Makes the README's quick-start pictures (docs/images/quick-start/) by the
# test that walks the quick start in the workbench
# (tests/widgets/quick_start_test.cc), under a virtual display. Run after a
# change to the workbench's look, then commit the pictures.
set -euo pipefail
cd "$(dirname "$0")/.."
out="$PWD/docs/images/quick-start"
mkdir -p "$out"
DRAPE_QUICK_START_IMAGES="$out" xvfb-run -a -s "-screen 0 1600x1200x24" \
  build/tests/widgets_tests --gtest_filter='QuickStart.*'
echo "quick_start_images.sh: pictures in $out"
