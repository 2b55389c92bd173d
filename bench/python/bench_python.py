"""What the Python module costs on top of the C++ library, measured in one process:
  - Simulator.step() called once per step from Python against step(n) looping in C++ over
    the same steps (the belt scene, rk4 at 1 ms): the difference is the per-call overhead;
  - a built-in law's mu over a NumPy array of 1e6 slip speeds (one call, the loop in C++)
    against mu called once per speed from Python;
  - a friction law written in Python (roh_yoo as a Python function) against the built-in
    one on the belt (20 s): the extra time per law call (one call per contact point and
    force evaluation: 4 corners);
  - a PD controller written in Python (run(controller=f), called every step) against the same
    servo written in the scene (scenes/experiments/servo_stick_slip.yaml, 10 s, rk4 at
    50 us): the extra time per controller call.
Prints the figures; asserts nothing (timings are not tests).

    PYTHONPATH=build/python python3 bench/python/bench_python.py [--repeat N]
"""
import argparse
import math
import pathlib
import time

import numpy as np

import tribo

BELT = pathlib.Path(__file__).resolve().parents[2] / "scenes" / "belt.yaml"


def best(fn, repeat):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--steps", type=int, default=20000)
    args = parser.parse_args()
    scene = tribo.load_scene(BELT)
    n = args.steps

    def loop_in_cpp():
        sim = tribo.Simulator(scene)
        sim.step(n)

    def loop_in_python():
        sim = tribo.Simulator(scene)
        step = sim.step
        for _ in range(n):
            step()

    cpp = best(loop_in_cpp, args.repeat) / n
    py = best(loop_in_python, args.repeat) / n
    print(f"belt step: {cpp * 1e6:.3f} us in a C++ loop, {py * 1e6:.3f} us called from Python: "
          f"{(py - cpp) * 1e6:.3f} us added per call ({py / cpp:.2f}x)")

    law = tribo.friction_law("roh_yoo", mu_s=0.35, mu_k=0.3, v_s=0.01, a=1.5, beta=1 / 3)
    v = np.random.default_rng(0).uniform(-2, 2, 1_000_000)
    vectorized = best(lambda: law.mu(v), args.repeat) / v.size
    few = v[:100_000]
    mu = law.mu
    scalar = best(lambda: [mu(float(x)) for x in few], max(1, args.repeat // 2)) / few.size
    print(f"roh_yoo mu over 1e6 speeds: {vectorized * 1e9:.1f} ns a speed in one call; "
          f"{scalar * 1e9:.0f} ns a speed called one at a time ({scalar / vectorized:.0f}x)")

    def python_roh_yoo(v, mu_s=0.35, mu_k=0.3, v_s=0.01, a=1.5, beta=1 / 3):
        s, v = math.copysign(1.0, v), abs(v)
        if v <= v_s:
            return s * mu_s * (v / v_s) ** beta
        return s * (mu_k + (mu_s - mu_k) * a ** -(v - v_s))

    settings = {"duration": 20}
    builtin_scene = tribo.load_scene(BELT, set=settings)
    python_scene = tribo.load_scene(BELT, set={**settings, "friction": "py"},
                                    laws={"py": python_roh_yoo})
    builtin = best(builtin_scene.run, args.repeat)
    python = best(python_scene.run, args.repeat)
    calls = 4 * python_scene.run().summary["run"]["force_evaluations"]
    print(f"belt 20 s: built-in roh_yoo {builtin * 1e3:.1f} ms, Python roh_yoo "
          f"{python * 1e3:.1f} ms: {(python - builtin) / calls * 1e9:.0f} ns added per law call "
          f"({calls} calls)")

    servo_file = BELT.parent / "experiments" / "servo_stick_slip.yaml"
    servo_scene = tribo.load_scene(servo_file, set={"duration": 10})
    motor_text = servo_file.read_text().replace(
        "type: position, target: {ramp: {rate: $v}}, kp: $kp, kd: $kd",
        "type: motor, target: 0")
    motor_scene = tribo.load_scene(motor_text, set={"duration": 10})

    def pd(c):
        c.set("servo", 2.0 * (0.1 * c.time - c.q[0]) + 0.0 * (0.1 - c.qd[0]))

    in_scene = best(servo_scene.run, args.repeat)
    in_python = best(lambda: motor_scene.run(controller=pd), args.repeat)
    steps = servo_scene.run().summary["run"]["steps"]
    print(f"servo 10 s ({steps} steps): in the scene {in_scene * 1e3:.1f} ms, as a Python "
          f"controller {in_python * 1e3:.1f} ms: {(in_python - in_scene) / steps * 1e6:.2f} us "
          f"added per controller call ({in_python / in_scene:.2f}x)")


if __name__ == "__main__":
    main()
