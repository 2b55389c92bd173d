#!/usr/bin/env bash
# Installs Tribo's build dependencies (Debian 12 packages) and builds it in build/
# (Release). Safe to re-run: installs only what is missing, rebuilds incrementally.
#   scripts/setup.sh                 # Release build in build/
#   BUILD_DIR=build-asan CMAKE_ARGS="-DCMAKE_BUILD_TYPE=RelWithDebInfo -DTRIBO_SANITIZE=ON" scripts/setup.sh
set -euo pipefail
cd "$(dirname "$0")/.."

PACKAGES=(build-essential cmake pkg-config clang-format
          libjs-three chromium python3-pil python3-yaml  # tribo view (three.js inlined), its browser tests
          libeigen3-dev libfcl-dev libccd-dev liburdfdom-dev libyaml-cpp-dev nlohmann-json3-dev
          libgtest-dev libgmock-dev libbenchmark-dev libassimp-dev
          libsundials-dev libmuparser-dev libspectra-dev gnuplot-nox
          libcli11-dev  # the tribo command's argument parser (apps/)
          openmpi-bin libopenmpi-dev
          pybind11-dev python3-dev python3-numpy python3-pytest  # the Python module (python/)
          python3-matplotlib  # examples/fig4_belt.py
          python3-setuptools python3-wheel python3-venv python3-build  # pip install . (pyproject.toml)
          python3-pandas python3-nbclient python3-nbformat python3-ipykernel  # notebooks (examples/*.ipynb)
          python3-distributed  # tribo.sweep(executor=) on a Dask cluster, tested
          clang libclang-rt-14-dev  # libFuzzer and the sanitizers' runtimes (scripts/fuzz.sh)
          libomp-dev)  # OpenMP for the clang build (threads of one evaluation)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

BUILD_DIR=${BUILD_DIR:-build}
# shellcheck disable=SC2086
cmake -S . -B "$BUILD_DIR" ${CMAKE_ARGS:-} >/dev/null
cmake --build "$BUILD_DIR" -j "$(nproc)"
