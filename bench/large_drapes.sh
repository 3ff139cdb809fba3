#!/usr/bin/env bash
# Whole `drape run` processes for the large drapes of issue 16: the paper's
# polyester block drape (resources/scenes/block-drape.json) and the same sheet
# with E = 5 MPa, at 100 × 100 and 200 × 200 elements, with the path on the
# scene's own mesh and with mesh sequencing (solver.sequencing 5: the path
# on a mesh 5 times coarser). Median wall time of RUNS runs and the peak
# resident memory, as a Markdown table.
#
#   bench/large_drapes.sh [-n RUNS] [DRAPE]    (default build/app/drape)
set -euo pipefail

source "$(dirname "$0")/timing_lib.sh"
parse_runs 3 "$@"
set -- "${rest[@]}"
root="$(cd "$(dirname "$0")/.." && pwd)"
drape=$(realpath "${1:-$root/build/app/drape}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT


# scene n modulus sequencing → a variant of the block drape
variant() {
  sed -e "s/\"elements\": \[20, 20\]/\"elements\": [$1, $1]/" \
    -e "s|\"youngs_modulus\": \"2688 oz/in^2\"|\"youngs_modulus\": \"$2\"|" \
    -e "s/\"acceleration\": true}/\"acceleration\": true, \"sequencing\": $3}/" \
    "$root/resources/scenes/block-drape.json"
}

echo "| sheet | elements | sequencing | steps | factorisations | median wall [s] | peak memory [MiB] |"
echo "|---|---|---|---|---|---|---|"
for n in 100 200; do
  for modulus in "2688 oz/in^2" "5 MPa"; do
    for sequencing in 1 5; do
      variant $n "$modulus" $sequencing >"$work/scene.json"
      : >"$work/times"
      peak=0
      for ((r = 0; r < runs; ++r)); do
        /usr/bin/time -f "%e %M" -o "$work/time" "$drape" run "$work/scene.json" -o "$work/out" -v \
          >"$work/report" 2>&1
        read -r seconds kib <"$work/time"
        echo "$seconds" >>"$work/times"
        peak=$((kib > peak ? kib : peak))
      done
      steps=$(awk '/^  stage .* steps  iters/ {on = 1; next} /^  time:/ {on = 0}
        on {s += $(NF - 4)} END {print s}' "$work/report")
      factorizations=$(sed -n 's/.*factorisation [0-9.]* s (\([0-9]*\),.*/\1/p' "$work/report")
      label=$([[ "$modulus" == "5 MPa" ]] && echo "E = 5 MPa" || echo "polyester (paper)")
      printf '| %s | %d × %d | %s | %s | %s | %.2f | %d |\n' "$label" $n $n \
        "$([[ $sequencing == 1 ]] && echo off || echo $sequencing)" "$steps" "$factorizations" \
        "$(median <"$work/times")" $((peak / 1024))
    done
  done
done
