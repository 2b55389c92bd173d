"""The setuptools side of pyproject.toml: builds the extension tribo._core with the project's
own CMake (the target tribo_python, Release, without tests, benches or fuzzers) and packs it
with python/tribo/*.py into the wheel. The version is the CMake project's.

Environment (all optional):
  TRIBO_CMAKE_BUILD_DIR  a CMake build folder to use (configured if it has no CMakeCache.txt,
                         else only built): e.g. the build/ of scripts/setup.sh, which makes
                         the install take seconds; default build-pip/cmake in the checkout
  TRIBO_PIP_WORK_DIR     where setuptools keeps its own scratch files; default build-pip
  CMAKE_ARGS             more arguments for the CMake configuration
Not here: the engine's build description (CMakeLists.txt, python/CMakeLists.txt).
"""

import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = pathlib.Path(__file__).parent.resolve()
WORK = pathlib.Path(os.environ.get("TRIBO_PIP_WORK_DIR") or SOURCE / "build-pip").resolve()


def project_version():
    text = (SOURCE / "CMakeLists.txt").read_text()
    match = re.search(r"project\(\s*tribo\s+VERSION\s+([0-9][0-9.]*)", text)
    if not match:
        raise RuntimeError("setup.py: no project(tribo VERSION x.y.z) in CMakeLists.txt")
    return match.group(1)


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    """Builds tribo._core with CMake and copies it where setuptools packs extensions."""

    def build_extension(self, ext):
        build = pathlib.Path(os.environ.get("TRIBO_CMAKE_BUILD_DIR") or WORK / "cmake").resolve()
        if not (build / "CMakeCache.txt").exists():
            configure = ["cmake", "-S", str(SOURCE), "-B", str(build),
                         "-DCMAKE_BUILD_TYPE=Release", "-DTRIBO_BUILD_TESTS=OFF",
                         "-DTRIBO_BUILD_BENCH=OFF", "-DTRIBO_PYTHON=ON",
                         f"-DPython3_EXECUTABLE={sys.executable}"]
            configure += shlex.split(os.environ.get("CMAKE_ARGS", ""))
            subprocess.run(configure, check=True)
        jobs = str(os.cpu_count() or 1)
        subprocess.run(["cmake", "--build", str(build), "--target", "tribo_python", "-j", jobs],
                       check=True)
        built = sorted((build / "python" / "tribo").glob("_core*.so"))
        if not built:
            raise RuntimeError(f"setup.py: CMake built no tribo/_core*.so in {build}/python/tribo")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[-1], target)


WORK.mkdir(parents=True, exist_ok=True)
setup(
    version=project_version(),
    packages=["tribo"],
    package_dir={"tribo": "python/tribo"},
    ext_modules=[CMakeExtension("tribo._core")],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": str(WORK / "setuptools")},
             "egg_info": {"egg_base": str(WORK)}},
    zip_safe=False,
)
