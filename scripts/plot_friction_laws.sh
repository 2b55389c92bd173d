#!/usr/bin/env bash
# Figures of docs/friction-laws.md (gnuplot; build/apps/tribo for the engine's run):
#   docs/figures/dynamic-steady-state.png: the steady-state curves mu_ss(v) of the dynamic
#     laws with the parameters scenes/belt.yaml gives them (--set friction=...): lugre and
#     elasto_plastic mu_c + (mu_s - mu_c) exp(-(v/v_s)^2) (sigma2 = 0), gms the same with
#     delta = 2, dahl mu_c, rate_state a asinh((v / 2 v0) exp(mu0 / a) (v0 / v)^(b / a)) with
#     mu0 = mu_k at v0 = v_b. The formulas of docs/friction-laws.md, which
#     tests/friction/dynamic_law_properties_test.cpp checks against each law's integrated
#     steady state; not the engine's output.
#   docs/figures/lugre-presliding-loop.png: the engine's presliding loop, `tribo run
#     scenes/lugre_presliding.yaml` (two drive cycles): block displacement against the
#     spring's force, with the virgin curve x = -(mu_s / sigma0) ln(1 - F / (mu_s N)).
# Usage: scripts/plot_friction_laws.sh [OUT_DIR]   (default docs/figures)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/figures}
tribo=${TRIBO:-build/apps/tribo}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"

gnuplot <<GP
set terminal pngcairo noenhanced size 900,560 font 'Helvetica,11'
set output '$out/dynamic-steady-state.png'
set logscale x
set format x '1e%L'
set xlabel 'slip speed v [m/s]'
set ylabel 'steady-state coefficient mu_ss(v)'
set title 'Dynamic laws at the belt scene''s parameters (mu_k 0.3, mu_s 0.35, v_s 0.01 m/s, v_b 1.5 m/s)'
set key top right
set grid
set samples 400
set xrange [1e-5:10]
set yrange [0.27:0.37]
muc = 0.3; mus = 0.35; vs = 0.01; a = 0.01; b = 0.015; v0 = 1.5
stribeck(v) = muc + (mus - muc) * exp(-(v / vs)**2)
rs(v) = a * asinh(v / (2 * v0) * exp(muc / a) * (v0 / v)**(b / a))
plot stribeck(x) lw 3 lc rgb '#1f77b4' title 'lugre, elasto_plastic, gms (delta 2)', \
     muc lw 2 dt 2 lc rgb '#2ca02c' title 'dahl', \
     rs(x) lw 2 lc rgb '#d62728' title 'rate_state (a 0.01, b 0.015, mu_0 0.3 at v_0 = v_b)'
GP

"$tribo" run scenes/lugre_presliding.yaml --out "$work/loop" --quiet > /dev/null
csv="$work/loop/trajectory.csv"
col() { head -1 "$csv" | tr ',' '\n' | grep -nx "$1" | cut -d: -f1; }
p=$(col puller.x) x=$(col block.x)
# Force k (x_p - x) with k = 100 N/m and the puller's rest at x = 1 m; x in micrometres.
awk -F, -v p="$p" -v x="$x" 'NR > 1 { printf "%s %.9g %.9g\n", $1, 100 * ($p - 1 - $x), 1e6 * $x }' \
  "$csv" > "$work/loop.dat"
gnuplot <<GP
set terminal pngcairo noenhanced size 800,600 font 'Helvetica,11'
set output '$out/lugre-presliding-loop.png'
set xlabel 'spring force F [N]  (mu_s N = 1.5 N)'
set ylabel 'block displacement x [micrometre]'
set title 'LuGre presliding (scenes/lugre_presliding.yaml: Table I, N = 1 N, F = 1.35 sin(0.1 t) N)'
set key top left
set grid
set xrange [-1.5:1.5]
virgin(F) = -(1.5 / 1e5) * log(1 - F / 1.5) * 1e6
plot '$work/loop.dat' using 2:3 with lines lw 2 lc rgb '#1f77b4' title 'engine (tribo run, RK4 1 ms), two cycles', \
     [0:1.35] virgin(x) lw 2 dt 2 lc rgb '#d62728' title 'virgin curve -(mu_s/sigma_0) ln(1 - F/(mu_s N))'
GP
echo "wrote $out/dynamic-steady-state.png $out/lugre-presliding-loop.png"
