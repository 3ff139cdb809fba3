#!/usr/bin/env bash
# Installs what is missing, builds, and runs the main job on the paper's strip
# fold (resources/scenes/strip-fold.json), headless, writing results/.
set -euo pipefail
cd "$(dirname "$0")"
source scripts/setup.sh
drape_setup
drape=build/app/drape
"$drape" run resources/scenes/strip-fold.json -o results/strip-fold
echo "run.sh: the strip fold is solved; results in results/strip-fold/ (result.json, states.bin, steps.csv)"
