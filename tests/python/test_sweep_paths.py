"""Every way to run a sweep from Python ends in the results.csv `tribo sweep` writes: the
slices of one grid run as separate calls (as `tribo sweep --slice I/N`, then merge_sweep),
and the points sent to a concurrent.futures executor (a ProcessPoolExecutor, a Dask
LocalCluster), give the command line's rows, field for field (clock readings apart); a
folder part done by a slice is finished by an executor without re-running a point; a scene
whose law is written in Python sweeps on an executor and gives the built-in law's figures,
and a law that cannot be pickled is refused by name before anything runs."""
import concurrent.futures
import csv
import math
import subprocess

import pytest

import tribo

CLOCK = {"wall_seconds", "simulated_per_wall"}  # clock readings differ from run to run
GRID = {"v_b": "0.5:1.5:3", "k": [200, 300]}
FIXED = {"duration": 3}
CLI_GRID = ["--grid", "v_b=0.5:1.5:3", "--list", "k=200,300", "--set", "duration=3"]


def read(path):
    with open(path, newline="") as f:
        return list(csv.reader(f))


def without_clock(table):
    header = table[0]
    keep = [i for i, name in enumerate(header) if name not in CLOCK]
    return [[row[i] for i in keep] for row in table]


@pytest.fixture(scope="module")
def cli_results(cli, belt, tmp_path_factory):
    out = tmp_path_factory.mktemp("cli")
    subprocess.run([cli, "sweep", belt, "--out", str(out), "--quiet", "--jobs", "2"] + CLI_GRID,
                   check=True, capture_output=True)
    return without_clock(read(out / "results.csv"))


def test_slices_then_merge_give_the_cli_results(belt, cli_results, tmp_path):
    out = tmp_path / "sliced"
    assert tribo.sweep(belt, grid=GRID, set=FIXED, out=out, slice="1/3") is None
    assert tribo.sweep(belt, grid=GRID, set=FIXED, out=out, slice="3/3") is None
    with pytest.raises(RuntimeError, match=r"2 of 6 points .* have no row yet \(points 1, 4\)"):
        tribo.merge_sweep(out)
    rows = tribo.sweep(belt, grid=GRID, set=FIXED, out=out, slice="2/3")  # the last one merges
    assert len(rows) == 6
    assert without_clock(read(out / "results.csv")) == cli_results
    assert tribo.merge_sweep(out) == rows


def test_a_slice_is_checked(belt, tmp_path):
    with pytest.raises(ValueError, match="slice needs an out folder"):
        tribo.sweep(belt, grid=GRID, slice="1/2")
    with pytest.raises(ValueError, match="--slice"):
        tribo.sweep(belt, grid=GRID, out=tmp_path, slice="3/2")


def test_a_process_pool_gives_the_cli_results(belt, cli_results, tmp_path):
    with concurrent.futures.ProcessPoolExecutor(max_workers=2) as pool:
        rows = tribo.sweep(belt, grid=GRID, set=FIXED, out=tmp_path / "pool", executor=pool)
    assert len(rows) == 6
    assert without_clock(read(tmp_path / "pool" / "results.csv")) == cli_results


def test_an_executor_finishes_a_folder_a_slice_began(belt, cli_results, tmp_path):
    out = tmp_path / "mixed"
    tribo.sweep(belt, grid=GRID, set=FIXED, out=out, slice="1/2")
    before = {p.name: p.stat().st_mtime_ns for p in (out / "rows").iterdir()}
    assert len(before) == 3

    class Counting(concurrent.futures.ThreadPoolExecutor):
        submitted = []

        def submit(self, fn, *args, **kwargs):
            self.submitted.append(args[0])
            return super().submit(fn, *args, **kwargs)

    with Counting(max_workers=2) as pool:
        tribo.sweep(belt, grid=GRID, set=FIXED, out=out, executor=pool)
    assert sorted(Counting.submitted) == [1, 3, 5]  # only slice 2/2's points ran
    assert {p.name: p.stat().st_mtime_ns for p in (out / "rows").iterdir()
            if p.name in before} == before
    assert without_clock(read(out / "results.csv")) == cli_results


def test_a_dask_cluster_gives_the_cli_results(belt, cli_results, tmp_path):
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            rows = tribo.sweep(belt, grid=GRID, set=FIXED, out=tmp_path / "dask",
                               executor=client.get_executor())
    assert len(rows) == 6
    assert without_clock(read(tmp_path / "dask" / "results.csv")) == cli_results


# The belt's roh_yoo law written in Python, at module level so that it pickles by reference.
P = dict(mu_s=0.35, mu_k=0.3, v_s=0.01, a=1.5, beta=1 / 3)


class RohYoo:
    stick_speed = P["v_s"]

    def mu(self, v):
        s, v = math.copysign(1.0, v), abs(v)
        if v <= P["v_s"]:
            return s * P["mu_s"] * (v / P["v_s"]) ** P["beta"]
        return s * (P["mu_k"] + (P["mu_s"] - P["mu_k"]) * P["a"] ** -(v - P["v_s"]))


def test_a_python_law_sweeps_on_an_executor(belt, cli_results):
    scene = tribo.load_scene(belt, set={"friction": "mine"}, laws={"mine": RohYoo()})
    with pytest.raises(ValueError, match="executor"):
        tribo.sweep(scene, grid=GRID, set=FIXED)  # threads cannot share a Python law
    with concurrent.futures.ProcessPoolExecutor(max_workers=2) as pool:
        rows = tribo.sweep(scene, grid=GRID, set=FIXED, executor=pool)
    header = cli_results[0]
    for ours, theirs in zip(rows, cli_results[1:]):
        cli_row = dict(zip(header, theirs))
        assert ours["status"] == cli_row["status"] == "complete"
        # The same formula in another language: round-off apart, the same orbits.
        for key in ("amplitude_pp", "period"):
            assert ours[key] == pytest.approx(float(cli_row[key]), rel=1e-6), key


def test_a_law_that_does_not_pickle_is_named(belt):
    scene = tribo.load_scene(belt, set={"friction": "mine"},
                             laws={"mine": lambda v: 0.3 * math.tanh(v / 1e-3)})
    with concurrent.futures.ProcessPoolExecutor(max_workers=1) as pool:
        with pytest.raises(TypeError, match=r"law 'mine' \(function\) cannot be sent"):
            tribo.sweep(scene, grid={"v_b": [1.0]}, executor=pool)


def test_executor_errors(belt, tmp_path):
    with concurrent.futures.ThreadPoolExecutor(1) as pool:
        with pytest.raises(ValueError, match="not both"):
            tribo.sweep(belt, grid=GRID, out=tmp_path, slice="1/2", executor=pool)
        with pytest.raises(tribo.SweepSpecError, match="not a parameter"):
            tribo.sweep(belt, grid={"nope": [1]}, executor=pool)
