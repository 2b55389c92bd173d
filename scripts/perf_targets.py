#!/usr/bin/env python3
"""The throughput targets' table of docs/performance.md, from the benches' own JSON.

Each target is a figure the benches measure as a ratio or a rate in one process
(bench/, bench/peers/); this script only reads their Google Benchmark JSON
(--benchmark_out=FILE --benchmark_out_format=json), computes each target's measured value,
says met or not, and writes the markdown table. It never times anything itself.

    scripts/perf_targets.py JSON... [--write docs/performance.md]

Without --write it prints the table; with it, it replaces the lines between the markers
`<!-- perf-targets:begin -->` and `<!-- perf-targets:end -->` in that file. Where a run holds
repetitions, the median aggregate is read; a target whose benches are missing from the
files (a peer not installed, a filter that left it out) reads "not measured" and names them.
scripts/perf_targets.sh runs the benches and then this script.
"""
import argparse
import json
import math
import pathlib
import sys

BEGIN = "<!-- perf-targets:begin -->"
END = "<!-- perf-targets:end -->"


class Missing(Exception):
    """A bench a target needs is not in the files read."""


class Runs:
    """The benchmarks of the JSON files, by run name (the median aggregate where there are
    repetitions, else the single run)."""

    def __init__(self, documents):
        self.by_name = {}
        self.contexts = []
        for doc in documents:
            self.contexts.append(doc.get("context", {}))
            plain = {}
            for b in doc.get("benchmarks", []):
                name = b.get("run_name", b.get("name"))
                if b.get("run_type") == "aggregate":
                    if b.get("aggregate_name") == "median":
                        self.by_name[name] = b
                elif b.get("error_occurred"):
                    continue
                else:
                    plain.setdefault(name, b)
            for name, b in plain.items():
                self.by_name.setdefault(name, b)

    def get(self, prefix):
        """The run whose name is `prefix` or starts with `prefix` + "/"."""
        for name, b in self.by_name.items():
            if name == prefix or name.startswith(prefix + "/"):
                return b
        raise Missing(prefix)

    def counter(self, prefix, key):
        b = self.get(prefix)
        if key not in b:
            raise Missing(f"{prefix} counter {key}")
        return float(b[key])

    def milliseconds(self, prefix):
        b = self.get(prefix)
        scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b.get("time_unit", "ns")]
        return float(b["real_time"]) * scale


def points_per_second_on_two_threads(runs, bench):
    return runs.counter(bench, "points_per_step") / (runs.counter(bench, "step_us_2") * 1e-6)


def bullet_ratio_at_mujoco_depth(runs, scene, settings=()):
    """Bullet's time over Tribo's on `scene` when Tribo rests there no deeper than MuJoCo.
    Else, Tribo on `settings` (bench cases of the same scene with other parameters, Tribo
    alone): Bullet's time a simulated millisecond on the scene over the fastest of those that
    rest no deeper than MuJoCo does on it. With none, the scene's own ratio, not met."""
    ratio = runs.counter(f"BM_Peers/{scene}/bullet", "x_tribo")
    own = runs.counter(f"BM_Peers/{scene}/tribo", "penetration_um")
    mujoco = runs.counter(f"BM_Peers/{scene}/mujoco", "penetration_um")
    own_note = f"depth {own:.1f} um against MuJoCo's {mujoco:.1f} um"
    if own <= mujoco:
        return ratio, own_note
    best = None
    for case in settings:
        try:
            depth = runs.counter(f"BM_Peers/{case}/tribo", "penetration_um")
            cost = runs.counter(f"BM_Peers/{case}/tribo", "us_per_sim_ms")
        except Missing:
            continue
        if depth <= mujoco and (best is None or cost < best[2]):
            best = (case, depth, cost)
    if best is None:
        return ratio, own_note, False  # the ratio counts only at MuJoCo's depth or less
    case, depth, cost = best
    bullet = runs.counter(f"BM_Peers/{scene}/bullet", "us_per_sim_ms")
    return bullet / cost, (f"Tribo on `{case}`: depth {depth:.1f} um against MuJoCo's "
                           f"{mujoco:.1f} um; the scene as written {ratio:.2f} x at {own:.1f} um")


def granular_against_lammps(runs, case, engine):
    bench = f"BM_Peers/{case}/{engine}"
    ratio = runs.counter(bench, "x_lammps")
    if engine != "tribo_auto":
        return ratio
    return ratio, f"{runs.counter(bench, 'threads'):.2f} threads a step on the mean"


def chute_threads(runs):
    one = runs.counter("BM_Peers/granular_chute/tribo", "us_per_step")
    two = runs.counter("BM_Peers/granular_chute/tribo_2threads", "us_per_step")
    return one / two


def step_exponent(runs):
    small = runs.counter("BM_GridStep/10", "step_us")
    large = runs.counter("BM_GridStep/142", "step_us")
    return math.log(large / small) / math.log(142 * 142 / 100.0)


# (target, what is measured, comparison, bound, unit, value(runs)); value returns the number,
# or (number, note), or (number, note, condition) where the target also needs `condition`.
TARGETS = [
    *[(f"{scene}: Tribo on {how} at LAMMPS's per-core rate",
       f"`BM_Peers/{case}/{engine}` `x_lammps`", ">=", 1.0, "x",
       lambda r, case=case, engine=engine: granular_against_lammps(r, case, engine))
      for engine, how in (("tribo_2threads", "two threads"),
                          ("tribo_auto", "`threads: auto` (the measured choice, up to two)"))
      for scene, case in (("200-sphere pile", "granular_pile"),
                          ("32 000-sphere chute", "granular_chute"))],
    ("400 boxes on a half-space: contact points a second on two threads",
     "`BM_Threads/grid20` `points_per_step` / `step_us_2`", ">=", 16e6, "points/s",
     lambda r: points_per_second_on_two_threads(r, "BM_Threads/grid20")),
    ("400 boxes on a box ground: contact points a second on two threads",
     "`BM_Threads/grid20_box_ground` `points_per_step` / `step_us_2`", ">=", 16e6, "points/s",
     lambda r: points_per_second_on_two_threads(r, "BM_Threads/grid20_box_ground")),
    ("400 boxes on a half-space: times Bullet, at a depth no larger than MuJoCo's",
     "`BM_Peers/box_grid20/bullet` `x_tribo` where `tribo` rests no deeper than `mujoco` "
     "(`penetration_um`), else its `us_per_sim_ms` over the fastest of `box_grid20_stiff` and "
     "`box_grid20_stiff_1ms` `tribo` that does",
     ">=", 6.0, "x",
     lambda r: bullet_ratio_at_mujoco_depth(
         r, "box_grid20", ("box_grid20_stiff", "box_grid20_stiff_1ms"))),
    ("400 boxes on a box ground: times Bullet, at a depth no larger than MuJoCo's",
     "`BM_Peers/box_grid20_box_ground/bullet` `x_tribo`; `penetration_um` of tribo and mujoco",
     ">=", 6.0, "x", lambda r: bullet_ratio_at_mujoco_depth(r, "box_grid20_box_ground")),
    ("1600 boxes: two threads against one",
     "`BM_Threads/grid40` `speedup`", ">=", 1.7, "x",
     lambda r: r.counter("BM_Threads/grid40", "speedup")),
    ("32 000-sphere chute: two threads against one",
     "`BM_Peers/granular_chute/tribo` over `tribo_2threads` `us_per_step`", ">=", 1.7, "x",
     chute_threads),
    ("Step cost a body from 100 to 20 164 boxes: growth exponent",
     "`BM_GridStep/10` and `/142` `step_us`", "<=", 1.05, "",
     step_exponent),
    ("Heap held a body (20 164 boxes)",
     "`BM_GridSetUp/142` `heap_per_box_kB`", "<=", 3.0, "kB",
     lambda r: r.counter("BM_GridSetUp/142", "heap_per_box_kB")),
    ("20 000-body pattern scene set up",
     "`BM_PatternScene/20000` time", "<", 50.0, "ms",
     lambda r: r.milliseconds("BM_PatternScene/20000")),
    ("The belt's RK4 step against the hand-written loop",
     "`BM_BeltStepVsLoop/1000` `ratio`", "<=", 15.0, "x",
     lambda r: r.counter("BM_BeltStepVsLoop/1000", "ratio")),
]


def number(x, unit):
    if unit == "points/s":
        return f"{x / 1e6:.1f} M points/s"
    if abs(x) >= 100:
        text = f"{x:.0f}"
    elif abs(x) >= 10:
        text = f"{x:.1f}"
    else:
        text = f"{x:.2f}"
    return f"{text} {unit}".strip() if unit != "x" else f"{text} x"


def unpack(got):
    """A target's value as (number, note, condition)."""
    if not isinstance(got, tuple):
        return got, "", True
    if len(got) == 2:
        return got[0], got[1], True
    return got


def evaluate(runs):
    """Rows: (target, bound text, measured text, met: True/False/None, source)."""
    rows = []
    compare = {">=": lambda v, b: v >= b, "<=": lambda v, b: v <= b, "<": lambda v, b: v < b}
    for target, source, op, bound, unit, value in TARGETS:
        bound_text = f"{op} {number(bound, unit)}"
        try:
            got = value(runs)
        except Missing as e:
            rows.append((target, bound_text, f"none: {e} is not in the files", None, source))
            continue
        got, note, condition = unpack(got)
        measured = number(got, unit) + (f" ({note})" if note else "")
        met = compare[op](got, bound) and condition
        rows.append((target, bound_text, measured, met, source))
    return rows


def table(runs, files):
    lines = ["| target | bound | measured | met | bench and counters |",
             "| --- | --- | --- | --- | --- |"]
    for target, bound, measured, met, source in evaluate(runs):
        verdict = "not measured" if met is None else ("**met**" if met else "not met")
        lines.append(f"| {target} | {bound} | {measured} | {verdict} | {source} |")
    conditions = []
    for f, ctx in zip(files, runs.contexts):
        load = ", ".join(f"{x:.1f}" for x in ctx.get("load_avg", []))
        conditions.append(f"`{pathlib.Path(f).name}` {ctx.get('date', '?')}"
                          + (f", load {load}" if load else ""))
    lines.append("")
    lines.append("Generated by `scripts/perf_targets.py` from " + "; ".join(conditions) + ".")
    return "\n".join(lines)


def write_between_markers(path, text):
    content = pathlib.Path(path).read_text()
    begin, end = content.find(BEGIN), content.find(END)
    if begin < 0 or end < begin:
        sys.exit(f"perf_targets.py: {path}: the markers {BEGIN} and {END} are not there in order")
    head = content[: begin + len(BEGIN)]
    pathlib.Path(path).write_text(head + "\n" + text + "\n" + content[end:])


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("json", nargs="+", help="Google Benchmark JSON files")
    parser.add_argument("--write", metavar="MARKDOWN", help="replace the table in this file")
    args = parser.parse_args(argv)
    documents = []
    for f in args.json:
        try:
            documents.append(json.loads(pathlib.Path(f).read_text()))
        except (OSError, json.JSONDecodeError) as e:
            sys.exit(f"perf_targets.py: {f}: {e}")
    text = table(Runs(documents), args.json)
    if args.write:
        write_between_markers(args.write, text)
    else:
        print(text)


if __name__ == "__main__":
    main(sys.argv[1:])
