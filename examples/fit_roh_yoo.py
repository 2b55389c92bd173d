"""Fitting the roh_yoo law to a measured mu(v) curve with NumPy: Gauss-Newton on
(mu_s, mu_k, a) with the law evaluated by tribo (the same mu(v) the engine uses), v_s and
beta held at the values the test rig's resolution gives. The "measurement" here is made up:
a known curve plus 0.002 of noise; with a real one, load it with numpy.loadtxt instead.

    PYTHONPATH=build/python python3 examples/fit_roh_yoo.py
"""
import numpy as np

import tribo

V_S, BETA = 0.01, 1 / 3


def curve(params, v):
    mu_s, mu_k, a = params
    return tribo.friction_law("roh_yoo", mu_s=mu_s, mu_k=mu_k, v_s=V_S, a=a, beta=BETA).mu(v)


def fit(v, mu, start, iterations=30):
    p = np.array(start, dtype=float)
    for _ in range(iterations):
        r = curve(p, v) - mu
        # Jacobian by central differences, one column per parameter
        J = np.empty((len(v), len(p)))
        for j in range(len(p)):
            h = 1e-6 * max(abs(p[j]), 1.0)
            dp = np.zeros_like(p)
            dp[j] = h
            J[:, j] = (curve(p + dp, v) - curve(p - dp, v)) / (2 * h)
        step = np.linalg.lstsq(J, -r, rcond=None)[0]
        p += step
        p[2] = max(p[2], 1.0 + 1e-9)  # the law needs a > 1
        p[0] = max(p[0], p[1] + 1e-9)  # and mu_s > mu_k
        if np.max(np.abs(step)) < 1e-12:
            break
    return p, np.sqrt(np.mean((curve(p, v) - mu) ** 2))


def main(seed=7):
    truth = (0.42, 0.31, 2.5)
    v = np.concatenate([np.linspace(0.001, 0.01, 10), np.linspace(0.02, 3.0, 60)])
    mu = curve(truth, v) + np.random.default_rng(seed).normal(0.0, 0.002, v.size)
    p, rms = fit(v, mu, start=(0.5, 0.25, 1.5))
    print("fitted mu_s %.4f  mu_k %.4f  a %.3f   (truth %.2f %.2f %.1f), rms %.4f" % (*p, *truth, rms))
    return truth, p, rms


if __name__ == "__main__":
    main()
