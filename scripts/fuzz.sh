#!/usr/bin/env bash
# Builds the libFuzzer harnesses (fuzz/, clang, ASan + UBSan) in build-fuzz/ and runs them.
#   scripts/fuzz.sh HARNESS [SECONDS]   fuzz one harness for SECONDS (default 600), niced,
#                                       growing build-fuzz/corpus/HARNESS from fuzz/corpus
#   scripts/fuzz.sh --replay            run every harness once over its seeds and regressions
#   scripts/fuzz.sh --ci                the CI step: replay, then a fixed number of inputs per
#                                       harness (FUZZ_RUNS below), seed 1, JOBS harnesses at
#                                       a time
#   scripts/fuzz.sh --list              the harness names
# HARNESS: scene_yaml_fuzzer urdf_fuzzer urdf_tree_fuzzer mesh_fuzzer hull_fuzzer
#          cli_values_fuzzer
# (docs/fuzzing.md).
# A finding is written to build-fuzz/artifacts/HARNESS/ (crash-*, leak-*, timeout-*, oom-*);
# fix it, then keep the input as fuzz/regressions/HARNESS/NAME so --replay and CI run it.
# Extra libFuzzer flags: FUZZ_FLAGS="-jobs=2 -workers=2" scripts/fuzz.sh HARNESS 3600.
set -euo pipefail
cd "$(dirname "$0")/.."

# Longest CI budget first (--ci runs them JOBS at a time in this order).
HARNESSES=(urdf_fuzzer scene_yaml_fuzzer cli_values_fuzzer urdf_tree_fuzzer mesh_fuzzer hull_fuzzer)
# Inputs per harness in CI, from the rates measured on the shared 2-core machine at load 5
# (scene 830/s, urdf 15000/s, mesh 4000/s since Tribo reads OBJ itself, cli 25000/s;
# docs/fuzzing.md): about 2.5 minutes together, three times that at load 15.
# urdf_tree_fuzzer: generated robots of up to 12 000 links, so its count is by the time
# measured for it (docs/fuzzing.md). Its CI run starts from its seeds only: the 12 000-link
# regressions (replayed just before) and their mutations took most of 23 s for 21 inputs.
declare -A FUZZ_RUNS=([scene_yaml_fuzzer]=40000 [urdf_fuzzer]=300000 [urdf_tree_fuzzer]=1000
                      [mesh_fuzzer]=50000 [hull_fuzzer]=30000 [cli_values_fuzzer]=500000)
BUILD_DIR=${BUILD_DIR:-build-fuzz}
JOBS=${JOBS:-2}

# A tree already configured for fuzzing (TRIBO_FUZZ=ON: build-fuzz/ after its first run, or
# scripts/test.sh's build-sanitize/, which also holds the sanitized tests) is only brought up
# to date, its settings kept; a new one (or any tree, when CMAKE_ARGS is set) is configured
# here: clang, RelWithDebInfo, harnesses only.
build() {
  if ! command -v clang++ >/dev/null; then
    echo "fuzz: clang++ not found (scripts/setup.sh installs clang and libclang-rt-14-dev)" >&2
    exit 1
  fi
  if [ -n "${CMAKE_ARGS:-}" ] || ! grep -qs '^TRIBO_FUZZ:BOOL=ON' "$BUILD_DIR/CMakeCache.txt"; then
    cmake -S . -B "$BUILD_DIR" -DCMAKE_CXX_COMPILER=clang++ -DTRIBO_FUZZ=ON -DTRIBO_BUILD_TESTS=OFF \
      -DTRIBO_BUILD_BENCH=OFF -DTRIBO_WITH_MPI=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      ${CMAKE_ARGS:-} >/dev/null
  fi
  cmake --build "$BUILD_DIR" -j "$JOBS" --target "${HARNESSES[@]}" scene_dictionary
  # The scene dictionary: the words generated from the loader's own key tables (a key added
  # there is fuzzed at once), joined with the committed one (expression fragments, extremes).
  { cat fuzz/dictionaries/scene.dict; "$BUILD_DIR/fuzz/scene_dictionary"; } >"$BUILD_DIR/scene.dict"
}

# Options every run shares: the harness's own dictionary if it has one, a 10 s hang limit,
# a 2 GB memory limit, inputs up to 16 kB, findings into build-fuzz/artifacts/HARNESS/.
flags() {
  local h=$1
  mkdir -p "$BUILD_DIR/artifacts/$h"
  echo "-timeout=10 -rss_limit_mb=2048 -max_len=16384 -artifact_prefix=$BUILD_DIR/artifacts/$h/"
  case $h in
    scene_yaml_fuzzer) echo "-dict=$BUILD_DIR/scene.dict" ;;
    # assimp leaks on many malformed files (fuzz/mesh_fuzzer.cpp); LeakSanitizer's check
    # after each such input brought the rate from thousands to 2 inputs a second.
    mesh_fuzzer) echo "-detect_leaks=0" ;;
  esac
}

# The committed input folders of a harness that exist; the URDF harness also starts from the
# real robots beside the checkout (../shared/urdf) when they are there.
inputs() {
  for d in "fuzz/corpus/$1" "fuzz/regressions/$1"; do
    # CI's fixed budget of the tree harness starts from its small seeds only (above).
    [ "${FROM_SEEDS_ONLY:-}" = "$1" ] && [ "$d" = "fuzz/regressions/$1" ] && continue
    [ -d "$d" ] && echo "$d"
  done
  if [ "$1" = urdf_fuzzer ] && [ -d ../shared/urdf ]; then echo ../shared/urdf; fi
}

# Every seed and regression once: the fixed defects stay fixed.
replay() {
  local h=$1 files=()
  mapfile -t files < <(find $(inputs "$h") -type f ! -name '.*' | sort)
  echo "fuzz: $h: replaying ${#files[@]} seeds and regressions"
  # shellcheck disable=SC2046
  "$BUILD_DIR/fuzz/$h" $(flags "$h") "${files[@]}" >"$BUILD_DIR/$h.replay.log" 2>&1 ||
    { cat "$BUILD_DIR/$h.replay.log"; echo "fuzz: $h: a seed or regression fails" >&2; exit 1; }
}

run() {  # HARNESS then libFuzzer options
  local h=$1
  shift
  local work="$BUILD_DIR/corpus/$h"
  mkdir -p "$work"
  # shellcheck disable=SC2046
  ${NICE:-} "$BUILD_DIR/fuzz/$h" $(flags "$h") "$@" ${FUZZ_FLAGS:-} -print_final_stats=1 \
    "$work" $(inputs "$h")
}

case "${1:-}" in
  --list) printf '%s\n' "${HARNESSES[@]}" ;;
  --replay)
    build
    for h in "${HARNESSES[@]}"; do replay "$h"; done ;;
  --ci)
    build
    for h in "${HARNESSES[@]}"; do replay "$h"; done
    # The fixed budgets run JOBS harnesses at a time (one per core), in HARNESSES' order
    # (longest first); each prints its line when it ends. xargs exits non-zero when any of
    # them found a defect.
    printf '%s\n' "${HARNESSES[@]}" | BUILD_DIR="$BUILD_DIR" xargs -P "$JOBS" -n 1 "$0" --ci-one ;;
  --ci-one)  # one harness's CI budget (called by --ci on a built tree)
    h=$2
    start=$(date +%s)
    # A fresh working corpus each time, so CI runs the same inputs every time.
    rm -rf "$BUILD_DIR/corpus/$h"
    FROM_SEEDS_ONLY=urdf_tree_fuzzer run "$h" -seed=1 -runs="${FUZZ_RUNS[$h]}" \
      >"$BUILD_DIR/$h.ci.log" 2>&1 ||
      { tail -n 60 "$BUILD_DIR/$h.ci.log"; echo "fuzz: $h found a defect" >&2; exit 1; }
    echo "fuzz: $h: $(grep -o 'Done [0-9]* runs in [0-9]* second(s)' "$BUILD_DIR/$h.ci.log")" \
         "(wall $(($(date +%s) - start)) s)" ;;
  ""|-h|--help) sed -n '2,14p' "$0" ;;
  *)
    h=$1
    seconds=${2:-600}
    [[ " ${HARNESSES[*]} " == *" $h "* ]] || { echo "fuzz: unknown harness '$h'" >&2; exit 1; }
    build
    NICE="nice -n 10" run "$h" -max_total_time="$seconds" ;;
esac
