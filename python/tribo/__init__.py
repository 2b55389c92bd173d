"""Tribo: rigid multibody dynamics with swappable friction laws (docs/python.md).

load_scene/load_urdf -> Scene; Scene.run -> Result (trajectory as NumPy arrays, summary as a
dict; shown as a table in a notebook, Result.view() replays it, Result.to_pandas() gives a
DataFrame); Simulator for step-by-step control; friction_law for the laws' mu(v); sweep
(local threads, a slice of a cluster job, or any concurrent.futures executor), modes and
tradeoff for studies.

The compiled part is tribo._core (python/*.cpp); this package re-exports it and adds what is
written in Python: the notebook display (_notebook.py) and sweeps on executors (_sweep.py).
Nothing heavy is imported here: pandas and IPython only when their methods are called.
"""

from . import _core
from ._core import *  # noqa: F401,F403  (the public names of the extension)
from ._core import __version__  # noqa: F401  (the CMake project's version)
from . import _notebook
from ._sweep import sweep  # noqa: F401

_notebook.attach(_core.Result)

__all__ = [name for name in dir(_core) if not name.startswith("_")] + ["sweep", "__version__"]
