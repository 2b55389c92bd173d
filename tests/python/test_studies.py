"""Studies from Python: tribo.sweep gives the rows `tribo sweep` writes to results.csv, and
tribo.modes the belt's unstable pair at the growth rate of the 1-DOF formula
sigma = -(c + N mu'(v_b)) / (2 m) and the damped frequency, computed here from the law's slope."""
import csv
import json
import math
import subprocess

import pytest

import tribo


def test_sweep_rows_equal_the_cli(cli, belt, tmp_path):
    grid = {"v_b": "0.5:1.5:3", "k": [200, 300]}
    fixed = {"duration": 3}
    rows = tribo.sweep(belt, grid=grid, set=fixed, jobs=2)
    assert len(rows) == 6
    args = [cli, "sweep", belt, "--out", str(tmp_path / "cli"), "--quiet", "--jobs", "1",
            "--grid", "v_b=0.5:1.5:3", "--list", "k=200,300", "--set", "duration=3"]
    subprocess.run(args, check=True, capture_output=True)
    with open(tmp_path / "cli" / "results.csv", newline="") as f:
        cli_rows = list(csv.DictReader(f))
    assert len(cli_rows) == 6
    skip = {"wall_seconds", "simulated_per_wall"}  # clock readings differ from run to run
    for ours, theirs in zip(rows, cli_rows):
        assert set(ours) == set(theirs)
        for key, text in theirs.items():
            if key in skip:
                continue
            value = ours[key]
            if text == "":
                assert value is None, key
            elif isinstance(value, float):
                assert value == float(text), key
            else:
                assert value == text, key


def test_sweep_into_a_folder_resumes(belt, tmp_path):
    out = tmp_path / "map"
    first = tribo.sweep(belt, grid={"v_b": [1.0, 2.0]}, set={"duration": 2}, out=out)
    again = tribo.sweep(belt, grid={"v_b": [1.0, 2.0]}, set={"duration": 2}, out=out)
    assert (out / "results.csv").exists()
    assert [r["v_b"] for r in first] == [1.0, 2.0]
    assert again == first  # nothing re-run: the same rows, timings included


@pytest.mark.parametrize("v_b,k", [(1.5, 300.0), (0.4, 300.0), (3.0, 120.0)])
def test_modes_of_the_belt_follow_the_formula(belt, v_b, k):
    scene = tribo.load_scene(belt, set={"v_b": v_b, "k": k})
    result = tribo.modes(scene)
    m, g = 10.0, 9.81
    law = tribo.friction_law("roh_yoo", mu_s=0.35, mu_k=0.3, v_s=0.01, a=1.5, beta=1 / 3)
    sigma = -(0.0 + m * g * law.slope(v_b)) / (2 * m)  # the belt spring has no damping
    freq = math.sqrt(k / m - sigma**2) / (2 * math.pi)
    lead = result["modes"][0]
    assert lead["unstable"] and result["unstable_count"] >= 1 and not result["stable"]
    assert lead["growth_rate"] == pytest.approx(sigma, rel=1e-4)
    assert lead["frequency_hz"] == pytest.approx(freq, rel=1e-4)
    assert lead["eigenvalue"] == pytest.approx([sigma, 2 * math.pi * freq], rel=1e-4)
    shape = {e["coordinate"]: e["magnitude"] for e in lead["shape"]}
    assert shape["box.x"] == pytest.approx(1.0)


def test_modes_dict_is_the_cli_modes_json(cli, belt, tmp_path):
    """One source: tribo.modes gives modes.json's document, field for field."""
    result = tribo.modes(tribo.load_scene(belt, set={"v_b": 0.4}))
    subprocess.run([cli, "modes", belt, "--out", str(tmp_path), "--set", "v_b=0.4"],
                   capture_output=True)
    with open(tmp_path / "modes.json") as f:
        theirs = json.load(f)
    assert set(result) == set(theirs)
    timing = {"steady_state_s", "linearization_and_eigenvalues_s"}  # clock readings
    assert {k: v for k, v in result["timing"].items() if k not in timing} == {
        k: v for k, v in theirs["timing"].items() if k not in timing}
    for key in set(theirs) - {"timing", "scene"}:
        assert result[key] == theirs[key], key


def test_modes_errors():
    kinematic_only = """
simulation: {duration: 1, time_step: 1.0e-3}
bodies:
  - {name: ground, kind: kinematic, geometry: [{name: floor, shape: halfspace}]}
"""
    with pytest.raises(tribo.Error) as e:
        tribo.modes(tribo.load_scene(kinematic_only))
    assert "dynamic" in str(e.value) or "no body" in str(e.value)


def test_tradeoff_rows_equal_the_cli(cli, belt, tmp_path):
    fixed = {"duration": 4}
    rows = tribo.tradeoff(belt, set=fixed, integrators=["rk4"], window=3)
    subprocess.run([cli, "tradeoff", belt, "--out", str(tmp_path), "--integrators", "rk4",
                    "--window", "3", "--set", "duration=4"], check=True, capture_output=True)
    with open(tmp_path / "tradeoff.csv", newline="") as f:
        cli_rows = list(csv.DictReader(f))
    assert len(rows) == len(cli_rows) > 5
    assert rows[0]["status"] == "reference"
    for ours, theirs in zip(rows, cli_rows):
        assert list(ours) == list(theirs)  # one source: the same columns in the same order
        assert ours["status"] == theirs["status"]
        assert (ours["integrator"], ours["setting"]) == (theirs["integrator"], theirs["setting"])
        assert ours["steps"] == int(theirs["steps"])
        for key in ("amplitude_error", "trajectory_error"):
            if theirs[key] == "":
                assert math.isnan(ours[key])
            else:  # the file keeps 4 significant digits of the errors
                assert format(ours[key], ".4g") == theirs[key]
    # rk4 converges: the error of the finest complete step is below the coarsest's
    done = [r for r in rows[1:] if r["status"] == "complete"]
    assert all(r["setting"] == "dt" for r in done)
    assert done[-1]["value"] < done[0]["value"]
    assert done[-1]["trajectory_error"] < done[0]["trajectory_error"]


def test_orbit_is_the_cli_orbit_json(cli, belt, tmp_path):
    """tribo.orbit gives the document `tribo orbit` writes (the same numbers, the orbit at half
    the step among them; step_check=False leaves it out), with the sampled period as arrays
    that start and end on the orbit's maximum."""
    subprocess.run([cli, "orbit", belt, "--out", str(tmp_path), "--set", "duration=30"],
                   check=True, capture_output=True)
    theirs = json.loads((tmp_path / "orbit.json").read_text())
    ours = tribo.orbit(tribo.load_scene(belt, set={"duration": 30}))
    for key in ("period", "amplitude_pp", "stable", "multipliers", "start", "newton",
                "step_check"):
        assert ours[key] == theirs[key], key
    assert "step_check" not in tribo.orbit(tribo.load_scene(belt, set={"duration": 30}),
                                           step_check=False)
    assert ours["t"][0] == 0 and ours["t"][-1] == pytest.approx(ours["period"], abs=1e-12)
    assert ours["x"][0] == pytest.approx(ours["x"][-1], abs=1e-7)
    with pytest.raises(tribo.OrbitError, match="no oscillation"):
        tribo.orbit(tribo.load_scene(belt, set={"v_b": 0, "duration": 3}))


def test_orbit_newton_only_is_the_same_orbit_at_more_periods_of_integration(belt):
    """The return-map iterations (default) and Newton's method alone (newton_only=True, as
    --newton-only) find the same stick-slip orbit; the first converges within ten periods of
    integration, the second spends a 26-flow Jacobian an iteration."""
    scene = tribo.load_scene(belt, set={"duration": 30})
    fast = tribo.orbit(scene)
    slow = tribo.orbit(scene, newton_only=True)
    assert fast["period"] == pytest.approx(slow["period"], rel=1e-9)
    assert fast["amplitude_pp"] == pytest.approx(slow["amplitude_pp"], rel=1e-8)
    assert fast["newton"]["picard_iterations"] >= 1
    assert slow["newton"]["picard_iterations"] == 0
    assert fast["newton"]["periods_to_converge"] <= 10
    assert slow["newton"]["periods_to_converge"] >= 26


def test_forced_orbit_is_the_linear_oscillators_closed_form_response(source_dir):
    """A block shaken by F0 sin(w t) on a spring and a damper has a forced orbit of the
    forcing's period, of peak-to-peak 2 F0 / |k - m w^2 + i c w| (closed form here), with
    both multipliers of the slide at exp(-c T / 2m); periods=2 gives the same response over
    two forcing periods; a period that does not fit the forcing is refused naming it."""
    scene = tribo.load_scene(str(source_dir / "scenes" / "forced_oscillator.yaml"),
                             set={"m": 2.0, "k": 300.0, "c": 3.0, "F0": 6.0, "f": 2.0})
    m, k, c, f0, w = 2.0, 300.0, 3.0, 6.0, 2 * math.pi * 2.0
    o = tribo.orbit(scene)
    assert o["forced"] and o["forcing_period"] == pytest.approx(0.5, rel=1e-12)
    assert o["period"] == pytest.approx(0.5, rel=1e-12)
    assert o["amplitude_pp"] == pytest.approx(2 * f0 / math.hypot(k - m * w * w, c * w), rel=1e-6)
    slide = math.exp(-c * 0.5 / (2 * m))
    assert [mu["modulus"] for mu in o["multipliers"][:2]] == pytest.approx([slide] * 2, rel=1e-6)
    assert "trivial_multiplier_error" not in o
    two = tribo.orbit(scene, periods=2)
    assert two["period"] == pytest.approx(1.0, rel=1e-12)
    assert two["amplitude_pp"] == pytest.approx(o["amplitude_pp"], rel=1e-7)
    with pytest.raises(tribo.OrbitError, match="not a whole number of load 'shaker'"):
        tribo.orbit(scene, period=0.3)
    with pytest.raises(ValueError, match="periods >= 1"):
        tribo.orbit(scene, periods=0)
    # Matrix-free shooting: the same orbit, the 8 leading multipliers.
    k = tribo.orbit(scene, solver="krylov")
    assert k["newton"]["solver"] == "krylov" and o["newton"]["solver"] == "dense"
    assert k["amplitude_pp"] == pytest.approx(o["amplitude_pp"], rel=1e-9)
    assert len(k["multipliers"]) == 8 and k["multipliers"][0]["modulus"] == pytest.approx(slide)
    with pytest.raises(ValueError, match="solver must be"):
        tribo.orbit(scene, solver="lu")


def test_sweep_of_forced_orbits_is_the_frequency_response_curve(source_dir):
    """analysis="orbit" gives each point's orbit: over the forcing frequency of the forced
    oscillator, the closed-form response 2 F0 / |k - m w^2 + i c w| through resonance."""
    scene = str(source_dir / "scenes" / "forced_oscillator.yaml")
    rows = tribo.sweep(scene, grid={"f": [0.8, 1.59, 2.4]}, set={"duration": 10}, jobs=2,
                       analysis="orbit")
    assert [r["status"] for r in rows] == ["complete"] * 3
    for r in rows:
        w = 2 * math.pi * r["f"]
        assert r["amplitude_pp"] == pytest.approx(20 / math.hypot(100 - w * w, 2 * w), rel=1e-6)
        assert r["stable"] == 1
    with pytest.raises(ValueError, match="'run', 'modes' or 'orbit'"):
        tribo.sweep(scene, grid={"f": [1]}, analysis="orbits")


def test_orbit_branch_points_are_the_orbits_at_their_parameter(belt):
    """tribo.orbit_branch continues the belt's orbit in v_b as `tribo orbit --continue` does;
    each point is the orbit tribo.orbit finds at that v_b (the same shooting: equal to
    rounding, measured 4e-16), its columns are the branch's points as arrays, and each
    point's sampled orbit spans one period."""
    b = tribo.orbit_branch(tribo.load_scene(belt), "v_b", 1.0, 1.5, step=0.25, max_points=4)
    assert b["status"] == "reached_end"
    cols = b["columns"]
    n = len(b["branch"])
    assert n >= 3 and len(b["orbits"]) == n
    assert cols["parameter"][0] == 1.0 and cols["parameter"][-1] >= 1.5
    assert cols["stable"].dtype == bool and all(cols["stable"])
    for i, point in enumerate(b["branch"]):
        assert cols["period"][i] == point["period"]
        assert cols["amplitude_pp"][i] == point["amplitude_pp"]
        t = b["orbits"][i]["t"]
        assert t[0] == 0 and t[-1] == pytest.approx(point["period"], abs=1e-12)
    for i in (1, n - 1):
        alone = tribo.orbit(tribo.load_scene(belt, set={"v_b": float(cols["parameter"][i])}))
        assert alone["period"] == pytest.approx(cols["period"][i], rel=1e-9)
        assert alone["amplitude_pp"] == pytest.approx(cols["amplitude_pp"][i], rel=1e-9)
    with pytest.raises(tribo.SceneError, match="not a parameter"):
        tribo.orbit_branch(tribo.load_scene(belt), "no_such", 1.0, 1.5)
    with pytest.raises(ValueError, match="max_points must be >= 2"):
        tribo.orbit_branch(tribo.load_scene(belt), "v_b", 1.0, 1.5, max_points=1)
    with pytest.raises(ValueError, match="arclength must be 'si' or 'scaled'"):
        tribo.orbit_branch(tribo.load_scene(belt), "v_b", 1.0, 1.5, arclength="SI")


def test_orbit_branch_scaled_arclength_weighs_the_parameter_by_its_range(belt):
    """arclength='scaled' measures each unknown over its scale: the parameter over the range
    (0.5 here), the period over the first period; a step of 0.1 (the default) then moves the
    belt speed by at most 4 x 0.1 of the range, and the points are the orbits at their speed."""
    b = tribo.orbit_branch(tribo.load_scene(belt), "v_b", 1.0, 1.5, max_points=3,
                           arclength="scaled")
    settings = b["settings"]
    assert settings["arclength_norm"] == "scaled"
    assert settings["weights"]["parameter"] == 0.5
    assert settings["weights"]["period"] == b["branch"][0]["period"]
    p = b["columns"]["parameter"]
    assert len(p) == 3 and all(0 < p[i + 1] - p[i] <= 0.2 + 1e-12 for i in range(2))
    alone = tribo.orbit(tribo.load_scene(belt, set={"v_b": float(p[-1])}))
    assert alone["period"] == pytest.approx(b["columns"]["period"][-1], rel=1e-9)


def test_orbit_branch_from_hopf_starts_where_the_damper_cancels_the_slope(belt):
    """from_hopf=True starts the branch at the damped Stribeck belt's Hopf point: where the
    10 N s/m damper cancels the law's falling slope, c = -mu'(v_H) m g (closed form by
    bisection here), with the undamped period 2 pi sqrt(m / k) there; the unstable cycle
    born there lives where steady sliding is stable (v_b > v_H)."""
    d_mu, v_st, mg, c = 0.05, 0.15, 10 * 9.81, 10.0

    def excess(v):  # -mu'(v) m g - c
        s = v / v_st
        return 2 * d_mu * s / v_st * math.exp(-s * s) * mg - c

    lo, hi = v_st / math.sqrt(2), 1.0
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if excess(mid) > 0 else (lo, mid)
    scene = tribo.load_scene(
        belt, set={"friction": "stribeck", "springs[wall_spring].damping": c})
    b = tribo.orbit_branch(scene, "v_b", 0.15, 0.5, step=0.004, max_points=2, from_hopf=True)
    assert b["start"] == "hopf"
    assert b["hopf"]["parameter"] == pytest.approx(lo, rel=1e-5)
    assert b["hopf"]["period"] == pytest.approx(2 * math.pi * math.sqrt(10 / 300), rel=1e-6)
    assert all(p > lo for p in b["columns"]["parameter"])
    assert not any(b["columns"]["stable"])
    with pytest.raises(tribo.OrbitError, match="no Hopf point between"):
        tribo.orbit_branch(scene, "v_b", 0.3, 0.6, from_hopf=True)
    with pytest.raises(ValueError, match="hopf_amplitude >= 0"):
        tribo.orbit_branch(scene, "v_b", 0.15, 0.5, from_hopf=True, hopf_amplitude=-1)


def test_orbit_branch_of_a_forced_scene_follows_the_frequency_response(source_dir):
    """A scene whose inputs vary in time gives a branch of forced orbits: in the forcing
    frequency f, each point is the forced linear oscillator's closed-form response
    2 F0 / sqrt((k - m w^2)^2 + (c w)^2) (m 1, k 100, c 2, F0 10) with period 1 / f, or
    periods / f with periods=2; a bad period is refused before any work."""
    scene = tribo.load_scene(str(source_dir / "scenes" / "forced_oscillator.yaml"))
    b = tribo.orbit_branch(scene, "f", 1.0, 1.2, max_points=3, arclength="scaled", step=0.3)
    assert b["forced"] is True
    for f, amplitude, period in zip(b["columns"]["parameter"], b["columns"]["amplitude_pp"],
                                    b["columns"]["period"]):
        w = 2 * math.pi * f
        assert amplitude == pytest.approx(20 / math.hypot(100 - w * w, 2 * w), rel=1e-4)
        assert period * f == pytest.approx(1.0, abs=1e-9)
    two = tribo.orbit_branch(scene, "f", 1.0, 1.2, max_points=2, periods=2)
    assert two["periods"] == 2
    assert two["branch"][0]["period"] == pytest.approx(2.0, rel=1e-9)
    with pytest.raises(ValueError, match="periods >= 1"):
        tribo.orbit_branch(scene, "f", 1.0, 1.2, periods=0)


def test_orbit_branch_switches_at_the_parametric_pendulums_period_doubling(source_dir):
    """switch='period_doubling' follows the shaken pendulum's hanging orbit to the edge of the
    damped Mathieu equation's first tongue (multiplier -1; its frequency found here by RK4 on
    th'' + (c th' + m L (g + a(t)) th) / I_O = 0 and bisection) and returns the swinging
    orbits of twice the shaking's period that leave it there; a kind it does not know is
    refused."""
    m, L, i_bob, c, V, g = 1.0, 1.0, 1e-4, 0.1, 0.5, 9.81
    inertia = i_bob + m * L * L

    def monodromy_g(f, n=2000):
        def rhs(t, y):
            a = 2 * math.pi * f * V * math.cos(2 * math.pi * f * t)
            return (y[1], -(c * y[1] + m * L * (g + a) * y[0]) / inertia)

        def flow(y):
            h, t = 1 / f / n, 0.0
            for _ in range(n):
                k1 = rhs(t, y)
                k2 = rhs(t + h / 2, (y[0] + h / 2 * k1[0], y[1] + h / 2 * k1[1]))
                k3 = rhs(t + h / 2, (y[0] + h / 2 * k2[0], y[1] + h / 2 * k2[1]))
                k4 = rhs(t + h, (y[0] + h * k3[0], y[1] + h * k3[1]))
                y = tuple(y[j] + h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]) for j in (0, 1))
                t += h
            return y

        a, b = flow((1.0, 0.0)), flow((0.0, 1.0))
        tr, det = a[0] + b[1], a[0] * b[1] - a[1] * b[0]
        disc = tr * tr / 4 - det
        return math.sqrt(det) - 1 if disc < 0 else -(tr / 2 - math.sqrt(disc)) - 1

    lo, hi = 1.06, 1.12  # unstable at lo, stable at hi
    for _ in range(40):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if monodromy_g(mid) > 0 else (lo, mid)
    scene = tribo.load_scene(str(source_dir / "scenes" / "parametric_pendulum.yaml"))
    b = tribo.orbit_branch(scene, "f", 1.2, 0.85, step=0.1, max_points=3,
                           switch="period_doubling")
    assert b["switch"]["found"] is True
    assert b["switch"]["parameter"] == pytest.approx(lo, rel=1e-6)
    assert b["switch"]["multiplier"]["re"] == pytest.approx(-1.0, abs=1e-8)
    assert len(b["primary_columns"]["parameter"]) == b["switch"]["primary_points"]
    assert max(b["primary_columns"]["amplitude_pp"]) < 1e-12  # hanging straight down
    for f, period in zip(b["columns"]["parameter"], b["columns"]["period"]):
        assert f * period == pytest.approx(2.0, rel=1e-9)
    assert b["columns"]["amplitude_pp"][-1] > 0.1
    with pytest.raises(ValueError, match="switch must be"):
        tribo.orbit_branch(scene, "f", 1.2, 0.85, switch="torus")
