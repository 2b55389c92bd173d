"""Controllers written in Python (run(..., controller=f), tribo.Control, Simulator.set_actuator):
a PD law written in Python through a motor gives the scene's own position servo's trajectory
to the last bit (semi-implicit Euler: one force evaluation a step, at the state the controller
sees); a control interval calls the controller on its schedule and holds its command; an
exception in the controller stops the run with the rows so far and says why; bad commands are
refused by name."""
import math

import numpy as np
import pytest

import tribo

SLIDER = """
simulation: {duration: 0.5, time_step: 0.001, integrator: semi_implicit_euler, gravity: [0, 0, 0]}
bodies:
  - {name: block, mass: %(m)s, inertia: [0.1, 0.1, 0.1]}
joints:
  - {name: slide, type: prismatic, parent: world, child: block, anchor: [0, 0, 0], axis: [1, 0, 0]}
actuators:
  - %(actuator)s
output: {interval: 0.001, channels: [position, velocity, joints, actuators]}
"""

KP, KD, TARGET = 250.0, 6.0, 0.02


def slider(actuator, m=1.5):
    return tribo.load_scene(SLIDER % {"m": m, "actuator": actuator})


@pytest.mark.parametrize("m", [0.2, 1.5, 30.0])
def test_python_pd_matches_the_scene_servo_bit_for_bit(m):
    servo = slider("{name: act, joint: slide, type: position, target: %r, kp: %r, kd: %r}"
                   % (TARGET, KP, KD), m).run()
    calls = []

    def pd(c):
        calls.append(c.time)
        i = c.joint_names.index("slide")
        # The scene's servo: kp (r - q) + kd (r' - q') with r' = 0.
        return {"act": KP * (TARGET - c.q[i]) + KD * (0.0 - c.qd[i])}

    python = slider("{name: act, joint: slide, type: motor, target: 0}", m).run(controller=pd)
    assert servo.complete and python.complete
    assert len(calls) == 500  # before each of the 500 steps
    for column in ("block.x", "block.vx", "slide.q", "slide.rate"):
        assert np.array_equal(servo[column], python[column]), column
    # A row shows the effort at its state: the scene's servo's from that state, the motor's
    # the command held since the call before the step that led there.
    assert np.array_equal(servo["act.effort"][:-1], python["act.effort"][1:])
    # And it moved: a servo's response, not two resting blocks.
    assert servo["block.x"][-1] > 0.5 * TARGET


def test_control_interval_holds_the_command():
    times = []

    def bang(c):
        times.append(c.time)
        c.set("act", 1.0 if len(times) % 2 else -1.0)

    r = slider("{name: act, joint: slide, type: motor, target: 0}").run(
        controller=bang, control_interval=0.1)
    assert r.complete
    assert times == pytest.approx([0.0, 0.1, 0.2, 0.3, 0.4], abs=1e-9)
    effort = r["act.effort"]
    t = r["t"]
    # Held between calls: +1 N over [0, 0.1), -1 N over [0.1, 0.2), ...
    for k in range(5):
        inside = (t > k * 0.1 + 1e-6) & (t < (k + 1) * 0.1 - 1e-6)
        assert np.all(effort[inside] == (1.0 if k % 2 == 0 else -1.0)), k


def test_a_raising_controller_stops_the_run_with_its_rows():
    def failing(c):
        if c.time >= 0.2 - 1e-9:
            raise ZeroDivisionError("gain schedule broke")

    with pytest.raises(ZeroDivisionError) as caught:
        slider("{name: act, joint: slide, type: motor, target: 0.5}").run(controller=failing)
    result = caught.value.result
    assert result.status == "stopped"
    assert not result.complete
    assert "controller raised ZeroDivisionError: gain schedule broke" in result.message
    assert result["t"][-1] == pytest.approx(0.2, abs=1e-9)
    # Everything before is there: a constant 0.5 N on 1.5 kg, x = F t^2 / (2 m).
    assert result["block.x"][-1] == pytest.approx(0.5 * 0.2 ** 2 / (2 * 1.5), rel=1e-2)


def test_bad_commands_are_refused_by_name():
    def unknown(c):
        c.set("nope", 1.0)

    with pytest.raises(KeyError, match="no actuator 'nope' \\(actuators: act\\)"):
        slider("{name: act, joint: slide, type: motor, target: 0}").run(controller=unknown)

    def infinite(c):
        return {"act": math.inf}

    with pytest.raises(ValueError, match="must be finite"):
        slider("{name: act, joint: slide, type: motor, target: 0}").run(controller=infinite)

    kept = []
    slider("{name: act, joint: slide, type: motor, target: 0}").run(
        controller=lambda c: kept.append(c))
    with pytest.raises(ValueError, match="used after its controller call returned"):
        kept[0].q


def test_simulator_set_actuator_commands_between_steps():
    sim = tribo.Simulator(slider("{name: act, joint: slide, type: motor, target: 0}"))
    sim.set_actuator("act", 3.0)
    assert sim.step(100)
    # 3 N on 1.5 kg for 0.1 s: v = 0.2 m/s (semi-implicit Euler is exact for the velocity).
    assert sim.state.velocities[0, 0] == pytest.approx(0.2, rel=1e-12)
    with pytest.raises(KeyError):
        sim.set_actuator("missing", 1.0)


FREE_BODY = """
simulation: {duration: 10, time_step: 0.001, integrator: rk4, gravity: [0, 0, 0]}
bodies:
  - {name: block, mass: 2, inertia: [0.3, 0.3, 0.4]}
loads:
  - {name: push, body: block, force: [{ramp: {rate: 1}}, 0, 0], frame: world}
  - {name: spin, body: block, torque: [0, 0, 0], frame: body}
"""


def test_a_load_set_from_python_moves_the_body_as_the_closed_form_says():
    """A free 2 kg body pushed by F = t (its signal); from t1 on, set_load holds F = 3 N
    (constant acceleration 1.5 m/s^2), then set_load(name) gives the ramp back (a = t / m).
    RK4 integrates these polynomials exactly, so x and v follow the closed forms to
    round-off; a torque held on the spin load turns it at tau / I_z."""
    m, h = 2.0, 1e-3
    sim = tribo.Simulator(tribo.load_scene(FREE_BODY))
    assert sim.step(1000)  # t1 = 1 s under the ramp: v = t^2 / 2m, x = t^3 / 6m
    t1 = sim.time
    x1, v1 = t1 ** 3 / (6 * m), t1 ** 2 / (2 * m)
    assert sim.state.positions[0, 0] == pytest.approx(x1, rel=1e-12)
    sim.set_load("push", force=np.array([3.0, 0.0, 0.0]))
    sim.set_load("spin", torque=[0.0, 0.0, 0.2])
    assert sim.step(500)
    tau = sim.time - t1
    x2, v2 = x1 + v1 * tau + 0.75 * tau ** 2, v1 + 1.5 * tau
    assert sim.state.positions[0, 0] == pytest.approx(x2, rel=1e-12)
    assert sim.state.velocities[0, 0] == pytest.approx(v2, rel=1e-12)
    assert sim.state.angular_velocities[0, 2] == pytest.approx(0.2 / 0.4 * tau, rel=1e-12)
    t2 = sim.time
    sim.set_load("push")  # the ramp again: a = t / m
    assert sim.step(700)
    t3 = sim.time
    v3 = v2 + (t3 ** 2 - t2 ** 2) / (2 * m)
    x3 = x2 + v2 * (t3 - t2) + (t3 ** 3 - t2 ** 3) / (6 * m) - t2 ** 2 / (2 * m) * (t3 - t2)
    assert sim.state.velocities[0, 0] == pytest.approx(v3, rel=1e-12)
    assert sim.state.positions[0, 0] == pytest.approx(x3, rel=1e-12)


def test_a_controller_setting_a_load_is_the_scene_with_that_load():
    """F = 3 N held by a controller from the first step gives the trajectory of the scene
    whose load is the constant 3 N, to the last bit."""
    scene = FREE_BODY.replace("{ramp: {rate: 1}}", "0")
    held = tribo.load_scene(scene).run(duration=1, controller=lambda c: c.set_load(
        "push", force=[3, 0, 0]))
    written = tribo.load_scene(scene.replace("force: [0, 0, 0]", "force: [3, 0, 0]")).run(
        duration=1)
    np.testing.assert_array_equal(held["block.x"], written["block.x"])
    assert held["block.x"][-1] == pytest.approx(0.75, rel=1e-12)  # x = F t^2 / 2m at t = 1


def test_set_load_errors_name_what_is_wrong():
    sim = tribo.Simulator(tribo.load_scene(FREE_BODY))
    with pytest.raises(KeyError, match=r"no load 'pull' \(loads: push, spin\)"):
        sim.set_load("pull", force=[1, 0, 0])
    with pytest.raises(ValueError, match="force: expected 3 numbers, got 2"):
        sim.set_load("push", force=[1, 0])
    with pytest.raises(ValueError, match="torque: expected finite numbers"):
        sim.set_load("spin", torque=[0, 0, float("nan")])
    assert sim.step(10)  # a refused command leaves the run as it was
