#!/usr/bin/env bash
# Installs what is missing, builds, and runs the main job on the paper's strip
# fold (resources/scenes/strip-fold.json): solves it, draws its last step and
# an animation of the fold (headless, under a virtual display), then, on a
# desktop (DISPLAY set), opens the workbench on the scene and solves it there,
# ending on the folded strip.
set -euo pipefail
cd "$(dirname "$0")"
source scripts/setup.sh
drape_setup
drape=build/app/drape
out=results/strip-fold
"$drape" run resources/scenes/strip-fold.json -o "$out"
xvfb-run -a "$drape" render "$out" -o "$out/fold.png" --field curvature
xvfb-run -a "$drape" animate "$out" -o "$out/fold.mp4"
echo "run.sh: the strip fold is solved; results in $out/ (result.json, states.bin, steps.csv, fold.png, fold.mp4)"
if [ -n "${DISPLAY:-}" ] && [ -x build/app/drape-studio ]; then
  exec build/app/drape-studio resources/scenes/strip-fold.json --run
fi
