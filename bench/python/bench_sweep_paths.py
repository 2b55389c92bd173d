"""What each way of running a sweep costs against the threaded sweep, measured in one
process on the same grid (the belt, 400 speeds, every path on the machine's 2 cores):
  - `tribo sweep --jobs 2` (the baseline: one process, two threads);
  - two `tribo sweep --slice I/2 --jobs 1` processes at once into one folder (a job array's
    tasks on one machine: the cost of going through row files and the folder's lock);
  - tribo.sweep(executor=ProcessPoolExecutor(2)) (a task per point, pickled);
  - tribo.sweep(executor=Client(LocalCluster(2)).get_executor()) (Dask);
and how long `import tribo` takes (a fresh interpreter, minus one that imports nothing).
Prints the figures and the ratios; asserts nothing (timings are not tests).

    PYTHONPATH=build/python python3 bench/python/bench_sweep_paths.py [--points 400]
        [--duration 10] [--repeat 3] [--cli build/apps/tribo]
"""
import argparse
import concurrent.futures
import pathlib
import shutil
import subprocess
import sys
import tempfile

import tribo

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from bench_python import best  # noqa: E402  (the best of N wall times, as there)

ROOT = pathlib.Path(__file__).resolve().parents[2]
BELT = ROOT / "scenes" / "belt.yaml"


def fresh(path):
    shutil.rmtree(path, ignore_errors=True)
    return path


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--points", type=int, default=400)
    parser.add_argument("--duration", type=float, default=10.0)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--cli", default=str(ROOT / "build" / "apps" / "tribo"))
    args = parser.parse_args()

    py = sys.executable
    nothing = best(lambda: subprocess.run([py, "-c", "pass"], check=True), 10)
    imported = best(lambda: subprocess.run([py, "-c", "import tribo"], check=True), 10)
    print(f"import tribo: {imported - nothing:.3f} s (interpreter start {nothing:.3f} s apart)")

    work = pathlib.Path(tempfile.mkdtemp(prefix="tribo-bench-sweep-"))
    grid = f"v_b=0.2:3:{args.points}"
    common = ["--grid", grid, "--set", f"duration={args.duration}", "--quiet"]

    def threads():
        subprocess.run([args.cli, "sweep", str(BELT), "--out", str(fresh(work / "threads")),
                        "--jobs", "2"] + common, check=True)

    def slices():
        out = fresh(work / "slices")
        procs = [subprocess.Popen([args.cli, "sweep", str(BELT), "--out", str(out), "--jobs",
                                   "1", "--slice", f"{i}/2"] + common) for i in (1, 2)]
        assert all(p.wait() == 0 for p in procs)
        assert (out / "results.csv").exists()

    sweep_args = dict(grid={"v_b": f"0.2:3:{args.points}"}, set={"duration": args.duration})

    def pool():
        with concurrent.futures.ProcessPoolExecutor(max_workers=2) as ex:
            tribo.sweep(BELT, out=fresh(work / "pool"), executor=ex, **sweep_args)

    figures = {"threads (tribo sweep --jobs 2)": best(threads, args.repeat),
               "2 slices at once (--slice I/2 --jobs 1)": best(slices, args.repeat),
               "ProcessPoolExecutor(2)": best(pool, args.repeat)}
    try:
        import distributed
        with distributed.LocalCluster(n_workers=2, threads_per_worker=1,
                                      dashboard_address=None) as cluster, \
                distributed.Client(cluster) as client:
            ex = client.get_executor()
            figures["Dask LocalCluster(2)"] = best(
                lambda: tribo.sweep(BELT, out=fresh(work / "dask"), executor=ex, **sweep_args),
                args.repeat)
    except ImportError:
        print("(no Dask: python3-distributed is not installed)")
    base = figures["threads (tribo sweep --jobs 2)"]
    print(f"{args.points} belt points of {args.duration} s simulated, best of {args.repeat}:")
    for name, seconds in figures.items():
        print(f"  {name:42s} {seconds:7.2f} s  {seconds / base:5.2f}x the threads")
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
