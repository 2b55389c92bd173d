"""Scene.run gives the numbers `tribo run` writes: every trajectory column equal to
trajectory.csv's text at the file's 10 significant digits, and the summary dict equal to
summary.json except the wall-clock figures."""
import csv
import json
import subprocess

import numpy as np
import pytest

import tribo

SETTINGS = {"duration": "4"}  # 4 s of the belt: the limit cycle has formed (period ~0.9 s)


def cli_run(cli, scene, out, settings):
    args = [cli, "run", scene, "--out", str(out), "--quiet"]
    for k, v in settings.items():
        args += ["--set", f"{k}={v}"]
    run = subprocess.run(args, capture_output=True, text=True)
    with open(out / "trajectory.csv", newline="") as f:
        rows = list(csv.reader(f))
    with open(out / "summary.json") as f:
        summary = json.load(f)
    return rows[0], rows[1:], summary, run


def strip_clock(summary):
    run = dict(summary["run"])
    for key in ("wall_seconds", "simulated_seconds_per_wall_second"):
        run.pop(key)
    return {**summary, "run": run}


@pytest.mark.parametrize("settings,status", [
    ({"friction": "roh_yoo"}, "complete"),
    ({"friction": "lugre", "integrator": "semi_implicit_euler", "dt": 1e-4}, "complete"),
    # LuGre's bristles need a smaller step than rk4's 1 ms: the run stops part way, and
    # both keep the same rows up to the last good step and say the same about it.
    ({"friction": "lugre"}, "diverged"),
])
def test_belt_run_equals_cli(cli, belt, tmp_path, settings, status):
    settings = {**SETTINGS, **settings}
    header, rows, summary, run = cli_run(cli, belt, tmp_path, settings)
    assert run.returncode == (0 if status == "complete" else 3)
    result = tribo.load_scene(belt, set=settings).run()
    assert result.status == status == summary["status"]
    if status != "complete":
        assert result.message and result.message in run.stderr
    assert result.columns == header
    assert len(result["t"]) == len(rows)
    for c, name in enumerate(header):
        ours = [format(v, ".10g") if np.isfinite(v) else "" for v in result[name]]
        theirs = [row[c] for row in rows]
        # to_chars' general format at 10 digits is printf's %.10g
        assert ours == theirs, name
    assert strip_clock(result.summary) == strip_clock(summary)


def test_arrays_view_the_recording(belt):
    result = tribo.load_scene(belt, set=SETTINGS).run(duration=1.0)
    x = result["box.x"]
    assert not x.flags.owndata and not x.flags.writeable  # a view, read-only
    assert np.shares_memory(x, result.trajectory["box.x"])
    del result  # the array keeps the recording alive
    assert np.isfinite(x).all() and len(x) == 1001


def test_run_settings_replace_the_scenes(belt):
    scene = tribo.load_scene(belt)
    assert scene.settings["duration"] == 60.0
    result = scene.run(duration=0.5, time_step=5e-4, integrator="semi_implicit_euler")
    assert result.summary["settings"] == {
        **result.summary["settings"],
        "integrator": "semi_implicit_euler",
        "time_step": 5e-4,
        "duration": 0.5,
    }
    assert result["t"][-1] == pytest.approx(0.5, abs=1e-12)
    with pytest.raises(ValueError, match="integrator"):
        scene.run(integrator="leapfrog")
