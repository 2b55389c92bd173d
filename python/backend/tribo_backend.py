"""The build backend pyproject.toml names: setuptools' own (setuptools.build_meta, which runs
setup.py, which runs CMake), taken from the system when pip's or build's isolated
environment lacks it, and asking for nothing more. So `pip install .` and
`python3 -m build` work offline with Debian's python3-setuptools and python3-wheel
(scripts/setup.sh installs them): an isolated build would otherwise download setuptools and
wheel from PyPI. Nothing else here: the build is setup.py's, the engine's is CMake's.
"""

import site
import sys
import sysconfig


def _system_site_paths():
    """The interpreter's system package folders (Debian: /usr/lib/python3/dist-packages),
    which an isolated build environment leaves off sys.path."""
    paths = []
    try:
        paths += site.getsitepackages([sys.base_prefix])
    except (AttributeError, TypeError):  # old site modules take no prefixes
        paths += site.getsitepackages()
    paths.append(sysconfig.get_path("purelib", vars={"base": sys.base_prefix}))
    paths.append(f"{sys.base_prefix}/lib/python3/dist-packages")
    return paths


try:
    import setuptools.build_meta as _meta
    import wheel  # noqa: F401  (bdist_wheel)
except ImportError:
    for path in _system_site_paths():
        if path not in sys.path:
            sys.path.append(path)
    import setuptools.build_meta as _meta

build_wheel = _meta.build_wheel
build_sdist = _meta.build_sdist
prepare_metadata_for_build_wheel = _meta.prepare_metadata_for_build_wheel
build_editable = getattr(_meta, "build_editable", None)
prepare_metadata_for_build_editable = getattr(_meta, "prepare_metadata_for_build_editable", None)
if build_editable is None:
    del build_editable
if prepare_metadata_for_build_editable is None:
    del prepare_metadata_for_build_editable


def get_requires_for_build_wheel(config_settings=None):
    return []  # setuptools and wheel come from the system (above); nothing to download


def get_requires_for_build_sdist(config_settings=None):
    return []


def get_requires_for_build_editable(config_settings=None):
    return []
