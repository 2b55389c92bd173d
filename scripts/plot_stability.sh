#!/usr/bin/env bash
# Plots of linear stability (tribo modes, docs/stability.md):
#   scripts/plot_stability.sh map OUT.png RESULTS.csv
#     the stability map of a two-parameter `tribo sweep --analysis modes` (--grid X --grid Y):
#     the largest growth rate [1/s] over the two swept parameters, the first grid the
#     horizontal axis, its zero contour (the stability boundary) drawn in black where the
#     rate changes sign (the title says when it does not), the colours symmetric about 0.
#   scripts/plot_stability.sh locus OUT.png SCENE NAME V1,V2,... [--set NAME=VALUE ...]
#     a root locus: every eigenvalue (growth rate, angular frequency) of `tribo modes SCENE`
#     as parameter NAME takes the listed values, coloured by the value (the upper half plane:
#     each pair is shown once). The modes of each value are kept in OUT.png's folder as
#     locus-NAME-VALUE.csv.
#   scripts/plot_stability.sh growth OUT.png TRAJECTORY.csv COLUMN X_EQ SIGMA
#     prediction against simulation: COLUMN of a `tribo run` trajectory against
#     X_EQ +- A e^(SIGMA t), A fitted to the first peak (SIGMA from tribo modes).
# Needs gnuplot (Debian gnuplot-nox; scripts/setup.sh installs it) and build/apps/tribo.
set -euo pipefail
usage() {
  sed -n '2,15p' "$0" >&2
  exit 1
}
[ $# -ge 3 ] || usage
kind=$1 out=$2
shift 2
tribo=${TRIBO:-$(dirname "$0")/../build/apps/tribo}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Column number of NAME in the header of CSV FILE.
column() { head -1 "$2" | tr ',' '\n' | grep -nx "$1" | cut -d: -f1; }

case "$kind" in
map)
  csv=$1
  x=$(head -1 "$csv" | cut -d, -f2) y=$(head -1 "$csv" | cut -d, -f3)
  g=$(column max_growth_rate "$csv")
  # One block per value of the first parameter, for gnuplot's pm3d.
  awk -F, -v g="$g" 'NR > 1 && $4 == "complete" { print $2, $3, $g }' "$csv" |
    sort -g -k1,1 -k2,2 | awk 'NR > 1 && $1 != last { print "" } { print; last = $1 }' \
      > "$work/map.dat"
  # A colour scale symmetric about zero (blue stable, red unstable), and whether the rate
  # changes sign at all (else there is no boundary to draw, and the title says so).
  lo=$(awk 'NF == 3 { if (!n++ || $3 < v) v = $3 } END { print v + 0 }' "$work/map.dat")
  hi=$(awk 'NF == 3 { if (!n++ || $3 > v) v = $3 } END { print v + 0 }' "$work/map.dat")
  m=$(awk -v a="$lo" -v b="$hi" 'BEGIN { a = a < 0 ? -a : a; b = b < 0 ? -b : b; m = a > b ? a : b; print (m > 0 ? m : 1) }')
  if awk -v a="$lo" -v b="$hi" 'BEGIN { exit !(a < 0 && b > 0) }'; then
    boundary=", '' using 1:2:3 with lines nosurface lw 2.5 lc rgb 'black' title 'growth rate 0: the stability boundary'"
    note=""
  else
    boundary=""
    note=$(awk -v a="$lo" 'BEGIN { print (a >= 0 ? " - unstable everywhere here: no boundary in range" : " - stable everywhere here: no boundary in range") }')
  fi
  gnuplot <<GP
set terminal pngcairo noenhanced size 900,700 font 'Helvetica,11'
set output '$out'
set xlabel "$x (swept parameter, in the scene's units)"
set ylabel "$y (swept parameter, in the scene's units)"
set cblabel 'largest growth rate [1/s]'
set view map
set pm3d map interpolate 0,0
set palette defined (0 '#2c7bb6', 0.5 '#ffffbf', 1 '#d7191c')
set cbrange [-$m:$m]
set contour base
set cntrparam levels discrete 0
unset clabel
set autoscale xfix
set autoscale yfix
set bmargin 6
set key at screen 0.5, 0.04 center horizontal
set title 'Stability map: largest growth rate of steady sliding (> 0: unstable)$note'
splot '$work/map.dat' using 1:2:3 with pm3d notitle$boundary
GP
  ;;
locus)
  scene=$1 name=$2 values=$3
  shift 3
  dir=$(dirname "$out")
  : > "$work/locus.dat"
  IFS=, read -ra list <<< "$values"
  for v in "${list[@]}"; do
    status=0
    "$tribo" modes "$scene" --out "$work/m" --set "$name=$v" "$@" > /dev/null || status=$?
    [ "$status" -eq 0 ] || [ "$status" -eq 8 ] || { echo "$0: tribo modes failed at $name=$v" >&2; exit 1; }
    cp "$work/m/modes.csv" "$dir/locus-$name-$v.csv"
    re=$(column eigen_re "$work/m/modes.csv") im=$(column eigen_im "$work/m/modes.csv")
    awk -F, -v v="$v" -v re="$re" -v im="$im" 'NR > 1 { print $re, $im, v }' \
      "$work/m/modes.csv" >> "$work/locus.dat"
  done
  gnuplot <<GP
set terminal pngcairo noenhanced size 900,650 font 'Helvetica,11'
set output '$out'
set xlabel 'growth rate Re(lambda) [1/s]'
set ylabel 'angular frequency Im(lambda) [rad/s]'
set cblabel '$name'
set grid
set arrow from 0, graph 0 to 0, graph 1 nohead dt 2 lc rgb 'black'
set palette defined (0 '#2c7bb6', 0.5 '#abd9e9', 0.75 '#fdae61', 1 '#d7191c')
set title 'Root locus of $(basename "$scene") over $name'
plot '$work/locus.dat' using 1:2:3 with points pt 7 ps 0.8 lc palette notitle
GP
  ;;
growth)
  csv=$1 col=$2 xeq=$3 sigma=$4
  t=$(column t "$csv") c=$(column "$col" "$csv")
  awk -F, -v t="$t" -v c="$c" 'NR > 1 { print $t, $c }' "$csv" > "$work/run.dat"
  # A: the first maximum's distance from X_EQ, carried back to t = 0.
  amp=$(awk -v x="$xeq" -v s="$sigma" 'NR > 2 && p > q && p >= $2 { print (p - x) * exp(-s * tp); exit }
    { q = p; p = $2; tp = $1 }' "$work/run.dat")
  gnuplot <<GP
set terminal pngcairo noenhanced size 1000,500 font 'Helvetica,11'
set output '$out'
set xlabel 't [s]'
set ylabel '$col - x_eq [m]'
set grid
set key top left
set title 'Simulation against the linear prediction (envelope A exp(sigma t), sigma = $sigma 1/s)'
plot '$work/run.dat' using 1:(\$2 - $xeq) with lines lw 1 lc rgb '#2c7bb6' title 'tribo run', \
     $amp * exp($sigma * x) with lines lw 2 dt 2 lc rgb '#d7191c' title 'tribo modes', \
     -$amp * exp($sigma * x) with lines lw 2 dt 2 lc rgb '#d7191c' notitle
GP
  ;;
*) usage ;;
esac
echo "$out"
