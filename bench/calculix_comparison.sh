#!/usr/bin/env bash
# Drape against CalculiX (ccx 2.20, S4 shells with NLGEOM) on two problems,
# both engines run as whole processes, alternately, RUNS times each; prints
# median wall times, the answers, and the speed ratio.
#
#  1. Heavy cantilever, α = wbL³/EI = 32: a 20 × 1 cm strip (h = 0.5 mm,
#     E = 1 MPa, ν = 0) clamped at one end sags under its own weight. The
#     reference is the heavy elastica θ'' = −α(1 − s)cos θ, θ(0) = 0,
#     θ'(1) = 0, solved here by shooting with RK4. Equal accuracy: the tip
#     error against it is printed for each mesh; the ratio compares the
#     CalculiX mesh whose error is nearest drape's at 40 × 1 elements.
#  2. The paper's polyester block drape (resources/scenes/block-drape.json,
#     10 × 10 in, pinned at its four corners) at 20 × 20 elements: the
#     centre's sag from both engines and how far they differ.
#
#   bench/calculix_comparison.sh [-n RUNS] [DRAPE]    (default build/app/drape)
#
# Installs calculix-ccx with apt when ccx is missing. The decks and scenes are
# written into a temporary folder. Results: docs/performance.md.
set -euo pipefail

source "$(dirname "$0")/timing_lib.sh"
parse_runs 3 "$@"
set -- "${rest[@]}"
root="$(cd "$(dirname "$0")/.." && pwd)"
drape=$(realpath "${1:-$root/build/app/drape}")
if ! command -v ccx >/dev/null; then
  sudo=""
  [[ $(id -u) -ne 0 ]] && sudo=sudo
  $sudo apt-get install -y -qq --no-install-recommends calculix-ccx >/dev/null
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

seconds() { # command... → wall seconds on stdout (its own output discarded)
  local TIMEFORMAT=%3R elapsed
  # The shell's own clock: no helper process inside the timed span.
  elapsed=$({ time "$@" >/dev/null 2>&1; } 2>&1) || {
    echo "failed: $*" >&2
    exit 1
  }
  echo "$elapsed"
}

# ---- 1. heavy cantilever -----------------------------------------------------
L=0.2 B=0.01 H=5e-4 E=1e6 ALPHA=32 G=9.80665
EI=$(awk "BEGIN {print $E * $B * $H ^ 3 / 12}")
W=$(awk "BEGIN {print $ALPHA * $EI / ($B * $L ^ 3)}") # areal weight [N/m²]
RHO=$(awk "BEGIN {print $W / ($G * $H)}")

# The heavy elastica's tip (x/L, z/L) by shooting on θ'(0) ∈ [0, α/2],
# bisecting on whether θ' turns negative anywhere (heavy_elastica_test.cc).
read -r ref_x ref_z < <(awk -v a=$ALPHA 'function shoot(k,   n,h,i,s,t,d,x,z,k1,k2,k3,k4,l1,l2,l3,l4,m1,m2,m3,m4,back) {
    n = 4000; h = 1 / n; t = 0; d = k; x = 0; z = 0; back = 0
    for (i = 0; i < n; ++i) {
      s = i * h
      k1 = d;              l1 = -a * (1 - s) * cos(t)
      k2 = d + h / 2 * l1; l2 = -a * (1 - s - h / 2) * cos(t + h / 2 * k1)
      k3 = d + h / 2 * l2; l3 = -a * (1 - s - h / 2) * cos(t + h / 2 * k2)
      k4 = d + h * l3;     l4 = -a * (1 - s - h) * cos(t + h * k3)
      m1 = cos(t); m2 = cos(t + h / 2 * k1); m3 = cos(t + h / 2 * k2); m4 = cos(t + h * k3)
      x += h / 6 * (m1 + 2 * m2 + 2 * m3 + m4)
      m1 = sin(t); m2 = sin(t + h / 2 * k1); m3 = sin(t + h / 2 * k2); m4 = sin(t + h * k3)
      z -= h / 6 * (m1 + 2 * m2 + 2 * m3 + m4)
      t += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
      d += h / 6 * (l1 + 2 * l2 + 2 * l3 + l4)
      if (d < 0) back = 1
    }
    tip_x = x; tip_z = z
    return back
  }
  BEGIN { lo = 0; hi = a / 2
    for (j = 0; j < 50; ++j) { mid = (lo + hi) / 2; if (shoot(mid)) lo = mid; else hi = mid }
    shoot(hi); printf "%.8f %.8f\n", tip_x, tip_z }')

cantilever_scene() { # elements → drape scene on stdout
  cat <<EOF
{"drape_scene": 1, "name": "heavy cantilever, alpha = $ALPHA",
 "fabric": {"outline": {"rectangle": {"size": [$L, $B], "center": [$(awk "BEGIN {print $L / 2}"), 0]}},
            "mesh": {"elements": [$1, 1]}},
 "material": {"thickness": $H, "areal_weight": $W, "youngs_modulus": $E, "poisson_ratio": 0},
 "supports": [{"name": "root", "select": {"edge": "left"}, "fix": "clamp"}],
 "stages": [{"name": "weight", "kind": "gravity", "initial_increment": 0.05}],
 "solver": {"tolerance": 1e-6},
 "probes": [{"name": "tip", "at": [$L, 0]}]}
EOF
}

cantilever_deck() { # elements → CalculiX deck on stdout; tip nodes in set TIP
  awk -v nx="$1" -v L=$L -v b=$B 'BEGIN {
    print "*NODE"; n = 0
    for (j = 0; j <= 1; j++) for (i = 0; i <= nx; i++) printf "%d, %.12g, %.12g, 0\n", ++n, L * i / nx, -b / 2 + b * j
    print "*ELEMENT, TYPE=S4, ELSET=EALL"
    for (i = 1; i <= nx; i++) printf "%d, %d, %d, %d, %d\n", i, i, i + 1, i + nx + 2, i + nx + 1
    printf "*NSET, NSET=ROOT\n1, %d\n*NSET, NSET=TIP\n%d, %d\n", nx + 2, nx + 1, 2 * nx + 2 }'
  cat <<EOF
*MATERIAL, NAME=FABRIC
*ELASTIC
$E, 0
*DENSITY
$RHO
*SHELL SECTION, ELSET=EALL, MATERIAL=FABRIC
$H
*BOUNDARY
ROOT, 1, 6
*STEP, NLGEOM, INC=1000
*STATIC
0.05, 1.0, 1e-6, 0.25
*DLOAD
EALL, GRAV, $G, 0., 0., -1.
*NODE PRINT, NSET=TIP
U
*END STEP
EOF
}

# Tip error / L of a result: drape's result.json, or ccx's .dat (the tip's
# displacement at the last time, added to its reference position (L, ±b/2)).
drape_tip_error() {
  sed -n '/"final"/,$p' "$1" | tr -d '\n ' | sed 's/.*"tip":\[\([^]]*\)\].*/\1/' |
    awk -F, -v L=$L -v rx="$ref_x" -v rz="$ref_z" '{print sqrt(($1 / L - rx) ^ 2 + ($3 / L - rz) ^ 2)}'
}
ccx_tip_error() {
  awk -v L=$L -v rx="$ref_x" -v rz="$ref_z" '/displacements/ {n = 0} NF == 4 && $1 ~ /^[0-9]+$/ {ux = $2; uz = $4}
    END {print sqrt(((L + ux) / L - rx) ^ 2 + (uz / L - rz) ^ 2)}' "$1"
}

echo "Heavy cantilever, alpha = $ALPHA: elastica tip (x, z)/L = ($ref_x, $ref_z)"
echo
echo "| engine | mesh | tip error / L | median wall [s] |"
echo "|---|---|---|---|"
cantilever_scene 40 >cantilever.json
for n in 20 40 80; do cantilever_deck $n >"cant$n.inp"; done
: >t_drape
declare -A t_ccx
for ((r = 0; r < runs; ++r)); do
  seconds "$drape" run cantilever.json -o drape-cantilever -q >>t_drape
  for n in 20 40 80; do t_ccx[$n]+="$(seconds ccx -i "cant$n") "; done
done
drape_err=$(drape_tip_error drape-cantilever/result.json)
drape_t=$(median <t_drape)
printf '| drape | 40 × 1 | %.2e | %.3f |\n' "$drape_err" "$drape_t"
best_n="" best_gap=""
for n in 20 40 80; do
  err=$(ccx_tip_error "cant$n.dat")
  t=$(tr ' ' '\n' <<<"${t_ccx[$n]}" | grep . | median)
  printf '| CalculiX S4 | %d × 1 | %.2e | %.3f |\n' "$n" "$err" "$t"
  gap=$(awk "BEGIN {g = log($err / $drape_err); print g < 0 ? -g : g}")
  if [[ -z "$best_gap" ]] || awk "BEGIN {exit !($gap < $best_gap)}"; then
    best_gap=$gap best_n=$n best_t=$t best_err=$err
  fi
done
printf '\nAt the nearest accuracy (CalculiX %d × 1, tip error %.2e vs drape %.2e): CalculiX / drape = %.1f\n\n' \
  "$best_n" "$best_err" "$drape_err" "$(awk "BEGIN {print $best_t / $drape_t}")"

# ---- 2. block drape, 20 × 20 -------------------------------------------------
IN=0.0254 OZ_IN2=430.922 # oz/in² in Pa (1 ozf / in² = 0.278014 N / 6.4516e-4 m²)
SIDE=$(awk "BEGIN {print 10 * $IN}")
BH=$(awk "BEGIN {print 0.02135 * $IN}")
BE=$(awk "BEGIN {print 2688 * $OZ_IN2}")
BW=$(awk "BEGIN {print 5.425e-3 * $OZ_IN2}")
BRHO=$(awk "BEGIN {print $BW / ($G * $BH)}")
awk -v n=20 -v a="$SIDE" 'BEGIN {
  print "*NODE"; k = 0
  for (j = 0; j <= n; j++) for (i = 0; i <= n; i++) printf "%d, %.12g, %.12g, 0\n", ++k, -a / 2 + a * i / n, -a / 2 + a * j / n
  print "*ELEMENT, TYPE=S4, ELSET=EALL"; e = 0
  for (j = 0; j < n; j++) for (i = 0; i < n; i++) { p = 1 + i + (n + 1) * j; printf "%d, %d, %d, %d, %d\n", ++e, p, p + 1, p + n + 2, p + n + 1 }
  printf "*NSET, NSET=CORNERS\n1, %d, %d, %d\n", n + 1, (n + 1) * n + 1, (n + 1) * (n + 1)
  printf "*NSET, NSET=CENTRE\n%d\n", (n + 1) * (n / 2) + n / 2 + 1 }' >block.inp
cat >>block.inp <<EOF
*MATERIAL, NAME=POLYESTER
*ELASTIC
$BE, 0.3
*DENSITY
$BRHO
*SHELL SECTION, ELSET=EALL, MATERIAL=POLYESTER
$BH
*BOUNDARY
CORNERS, 1, 3
*STEP, NLGEOM, INC=1000
*STATIC
0.00025, 1.0, 1e-9, 0.25
*DLOAD
EALL, GRAV, $G, 0., 0., -1.
*NODE PRINT, NSET=CENTRE
U
*END STEP
EOF
: >t_drape && : >t_ccx
for ((r = 0; r < runs; ++r)); do
  seconds "$drape" run "$root/resources/scenes/block-drape.json" -o drape-block -q >>t_drape
  seconds ccx -i block >>t_ccx
done
drape_z=$(sed -n '/"final"/,$p' drape-block/result.json | tr -d '\n ' |
  sed 's/.*"centre":\[\([^]]*\)\].*/\1/' | cut -d, -f3)
ccx_z=$(awk 'NF == 4 && $1 ~ /^[0-9]+$/ {uz = $4} END {print uz}' block.dat)
drape_t=$(median <t_drape)
ccx_t=$(median <t_ccx)
echo "Block drape 20 × 20 (corners pinned; CalculiX pins the expanded shell's corner nodes):"
echo
echo "| engine | centre sag [mm] | median wall [s] |"
echo "|---|---|---|"
printf '| drape | %.3f | %.3f |\n' "$(awk "BEGIN {print -1000 * $drape_z}")" "$drape_t"
printf '| CalculiX S4 | %.3f | %.3f |\n' "$(awk "BEGIN {print -1000 * $ccx_z}")" "$ccx_t"
printf '\nCentres differ by %.2f %%; CalculiX / drape = %.1f\n' \
  "$(awk "BEGIN {d = ($ccx_z - $drape_z) / $drape_z; print 100 * (d < 0 ? -d : d)}")" \
  "$(awk "BEGIN {print $ccx_t / $drape_t}")"
