"""The friction test bench's presliding experiment (scenes/experiments/presliding_drift.yaml)
against the block's one-degree-of-freedom equations integrated here by hand (RK4 at 25 us,
sharing nothing with the engine but the laws' published formulas): under an oscillating
load that never reaches the Coulomb level, LuGre's block walks forward every cycle and the
elasto-plastic one (Dupont, Hayward, Armstrong & Altpeter, IEEE TAC 47(5) 2002) stays in its
elastic range and does not, at two load levels and two frequencies."""
import math
import pathlib

import numpy as np
import pytest

import tribo

SIGMA0, SIGMA1, SIGMA2 = 1.0e5, math.sqrt(1.0e5), 0.4
MU_C, MU_S, V_S = 1.0, 1.5, 1.0e-3
F_N, M = 1.0, 1.0  # 1 kg under gravity 1 m/s^2


def g(v):
    return MU_C + (MU_S - MU_C) * math.exp(-(v / V_S) ** 2)


def alpha(z, v, law):
    """1 for LuGre; the elasto-plastic blend for the other (z_ba = 0.7 mu_c / sigma0)."""
    if law == "lugre":
        return 1.0
    z_ba, z_ss = 0.7 * MU_C / SIGMA0, g(abs(v)) / SIGMA0
    if abs(z) <= z_ba or z * v <= 0:
        return 0.0
    if abs(z) >= z_ss:
        return 1.0
    return 0.5 * (1 + math.sin(math.pi * (abs(z) - 0.5 * (z_ss + z_ba)) / (z_ss - z_ba)))


def rk4_samples(rates, y, duration, samples, h):
    """y[0] at the sample times (evenly spaced from 0) of y' = rates(t, y), y a tuple, by RK4
    at step h to `duration`."""
    out = []
    steps = int(round(duration / h))
    every = int(round((samples[1] - samples[0]) / h))
    for i in range(steps + 1):
        if i % every == 0:
            out.append(y[0])
        if i == steps:
            break
        t = i * h
        k1 = rates(t, y)
        k2 = rates(t + h / 2, tuple(a + h / 2 * b for a, b in zip(y, k1)))
        k3 = rates(t + h / 2, tuple(a + h / 2 * b for a, b in zip(y, k2)))
        k4 = rates(t + h, tuple(a + h * b for a, b in zip(y, k3)))
        y = tuple(a + h / 6 * (b1 + 2 * b2 + 2 * b3 + b4)
                  for a, b1, b2, b3, b4 in zip(y, k1, k2, k3, k4))
    return np.array(out)


def reference(law, f_b, f_a, freq, duration, samples, h=2.5e-5):
    """x at the sample times of m v' = F(t) - F_n (sigma0 z + sigma1 z' + sigma2 v),
    z' = v - alpha sigma0 |v| z / g(|v|), x' = v, from rest with z = 0."""

    def rates(t, y):
        _, v, z = y
        zdot = v - alpha(z, v, law) * SIGMA0 * abs(v) * z / g(abs(v))
        force = f_b + f_a * math.sin(2 * math.pi * freq * t)
        return v, (force - F_N * (SIGMA0 * z + SIGMA1 * zdot + SIGMA2 * v)) / M, zdot

    return rk4_samples(rates, (0.0, 0.0, 0.0), duration, samples, h)


@pytest.mark.parametrize("law", ["lugre", "elasto_plastic"])
@pytest.mark.parametrize("f_b,f_a,freq", [(0.35, 0.3, 2.0), (0.2, 0.15, 5.0)])
def test_presliding_drift_follows_the_block_equations(source_dir, law, f_b, f_a, freq):
    scene = pathlib.Path(source_dir) / "scenes" / "experiments" / "presliding_drift.yaml"
    duration = 3.0
    run = tribo.load_scene(str(scene), set={"friction": law, "F_b": f_b, "F_a": f_a, "f": freq,
                                            "duration": duration}).run()
    assert run.status == "complete", run.message
    t, x = run["t"], run["block.x"]
    ref = reference(law, f_b, f_a, freq, duration, t)
    assert len(ref) == len(x)
    # The engine (four contact corners, RK4 at 50 us) against the 1-DOF equations: to 1e-11 m
    # (measured 2.0e-12 m at worst, lugre at 2 Hz) while the block moves by up to 2.4e-5 m.
    assert np.max(np.abs(x - ref)) < 1e-11
    # Whole periods apart (the load's phase the same): LuGre walks, elasto-plastic does not.
    period = int(round(1 / freq / (t[1] - t[0])))
    walk = x[-1] - x[-1 - 2 * period]  # over the last two periods
    if law == "lugre":
        assert walk > 1e-6  # measured 6.2e-6 m (2 Hz) and 1.7e-6 m (5 Hz) per two cycles
    else:
        assert abs(walk) < 1e-12  # measured 9e-17 m: it ends each cycle where it began


def ratchet_reference(ratio, samples, mu=0.3, g=9.81, v_eps=1e-3, freq=2.0, h=1e-4):
    """x at the sample times of the ratchet's block (scenes/experiments/ratchet_drive.yaml):
    u' = ratio mu g sin(2 pi f t) - r mu g tanh(r u / v_eps), r = 0.5 forward, 1.5 backward
    (the law sees the speed r u along its axis: contact/anisotropy.hpp); RK4 at the scene's
    step."""

    def rates(t, y):
        u = y[1]
        r = 0.5 if u >= 0 else 1.5
        return u, (ratio * mu * g * math.sin(2 * math.pi * freq * t)
                   - r * mu * g * math.tanh(r * u / v_eps))

    return rk4_samples(rates, (0.0, 0.0), samples[-1], samples, h)


@pytest.mark.parametrize("ratio", [0.8, 1.2])
def test_ratchet_walks_as_its_block_equation_says(source_dir, ratio):
    """Direction-dependent friction from Python: a symmetric push drives the block forward
    along the axis where its sole's coefficient is lower."""
    scene = pathlib.Path(source_dir) / "scenes" / "experiments" / "ratchet_drive.yaml"
    run = tribo.load_scene(str(scene), set={"ratio": ratio, "duration": 1.0}).run()
    assert run.status == "complete", run.message
    t, x = run["t"], run["block.x"]
    ref = ratchet_reference(ratio, t)
    assert len(ref) == len(x)
    # The engine (four corners at their static depth, a planar joint) against the equation at
    # the same step: rounding apart.
    assert np.max(np.abs(x - ref)) < 1e-9
    assert x[-1] > 0.01  # forward by centimetres under a push whose mean is zero


def test_slider_records_its_limit_surface_and_stops_where_coulomb_says(cli, source_dir, tmp_path):
    """The anisotropic slider from the command line: summary.json records the material's
    limit surface (unit axis, ratios per sense), and the block launched along its grain stops
    after v0^2 / (2 r mu g) (tanh's v_eps = 1e-3 adds 3e-6 of it)."""
    import json
    import subprocess

    scene = pathlib.Path(source_dir) / "scenes" / "experiments" / "anisotropic_slider.yaml"
    out = tmp_path / "slider"
    subprocess.run([cli, "run", str(scene), "--set", "beta=0", "--out", str(out), "--quiet"],
                   check=True, capture_output=True)
    result = json.loads((out / "summary.json").read_text())
    assert result["status"] == "complete"
    surface = result["settings"]["materials"][0]["anisotropy"]
    assert surface == {"frame": "b", "axis": [1.0, 0.0, 0.0], "forward": [0.5, 1.5],
                       "backward": [3.0, 1.5]}
    with open(out / "trajectory.csv") as f:
        header = f.readline().strip().split(",")
    x = np.loadtxt(out / "trajectory.csv", delimiter=",", skiprows=1)[:, header.index("block.x")]
    coulomb = 1.0 / (2 * 0.5 * 0.3 * 9.81)
    assert abs(x[-1] - coulomb) < 1e-4 * coulomb


def test_spinning_ball_spins_down_as_the_closed_form_says(source_dir):
    """Spinning friction from Python (scenes/experiments/spinning_ball.yaml): I w' =
    -mu_spin r_c m g, so the spin falls linearly to zero at I w0 / (mu_spin r_c m g) and stays
    there; the resistance channel records the moment while it spins."""
    scene = pathlib.Path(source_dir) / "scenes" / "experiments" / "spinning_ball.yaml"
    run = tribo.load_scene(str(scene)).run()
    assert run.status == "complete", run.message
    t, w, moment = run["t"], run["ball.wz"], run["ball.resisting_moment"]
    m, r, w0, torque = 1.0, 0.05, 20.0, 0.3 * 0.005 * 1.0 * 9.81
    rate = torque / (0.4 * m * r * r)
    spinning = t < 0.9 * w0 / rate
    assert np.max(np.abs(w[spinning] - (w0 - rate * t[spinning]))) < 1e-3 * w0
    assert np.max(np.abs(moment[spinning][1:] - torque)) < 1e-6 * torque
    # Stopped, the angular stick spring rings down (about 100 rad/s, damping ratio 0.5) and
    # holds: nothing left 0.3 s after the stop.
    stopped = t > w0 / rate + 0.3
    assert np.max(np.abs(w[stopped])) < 1e-6


@pytest.mark.parametrize("m", [0.5, 4.0])
def test_spinning_top_spins_down_and_its_pair_records_the_moment(source_dir, m):
    """The spinning top from Python (scenes/experiments/spinning_top.yaml): the tip's patch
    brakes the spin at mu_spin r_c m g / I with I = m R^2 / 2 (its sliding friction has no
    lever on the axis); the pair_resistance channel records mu_spin r_c m g while it spins,
    and its work over the rows is the kinetic energy the top lost."""
    scene = pathlib.Path(source_dir) / "scenes" / "experiments" / "spinning_top.yaml"
    run = tribo.load_scene(str(scene), set={"m": m}).run()
    assert run.status == "complete", run.message
    t, w, moment = run["t"], run["top.wz"], run["floor/tip.resisting_moment"]
    w0, r_disc, torque = 30.0, 0.04, 0.3 * 0.005 * m * 9.81
    inertia = 0.5 * m * r_disc * r_disc
    rate = torque / inertia
    spinning = t < 0.9 * w0 / rate
    assert np.max(np.abs(w[spinning] - (w0 - rate * t[spinning]))) < 1e-3 * w0
    assert np.max(np.abs(moment[spinning] - torque)) < 1e-9 * torque
    # The moment's work (trapezoids over the 5 ms rows, exact while w falls linearly) against
    # the energy lost; the last spinning interval, where w reaches zero inside a row, is the
    # trapezoid's error: half a row of the moment's power at most.
    work = np.sum(0.5 * (moment[1:] * w[1:] + moment[:-1] * w[:-1]) * np.diff(t))
    lost = 0.5 * inertia * (w0 * w0 - w[-1] * w[-1])
    assert abs(work - lost) < torque * rate * 0.005 ** 2
