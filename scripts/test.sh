#!/usr/bin/env bash
# Installs the dependencies, checks the formatting, builds Tribo with warnings as errors,
# and runs the whole test suite twice: in the Release build, then in a build with
# AddressSanitizer and UBSan (benches left out); then the libFuzzer harnesses for a fixed
# number of inputs each (scripts/fuzz.sh --ci, docs/fuzzing.md).
set -euo pipefail
cd "$(dirname "$0")/.."
CMAKE_ARGS="-DTRIBO_WERROR=ON ${CMAKE_ARGS:-}" scripts/setup.sh
scripts/check_format.sh
ctest --test-dir build --output-on-failure -j "$(nproc)"
BUILD_DIR=build-sanitize \
  CMAKE_ARGS="-DCMAKE_BUILD_TYPE=RelWithDebInfo -DTRIBO_SANITIZE=ON -DTRIBO_BUILD_BENCH=OFF -DTRIBO_WERROR=ON" \
  scripts/setup.sh
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build-sanitize --output-on-failure -j "$(nproc)"
scripts/fuzz.sh --ci
