"""tribo.sweep: a parameter sweep on the local threads (as `tribo sweep`), one slice of it into
a folder shared by several processes (as `tribo sweep --slice I/N`), or on any
concurrent.futures executor (a ProcessPoolExecutor, Dask's Client.get_executor(), mpi4py's
MPIPoolExecutor): the points are sent to the executor as tasks (tribo._core._SweepTask
pickles as the scene's text, the values and the scene's Python laws) and their rows recorded
into a sweep folder as they come back, so every path ends in the same results.csv, byte for
byte. Not here: running a point (study/sweep/sweep_point.hpp).
"""

import concurrent.futures
import os
import pickle
import shutil
import sys
import tempfile

from . import _core


def _pickler(executor):
    """The pickler the executor sends tasks with: Dask's is cloudpickle, others pickle."""
    if type(executor).__module__.split(".")[0] == "distributed":
        try:
            import cloudpickle
            return cloudpickle
        except ImportError:
            pass
    return pickle


def _check_sendable(task, executor):
    """Raises TypeError naming the Python law the executor cannot send to its workers."""
    pickler = _pickler(executor)
    for name, law in task.laws.items():
        try:
            pickler.dumps(law)
        except Exception as e:  # pickling raises several types (PicklingError, AttributeError...)
            raise TypeError(
                f"sweep: the scene's law '{name}' ({type(law).__name__}) cannot be sent to the "
                f"executor's workers: {pickler.__name__} says: {e}. Define it at the top level of "
                "an importable module (a lambda or a local class does not pickle), or sweep on "
                "threads without it") from e


def _progress(done, total):
    sys.stderr.write(f"\rsweep: {done}/{total} points")
    if done == total:
        sys.stderr.write("\n")
    sys.stderr.flush()


def _on_executor(scene, grid, set, analysis, out, progress, executor):
    task = _core._SweepTask(scene, grid, set=set, analysis=analysis)
    _check_sendable(task, executor)
    temporary = out is None
    folder_path = tempfile.mkdtemp(prefix="tribo-sweep-") if temporary else os.fspath(out)
    try:
        folder = _core._SweepFolder(folder_path, task)
        missing = folder.missing()
        futures = {executor.submit(task.run_point, k): k for k in missing}
        try:
            for done, future in enumerate(concurrent.futures.as_completed(futures), 1):
                folder.record(futures[future], future.result())
                if progress:
                    _progress(done, len(futures))
        except BaseException:
            for future in futures:  # stop what has not started; rows recorded stay
                future.cancel()
            raise
        folder.write_results()
        return folder.rows()
    finally:
        if temporary:
            shutil.rmtree(folder_path, ignore_errors=True)


def sweep(scene, grid, set=None, jobs=0, analysis="run", out=None, keep_trajectories=False,
          progress=False, slice=None, executor=None):
    """sweep(scene, grid={name: 'START:STOP:COUNT' or [values]}, set={...}, jobs=0,
    analysis='run'|'modes', out=None, slice=None, executor=None) -> list of dicts, one per
    grid point: the rows of results.csv (numbers as floats).

    scene: a path or a Scene (its set= overrides apply to every point; a Scene with laws
    written in Python needs an executor). out=None: a temporary folder, removed afterwards;
    with out, the folder `tribo sweep --out` writes (resumable: points done are skipped).
    jobs: threads (0: one per core). slice='I/N' (with out): only the I-th of N interleaved
    slices, as `tribo sweep --slice`; returns None until every slice is done (then the rows;
    merge_sweep(out) completes the folder). executor: any concurrent.futures.Executor; the
    points run as its tasks (jobs is then unused), their rows recorded in out as they come
    back; Ctrl-C cancels what has not started and keeps what is done.
    """
    if executor is None:
        return _core._sweep_on_threads(scene, grid, set=set, jobs=jobs, analysis=analysis,
                                       out=out, keep_trajectories=keep_trajectories,
                                       progress=progress, slice=slice)
    if keep_trajectories:
        raise ValueError("sweep: keep_trajectories is for threads and slices (the executor's "
                         "workers may not share the out folder)")
    if slice is not None:
        raise ValueError("sweep: give either slice= (one process's part) or executor= (all "
                         "points on the executor), not both")
    return _on_executor(scene, grid, set, analysis, out, progress, executor)
