"""Friction laws written in Python: the paper's roh_yoo law written here as a Python function
gives the belt the limit cycle of the built-in law (same amplitude and period), a class
with mu and slope gives the modes the built-in slope gives, and an exception raised inside
mu stops the run cleanly and comes back to the caller."""
import math

import numpy as np
import pytest

import tribo

P = dict(mu_s=0.35, mu_k=0.3, v_s=0.01, a=1.5, beta=1 / 3)


def roh_yoo(v):
    s, v = math.copysign(1.0, v), abs(v)
    if v <= P["v_s"]:
        return s * P["mu_s"] * (v / P["v_s"]) ** P["beta"]
    return s * (P["mu_k"] + (P["mu_s"] - P["mu_k"]) * P["a"] ** -(v - P["v_s"]))


class RohYoo:
    stick_speed = P["v_s"]

    def mu(self, v):
        return roh_yoo(v)

    def slope(self, v):
        v = abs(v)
        if v <= P["v_s"]:
            return P["mu_s"] * P["beta"] / P["v_s"] * (v / P["v_s"]) ** (P["beta"] - 1) if v else math.inf
        return -math.log(P["a"]) * (P["mu_s"] - P["mu_k"]) * P["a"] ** -(v - P["v_s"])


@pytest.mark.parametrize("law", [roh_yoo, RohYoo()], ids=["function", "class"])
def test_python_law_gives_the_builtin_limit_cycle(belt, law):
    settings = {"duration": 20}
    builtin = tribo.load_scene(belt, set=settings).run().summary
    ours = tribo.load_scene(belt, set={**settings, "friction": "mine"}, laws={"mine": law})
    summary = ours.run().summary
    assert summary["settings"]["materials"][0]["friction_law"] == "mine"
    # The same formula in another language: round-off apart, the same orbit.
    assert summary["amplitude_pp"] == pytest.approx(builtin["amplitude_pp"], rel=1e-7)
    assert summary["period"] == pytest.approx(builtin["period"], rel=1e-7)
    assert summary["cycles_found"] == builtin["cycles_found"]


def test_python_law_in_modes(belt):
    lead = tribo.modes(tribo.load_scene(belt, set={"friction": "mine"}, laws={"mine": RohYoo()}))
    builtin = tribo.modes(tribo.load_scene(belt))
    assert lead["modes"][0]["growth_rate"] == pytest.approx(
        builtin["modes"][0]["growth_rate"], rel=1e-6)


def test_a_builtin_law_under_a_new_name(belt):
    law = tribo.friction_law("roh_yoo", **P)
    a = tribo.load_scene(belt, set={"friction": "table1", "duration": 3}, laws={"table1": law})
    b = tribo.load_scene(belt, set={"duration": 3})
    assert (a.run()["box.x"] == b.run()["box.x"]).all()  # the same law: bit for bit


def test_an_exception_in_mu_comes_back(belt):
    def broken(v):
        if abs(v) > 1.0:
            raise ZeroDivisionError("measured curve ends at 1 m/s")
        return roh_yoo(v)

    scene = tribo.load_scene(belt, set={"friction": "broken"}, laws={"broken": broken})
    with pytest.raises(ZeroDivisionError, match="ends at 1 m/s"):
        scene.run(duration=5)
    sim = tribo.Simulator(scene)
    with pytest.raises(ZeroDivisionError):
        sim.step(5000)
    assert not sim.status["ok"]


@pytest.mark.parametrize("name,law,found", [
    ("pushing", lambda v: -roh_yoo(v), "returned -"),  # the sign of -v: drives the slip
    ("negative_when_fast", lambda v: math.copysign(1.0, v) * (0.3 - 2.0 * abs(v)), "returned -"),
    ("nan", lambda v: math.nan, "returned nan"),
    ("nan_when_fast", lambda v: math.nan if abs(v) > 0.5 else roh_yoo(v), "returned nan"),
    ("infinite", lambda v: math.copysign(math.inf, v), "inf"),
])
def test_a_coefficient_that_is_no_coefficient_stops_the_run_naming_the_law(belt, name, law, found):
    """mu(v) is odd with the sign of v (it opposes the slip) and finite: anything else stops
    the run there and says which law returned what at which slip speed, never a run that
    completes. On a contact the engine asks for mu at the slip speed |v| >= 0."""
    scene = tribo.load_scene(belt, set={"friction": name}, laws={name: law})
    with pytest.raises(ValueError, match=f"law '{name}': mu\\(v\\) returned") as e:
        scene.run(duration=5)
    assert found in str(e.value) and "slip speed" in str(e.value)
    sim = tribo.Simulator(scene)
    with pytest.raises(ValueError, match=f"law '{name}'"):
        sim.step(5000)
    assert not sim.status["ok"]


def test_a_slope_that_is_nan_stops_the_run_naming_the_law(belt):
    class NanSlope:
        def mu(self, v):
            return roh_yoo(v)

        def slope(self, v):
            return math.nan

    scene = tribo.load_scene(belt, set={"friction": "s"}, laws={"s": NanSlope()})
    with pytest.raises(ValueError, match="law 's': slope\\(v\\) returned nan at slip speed"):
        scene.run(duration=0.1)  # the stable-step estimate asks for the slope


def test_a_state_law_giving_nan_stops_the_run_naming_the_law_and_the_call(belt):
    class NanForce(PythonLuGre):
        def force(self, z, zdot, slip, fn):
            return [math.nan, 0.0, 0.0]

    class NanRate(PythonLuGre):
        def rate(self, z, slip, fn):
            return [0.0, math.inf, 0.0]

    for law, call in ((NanForce(), "force"), (NanRate(), "rate")):
        scene = tribo.load_scene(belt, set={"friction": "z", "integrator": "rk4", "dt": 2e-4},
                                 laws={"z": law})
        with pytest.raises(ValueError, match=f"law 'z': {call}\\(.*slip speed.*fn = "):
            scene.run(duration=0.1)


def test_bad_python_laws(belt):
    with pytest.raises(tribo.SceneError, match="built-in"):
        tribo.load_scene(belt, set={"friction": "roh_yoo"}, laws={"roh_yoo": roh_yoo})
    with pytest.raises(TypeError):
        tribo.load_scene(belt, set={"friction": "x"}, laws={"x": 0.3})
    scene = tribo.load_scene(belt, set={"friction": "text"}, laws={"text": lambda v: "fast"})
    with pytest.raises(TypeError, match="must return a number"):
        scene.run(duration=0.1)
    with pytest.raises(ValueError, match="cannot be swept"):
        tribo.sweep(tribo.load_scene(belt, set={"friction": "m"}, laws={"m": roh_yoo}),
                    grid={"v_b": [1.0]})


class PythonLuGre:
    """LuGre per unit normal force (Canudas de Wit et al. 1995), written here from the paper:
    dz/dt = s - sigma0 |s| z / g(|s|),  g(v) = mu_c + (mu_s - mu_c) exp(-(v / v_s)^2),
    F_t = -F_n (sigma0 z + sigma1 dz/dt + sigma2 s); z a tangent vector."""

    state_size = 3
    tangent_vectors = 1

    def __init__(self, sigma0=1e4, sigma1=30.0, sigma2=0.0, mu_c=0.3, mu_s=0.35, v_s=0.01):
        self.s0, self.s1, self.s2 = sigma0, sigma1, sigma2
        self.mu_c, self.mu_s, self.v_s = mu_c, mu_s, v_s
        self.stick_speed = v_s
        self.presliding = (sigma0, sigma1)

    def g(self, v):
        return self.mu_c + (self.mu_s - self.mu_c) * math.exp(-((v / self.v_s) ** 2))

    def mu(self, v):
        return math.copysign(self.g(abs(v)), v) + self.s2 * v

    def rate(self, z, slip, fn):
        v = float(np.linalg.norm(slip))
        return slip - self.s0 * v * z / self.g(v)

    def force(self, z, zdot, slip, fn):
        return -fn * (self.s0 * z + self.s1 * zdot + self.s2 * slip)


def test_python_lugre_follows_the_builtin_lugre(belt):
    # v_b = 0.1 m/s: stick-slip; rk4 at 0.2 ms resolves the state's rate sigma0 v / g.
    settings = {"v_b": 0.1, "integrator": "rk4", "dt": 2e-4, "duration": 1.0}
    builtin = tribo.load_scene(belt, set={**settings, "friction": "lugre"}).run()
    python = tribo.load_scene(belt, set={**settings, "friction": "py_lugre"},
                              laws={"py_lugre": PythonLuGre()}).run()
    assert builtin.status == python.status == "complete"
    x_builtin, x_python = builtin["box.x"], python["box.x"]
    assert np.ptp(x_builtin) > 1e-3  # it moves: the box sticks and slips
    # The same equations in another language: equal to round-off.
    assert np.max(np.abs(x_python - x_builtin)) < 1e-10
    assert np.max(np.abs(python["box.vx"] - builtin["box.vx"])) < 1e-8


def test_python_state_law_errors(belt):
    class WrongSize(PythonLuGre):
        def rate(self, z, slip, fn):
            return [0.0, 0.0]  # two numbers for a state of three

    scene = tribo.load_scene(belt, set={"friction": "w", "integrator": "rk4", "dt": 2e-4},
                             laws={"w": WrongSize()})
    with pytest.raises(TypeError, match="must give 3 numbers"):
        scene.run(duration=0.1)

    class NoRate:
        state_size = 1

        def mu(self, v):
            return 0.3

    with pytest.raises(TypeError, match="rate"):
        tribo.load_scene(belt, set={"friction": "n"}, laws={"n": NoRate()})


def test_a_direct_slope_enters_the_stable_step_as_a_damper(belt):
    # A state law's direct effect D (d|F_t|/d|s| per unit load with the state held) acts on
    # the box's slip like a damper c = D N, N = m g on the flat belt: where it binds, the
    # explicit step limit is RK4's real-axis bound z over c / m = D g, z the real root of
    # 1 - z + z^2/2 - z^3/6 + z^4/24 = 1 (z^3 - 4 z^2 + 12 z - 24 = 0, Newton from 3). Without
    # the method the estimate has no such term and prints a longer step.
    class Smooth(PythonLuGre):
        def mu(self, v):
            return math.tanh(v / 1e-3) * self.g(abs(v))

    class Direct(Smooth):
        def __init__(self, d):
            super().__init__()
            self.d = d

        def direct_slope(self, v):
            return self.d

    settings = {"friction": "p", "integrator": "rk4", "dt": 1e-5}

    def stability(law):
        result = tribo.load_scene(belt, set=settings, laws={"p": law}).run(duration=1e-4)
        assert result.complete, result.message
        return result.summary["stability"]

    z = 3.0
    for _ in range(50):
        z -= (((z - 4) * z + 12) * z - 24) / ((3 * z - 8) * z + 12)
    plain = stability(Smooth())
    assert "direct effect" not in plain["limiting_element"]
    for d in (1e3, 2e3, 1e4):
        s = stability(Direct(d))
        assert "direct effect" in s["limiting_element"]
        assert s["estimated_max_step"] == pytest.approx(z / (d * 9.81), rel=1e-9)
        assert s["estimated_max_step"] < plain["estimated_max_step"]
