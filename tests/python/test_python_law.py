"""Friction laws written in Python: the paper's roh_yoo law written here as a Python function
gives the belt the limit cycle of the built-in law (same amplitude and period), a class
with mu and slope gives the modes the built-in slope gives, and an exception raised inside
mu stops the run cleanly and comes back to the caller."""
import math

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
