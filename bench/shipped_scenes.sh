#!/usr/bin/env bash
# Whole `drape run` processes for every shipped scene: steps, Newton
# iterations, factorisations and the median wall time of N runs, as a
# Markdown table. With a second binary, both run alternately (the machine's
# noise hits both alike) and the table shows before, after and their ratio.
# With --self-contact-off instead, the baseline is the same binary on each
# scene with "contact": {"self": false}: what self-contact costs.
#
#   bench/shipped_scenes.sh [-n RUNS] DRAPE [BASELINE_DRAPE | --self-contact-off]
#
# e.g. bench/shipped_scenes.sh -n 5 build/app/drape /tmp/drape-before
set -euo pipefail

source "$(dirname "$0")/timing_lib.sh"
parse_runs 5 "$@"
set -- "${rest[@]}"
after=${1:?usage: bench/shipped_scenes.sh [-n RUNS] DRAPE [BASELINE_DRAPE | --self-contact-off]}
before=${2:-}
root="$(cd "$(dirname "$0")/.." && pwd)"
scenes_dir="$root/resources/scenes"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The baseline's scene for each scene: itself, or (--self-contact-off) a copy
# with self-contact off, in a copy of resources/ so relative paths still hold.
baseline_scene() { echo "$1"; }
if [[ "$before" == "--self-contact-off" ]]; then
  before=$after
  cp -r "$root/resources" "$work/"
  for scene in "$work"/resources/scenes/*.json; do
    if grep -q '"contact": {' "$scene"; then
      sed -i 's/"contact": {/"contact": {"self": false, /' "$scene"
    else
      sed -i '0,/{/s//{"contact": {"self": false},/' "$scene"
    fi
  done
  baseline_scene() { echo "$work/resources/scenes/$(basename "$1")"; }
fi


# One run: prints "seconds steps iterations factorisations".
run_once() {
  local drape=$1 scene=$2 out=$3 t0 t1 report
  t0=$(date +%s.%N)
  report=$("$drape" run "$scene" -o "$out" -v 2>&1) || true
  t1=$(date +%s.%N)
  local steps iterations factorizations
  # The report's stage table: steps and iterations in the 4th- and 3rd-last
  # columns but three (a stage's name may hold spaces).
  read -r steps iterations < <(awk '/^  stage .* steps  iters/ {on = 1; next}
    /^  time:/ {on = 0} on {s += $(NF - 4); i += $(NF - 3)} END {print s, i}' <<<"$report")
  factorizations=$(sed -n 's/.*factorisation [0-9.]* s (\([0-9]*\),.*/\1/p' <<<"$report" | head -1)
  echo "$(awk "BEGIN {print $t1 - $t0}") ${steps:-?} ${iterations:-?} ${factorizations:-?}"
}

if [[ -n "$before" ]]; then
  echo "| scene | steps | iterations | factorisations | before [s] | after [s] | after / before |"
  echo "|---|---|---|---|---|---|---|"
else
  echo "| scene | steps | iterations | factorisations | time [s] |"
  echo "|---|---|---|---|---|"
fi
for scene in "$scenes_dir"/*.json; do
  name=$(basename "$scene" .json)
  : >"$work/a" && : >"$work/b"
  for ((i = 0; i < runs; ++i)); do
    run_once "$after" "$scene" "$work/out-a" >>"$work/a"
    [[ -n "$before" ]] && run_once "$before" "$(baseline_scene "$scene")" "$work/out-b" >>"$work/b"
  done
  read -r _ steps iterations factorizations < <(tail -1 "$work/a")
  t_after=$(cut -d' ' -f1 "$work/a" | median)
  if [[ -n "$before" ]]; then
    read -r _ steps_b iterations_b factorizations_b < <(tail -1 "$work/b")
    t_before=$(cut -d' ' -f1 "$work/b" | median)
    printf '| %s | %s → %s | %s → %s | %s → %s | %.3f | %.3f | %.2f |\n' "$name" \
      "$steps_b" "$steps" "$iterations_b" "$iterations" "$factorizations_b" "$factorizations" \
      "$t_before" "$t_after" "$(awk "BEGIN {print $t_after / $t_before}")"
  else
    printf '| %s | %s | %s | %s | %.3f |\n' "$name" "$steps" "$iterations" "$factorizations" \
      "$t_after"
  fi
done
