#!/usr/bin/env bash
# Regenerates the figures of Roh & Yoo (2007) that Tribo reproduces, from sweeps of the belt
# scene, into docs/figures/ (PNG, gnuplot). One command per figure, or all of them:
#   scripts/figures/figures.sh                 # every figure
#   scripts/figures/figures.sh fig6 fig10      # some
#   scripts/figures/figures.sh fig11c fig12c   # Figs. 11-12 from branches of periodic orbits
# Sweeps go to out/figures/<fig>/ and resume when run again, so re-plotting is cheap.
# Environment: TRIBO (default build/apps/tribo), OUT (default out/figures), FIGURES (default
# docs/figures), LAUNCH (a prefix for the contour-map sweeps, e.g. "mpirun -n 2").
# Settings (docs/paper-reproduction.md says why): RK4 at 4 ms, every contour-map point run
# until its limit cycle settles (amplitude of the last 3 cycles within 0.1% of the 3
# before), capped at 3000 s; histories at 4 ms over a fixed window, sampled every 20 ms.
set -euo pipefail
cd "$(dirname "$0")/../.."
HERE=scripts/figures
TRIBO=${TRIBO:-build/apps/tribo}
OUT=${OUT:-out/figures}
FIGURES=${FIGURES:-docs/figures}
LAUNCH=${LAUNCH:-}
SCENE=scenes/belt.yaml
command -v gnuplot >/dev/null || { echo "figures: gnuplot not found (Debian: gnuplot-nox)" >&2; exit 1; }
[ -x "$TRIBO" ] || { echo "figures: no tribo at $TRIBO (build it, or set TRIBO)" >&2; exit 1; }
mkdir -p "$OUT" "$FIGURES"

STEP=(--set dt=0.004 --set output_interval=0.004)
SETTLE=(--set duration=3000 --settle 1e-3)
HISTORY=(--set dt=0.004 --set output_interval=0.02 --keep-trajectories)

# k values giving omega_n = sqrt(k/m) evenly from W0 to W1 in N steps (m = 10 kg).
omega_k() { awk -v a="$1" -v b="$2" -v n="$3" 'BEGIN{for(i=0;i<n;i++){w=a+i*(b-a)/(n-1);
  printf "%s%.10g", (i?",":""), 10*w*w}}'; }

sweep() {  # NAME ARGS...: one sweep into $OUT/NAME, timed
  local name=$1; shift
  local t0=$SECONDS
  $TRIBO sweep $SCENE --out "$OUT/$name" --quiet "$@" >"$OUT/$name.log"
  echo "figures: sweep $name: $(grep -E '^(points|wall time)' "$OUT/$name.log" | tr -s ' ' | paste -sd';')"
}

history() {  # FIG TITLE LABEL_COLUMNS...: stacked displacement histories of a sweep's points
  local fig=$1 title=$2; shift 2
  bash $HERE/history_data.sh "$OUT/$fig" "$@" >"$OUT/$fig.list"
  gnuplot -e "list='$OUT/$fig.list'; out='$FIGURES/$fig.png'; ttl='$title'" $HERE/history.gp
  echo "figures: $FIGURES/$fig.png"
}

contour() {  # FIG XCOL XEXPR XLABEL YCOL YEXPR YLABEL TITLE
  local fig=$1
  bash $HERE/contour_data.sh "$OUT/$fig/results.csv" "$2" "$3" "$5" "$6" amplitude_pp >"$OUT/$fig.dat"
  gnuplot -e "data='$OUT/$fig.dat'; out='$FIGURES/$fig.png'; xl='$4'; yl='$7'; ttl='$8'" \
    $HERE/contour.gp
  echo "figures: $FIGURES/$fig.png"
}

fig4() {
  sweep fig4 --list friction=roh_yoo,recurdyn --set duration=60 "${HISTORY[@]}"
  history fig4 "Fig. 4: proposed law against the RecurDyn law (Table 1)" friction
}
fig5() {
  sweep fig5 --list a=1.3,1.5,1.9,2.5,3.5 --set duration=40 "${HISTORY[@]}"
  history fig5 "Fig. 5: decay base a (v_b = 1.5 m/s)" a
}
fig6() {
  sweep fig6 --grid a=1.1:4:59 "${STEP[@]}" "${SETTLE[@]}"
  gnuplot -e "data='$OUT/fig6/results.csv'; out='$FIGURES/fig6.png'" $HERE/fig6.gp
  echo "figures: $FIGURES/fig6.png"
}
fig7() {
  sweep fig7 --list v_b=1,2,3,4,5 --set duration=200 "${HISTORY[@]}"
  history fig7 "Fig. 7: belt speed v_b [m/s]" v_b
}
fig8() {
  sweep fig8a --list mu_s=0.33,0.35,0.4,0.45 --set duration=40 "${HISTORY[@]}"
  history fig8a "Fig. 8a: mu_s (mu_k = 0.3)" mu_s
  sweep fig8b --list mu_k=0.2,0.25,0.3,0.32 --set duration=40 "${HISTORY[@]}"
  history fig8b "Fig. 8b: mu_k (mu_s = 0.35)" mu_k
  sweep fig8c --list mu_s=0.35,0.4,0.45 --list mu_k=0.3,0.35,0.4 --set duration=40 "${HISTORY[@]}"
  WHERE='v("mu_s") - v("mu_k") > 0.049 && v("mu_s") - v("mu_k") < 0.051' \
    history fig8c "Fig. 8c: equal mu_s - mu_k = 0.05" mu_s mu_k
}
fig9() {
  sweep fig9 --list k=40,90,160,300,640,1000 --set duration=60 "${HISTORY[@]}"
  history fig9 "Fig. 9: natural frequency (k = 10 omega_n^2)" k
}
fig10() {
  TRIBO="${LAUNCH:+$LAUNCH }$TRIBO" sweep fig10 --grid v_b=0.5:5:20 --grid mu_s=0.31:0.5:20 "${STEP[@]}" "${SETTLE[@]}"
  contour fig10 v_b '$1' "belt speed v_b [m/s]" mu_s '$1-0.3' "mu_s - mu_k" \
    "Fig. 10: limit-cycle amplitude p-p [m] (omega_n = 5.48 rad/s)"
}
fig11() {
  TRIBO="${LAUNCH:+$LAUNCH }$TRIBO" sweep fig11 --grid v_b=0.5:5:20 --list k="$(omega_k 1 10 20)" "${STEP[@]}" "${SETTLE[@]}"
  contour fig11 v_b '$1' "belt speed v_b [m/s]" k 'sqrt($1/10)' "omega_n [rad/s]" \
    "Fig. 11: limit-cycle amplitude p-p [m] (mu_s - mu_k = 0.05)"
}
fig12() {
  TRIBO="${LAUNCH:+$LAUNCH }$TRIBO" sweep fig12 --list k="$(omega_k 1 10 20)" --grid mu_s=0.31:0.5:20 "${STEP[@]}" "${SETTLE[@]}"
  contour fig12 k 'sqrt($1/10)' "omega_n [rad/s]" mu_s '$1-0.3' "mu_s - mu_k" \
    "Fig. 12: limit-cycle amplitude p-p [m] (v_b = 1.5 m/s)"
}

# The contour maps again from branches of periodic orbits (`tribo orbit --continue`,
# docs/orbits.md): one branch per value of the map's other parameter, sampled on the sweep's
# grid (branch_grid.py), timed; beside the sweep's map when it is there, the differences.
branches() {  # NAME PARAMETER FROM:TO OTHER VALUES(comma-separated)
  local name=$1 parameter=$2 range=$3 other=$4 values=$5 v t0 dirs=()
  mkdir -p "$OUT/$name"
  t0=$(date +%s.%N)
  for v in ${values//,/ }; do
    $TRIBO orbit $SCENE --out "$OUT/$name/$other=$v" --set dt=0.004 --set "$other=$v" \
      --continue "$parameter=$range" --arclength scaled --step 0.3 --max-points 80 --tolerance 1e-6 \
      >"$OUT/$name/$other=$v.log" 2>&1 || echo "figures: $name: $other=$v ended with $?" >&2
    dirs+=("$OUT/$name/$other=$v=$v")
  done
  echo "figures: branches $name: ${#dirs[@]} branches; wall time $(echo "$(date +%s.%N) - $t0" | bc) s"
  BRANCH_DIRS=("${dirs[@]}")
}
branch_contour() {  # FIG SWEEP GRID AXIS XEXPR YEXPR PARAMETER OTHER XLABEL YLABEL TITLE
  local fig=$1 sweep=$2 grid=$3 cmp=()
  [ -f "$OUT/$sweep/results.csv" ] && cmp=(--sweep "$OUT/$sweep/results.csv" "$7" "$8")
  python3 $HERE/branch_grid.py --grid "$grid" --branch-axis "$4" --x "$5" --y "$6" "${cmp[@]}" \
    "${BRANCH_DIRS[@]}" >"$OUT/$fig.dat"
  gnuplot -e "data='$OUT/$fig.dat'; out='$FIGURES/$fig.png'; xl='$9'; yl='${10}'; ttl='${11}'" \
    $HERE/contour.gp
  echo "figures: $FIGURES/$fig.png"
}
fig11c() {  # branches in v_b, one per omega_n
  branches fig11c v_b 0.5:5 k "$(omega_k 1 10 20)"
  branch_contour fig11c fig11 0.5:5:20 x 'v' 'math.sqrt(v / 10)' v_b k "belt speed v_b [m/s]" \
    "omega_n [rad/s]" "Fig. 11 from branches: limit-cycle amplitude p-p [m] (mu_s - mu_k = 0.05)"
}
fig12c() {  # branches in mu_s (down from 0.5, where stick-slip is strong), one per omega_n
  branches fig12c mu_s 0.5:0.31 k "$(omega_k 1 10 20)"
  branch_contour fig12c fig12 0.31:0.5:20 y 'math.sqrt(v / 10)' 'v - 0.3' mu_s k \
    "omega_n [rad/s]" "mu_s - mu_k" "Fig. 12 from branches: limit-cycle amplitude p-p [m] (v_b = 1.5 m/s)"
}

ALL=(fig4 fig5 fig6 fig7 fig8 fig9 fig10 fig11 fig12 fig11c fig12c)
for f in "${@:-${ALL[@]}}"; do
  [[ " ${ALL[*]} " == *" $f "* ]] || { echo "figures: unknown figure '$f' (${ALL[*]})" >&2; exit 1; }
  $f
done
