#!/usr/bin/env bash
# Work-precision plot of `tribo tradeoff` results: processor time of each run against its
# amplitude error (left) and its trajectory error over the first 10 s (right), one row per
# scene, one series per integrator; runs that diverged or carry a stability warning are left
# out.
#   scripts/plot_work_precision.sh OUT.svg|OUT.png CSV [CSV ...]
# Needs gnuplot (Debian gnuplot-nox; scripts/setup.sh installs it).
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: $0 OUT.svg|OUT.png tradeoff.csv [more.csv ...]" >&2; exit 1; }
out=$1
shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Whitespace-separated copies without the quoted message column (the last one), per scene:
# integrator value amplitude_error trajectory_error cpu_seconds.
scenes=()
for csv in "$@"; do
  while IFS= read -r scene; do
    scenes+=("$scene")
    awk -F, -v s="$scene" 'NR > 1 && $1 == s && $5 == "complete" {
      print $2, $4, $7, $8, $10 }' "$csv" > "$work/$scene.dat"
  done < <(awk -F, 'NR > 1 { print $1 }' "$csv" | sort -u)
done
[ ${#scenes[@]} -gt 0 ] || { echo "$0: no results in $*" >&2; exit 1; }

case "$out" in
  *.svg) terminal="svg size 1000,$((420 * ${#scenes[@]})) dynamic font 'Helvetica,13'" ;;
  *.png) terminal="pngcairo size 1000,$((420 * ${#scenes[@]})) font 'Helvetica,11'" ;;
  *) echo "$0: output must end in .svg or .png" >&2; exit 1 ;;
esac

{
  echo "set terminal $terminal"
  echo "set output '$out'"
  echo "set multiplot layout ${#scenes[@]},2"
  echo "set logscale xy"
  echo "set format x '10^{%L}'; set format y '10^{%L}'"
  echo "set grid"
  echo "set ylabel 'processor time [s]'"
  echo "set key top right font ',10' spacing 0.9 noenhanced"
  for scene in "${scenes[@]}"; do
    for column in 3 4; do
      title="amplitude error |A - A_{ref}| / A_{ref}"
      [ $column -eq 4 ] && title="trajectory error max |x - x_{ref}| / A_{ref} (first 10 s)"
      echo "set title '$scene' noenhanced"
      echo "set xlabel '$title'"
      plot="plot"
      sep=""
      style=1
      for integrator in semi_implicit_euler rk4 dopri5 dopri5_noevents bdf bdf_noevents; do
        plot+="$sep '$work/$scene.dat' using (strcol(1) eq '$integrator' && \$$column > 0 ? \$$column : NaN):5"
        plot+=" with linespoints linestyle $style pointtype $((style + 4)) title '$integrator'"
        sep=","
        style=$((style + 1))
      done
      echo "$plot"
    done
  done
  echo "unset multiplot"
} | gnuplot
echo "wrote $out"
