#!/usr/bin/env bash
# Runs the benches behind the throughput targets' table of docs/performance.md and writes the
# table again from their JSON (scripts/perf_targets.py). The peers (Bullet, MuJoCo, LAMMPS) are
# measured only where their Debian packages are installed (libbullet-dev, libmujoco-dev,
# liblammps-dev; bench/peers/CMakeLists.txt); a missing one reads "not measured". Run it on an
# idle machine: the two-thread figures need both cores. About a minute once built.
#   scripts/perf_targets.sh [OUT_DIR]     (default build/perf; BUILD_DIR=build)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
OUT=${1:-$BUILD_DIR/perf}
mkdir -p "$OUT"
cmake -S . -B "$BUILD_DIR" >/dev/null
targets=(tribo_bench_contact tribo_bench_scenes)
help=$(cmake --build "$BUILD_DIR" --target help)  # the peers' target exists when one is found
[[ $help == *tribo_bench_peers* ]] && targets+=(tribo_bench_peers)
cmake --build "$BUILD_DIR" -j "$(nproc)" --target "${targets[@]}"
run() {  # binary, filter, json name, extra flags
  echo "perf_targets.sh: $1 --benchmark_filter='$2'" >&2
  "$BUILD_DIR/bench/$1" --benchmark_filter="$2" --benchmark_out="$OUT/$3.json" \
    --benchmark_out_format=json "${@:4}"
}
if [ -x "$BUILD_DIR/bench/peers/tribo_bench_peers" ]; then
  run peers/tribo_bench_peers 'BM_Peers/(box_grid20|box_grid20_stiff|box_grid20_stiff_1ms|box_grid20_box_ground|granular_pile|granular_chute)/' peers
fi
run contact/tribo_bench_contact 'BM_Threads/grid(20|20_box_ground|40)$' threads --benchmark_repetitions=5
run contact/tribo_bench_contact 'BM_GridStep/(10|142)/' scale --benchmark_repetitions=3
# The heap a body: alone in its process (what earlier runs left allocated would count).
run contact/tribo_bench_contact 'BM_GridSetUp/142/' setup
run scenes/tribo_bench_scenes 'BM_PatternScene/20000$|BM_BeltStepVsLoop/1000$' scenes --benchmark_repetitions=3
python3 scripts/perf_targets.py "$OUT"/*.json --write docs/performance.md
echo "perf_targets.sh: docs/performance.md's targets table written from $OUT/*.json"
