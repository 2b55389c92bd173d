#!/usr/bin/env bash
# Installs the dependencies, checks the formatting, builds Tribo with GCC (Release, warnings
# as errors) and runs the whole test suite there; then builds it once more with clang in
# build-sanitize/ (warnings as errors, AddressSanitizer, UBSan and libFuzzer's coverage
# instrumentation, -O1 with line tables only, benches and the Python module left out: an
# instrumented extension does not load into an uninstrumented interpreter), runs the whole suite again
# in that build and, from the same tree, the libFuzzer harnesses for a fixed number of
# inputs each (scripts/fuzz.sh --ci, docs/fuzzing.md). Two compilers check the warnings;
# one sanitized tree serves the tests and the fuzzers. Each phase prints its duration, and a
# summary of them ends the log (also when a phase fails).
set -euo pipefail
cd "$(dirname "$0")/.."

PHASES=()
START=$(date +%s)
summary() {
  echo "test.sh: phase durations"
  for p in "${PHASES[@]}"; do echo "  $p"; done
  echo "  total: $(($(date +%s) - START)) s"
}
trap summary EXIT

phase() {  # NAME COMMAND...: runs COMMAND, records how long it took (also when it fails)
  local name=$1 start status=0
  shift
  start=$(date +%s)
  echo "test.sh: == $name"
  "$@" || status=$?
  PHASES+=("$name: $(($(date +%s) - start)) s$([ $status -eq 0 ] || echo ", failed ($status)")")
  echo "test.sh: $name took $(($(date +%s) - start)) s"
  [ $status -eq 0 ] || exit $status
}

release_build() { CMAKE_ARGS="-DTRIBO_WERROR=ON ${CMAKE_ARGS:-}" scripts/setup.sh; }
sanitized_build() {
  BUILD_DIR=build-sanitize CMAKE_ARGS="-DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DTRIBO_SANITIZE=ON -DTRIBO_FUZZ=ON -DTRIBO_BUILD_BENCH=OFF -DTRIBO_WERROR=ON \
    -DTRIBO_PYTHON=OFF" scripts/setup.sh
}
# Every test but the long physics runs of tests/release_only.txt (run in Release above; the
# file says why), each of which must still be a test. A name matches with or without the
# "  # GetParam() = ..." that ctest appends to a parameterised case.
sanitized_tests() {
  local names regex missing=0
  mapfile -t names < <(grep -v -e '^#' -e '^ *$' tests/release_only.txt)
  for n in "${names[@]}"; do
    ctest --test-dir build-sanitize -N -R "^${n//./\\.}( |\$)" | grep -q "Total Tests: 1" ||
      { echo "test.sh: tests/release_only.txt names no test: $n" >&2; missing=1; }
  done
  [ $missing -eq 0 ] || return 1
  regex="^($(printf '%s|' "${names[@]//./\\.}" | sed 's/|$//'))( |\$)"
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir build-sanitize --output-on-failure -j "$(nproc)" -E "$regex"
}

phase "setup and GCC Release build" release_build
phase "format check" scripts/check_format.sh
phase "tests, Release" ctest --test-dir build --output-on-failure -j "$(nproc)"
phase "clang sanitized and fuzzer build" sanitized_build
phase "tests, ASan + UBSan" sanitized_tests
phase "fuzzing (scripts/fuzz.sh --ci)" env -u CMAKE_ARGS BUILD_DIR=build-sanitize scripts/fuzz.sh --ci
