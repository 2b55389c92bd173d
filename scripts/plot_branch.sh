#!/usr/bin/env bash
# Bifurcation diagram of a branch of periodic orbits (`tribo orbit --continue`, docs/orbits.md):
# the orbits' peak-to-peak amplitude against the parameter, stable orbits solid and unstable
# ones dashed, with steady sliding along the axis beside them (its `tribo modes` growth rate at
# each point: solid where it is stable, dashed where it is not) and the located events marked.
# Where a stable orbit stands above a stable stretch of the axis, both motions coexist: a sweep
# up and a sweep down disagree (hysteresis). After `--switch`, the branch switched from
# (primary_branch.csv) is drawn in grey beside the new one.
#   scripts/plot_branch.sh BRANCH_DIR [OUT.png]      # needs gnuplot; default BRANCH_DIR/branch.png
# The figure in docs/figures/branch_stribeck.png comes from
#   build/apps/tribo orbit scenes/belt.yaml --set friction=stribeck \
#     --set 'springs[wall_spring].damping=10' --settle 30 --out out/branch_stribeck \
#     --continue v_b=0.15:0.5 --step 0.02 --max-points 30
#   scripts/plot_branch.sh out/branch_stribeck docs/figures/branch_stribeck.png
# and docs/figures/branch_grazing_corner.png (the paper's law: a corner at grazing) from
#   build/apps/tribo orbit scenes/belt.yaml --set 'springs[wall_spring].damping=1.5' \
#     --settle 30 --out out/branch_corner --from-hopf --continue v_b=0.5:2 --max-step 0.05 \
#     --max-points 60
#   scripts/plot_branch.sh out/branch_corner docs/figures/branch_grazing_corner.png
set -euo pipefail
dir=${1:?usage: plot_branch.sh BRANCH_DIR [OUT.png]}
out=${2:-$dir/branch.png}
csv=$dir/branch.csv
[ -f "$csv" ] || { echo "plot_branch: no $csv (run tribo orbit --continue first)" >&2; exit 1; }
# Column numbers by name, for gnuplot's `using`.
col() { head -1 "$csv" | tr ',' '\n' | grep -nx "$1" | cut -d: -f1; }
p=$(col parameter) a=$(col amplitude_pp) s=$(col stable) g=$(col steady_growth_rate)
e=$(col event)
# The points that close an event, as "parameter,amplitude,event" rows (gnuplot reads an empty
# last field badly).
events=$(mktemp)
trap 'rm -f "$events"' EXIT
awk -F, -v OFS=, -v p="$p" -v a="$a" -v e="$e" 'NR > 1 && $e != "" {print $p, $a, $e}' "$csv" \
  > "$events"
# With --switch: the branch it left (primary_branch.csv) in grey beside it.
primary_plot=""
if [ -f "$dir/primary_branch.csv" ]; then
  primary_plot=", '$dir/primary_branch.csv' every ::1 using $p:(\$$s == 1 ? \$$a : 1/0) with linespoints lw 2 pt 7 lc 'gray40' title 'primary, stable', '' every ::1 using $p:(\$$s == 0 ? \$$a : 1/0) with linespoints lw 2 dt 2 pt 6 lc 'gray60' title 'primary, unstable'"
fi
name=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['parameter'])" \
  "$dir/branch.json" 2>/dev/null || echo parameter)
observed=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['observed'])" \
  "$dir/branch.json" 2>/dev/null || echo x)
gnuplot <<GP
set terminal pngcairo noenhanced size 900,560 font 'Helvetica,11'
set output '$out'
set datafile separator ','
set key top left
set grid
set offsets graph 0.02, graph 0.15, graph 0.05, 0
set xlabel '$name'
set ylabel 'peak to peak of $observed'
set title 'orbits (solid: stable, dashed: unstable) and steady sliding on the axis'
plot '$csv' every ::1 using $p:(\$$s == 1 ? \$$a : 1/0) with linespoints lw 2 pt 7 lc 'blue' title 'stable orbit', \
     '' every ::1 using $p:(\$$s == 0 ? \$$a : 1/0) with linespoints lw 2 dt 2 pt 6 lc 'red' title 'unstable orbit', \
     '' every ::1 using $p:(\$$g < 0 ? 0 : 1/0) with points pt 5 ps 1.2 lc 'dark-green' title 'steady sliding stable', \
     '' every ::1 using $p:(\$$g >= 0 ? 0 : 1/0) with points pt 4 ps 1.2 lc 'orange' title 'steady sliding unstable', \
     '$events' using 1:2:3 with labels offset 0,1.2 notitle$primary_plot
GP
echo "wrote $out"
