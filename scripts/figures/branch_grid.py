#!/usr/bin/env python3
"""Samples branches of periodic orbits (`tribo orbit --continue`, one per value of a second
parameter) on a grid of the branch's own parameter, as gnuplot grid data for contour.gp: "x y z"
lines, the branch's parameter on x (one block per grid value, one line per branch) or, with
--branch-axis y, on y (one block per branch). Each branch's
amplitude_pp is interpolated between its two points around x (see sample); a grid
value the branch did not reach gives NaN (a hole in the map). With --sweep, the same map's
settled sweep (results.csv) is compared point by point and the differences printed.

  branch_grid.py --grid 0.5:5:20 --x 'v' --y 'math.sqrt(v / 10)' \
      --sweep out/figures/fig11/results.csv v_b k  DIR=VALUE...  > fig11c.dat

--x/--y are Python expressions of v (the parameter's value) giving the plotted coordinate."""
import argparse
import csv
import math
import sys


def grid_values(text):
    """FROM:TO:N (N values, both ends included) or a comma-separated list."""
    if ":" not in text:
        return [float(v) for v in text.split(",")]
    lo, hi, n = text.split(":")
    lo, hi, n = float(lo), float(hi), int(n)
    return [lo + i * (hi - lo) / (n - 1) for i in range(n)]


def branch_points(folder):
    """(parameter, amplitude_pp) of a branch.csv, in the order of the branch."""
    with open(folder + "/branch.csv", newline="") as f:
        return [(float(r["parameter"]), float(r["amplitude_pp"])) for r in csv.DictReader(f)]


def sample(points, x):
    """amplitude_pp at parameter x: the cubic through the four branch points around it (two on
    each side where the branch has them, fewer near its ends), in log(amplitude) against
    log(parameter) where all are positive (the stick-slip amplitude's power laws, 1 / omega_n^2
    at low stiffness, are then near exact; linear interpolation in the plain values errs by 2%
    between points 20 N/m apart there), else in the plain values; NaN where the branch does
    not reach x."""
    pts = sorted(points)
    for i in range(len(pts) - 1):
        if pts[i][0] <= x <= pts[i + 1][0] and pts[i][0] < pts[i + 1][0]:
            window = pts[max(0, i - 1):i + 3]
            logs = all(p > 0 and a > 0 for p, a in window) and x > 0
            f = math.log if logs else (lambda v: v)
            ps, avals, t = [f(p) for p, _ in window], [f(a) for _, a in window], f(x)
            value = 0.0
            for j, (pj, aj) in enumerate(zip(ps, avals)):
                weight = 1.0
                for k, pk in enumerate(ps):
                    if k != j:
                        weight *= (t - pk) / (pj - pk)
                value += weight * aj
            return math.exp(value) if logs else value
    for p, a in pts:
        if p == x:
            return a
    return math.nan


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--grid", required=True,
                    help="FROM:TO:N or a comma-separated list of the branch's parameter")
    ap.add_argument("--x", default="v", help="plotted x from the branch's parameter v")
    ap.add_argument("--y", default="v", help="plotted y from the second parameter v")
    ap.add_argument("--branch-axis", choices=("x", "y"), default="x",
                    help="the axis the branches run along (y: one block per branch)")
    ap.add_argument("--sweep", nargs=3, metavar=("RESULTS", "XCOL", "YCOL"),
                    help="a settled sweep of the same map to compare with")
    ap.add_argument("branches", nargs="+", metavar="DIR=VALUE")
    args = ap.parse_args()
    fx = eval("lambda v: " + args.x, {"math": math})
    fy = eval("lambda v: " + args.y, {"math": math})
    branches = []
    for item in args.branches:
        folder, value = item.rsplit("=", 1)
        try:
            branches.append((float(value), branch_points(folder)))
        except OSError as e:
            print(f"branch_grid: {folder}: {e.strerror}", file=sys.stderr)
            branches.append((float(value), []))
    branches.sort()
    table = {}  # (the branch's parameter, the other's value) -> amplitude
    for g in grid_values(args.grid):
        for other, points in branches:
            table[(g, other)] = sample(points, g)
    if args.branch_axis == "x":  # one block per grid value, a line per branch
        blocks = [[(fx(g), fy(o), table[(g, o)]) for o, _ in branches]
                  for g in grid_values(args.grid)]
    else:  # one block per branch (x = fx(its value)), a line per grid value
        blocks = [[(fx(o), fy(g), table[(g, o)]) for g in grid_values(args.grid)]
                  for o, _ in branches]
    print("\n\n".join("\n".join(f"{x:.10g} {y:.10g} {z:.10g}" for x, y, z in b)
                      for b in blocks))
    if args.sweep:
        results, xcol, ycol = args.sweep
        diffs = []
        with open(results, newline="") as f:
            for r in csv.DictReader(f):
                if r.get("status") != "complete":
                    continue
                x, y, a = float(r[xcol]), float(r[ycol]), float(r["amplitude_pp"])
                z = min(((abs(x - gx) + abs(y - gy), z) for (gx, gy), z in table.items()),
                        default=(math.inf, math.nan))
                if z[0] <= 1e-9 * (1 + abs(x) + abs(y)) and math.isfinite(z[1]) and a > 0:
                    diffs.append(abs(z[1] - a) / a)
        diffs.sort()
        if diffs:
            print(f"branch_grid: {len(diffs)} points beside the sweep's: relative difference "
                  f"median {diffs[len(diffs) // 2]:.2e}, largest {diffs[-1]:.2e}",
                  file=sys.stderr)
        else:
            print("branch_grid: no point of the sweep lies on the grid", file=sys.stderr)


if __name__ == "__main__":
    main()
