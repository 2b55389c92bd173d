#!/usr/bin/env bash
# Step study of a scene: runs every integrator over a range of steps and prints, per run,
# the limit-cycle amplitude, its error against the finest RK4 run, and the wall time of the
# stepping. CSV on stdout. Usage:
#   scripts/step_study.sh [SCENE] [--set NAME=VALUE ...]
# Uses build/apps/tribo (scripts/setup.sh builds it).
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${1:-scenes/belt.yaml}
shift || true
extra=("$@")
tribo=build/apps/tribo
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

field() { sed -n "s/^ *\"$2\": \([^,]*\),\{0,1\}$/\1/p" "$1" | head -n 1; }

run() {  # integrator dt -> "status amplitude wall"
  local dir="$out/$1-$2"
  "$tribo" run "$scene" --out "$dir" --set "integrator=$1" --set "dt=$2" --set output_interval=0.001 "${extra[@]}" \
    >/dev/null 2>&1 || true
  local s="$dir/summary.json"
  [ -f "$s" ] || { echo "error nan nan"; return; }
  echo "$(field "$s" status | tr -d '"') $(field "$s" amplitude_pp) $(field "$s" wall_seconds)"
}

read -r _ reference _ < <(run rk4 0.0001)
echo "integrator,time_step,status,amplitude_pp,relative_error,wall_seconds"
for integrator in rk4 semi_implicit_euler; do
  for dt in 0.009 0.008 0.006 0.004 0.002 0.001 0.0005 0.00025; do
    read -r status amp wall < <(run "$integrator" "$dt")
    err=$(awk -v a="$amp" -v r="$reference" 'BEGIN { if (a == "nan" || a == "") print "nan"; else { e = (a - r) / r; if (e < 0) e = -e; printf "%.2e", e } }')
    echo "$integrator,$dt,$status,$amp,$err,$wall"
  done
done
