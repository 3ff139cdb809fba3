#!/usr/bin/env bash
# Whole `drape drag` processes: the frame rate the command reports (its
# frames' own time, the scene's run and the release excluded) and the wall
# time of the whole process, median of N runs, as a Markdown table.
#
#   bench/drag.sh [-n RUNS] DRAPE
set -euo pipefail

source "$(dirname "$0")/timing_lib.sh"
parse_runs 3 "$@"
set -- "${rest[@]}"
drape=${1:?usage: bench/drag.sh [-n RUNS] DRAPE}
root="$(cd "$(dirname "$0")/.." && pwd)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cases=(
  "tests/data/corner-lift-20x20.json corner 0,0,3cm"
  "resources/scenes/diagonal-fold.json corner 0,0,2cm"
)
echo "| scene | threads | frames/s (median) | whole process [s] (median) |"
echo "|---|---|---|---|"
for c in "${cases[@]}"; do
  read -r scene gripper by <<<"$c"
  for threads in 1 2; do
    rates=() walls=()
    for ((i = 0; i < runs; i++)); do
      start=$(date +%s.%N)
      out=$("$drape" drag "$root/$scene" --gripper "$gripper" --by "${by/cm/ cm}" --frames 40 \
        --threads "$threads" -o "$work/out" 2>&1)
      end=$(date +%s.%N)
      rates+=("$(sed -n 's/.*(\([0-9.]*\) Hz).*/\1/p' <<<"$out")")
      walls+=("$(echo "$end - $start" | bc -l)")
    done
    rate=$(printf '%s\n' "${rates[@]}" | median)
    wall=$(printf '%s\n' "${walls[@]}" | median)
    printf '| %s | %d | %.1f | %.2f |\n' "$(basename "$scene" .json)" "$threads" "$rate" "$wall"
  done
done
