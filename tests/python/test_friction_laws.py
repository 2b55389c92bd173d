"""Friction laws from Python: mu(v) and slope(v) against the laws' closed forms written
here from the paper (Roh & Yoo 2007) and textbook (Coulomb with tanh regularization),
vectorized over arrays of any shape with the same numbers as one at a time, and bad
parameters raising FrictionParameterError with the law's message."""
import math

import numpy as np
import pytest

import tribo

TABLE1 = dict(mu_s=0.35, mu_k=0.3, v_s=0.01, a=1.5, beta=1 / 3)


def roh_yoo(v, mu_s, mu_k, v_s, a, beta):
    s = math.copysign(1.0, v)
    v = abs(v)
    if v <= v_s:
        return s * mu_s * (v / v_s) ** beta
    b = -math.log(mu_s - mu_k) / math.log(a) - v_s  # continuity at v_s
    return s * (a ** -(v + b) + mu_k)


@pytest.mark.parametrize("params", [TABLE1, dict(mu_s=0.8, mu_k=0.1, v_s=1e-4, a=40.0, beta=0.5),
                                    dict(mu_s=1.2, mu_k=1.0, v_s=2.0, a=1.01, beta=1.0)])
def test_roh_yoo_equals_its_formula(params):
    law = tribo.friction_law("roh_yoo", **params)
    vs = np.concatenate([-np.logspace(-6, 2, 200), [0.0], np.logspace(-6, 2, 200)])
    expected = np.array([roh_yoo(v, **params) for v in vs])
    assert np.allclose(law.mu(vs), expected, rtol=1e-12, atol=1e-15)
    above = vs[np.abs(vs) > params["v_s"] * 1.01]
    # Slope above the peak: -ln(a) (mu_s - mu_k) a^-(|v| - v_s), even in v
    slope = -math.log(params["a"]) * (params["mu_s"] - params["mu_k"]) * params["a"] ** -(
        np.abs(above) - params["v_s"])
    assert np.allclose(law.slope(above), slope, rtol=1e-10)


def test_coulomb_tanh():
    law = tribo.friction_law("coulomb", mu=0.4, regularization="tanh", v_eps=1e-3)
    v = np.linspace(-0.01, 0.01, 101)
    assert np.allclose(law.mu(v), 0.4 * np.tanh(v / 1e-3), rtol=1e-12, atol=1e-16)
    assert law.name == "coulomb" and not law.has_internal_state


def test_arrays_of_any_shape_and_scalars():
    law = tribo.friction_law("roh_yoo", **TABLE1)
    v = np.linspace(-1, 1, 24).reshape(2, 3, 4)
    mu = law.mu(v)
    assert mu.shape == (2, 3, 4) and mu.dtype == np.float64
    assert all(mu[i, j, k] == law.mu(float(v[i, j, k])) for i in range(2) for j in range(3)
               for k in range(4))
    assert isinstance(law.mu(0.5), float)
    assert law.mu([0.1, 0.2]).shape == (2,)  # lists too
    assert np.array_equal(law.mu(v.astype(np.float32)), law.mu(v.astype(np.float32).astype(float)))
    big = np.random.default_rng(1).uniform(-2, 2, 1_000_000)
    assert np.array_equal(law.mu(big), -law.mu(-big))  # odd, through a million speeds


def test_dynamic_laws_give_their_steady_curve():
    law = tribo.friction_law("lugre", sigma0=1e4, sigma1=30, sigma2=0.5, mu_c=0.3, mu_s=0.35,
                             v_s=0.01)
    assert law.has_internal_state
    v = np.array([0.005, 0.05, 1.0])
    # Steady LuGre: g(v) + sigma2 v, g = mu_c + (mu_s - mu_c) exp(-(v/v_s)^2)
    assert np.allclose(law.mu(v), 0.3 + 0.05 * np.exp(-(v / 0.01) ** 2) + 0.5 * v, rtol=1e-12)


def test_bad_laws_raise_with_the_message():
    with pytest.raises(tribo.FrictionParameterError, match="roh_yoo: a must be > 1"):
        tribo.friction_law("roh_yoo", **{**TABLE1, "a": 0.9})
    with pytest.raises(tribo.FrictionParameterError, match="no_such_law"):
        tribo.friction_law("no_such_law")
    with pytest.raises(ValueError):  # a FrictionParameterError is a ValueError
        tribo.friction_law("coulomb", mu=-1.0)
    with pytest.raises(TypeError):
        law = tribo.friction_law("roh_yoo", **TABLE1)
        law.mu("fast")
    names = tribo.friction_laws()
    assert "roh_yoo" in names["memoryless"] and "lugre" in names["dynamic"]


def test_a_numbers_text_is_the_number():
    assert tribo.friction_law("coulomb", mu="0.3").mu(1.0) == tribo.friction_law(
        "coulomb", mu=0.3).mu(1.0)
    law = tribo.friction_law("coulomb", mu="0.3", regularization="tanh", v_eps="1e-3")
    assert law.mu(1.0) == pytest.approx(0.3 * math.tanh(1.0 / 1e-3), rel=1e-12)
    with pytest.raises(TypeError, match="mu must be a number or a string, not list"):
        tribo.friction_law("coulomb", mu=[0.3])


def test_tabulated_law_from_points_and_from_a_file(tmp_path):
    speeds, mus = [0.0, 0.01, 0.1, 1.0], [0.0, 0.5, 0.4, 0.3]
    law = tribo.friction_law("tabulated", speeds=speeds, coefficients=mus)
    # Between points the curve is the table's (interpolation exact at the points).
    for v, mu in zip(speeds, mus):
        assert law.mu(v) == pytest.approx(mu, abs=1e-12)
        assert law.mu(-v) == pytest.approx(-mu, abs=1e-12)  # odd
    csv = tmp_path / "curve.csv"
    csv.write_text("speed,mu\n" + "".join(f"{v},{m}\n" for v, m in zip(speeds, mus)))
    from_file = tribo.friction_law("tabulated", file=csv)
    vs = np.linspace(-2, 2, 101)
    assert np.array_equal(from_file.mu(vs), law.mu(vs))
    assert "tabulated" in tribo.friction_laws()["tabulated"]
    with pytest.raises(TypeError, match="tabulated: give file"):
        tribo.friction_law("tabulated", mu=0.3)
    with pytest.raises(tribo.FrictionParameterError):
        tribo.friction_law("tabulated", speeds=[0.0, 0.1], coefficients=[0.5])  # lengths
