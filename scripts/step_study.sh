#!/usr/bin/env bash
# Step study of a scene: runs every integrator over a range of steps and prints, per run,
# the limit-cycle amplitude, its error against the finest RK4 run, and the wall time of the
# stepping; a run that stopped early (status diverged) gives the time it stopped at instead
# of an error (its amplitude is that of the partial run). CSV on stdout. Usage:
#   scripts/step_study.sh [SCENE] [--set NAME=VALUE ...]
# Uses build/apps/tribo (scripts/setup.sh builds it), or the binary named by $TRIBO.
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${1:-scenes/belt.yaml}
shift || true
extra=("$@")
tribo=${TRIBO:-build/apps/tribo}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

field() { sed -n "s/^ *\"$2\": \([^,]*\),\{0,1\}$/\1/p" "$1" | head -n 1; }

run() {  # integrator dt -> "status amplitude wall stopped_at"
  local dir="$out/$1-$2"
  "$tribo" run "$scene" --out "$dir" --set "integrator=$1" --set "dt=$2" --set output_interval=0.001 "${extra[@]}" \
    >/dev/null 2>&1 || true
  local s="$dir/summary.json"
  [ -f "$s" ] || { echo "error nan nan nan"; return; }
  local status stopped=-
  status=$(field "$s" status | tr -d '"')
  [ "$status" = complete ] || stopped=$(awk -v t="$(field "$s" time)" 'BEGIN { printf "%.6g", t }')
  echo "$status $(field "$s" amplitude_pp) $(field "$s" wall_seconds) ${stopped:-nan}"
}

read -r ref_status reference _ < <(run rk4 0.0001)
[ "$ref_status" = complete ] || { echo "$0: the reference run (rk4, 0.1 ms) did not complete" >&2; exit 1; }
echo "integrator,time_step,status,amplitude_pp,relative_error,wall_seconds,stopped_at"
for integrator in rk4 semi_implicit_euler; do
  for dt in 0.01 0.009 0.0085 0.008 0.006 0.004 0.002 0.001 0.0005 0.00025; do
    read -r status amp wall stopped < <(run "$integrator" "$dt")
    err=$(awk -v s="$status" -v a="$amp" -v r="$reference" 'BEGIN { if (s != "complete" || a == "nan" || a == "") print "nan"; else { e = (a - r) / r; if (e < 0) e = -e; printf "%.2e", e } }')
    [ "$stopped" = - ] && stopped=
    echo "$integrator,$dt,$status,$amp,$err,$wall,$stopped"
  done
done
