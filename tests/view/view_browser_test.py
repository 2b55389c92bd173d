#!/usr/bin/python3
"""Browser tests of the replay page (tribo view): a run is made with `tribo run --view`, the
page is opened in headless Chromium (software WebGL), and its DOM status and screenshots are
checked against expectations computed here from trajectory.csv and the camera parameters.

    view_browser_test.py TRIBO SOURCE_DIR WORK_DIR CASE
CASE: loads | position | controls | orientation | orientation_note | sweep | elements | branch.
Exit 0 pass, 1 fail, 77 skipped (no chromium, PIL or yaml). Not here: the page's own logic
(view/*.js), the C++ generators' unit tests.
"""
import csv
import html
import html.parser
import json
import math
import os
import re
import shutil
import subprocess
import sys

CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--enable-unsafe-swiftshader",
                  "--hide-scrollbars", "--no-first-run", "--mute-audio"]


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def check(condition, message):
    if not condition:
        fail(message)
    print("ok: " + message)


def chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def browse(work, url, mode, width=900, height=700, budget=3000, out=None, with_dom=False):
    """Runs headless Chromium on url; mode 'dom' returns the page's status JSON (and the
    dumped DOM with with_dom), 'shot' writes a screenshot to out."""
    profile = os.path.join(work, "profile-" + mode)
    args = [chromium()] + CHROMIUM_FLAGS + ["--user-data-dir=" + profile,
                                            "--window-size=%d,%d" % (width, height),
                                            "--virtual-time-budget=%d" % budget]
    args += ["--dump-dom"] if mode == "dom" else ["--screenshot=" + out]
    result = subprocess.run(args + [url], capture_output=True, text=True, timeout=90)
    if mode == "shot":
        if not os.path.exists(out):
            fail("no screenshot written: " + result.stderr[-2000:])
        return None
    dom = result.stdout
    start = dom.find('<pre id="tribo-status">')
    if start < 0:
        fail("no status element in the DOM: " + dom[:500] + result.stderr[-1000:])
    start += len('<pre id="tribo-status">')
    text = html.unescape(dom[start:dom.find("</pre>", start)])
    try:
        return (json.loads(text), dom) if with_dom else json.loads(text)
    except ValueError:
        fail("status is not JSON: " + text[:500])


def make_run(tribo, source, work, sets, scene="scenes/belt.yaml"):
    out = os.path.join(work, "run")
    if os.path.exists(out):
        shutil.rmtree(out)
    args = [tribo, "run", os.path.join(source, scene), "--out", out, "--quiet"]
    for s in sets:
        args += ["--set", s]
    result = subprocess.run(args + ["--view"], capture_output=True, text=True, timeout=120)
    if result.returncode != 0:
        fail("tribo run --view failed: " + result.stdout + result.stderr)
    return out


def read_csv(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    header = rows[0]
    return {name: [float(r[i]) for r in rows[1:]] for i, name in enumerate(header)}


def interpolate(times, values, t):
    for k in range(len(times) - 1):
        if times[k] <= t <= times[k + 1]:
            u = (t - times[k]) / (times[k + 1] - times[k])
            return values[k] + u * (values[k + 1] - values[k])
    return values[-1] if t > times[-1] else values[0]


def project(point, eye, target, fov_deg, width, height, with_depth=False):
    """Pixel of a world point through a perspective camera (z up), computed here (and its
    depth along the view direction)."""
    def sub(a, b): return [a[i] - b[i] for i in range(3)]
    def dot(a, b): return sum(a[i] * b[i] for i in range(3))
    def cross(a, b): return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                             a[0] * b[1] - a[1] * b[0]]
    def unit(a):
        n = math.sqrt(dot(a, a))
        return [x / n for x in a]
    forward = unit(sub(target, eye))
    right = unit(cross(forward, [0.0, 0.0, 1.0]))
    up = cross(right, forward)
    d = sub(point, eye)
    depth = dot(d, forward)
    tan_half = math.tan(math.radians(fov_deg) / 2.0)
    ndc_x = dot(d, right) / (depth * tan_half * width / height)
    ndc_y = dot(d, up) / (depth * tan_half)
    pixel = ((ndc_x + 1.0) / 2.0 * width, (1.0 - ndc_y) / 2.0 * height)
    return pixel + (depth,) if with_depth else pixel


def centroid(png, colour, width, height, tolerance=40):
    from PIL import Image
    image = Image.open(png).convert("RGB")
    target = tuple(int(colour[i:i + 2], 16) for i in (1, 3, 5))
    pixels = image.load()
    sx = sy = n = 0
    for y in range(min(height, image.size[1])):
        for x in range(min(width, image.size[0])):
            p = pixels[x, y]
            if abs(p[0] - target[0]) + abs(p[1] - target[1]) + abs(p[2] - target[2]) <= tolerance:
                sx += x + 0.5
                sy += y + 0.5
                n += 1
    return (sx / n, sy / n, n) if n else (None, None, 0)


def case_loads(tribo, source, work):
    run = make_run(tribo, source, work, ["duration=2"])
    status = browse(work, "file://" + run + "/view.html#t=0.5", "dom", budget=800)
    check(status.get("ready") is True, "the page ran to the end of its script")
    check(status["errors"] == [], "no JavaScript or console errors: %s" % status["errors"])
    check(status["bodies"] == 2 and status["names"] == ["belt", "box"],
          "the belt scene's two bodies, belt and box: %s" % status["names"])
    rows = len(read_csv(os.path.join(run, "trajectory.csv"))["t"])
    check(status["frames"] == rows and status["stride"] == 1,
          "all %d rows held (%d frames)" % (rows, status["frames"]))
    check(status["orientation"] is True, "tribo run --view recorded orientations")
    check(status["time"] > 0.5, "plays from t=0.5 on its own (t=%.3f)" % status["time"])


def case_position(tribo, source, work):
    run = make_run(tribo, source, work, ["duration=2"])
    traj = read_csv(os.path.join(run, "trajectory.csv"))
    width, height = 640, 480
    eye, target, fov = [0.1, -0.35, 0.9], [0.1, 0.0, 0.05], 40.0
    camera = ",".join(str(v) for v in eye + target + [fov])
    errors = []
    previous = None
    for t in (0.35, 0.9, 1.45):
        url = "file://%s/view.html#test&paused&t=%g&size=%dx%d&camera=%s" % (
            run, t, width, height, camera)
        status = browse(work, url, "dom", budget=500)
        check(status["errors"] == [], "no errors at t=%g" % t)
        png = os.path.join(work, "box_t%g.png" % t)
        browse(work, url, "shot", budget=500, out=png)
        p = [interpolate(traj["t"], traj["box." + a], t) for a in "xyz"]
        ex, ey = project(p, eye, target, fov, width, height)
        sx, sy = status["screen"]["box"]
        check(abs(sx - ex) < 0.5 and abs(sy - ey) < 0.5,
              "t=%g: the page projects the box to (%.1f, %.1f), computed here (%.1f, %.1f)" %
              (t, sx, sy, ex, ey))
        cx, cy, n = centroid(png, status["colours"]["box"], width, height)
        check(n > 500, "t=%g: the box's colour covers %d pixels" % (t, n))
        error = math.hypot(cx - ex, cy - ey)
        errors.append(error)
        check(error < 3.0, "t=%g: box drawn at (%.1f, %.1f), trajectory.csv puts it at (%.1f, %.1f):"
              " %.2f px off (tolerance 3 px)" % (t, cx, cy, ex, ey, error))
        if previous:
            moved = math.hypot(cx - previous[0], cy - previous[1])
            check(moved > 10, "t=%g: the box moved %.1f px on screen since the last time" % (t, moved))
        previous = (cx, cy)
    print("largest position error %.2f px" % max(errors))


def case_controls(tribo, source, work):
    run = make_run(tribo, source, work, ["duration=2"])
    traj = read_csv(os.path.join(run, "trajectory.csv"))
    url = ("file://%s/view.html#paused&t=0.5&clickdelay=400&"
           "click=wait,play,pause,wait,step,step,back,scrub:1500,wait" % run)
    status = browse(work, url, "dom", budget=5000)
    check(status["errors"] == [], "no errors: %s" % status["errors"])
    print("actions: %s" % json.dumps(status["actions"]))
    a = {i: x for i, x in enumerate(status["actions"])}
    check(len(a) == 9, "all nine scripted actions ran (%d)" % len(a))
    check(a[0]["time"] == 0.5 and not a[0]["playing"], "paused: t stays at 0.5 (%.4f)" % a[0]["time"])
    check(a[1]["playing"], "play starts the replay")
    # Replay time runs with the page's clock at speed 1: what it played between the two
    # clicks is the clock time between them (each action logs performance.now()).
    played, clock = a[2]["time"] - a[1]["time"], (a[2]["clock"] - a[1]["clock"]) / 1000.0
    check(clock >= 0.39 and abs(played - clock) < 0.01 and not a[2]["playing"],
          "played %.4f s in the %.4f s between the clicks, then paused" % (played, clock))
    check(a[3]["time"] == a[2]["time"], "paused: the time does not move (%.4f, %.4f)" %
          (a[2]["time"], a[3]["time"]))
    k = a[3]["frame"]
    check(a[4]["frame"] == k + 1 and a[4]["time"] == traj["t"][k + 1],
          "frame step: frame %d at t=%.4f (trajectory.csv row %d: %.4f)" %
          (a[4]["frame"], a[4]["time"], k + 1, traj["t"][k + 1]))
    check(a[5]["frame"] == k + 2 and a[6]["frame"] == k + 1, "step again, then back one frame")
    check(a[7]["frame"] == 1500 and a[7]["time"] == traj["t"][1500] and not a[7]["playing"],
          "scrub to frame 1500: t=%.4f (trajectory.csv: %.4f)" % (a[7]["time"], traj["t"][1500]))
    check(a[8]["time"] == a[7]["time"] and status["time"] == a[7]["time"],
          "after scrubbing the replay stays where it was put")


def rotate(q, v):
    """v rotated by the unit quaternion q = (w, x, y, z)."""
    w, x, y, z = q
    r = [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
         [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
         [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]
    return [sum(r[i][j] * v[j] for j in range(3)) for i in range(3)]


def long_axis_angle(png, colour, width, height, tolerance=40):
    """Angle [deg, 0..180) of the principal axis of the pixels of one colour (y down)."""
    from PIL import Image
    image = Image.open(png).convert("RGB")
    target = tuple(int(colour[i:i + 2], 16) for i in (1, 3, 5))
    pixels = image.load()
    points = [(x + 0.5, y + 0.5) for y in range(height) for x in range(width)
              if sum(abs(pixels[x, y][i] - target[i]) for i in range(3)) <= tolerance]
    if len(points) < 100:
        fail("the bar covers only %d pixels" % len(points))
    mx = sum(p[0] for p in points) / len(points)
    my = sum(p[1] for p in points) / len(points)
    sxx = sum((p[0] - mx) ** 2 for p in points)
    syy = sum((p[1] - my) ** 2 for p in points)
    sxy = sum((p[0] - mx) * (p[1] - my) for p in points)
    return math.degrees(0.5 * math.atan2(2 * sxy, sxx - syy)) % 180.0


def case_orientation(tribo, source, work):
    run = make_run(tribo, source, work, [], scene="tests/view/spinning_bar.yaml")
    traj = read_csv(os.path.join(run, "trajectory.csv"))
    width, height = 500, 500
    eye, target, fov = [0.0, -0.05, 1.2], [0.0, 0.0, 0.0], 30.0
    camera = ",".join(str(v) for v in eye + target + [fov])
    angles = []
    for t in (0.3, 1.2):
        url = "file://%s/view.html#test&paused&t=%g&size=%dx%d&camera=%s" % (
            run, t, width, height, camera)
        status = browse(work, url, "dom", budget=500)
        check(status["errors"] == [] and status["orientation"], "no errors, orientations held")
        png = os.path.join(work, "bar_t%g.png" % t)
        browse(work, url, "shot", budget=500, out=png)
        q = [interpolate(traj["t"], traj["bar." + a], t) for a in ("qw", "qx", "qy", "qz")]
        n = math.sqrt(sum(c * c for c in q))
        q = [c / n for c in q]
        centre = [interpolate(traj["t"], traj["bar." + a], t) for a in "xyz"]
        ends = [project([centre[i] + s * rotate(q, [0.2, 0, 0])[i] for i in range(3)],
                        eye, target, fov, width, height) for s in (-1, 1)]
        expected = math.degrees(math.atan2(ends[1][1] - ends[0][1], ends[1][0] - ends[0][0])) % 180.0
        drawn = long_axis_angle(png, status["colours"]["bar"], width, height)
        error = abs((drawn - expected + 90.0) % 180.0 - 90.0)
        angles.append(drawn)
        check(error < 1.5, "t=%g: the bar's long axis drawn at %.2f deg, the recorded quaternion "
              "puts it at %.2f deg: %.2f deg off (tolerance 1.5 deg)" % (t, drawn, expected, error))
    turned = abs((angles[1] - angles[0] + 90.0) % 180.0 - 90.0)
    check(turned > 30, "the bar turned %.1f deg on screen between the two times" % turned)


def case_sweep(tribo, source, work):
    out = os.path.join(work, "sweep")
    if os.path.exists(out):
        shutil.rmtree(out)
    result = subprocess.run([tribo, "sweep", os.path.join(source, "scenes", "belt.yaml"), "--out", out,
                             "--grid", "mu_k=0.2:0.3:3", "--grid", "v_b=1:2:4", "--set", "duration=3",
                             "--keep-trajectories", "--jobs", "1"], capture_output=True, text=True,
                            timeout=120)
    check(result.returncode == 0, "a 3 x 4 sweep keeping its trajectories")
    result = subprocess.run([tribo, "view", out], capture_output=True, text=True, timeout=120)
    # 12 points: folders 00..11 (zero-padded), results.csv's point column 0..11.
    check(result.returncode == 0 and "12 points, 12 with a replay page" in result.stdout,
          "tribo view SWEEP_DIR: " + result.stdout.strip() + result.stderr.strip())
    for p in range(12):
        check(os.path.exists(os.path.join(out, "points", "%02d" % p, "view.html")),
              "point %d has its page" % p)
    url = "file://" + out + "/view.html#metric=amplitude_pp"
    status = browse(work, url, "dom", width=1000, height=800, budget=500)
    check(status["errors"] == [] and status["points"] == 12 and status["linked"] == 12,
          "the sweep page loads with 12 points, all linked")
    with open(os.path.join(out, "results.csv")) as f:
        rows = list(csv.DictReader(f))
    expected = {r["point"]: float(r["amplitude_pp"]) for r in rows}
    cells = status["cells"]
    check(sorted(c["point"] for c in cells) == sorted(expected),
          "one cell per point of results.csv")
    for c in cells:
        check(abs(c["value"] - expected[c["point"]]) <= 1e-9 * abs(expected[c["point"]]),
              "point %s shows amplitude_pp %.6g" % (c["point"], c["value"]))
    png = os.path.join(work, "sweep.png")
    browse(work, url, "shot", width=1000, height=800, budget=500, out=png)
    from PIL import Image
    image = Image.open(png).convert("RGB")
    ox, oy = status["offset"]
    def brightness(c):
        p = image.getpixel((int(ox + c["x"] + 20), int(oy + c["y"])))  # beside the link dot
        return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]
    by_value = [c["point"] for c in sorted(cells, key=lambda c: c["value"])]
    by_brightness = [c["point"] for c in sorted(cells, key=brightness)]
    check(by_value == by_brightness, "cells brighter where amplitude_pp is larger: %s, %s" %
          (by_value, by_brightness))
    check_labels(status, 1000, 800, "amplitude_pp")
    # A small window and the result with the longest name: the labels still fit.
    skip = {"point", "status", "warnings", "message", "mu_k", "v_b"}
    def numeric(c):
        try:
            return all(math.isfinite(float(r[c])) for r in rows)
        except (TypeError, ValueError):
            return False
    longest = max((c for c in rows[0] if c not in skip and numeric(c)), key=len)
    status = browse(work, "file://" + out + "/view.html#metric=" + longest, "dom", width=640, height=480,
                    budget=500)
    check(status["errors"] == [] and status["metric"] == longest, "the page shows %s" % longest)
    check_labels(status, 640, 480, longest)


def check_labels(status, width, height, metric):
    """Every label of the sweep page (the colour bar's among them) lies inside the canvas and
    the viewport."""
    # The viewport: the window's width, its height less the headless window's frame.
    vw, vh = status["window"]
    check(vw == width and height - 200 <= vh <= height, "viewport %d x %d" % (vw, vh))
    labels = {l["name"]: l for l in status["labels"]}
    check("bar" in labels and labels["bar"]["text"] == metric,
          "the colour bar is labelled %s" % labels.get("bar", {}).get("text"))
    cw, ch = status["canvas"]
    for l in status["labels"]:
        x0, y0, x1, y1 = l["canvas_box"]
        check(0 <= x0 < x1 <= cw and 0 <= y0 < y1 <= ch,
              "label %s %r at %s lies inside the %d x %d canvas" % (l["name"], l["text"], l["canvas_box"], cw, ch))
        x0, y0, x1, y1 = l["page_box"]
        check(0 <= x0 < x1 <= vw and 0 <= y0 < y1 <= vh,
              "label %s at %s lies inside the %d x %d viewport" % (l["name"], l["page_box"], vw, vh))


def case_orientation_note(tribo, source, work):
    out = os.path.join(work, "run")
    if os.path.exists(out):
        shutil.rmtree(out)
    result = subprocess.run([tribo, "run", os.path.join(source, "scenes", "belt.yaml"), "--out", out,
                             "--quiet", "--set", "duration=0.5"], capture_output=True, text=True)
    check(result.returncode == 0, "a run without --view")
    result = subprocess.run([tribo, "view", out, "--frames", "100"], capture_output=True, text=True)
    check(result.returncode == 0 and "no orientations recorded" in result.stdout,
          "tribo view says the run has no orientations: " + result.stdout.strip())
    status = browse(work, "file://" + out + "/view.html#paused", "dom", budget=500)
    rows = len(read_csv(os.path.join(out, "trajectory.csv"))["t"])
    check(status["orientation"] is False and status["errors"] == [], "the page knows it too")
    check(status["frames"] <= 100 and status["rows"] == rows and status["stride"] == math.ceil((rows - 1) / 99),
          "%d rows decimated to %d frames (stride %d) under a cap of 100" %
          (rows, status["frames"], status["stride"]))


# What a column's unit is, by its suffix (docs/scene-format.md's channel table), for the
# plot's axis label.
UNITS = {"x": "m", "y": "m", "z": "m", "vx": "m/s", "vy": "m/s", "vz": "m/s", "slip": "m/s",
         "normal_force": "N", "friction_force": "N"}


class LegendParser(html.parser.HTMLParser):
    """The legend's entries in the dumped DOM: data-key -> (swatch colours, text)."""
    def __init__(self):
        super().__init__()
        self.entries, self.depth, self.key = {}, 0, None

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if a.get("id") == "legend":
            self.depth = 1
        elif self.depth:
            self.depth += 1
            if a.get("class") == "entry":
                self.key = a.get("data-key")
                self.entries[self.key] = ([], "")
            elif a.get("class") == "swatch" and self.key:
                self.entries[self.key][0].append(a.get("data-colour"))

    def handle_endtag(self, tag):
        if self.depth:
            self.depth -= 1

    def handle_data(self, data):
        if self.depth and self.key:
            colours, text = self.entries[self.key]
            self.entries[self.key] = (colours, text + data)


def rgb(hex_colour):
    return tuple(int(hex_colour[i:i + 2], 16) for i in (1, 3, 5))


def pixels_of(png, colour, tolerance=40):
    from PIL import Image
    image = Image.open(png).convert("RGB")
    target = rgb(colour)
    px = image.load()
    return [(x + 0.5, y + 0.5) for y in range(image.size[1]) for x in range(image.size[0])
            if sum(abs(px[x, y][i] - target[i]) for i in range(3)) <= tolerance]


def distance_to_segment(p, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    u = max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy)))
    return math.hypot(p[0] - a[0] - u * dx, p[1] - a[1] - u * dy)


def case_elements(tribo, source, work):
    """The belt scene's spring (wall anchor to the box), the box's joint and the belt's
    direction of motion are drawn where the scene and trajectory.csv put them; the legend
    names what each colour means; the plot has tick values and units."""
    import yaml
    with open(os.path.join(source, "scenes", "belt.yaml")) as f:
        scene = yaml.safe_load(f)
    run = make_run(tribo, source, work, ["duration=2"])
    traj = read_csv(os.path.join(run, "trajectory.csv"))
    z0 = traj["box.z"][0]  # the scene's $z0: the box starts there
    def value(v):  # a number or "$name" of the scene's parameters
        if isinstance(v, str) and v.startswith("$"):
            return z0 if v == "$z0" else float(scene["parameters"][v[1:]])
        return float(v)
    springs = scene["springs"]
    joints = [j for j in scene["joints"] if j["type"] != "free"]
    belt = next(b for b in scene["bodies"] if b["name"] == "belt")
    v_belt = [value(v) for v in belt["surface_velocity"]]
    check(len(springs) == 1 and springs[0]["a"] == "world" and springs[0]["b"] == "box",
          "belt.yaml: one spring, from the world to the box")
    wall = [value(v) for v in springs[0]["point_a"]]

    # The full page: legend, plot, counts and places of what is drawn.
    t = 1.0
    status, dom = browse(work, "file://%s/view.html#paused&t=%g&plot=box.x" % (run, t), "dom",
                         width=1000, height=700, budget=800, with_dom=True)
    check(status["errors"] == [], "no errors: %s" % status["errors"])
    expected = {"springs": len(springs), "anchors": 2 * len(springs), "joints": len(joints),
                "belt_arrows": 1}
    check(status["elements"] == expected, "drawn: %s, the scene has %s" % (status["elements"], expected))
    box = [interpolate(traj["t"], traj["box." + a], t) for a in "xyz"]
    drawn = status["drawn"]
    s = drawn["springs"][0]
    check(all(abs(s["a"][i] - wall[i]) < 1e-5 for i in range(3)),
          "the spring's wall end at %s, belt.yaml's point_a %s" % (s["a"], wall))
    # point_b is the box's initial origin: it moves with the box's origin.
    check(all(abs(s["b"][i] - box[i]) < 1e-5 for i in range(3)),
          "the spring's box end at %s follows the box to %s" % (s["b"], box))
    j = drawn["joints"][0]
    check(j["name"] == joints[0]["name"] and all(abs(j["anchor"][i] - box[i]) < 1e-5 for i in range(3)),
          "the joint %s drawn at the box's origin %s" % (j["name"], j["anchor"]))
    arrow = drawn["belt_arrows"][0]
    d = [arrow["end"][i] - arrow["start"][i] for i in range(3)]
    n = math.sqrt(sum(c * c for c in d))
    vn = math.sqrt(sum(c * c for c in v_belt))
    check(arrow["body"] == "belt" and all(abs(d[i] / n - v_belt[i] / vn) < 1e-6 for i in range(3)),
          "the belt's arrow points along its surface velocity %s: %s" % (v_belt, [c / n for c in d]))
    check(abs(arrow["start"][2]) < 0.02 and abs(arrow["end"][2]) < 0.02,
          "the arrow lies on the belt's surface z = 0 (z %.4f)" % arrow["start"][2])

    # Colours: no body looks like a contact state; the legend lists each meaning.
    parser = LegendParser()
    parser.feed(dom)
    legend = parser.entries
    for key in ("body", "sticking", "slipping", "spring", "joint", "belt"):
        check(key in legend and legend[key][0] and legend[key][1].strip(),
              "legend entry %s: %s" % (key, legend.get(key)))
    check(status["colours"]["box"] in legend["body"][0], "the legend shows the box's colour %s" %
          status["colours"]["box"])
    for state in ("sticking", "slipping"):
        c = rgb(legend[state][0][0])
        for name, body_colour in status["colours"].items():
            b = rgb(body_colour)
            dist = math.sqrt(sum((c[i] - b[i]) ** 2 for i in range(3)))
            check(dist > 120, "%s %s is far from %s's colour %s (RGB distance %.0f)" %
                  (state, legend[state][0][0], name, body_colour, dist))
    lx0, ly0, lx1, ly1 = status["legend_rect"]
    check(0 <= lx0 < lx1 <= 1000 and 0 <= ly0 < ly1 <= 700, "the legend lies in the window: %s" %
          status["legend_rect"])

    # The plot: time ticks within the run, value ticks over box.x's range, units in the labels.
    plot = status["plot"]
    check(plot["x_label"] == "t [s]", "time axis label %r" % plot["x_label"])
    check(plot["y_label"] == "box.x [%s]" % UNITS["x"], "value axis label %r" % plot["y_label"])
    for axis, ticks, lo, hi in (("time", plot["x_ticks"], traj["t"][0], traj["t"][-1]),
                                ("value", plot["y_ticks"], min(traj["box.x"]), max(traj["box.x"]))):
        values = [k["value"] for k in ticks]
        pixels = [k["px" if axis == "time" else "py"] for k in ticks]
        steps = [values[i + 1] - values[i] for i in range(len(values) - 1)]
        margin = 0.05 * (hi - lo)
        check(len(values) >= 3 and all(lo - margin <= v <= hi + margin for v in values),
              "%s ticks %s within [%.4g, %.4g]" % (axis, [k["text"] for k in ticks], lo, hi))
        check(all(abs(float(k["text"]) - k["value"]) <= 1e-9 + 1e-6 * abs(steps[0]) for k in ticks),
              "%s tick labels read as their values" % axis)
        check(all(st > 0 and abs(st - steps[0]) < 1e-9 * steps[0] for st in steps),
              "%s ticks evenly spaced by %g" % (axis, steps[0]))
        scale = [(pixels[i + 1] - pixels[i]) / steps[i] for i in range(len(steps))]
        check(all(abs(c - scale[0]) < 0.02 * abs(scale[0]) for c in scale) and
              (scale[0] > 0) == (axis == "time"),
              "%s ticks placed linearly (%.2f px per unit)" % (axis, scale[0]))

    # The flat-colour page through a fixed camera: where the spring, joint and arrow are drawn.
    width, height = 800, 600
    eye, target, fov = [0.0, -0.6, 0.5], [-0.05, 0.0, 0.05], 45.0
    url = "file://%s/view.html#test&paused&t=%g&size=%dx%d&camera=%s" % (
        run, t, width, height, ",".join(str(v) for v in eye + target + [fov]))
    status = browse(work, url, "dom", budget=500)
    check(status["errors"] == [], "no errors in test mode")
    png = os.path.join(work, "elements.png")
    browse(work, url, "shot", budget=500, out=png)
    s = status["drawn"]["springs"][0]
    for end, point in (("screen_b", box), ("screen_a", wall)):
        ex, ey = project(point, eye, target, fov, width, height)
        sx, sy = s[end]
        check(abs(sx - ex) < 0.5 + 1e-6 * abs(ex) and abs(sy - ey) < 0.5 + 1e-6 * abs(ey),
              "the page projects the spring's end %s to (%.1f, %.1f), computed here (%.1f, %.1f)" %
              (point, sx, sy, ex, ey))
    # The coil: from the box's left face towards the wall, spring-coloured pixels lie along
    # the line within the coil's radius on screen; and every spring-coloured pixel does.
    white = pixels_of(png, status["spring_colour"])
    focal = height / (2 * math.tan(math.radians(fov) / 2))
    radius = status["coil_radius"]
    samples = hits = 0
    far = None
    x = box[0] - 0.13
    while True:
        u = (box[0] - x) / (box[0] - wall[0])
        p = [box[i] + u * (wall[i] - box[i]) for i in range(3)]
        px, py, depth = project(p, eye, target, fov, width, height, with_depth=True)
        if not (12 <= px <= width - 12 and 12 <= py <= height - 12):
            break
        tol = radius * focal / depth + 2.5
        samples += 1
        hits += any(abs(q[0] - px) <= tol and abs(q[1] - py) <= tol and
                    math.hypot(q[0] - px, q[1] - py) <= tol for q in white)
        far = (px, py, tol)
        x -= 0.02
    check(samples >= 10 and hits >= 0.9 * samples,
          "the coil drawn at %d of %d points along the spring's line" % (hits, samples))
    near = project(box, eye, target, fov, width, height)
    off = [q for q in white if distance_to_segment(q, near, far[:2]) > far[2] + 12]
    check(len(white) > 50 and len(off) <= 0.02 * len(white),
          "%d of %d spring-coloured pixels off the spring's line" % (len(off), len(white)))
    # The joint's marker over the box's origin.
    jx, jy = project(box, eye, target, fov, width, height)
    yellow = [q for q in pixels_of(png, status["joint_colour"]) if math.hypot(q[0] - jx, q[1] - jy) < 40]
    check(len(yellow) > 20, "the joint's marker: %d joint-coloured pixels around (%.0f, %.0f)" %
          (len(yellow), jx, jy))
    # The belt's arrow: its pixels along the projected direction of the belt's motion.
    a = status["drawn"]["belt_arrows"][0]
    a0 = project(a["start"], eye, target, fov, width, height)
    a1 = project(a["end"], eye, target, fov, width, height)
    green = pixels_of(png, status["belt_colour"])
    check(len(green) > 50, "the arrow covers %d pixels" % len(green))
    along = [((q[0] - a0[0]) * (a1[0] - a0[0]) + (q[1] - a0[1]) * (a1[1] - a0[1])) /
             ((a1[0] - a0[0]) ** 2 + (a1[1] - a0[1]) ** 2) for q in green]
    off = [q for q in green if distance_to_segment(q, a0, a1) > 12]
    check(not off and min(along) > -0.05 and max(along) < 1.05,
          "the arrow's pixels lie on the projected belt direction from (%.0f, %.0f) to (%.0f, %.0f)"
          % (a0[0], a0[1], a1[0], a1[1]))
    head = sum(1 for u in along if u > 0.75)
    tail = sum(1 for u in along if u < 0.25)
    check(head > tail, "the arrow's head (%d px) at the end the belt moves to (tail %d px)" %
          (head, tail))


def case_branch(tribo, source, work):
    """A short branch of the belt's orbit in the belt speed (tribo orbit --continue) and its page
    (tribo view): one dot per row of branch.csv where its parameter and amplitude put it, a
    click on a dot chooses that point and shows its period, the replay plot spans its
    peak-to-peak amplitude and replays its sampled orbit, the arrow keys step along the branch."""
    out = os.path.join(work, "branch")
    if os.path.exists(out):
        shutil.rmtree(out)
    result = subprocess.run([tribo, "orbit", os.path.join(source, "scenes", "belt.yaml"), "--continue",
                             "v_b=1:1.5", "--step", "0.25", "--max-points", "4", "--out", out],
                            capture_output=True, text=True, timeout=120)
    check(result.returncode == 0, "tribo orbit --continue v_b=1:1.5: " + result.stdout.strip()[-300:] +
          result.stderr.strip()[-300:])
    with open(os.path.join(out, "branch.csv")) as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(out, "branch.json")) as f:
        manifest = json.load(f)
    samples, times = {}, {}
    with open(os.path.join(out, "branch_orbits.csv")) as f:
        for r in list(csv.reader(f))[1:]:
            times.setdefault(int(r[0]), []).append(float(r[1]))
            samples.setdefault(int(r[0]), []).append(float(r[2]))
    n = len(rows)
    check(n >= 2, "the branch has %d points" % n)
    result = subprocess.run([tribo, "view", out], capture_output=True, text=True, timeout=120)
    check(result.returncode == 0 and ("%d points" % n) in result.stdout and
          os.path.exists(os.path.join(out, "view.html")),
          "tribo view BRANCH_DIR: " + result.stdout.strip() + result.stderr.strip())

    def close(a, b, rel):
        return abs(a - b) <= rel * max(abs(a), abs(b))

    # A click on the last point's dot (the page dispatches it at the dot's pixel), then the
    # replay twice, 300 ms of the page's clock apart.
    last = n - 1
    status = browse(work, "file://%s/view.html#click=%d,wait,wait&clickdelay=300" % (out, last), "dom",
                    width=1000, height=800, budget=2000)
    check(status["errors"] == [], "no JavaScript or console errors: %s" % status["errors"])
    drawn = status["drawn_points"]
    check(status["points"] == n and len(drawn) == n,
          "%d points drawn, branch.csv has %d rows" % (len(drawn), n))
    for d in drawn:
        r = rows[d["index"]]
        check(close(d["parameter"], float(r["parameter"]), 1e-12) and
              close(d["amplitude_pp"], float(r["amplitude_pp"]), 1e-12) and
              d["stable"] == (r["stable"] == "1"),
              "point %d drawn at %s = %.6g, amplitude %.6g, %s, as branch.csv says" %
              (d["index"], manifest["parameter"], d["parameter"], d["amplitude_pp"],
               "stable" if d["stable"] else "unstable"))
    by_parameter = sorted(drawn, key=lambda d: d["parameter"])
    by_amplitude = sorted(drawn, key=lambda d: d["amplitude_pp"])
    check(all(a["x"] < b["x"] for a, b in zip(by_parameter, by_parameter[1:])) and
          all(a["y"] > b["y"] for a, b in zip(by_amplitude, by_amplitude[1:])),
          "the dots lie rightwards as the parameter grows and upwards as the amplitude does")
    cw, ch = status["canvas"]
    check(all(0 <= d["x"] <= cw and 0 <= d["y"] <= ch for d in drawn), "every dot inside the canvas")
    labels = {l["name"]: l for l in status["labels"]}
    check(labels["x_axis"]["text"] == manifest["parameter"] and
          labels["y_axis"]["text"] == "peak to peak of " + manifest["observed"],
          "axes labelled %r and %r" % (labels["x_axis"]["text"], labels["y_axis"]["text"]))
    for l in status["labels"]:
        x0, y0, x1, y1 = l["canvas_box"]
        check(0 <= x0 < x1 <= cw and 0 <= y0 < y1 <= ch,
              "label %s %r lies inside the %d x %d canvas" % (l["name"], l["text"], cw, ch))
    steady = status["segments"]["steady_solid"] + status["segments"]["steady_dashed"]
    check(steady >= n - 1, "steady sliding drawn on the axis (%d segments)" % steady)

    check(status["actions"] and status["actions"][0]["action"] == "click:%d" % last and
          status["selected"]["index"] == last,
          "the click chose point %d: %s" % (last, status["actions"]))
    period = float(rows[last]["period"])
    check(close(status["selected"]["period"], period, 1e-12),
          "the chosen point's period %.12g s, branch.csv's %.12g s" % (status["selected"]["period"], period))
    m = re.search(r"period (\S+) s", status["selected"]["text"])
    check(m is not None and close(float(m.group(1)), period, 1e-9),
          "the page shows it: %r" % status["selected"]["text"])
    replay = status["replay"]
    amplitude = float(rows[last]["amplitude_pp"])
    lo, hi = replay["x_range"]
    check(replay["point"] == last and close(hi - lo, amplitude, 1e-6),
          "the replay plot spans %.10g of %s, point %d's amplitude_pp %.10g" %
          (hi - lo, manifest["observed"], last, amplitude))
    check(replay["samples"] == len(samples[last]) and
          close(replay["t_range"][1] - replay["t_range"][0], period, 1e-6),
          "it replays point %d's %d samples of branch_orbits.csv over one period" %
          (last, replay["samples"]))
    # The samples' own extremes: the minimum is refined between samples for amplitude_pp
    # (docs/orbits.md), about 1e-6 of it lower than the lowest sample.
    slo, shi = replay["sample_range"]
    check(close(shi - slo, max(samples[last]) - min(samples[last]), 1e-8) and
          close(shi - slo, amplitude, 1e-5),
          "its samples span %.10g (branch_orbits.csv: %.10g)" %
          (shi - slo, max(samples[last]) - min(samples[last])))
    # The marker: on the orbit (branch_orbits.csv interpolated here), and running in time: one
    # period in seconds_per_period of the page's clock.
    waits = [a for a in status["actions"] if a["action"] == "wait"]
    check(len(waits) == 2, "two replays logged")
    for a in waits:
        t, x = a["marker"]["t"], a["marker"]["x"]
        expected = interpolate(times[last], samples[last], t)
        check(0 <= t <= replay["t_range"][1] and abs(x - expected) <= 1e-6 * amplitude,
              "the marker at t = %.4f s is on the orbit: %s = %.8g (branch_orbits.csv: %.8g)" %
              (t, manifest["observed"], x, expected))
    clock = (waits[1]["clock"] - waits[0]["clock"]) / 1000.0
    advance = clock / replay["seconds_per_period"] * period % period
    moved = (waits[1]["marker"]["t"] - waits[0]["marker"]["t"]) % period
    check(clock > 0.2 and abs(moved - advance) < 1e-3,
          "the marker moved %.4f s along the orbit in %.4f s of the page's clock (%.4f s expected at "
          "%.3g s a period)" % (moved, clock, advance, replay["seconds_per_period"]))

    # Arrow keys: right and left step along the branch, held at its ends.
    status = browse(work, "file://%s/view.html#click=0,right,right,left,left,left" % out, "dom",
                    width=1000, height=800, budget=2000)
    expected, k = [0], 0
    for step in (1, 1, -1, -1, -1):
        k = max(0, min(n - 1, k + step))
        expected.append(k)
    got = [a["selected"] for a in status["actions"]]
    check(status["errors"] == [] and got == expected, "selections %s, expected %s" % (got, expected))
    for a in status["actions"]:
        check(close(a["period"], float(rows[a["selected"]]["period"]), 1e-12),
              "%s: point %d, period %.10g s" % (a["action"], a["selected"], a["period"]))


def case_branch_switch(tribo, source, work):
    """A branch switched to at a period doubling (tribo orbit --continue --switch) and its page:
    the branch switched from (primary_branch.csv) drawn in grey beside the new one, solid
    between its stable points and dashed into the unstable one past the doubling, inside the
    diagram's ranges; the note says where the switch was."""
    out = os.path.join(work, "branch_switch")
    if os.path.exists(out):
        shutil.rmtree(out)
    result = subprocess.run([tribo, "orbit", os.path.join(source, "scenes", "parametric_pendulum.yaml"),
                             "--continue", "f=1.2:0.85", "--switch", "period_doubling", "--step", "0.1",
                             "--max-points", "4", "--out", out],
                            capture_output=True, text=True, timeout=120)
    check(result.returncode == 0, "tribo orbit --switch: " + result.stdout.strip()[-300:] +
          result.stderr.strip()[-300:])
    with open(os.path.join(out, "primary_branch.csv")) as f:
        primary = list(csv.DictReader(f))
    with open(os.path.join(out, "branch.csv")) as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(out, "branch.json")) as f:
        manifest = json.load(f)
    check(len(primary) >= 2 and manifest["switch"]["found"],
          "%d primary points, the switch found" % len(primary))
    result = subprocess.run([tribo, "view", out], capture_output=True, text=True, timeout=120)
    check(result.returncode == 0, "tribo view: " + result.stdout.strip() + result.stderr.strip())
    status, dom = browse(work, "file://%s/view.html" % out, "dom", width=1000, height=800,
                         budget=2000, with_dom=True)
    check(status["errors"] == [], "no JavaScript or console errors: %s" % status["errors"])
    check(status["points"] == len(rows) and len(status["drawn_points"]) == len(rows),
          "the new branch's %d points drawn as dots (branch.csv: %d)" %
          (len(status["drawn_points"]), len(rows)))
    stable = [r["stable"] == "1" for r in primary]
    solid = sum(1 for a, b in zip(stable, stable[1:]) if a and b)
    segments = status["segments"]
    check(segments["primary_solid"] == solid and
          segments["primary_solid"] + segments["primary_dashed"] == len(primary) - 1,
          "the primary's %d segments drawn, %d solid between stable points: %s" %
          (len(primary) - 1, solid, segments))
    first = float(primary[0]["parameter"])
    lo, hi = status["axes"]["x_range"]
    check(lo <= first <= hi and lo <= min(float(r["parameter"]) for r in rows),
          "the x range [%.4g, %.4g] holds the primary's start %.4g and the new branch" % (lo, hi, first))
    check("switched from the grey branch" in dom and ("%d points" % len(primary)) in dom,
          "the page notes the switch")


def main():
    tribo, source, work, case = sys.argv[1:5]
    if not chromium():
        print("SKIPPED: no chromium on PATH (scripts/setup.sh installs it)")
        sys.exit(77)
    try:
        import PIL  # noqa: F401
        import yaml  # noqa: F401
    except ImportError:
        print("SKIPPED: no PIL or yaml for /usr/bin/python3 (Debian python3-pil, python3-yaml; "
              "scripts/setup.sh)")
        sys.exit(77)
    work = os.path.abspath(work)
    os.makedirs(work, exist_ok=True)
    {"loads": case_loads, "position": case_position, "controls": case_controls,
     "orientation_note": case_orientation_note, "orientation": case_orientation, "sweep": case_sweep,
     "elements": case_elements, "branch": case_branch,
     "branch_switch": case_branch_switch}[case](os.path.abspath(tribo), source, work)
    print("PASS")


if __name__ == "__main__":
    main()
