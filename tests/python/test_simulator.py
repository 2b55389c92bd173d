"""The step-by-step Simulator: it takes the same steps as a run, its state round-trips bit
for bit (friction laws' internal states included), a state edited through its arrays takes
effect, and contacts carry the forces that hold a resting body up."""
import math
import subprocess

import numpy as np
import pytest

import tribo

BOX_ON_GROUND = """
parameters: {m: 2.5, k: 1.0e5, c: 400, dt: 5.0e-4}
simulation: {duration: 1.0, time_step: $dt, integrator: rk4, gravity: [0, 0, -9.81]}
bodies:
  - {name: ground, kind: kinematic, geometry: [{name: floor, shape: halfspace}]}
  - name: block
    mass: $m
    position: [0, 0, 0.05]
    geometry: [{name: block_shape, shape: box, size: [0.3, 0.2, 0.1]}]
materials:
  - {name: steel, normal: {law: linear, stiffness: $k, damping: $c}, friction: coulomb}
friction_laws:
  coulomb: {mu: 0.4, regularization: tanh, v_eps: 1.0e-3}
contacts:
  - {a: floor, b: block_shape, material: steel}
"""


def test_steps_equal_the_run(belt):
    scene = tribo.load_scene(belt, set={"duration": 0.3})
    result = scene.run()
    sim = tribo.Simulator(scene)
    i = sim.body_names.index("box")
    xs = [sim.state.positions[i, 0]]
    for _ in range(300):  # output interval == time step: one row per step
        assert sim.step()
        xs.append(sim.state.positions[i, 0])
    assert np.array_equal(np.array(xs), result["box.x"])
    # One source for the statistics: the Simulator's are summary.json's "run" block's.
    stats, run = sim.stats, result.summary["run"]
    assert stats["steps"] == 300 and stats["force_evaluations"] >= 300
    assert set(stats) < set(run)
    for key, value in stats.items():
        assert value == run[key], key


@pytest.mark.parametrize("law", ["roh_yoo", "lugre", "rate_state"])
def test_state_round_trips_bit_for_bit(belt, law):
    sim = tribo.Simulator(tribo.load_scene(belt, set={"friction": law, "integrator": "semi_implicit_euler",
                                                      "dt": 5e-5}))
    assert sim.step(2000)
    saved = sim.state
    assert saved == sim.state
    assert sim.step(500)
    later = sim.state
    sim.state = saved
    assert sim.state == saved and sim.time == saved.time
    assert sim.step(500)
    assert sim.state == later  # the friction states came back too
    if law != "roh_yoo":
        assert len(saved.friction_values) > 0


def test_state_edits_take_effect(belt):
    sim = tribo.Simulator(tribo.load_scene(belt))
    st = sim.state
    i = sim.body_names.index("box")
    assert st.positions.shape == (2, 3) and st.orientations.shape == (2, 4)
    assert np.array_equal(st.orientations[i], [0, 0, 0, 1])  # identity, (x, y, z, w)
    st.positions[i, 0] = 0.125  # writes into the State
    st.velocities[i, 0] = -0.5
    assert st.positions[i, 0] == 0.125
    sim.state = st
    assert sim.state.positions[i, 0] == 0.125 and sim.state.velocities[i, 0] == -0.5
    three = BOX_ON_GROUND.replace(
        "materials:", "  - {name: extra, mass: 1, position: [1, 0, 1]}\nmaterials:")
    with pytest.raises(ValueError, match="bodies"):
        sim.state = tribo.Simulator(tribo.load_scene(three)).state


@pytest.mark.parametrize("mass", [0.01, 2.5, 400.0])
def test_contacts_hold_up_a_resting_body(mass):
    # Per corner k = 4e4 m: the bounce at sqrt(4 k / m) = 400 rad/s whatever the mass;
    # c = 0.5 sqrt(k m) per corner is a damping ratio of 0.5: settled (e^-200t) long before 1 s.
    k = 4.0e4 * mass
    scene = tribo.load_scene(BOX_ON_GROUND, set={"m": mass, "k": k, "c": 0.5 * math.sqrt(k * mass)})
    sim = tribo.Simulator(scene)
    assert sim.step(2000), sim.status["message"]
    c = sim.contacts()
    assert len(c["depth"]) == 4  # the four bottom corners
    assert set(c["body_b"]) == {"block"} and set(c["body_a"]) == {"ground"}
    assert np.allclose(c["normal"], [0, 0, 1])
    # Newton: the normal forces carry the weight
    assert c["normal_force"].sum() == pytest.approx(mass * 9.81, rel=1e-6)
    assert np.all(c["depth"] > 0)
    assert np.abs(c["friction_force"]).max() < 1e-6 * mass * 9.81


def test_a_diverging_step_says_where_as_the_cli_does(cli, tmp_path):
    # A 1 kg block on 1e9 N/m corners with a 10 ms step: explicit integration explodes.
    settings = {"m": 1.0, "k": 1.0e9, "dt": 1.0e-2}
    sim = tribo.Simulator(tribo.load_scene(BOX_ON_GROUND, set=settings))
    assert not sim.step(100)
    status = sim.status
    assert not status["ok"] and status["body"] == "block" and status["quantity"]
    assert math.isfinite(status["time"]) and "block" in status["message"]
    assert np.isfinite(sim.state.positions).all()  # the last good state, never NaN
    scene_file = tmp_path / "block.yaml"
    scene_file.write_text(BOX_ON_GROUND)
    args = [cli, "run", str(scene_file), "--out", str(tmp_path / "out"), "--quiet"]
    for k, v in settings.items():
        args += ["--set", f"{k}={v}"]
    run = subprocess.run(args, capture_output=True, text=True)
    assert run.returncode == 3
    assert status["message"] in run.stderr


def test_ctrl_c_stops_a_long_step_after_a_whole_step(belt):
    # interrupt_main raises KeyboardInterrupt in this thread as Ctrl-C would, while step(n)
    # runs without the GIL; the loop looks for it every 1024 steps.
    import _thread
    import threading

    sim = tribo.Simulator(tribo.load_scene(belt))
    timer = threading.Timer(0.2, _thread.interrupt_main)
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        sim.step(10**9)  # some 40 minutes of stepping if nothing stopped it
    timer.join()
    t = sim.time
    assert 0 < t < 1e5
    assert t / 1e-3 == pytest.approx(round(t / 1e-3), abs=1e-6)  # a whole number of steps
    assert np.isfinite(sim.state.positions).all()
    assert sim.step(10)  # and it goes on from there


def test_set_parameters_goes_on_from_the_state(belt):
    """A parameter changed mid-run: the steps after it are those of a simulator loaded with
    the new value and started from the same state, bit for bit."""
    sim = tribo.Simulator(tribo.load_scene(belt))
    assert sim.step(3000)
    sim.set_parameters({"v_b": 0.8, "k": 250})
    assert sim.parameters["v_b"] == "0.8" and sim.parameters["k"] == "250"
    fresh = tribo.Simulator(tribo.load_scene(belt, set={"v_b": 0.8, "k": 250}))
    fresh.state = sim.state
    for _ in range(2000):
        assert sim.step() and fresh.step()
    assert sim.state == fresh.state
    sim.set_parameters({"v_b": 0.8})  # the same value again: nothing changes
    assert sim.parameters["k"] == "250"


def test_a_belt_slowed_mid_run_carries_the_sticking_block_at_its_new_speed(belt):
    """While the block sticks it moves with the belt (to within the law's stick speed
    v_s = 0.01 m/s): at 1.5 m/s before the change, at the new speed after it."""
    sim = tribo.Simulator(tribo.load_scene(belt))

    def fastest(seconds):
        top = -math.inf
        for _ in range(int(seconds / 1e-3)):
            assert sim.step()
            top = max(top, sim.state.velocities[1, 0])
        return top

    assert fastest(20) == pytest.approx(1.5, abs=0.01)
    for v_b in (0.6, 0.25):
        sim.set_parameters({"v_b": v_b})
        fastest(5)  # the transient of the change
        assert fastest(10) == pytest.approx(v_b, abs=0.01)


def test_set_parameters_refuses_what_cannot_go_on(belt):
    sim = tribo.Simulator(tribo.load_scene(belt))
    assert sim.step(100)
    with pytest.raises(ValueError, match="friction memory of contact material 0: roh_yoo -> lugre"):
        sim.set_parameters({"friction": "lugre"})  # bristle states the run does not have
    with pytest.raises(tribo.SceneError, match="v_b"):
        sim.set_parameters({"v_b": "fast"})
    assert sim.parameters["v_b"] == "1.5"  # a refused change leaves the run as it was
    assert sim.step(100)
