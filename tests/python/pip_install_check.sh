#!/usr/bin/env bash
# The package installs the way Python users install things, offline (--no-index: nothing may
# come from PyPI; the builds are isolated, as pip and build make them by default): a wheel
# made by `python3 -m build --wheel` installs into a fresh virtual environment
# (--system-site-packages: NumPy from Debian), so does `pip install .` from the checkout into
# another, and each imports from its environment (not the build
# tree), has the CMake project's version and runs a scene from a folder outside the source
# tree. Both reuse BUILD's CMake build (TRIBO_CMAKE_BUILD_DIR, setup.py), so the test takes
# seconds; a build from nothing is the same commands without it (docs/python.md).
#   pip_install_check.sh SOURCE_DIR BUILD_DIR PYTHON VERSION
set -euo pipefail
src=$1 build=$2 python=$3 version=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export TRIBO_CMAKE_BUILD_DIR=$build TRIBO_PIP_WORK_DIR=$work/setuptools
unset PYTHONPATH

check() {  # VENV: imports tribo from VENV and runs the belt from $work/run
  mkdir -p "$work/run"
  cp "$src/scenes/belt.yaml" "$work/run/belt.yaml"
  (cd "$work/run" && "$1/bin/python" - "$1" "$version" <<'PY'
import sys
import tribo
venv, version = sys.argv[1], sys.argv[2]
assert tribo.__file__.startswith(venv), f"tribo imported from {tribo.__file__}, not {venv}"
assert tribo.__version__ == version, (tribo.__version__, version)
result = tribo.load_scene("belt.yaml", set={"duration": 5}).run()
assert result.status == "complete", result.message
assert result.summary["cycles_found"] > 0
print(f"tribo {tribo.__version__} from {tribo.__file__}: {result.status}")
PY
  )
}

"$python" -m build --wheel --outdir "$work/dist" "$src" > "$work/build.log" 2>&1 ||
  { cat "$work/build.log"; exit 1; }
wheel=$(ls "$work"/dist/tribo-"$version"-*.whl)
"$python" -m venv --system-site-packages "$work/wheel-env"
"$work/wheel-env/bin/python" -m pip install -q --no-index --no-deps "$wheel"
check "$work/wheel-env"

"$python" -m venv --system-site-packages "$work/pip-env"
"$work/pip-env/bin/python" -m pip install -q --no-index "$src"
check "$work/pip-env"
