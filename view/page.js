// The replay page's main script: reads the embedded run (window.TRIBO_DATA), builds the
// view, replays the recorded motion (positions and orientations, interpolated between
// frames), wires the controls (play, pause, speed, scrub, frame steps, follow, trails,
// forces, stick/slip, plot channels, keyboard), fills the legend and writes a JSON status
// into #tribo-status for tests: errors, bodies, time, frame, camera, each body's projected
// screen position and colour, the springs, joints and surface arrows drawn (where, on
// screen), the legend's entries, the plot's axes, frame times. URL hash parameters (docs/view.md): t, paused, speed,
// camera=ex,ey,ez,tx,ty,tz[,fov], follow, trails, plot, forces, stickslip, test,
// click=ID,...,scrub:FRAME,wait (controls clicked in order, clickdelay ms apart), size=WxH,
// bench=N.
// Not here: geometry (scene.js), overlays (overlays.js), springs, joints and surface arrows
// (elements.js), the plot (plot.js).
(function () {
  var data = window.TRIBO_DATA;
  var statusEl = document.getElementById("tribo-status");
  var hash = {};
  location.hash.replace(/^#/, "").split("&").forEach(function (kv) {
    if (!kv) return;
    var i = kv.indexOf("=");
    hash[decodeURIComponent(i < 0 ? kv : kv.slice(0, i))] = i < 0 ? "" : decodeURIComponent(kv.slice(i + 1));
  });
  var test = "test" in hash;
  if (test) document.body.classList.add("test");

  var meta = data.meta;
  var series = data.series;
  var T = series[0];
  var frames = T.length;
  var columnIndex = {};
  meta.columns.forEach(function (c, k) { columnIndex[c] = k; });

  // Columns of each body's pose; undefined where not recorded.
  var pos = [], quat = [];
  data.scene.bodies.forEach(function (b, i) {
    var p = ["x", "y", "z"].map(function (a) { return columnIndex[b.name + "." + a]; });
    var q = ["qw", "qx", "qy", "qz"].map(function (a) { return columnIndex[b.name + "." + a]; });
    pos[i] = p.every(function (c) { return c !== undefined; }) ? p : null;
    quat[i] = q.every(function (c) { return c !== undefined; }) ? q : null;
  });
  var hasOrientation = quat.some(function (q) { return q; });

  // The scene's size: the spread of the recorded and initial body origins and the joints'
  // anchors, at least the bodies' own sizes (springs' far ends, on the world, do not count).
  var lo = new THREE.Vector3(Infinity, Infinity, Infinity), hi = lo.clone().negate();
  data.scene.bodies.forEach(function (b, i) {
    var v = new THREE.Vector3().fromArray(b.position);
    lo.min(v); hi.max(v);
    if (pos[i]) [0, frames - 1].forEach(function (f) {
      var w = new THREE.Vector3(series[pos[i][0]][f], series[pos[i][1]][f], series[pos[i][2]][f]);
      lo.min(w); hi.max(w);
    });
    b.geometries.forEach(function (g) {
      var r = g.half_extents ? Math.max.apply(null, g.half_extents) : (g.radius || 0) + (g.half_length || 0);
      lo.min(v.clone().subScalar(r)); hi.max(v.clone().addScalar(r));
    });
  });
  (data.scene.joints || []).forEach(function (j) {  // joint anchors are near their bodies
    if (j.type === "free") return;
    var v = new THREE.Vector3().fromArray(j.anchor);
    lo.min(v); hi.max(v);
  });
  if (!isFinite(lo.x)) { lo.set(-1, -1, -1); hi.set(1, 1, 1); }
  var centre = lo.clone().add(hi).multiplyScalar(0.5);
  var extent = Math.max(hi.clone().sub(lo).length(), 0.1);

  var built = TriboView.buildScene(data, extent, test);
  var renderer = new THREE.WebGLRenderer({ antialias: !test, preserveDrawingBuffer: true });
  renderer.setPixelRatio(test ? 1 : (window.devicePixelRatio || 1));
  // size=WxH fixes the canvas (tests: the same pixels in a screenshot as in the status).
  var fixed = hash.size ? hash.size.split("x").map(Number) : null;
  function width() { return fixed ? fixed[0] : window.innerWidth; }
  function height() { return fixed ? fixed[1] : window.innerHeight; }
  renderer.setSize(width(), height());
  document.getElementById("view").appendChild(renderer.domElement);
  var camera = new THREE.PerspectiveCamera(45, width() / height(), extent * 1e-3, extent * 1e3);

  var view = {
    data: data, series: series, frames: frames, columnIndex: columnIndex, pos: pos,
    scene: built.scene, bodies: built.bodies, extent: extent, renderer: renderer,
    camera: camera, frame: 0
  };
  var state = { t: T[0], playing: !("paused" in hash), speed: 1, follow: -1, stickSlip: false };
  var orbit = new TriboView.Orbit(camera, renderer.domElement, function () { render(); });
  var eye = centre.clone().add(new THREE.Vector3(1.1, -1.7, 1.0).multiplyScalar(extent));
  var target = centre.clone();
  if (hash.camera) {
    var c = hash.camera.split(",").map(Number);
    eye.set(c[0], c[1], c[2]);
    target.set(c[3], c[4], c[5]);
    if (c.length > 6) camera.fov = c[6];
  }
  camera.updateProjectionMatrix();
  orbit.set(eye, target);
  var overlays = new TriboView.Overlays(view);
  var elements = new TriboView.Elements(data, view);
  var plot = new TriboView.Plot(document.getElementById("plot"), view, function (t) { seek(t); });

  // Frame k with T[k] <= t < T[k+1] (binary search), and the fraction of the way to k+1.
  function locate(t) {
    var a = 0, b = frames - 1;
    if (t <= T[0]) return [0, 0];
    if (t >= T[b]) return [b, 0];
    while (b - a > 1) { var m = (a + b) >> 1; if (T[m] <= t) a = m; else b = m; }
    return [a, (t - T[a]) / (T[b] - T[a])];
  }
  var qa = new THREE.Quaternion(), qb = new THREE.Quaternion();
  function place(k, u) {
    var k1 = Math.min(k + 1, frames - 1);
    built.bodies.forEach(function (b, i) {
      var p = pos[i];
      if (p) b.group.position.set(
        series[p[0]][k] + u * (series[p[0]][k1] - series[p[0]][k]),
        series[p[1]][k] + u * (series[p[1]][k1] - series[p[1]][k]),
        series[p[2]][k] + u * (series[p[2]][k1] - series[p[2]][k]));
      var q = quat[i];
      if (q) {
        qa.set(series[q[1]][k], series[q[2]][k], series[q[3]][k], series[q[0]][k]);
        qb.set(series[q[1]][k1], series[q[2]][k1], series[q[3]][k1], series[q[0]][k1]);
        THREE.Quaternion.slerp(qa, qb, b.group.quaternion, u);
      }
    });
  }

  var scrub = document.getElementById("scrub");
  scrub.max = String(frames - 1);
  var clock = document.getElementById("clock");
  var frameTimes = [], renderTimes = [], lastStamp = null, renders = 0;

  function render() {
    var r0 = performance.now();
    var at = locate(state.t);
    view.frame = at[0];
    place(at[0], at[1]);
    elements.update();
    TriboView.movePlanes(built.planes, state.t);
    if (state.follow >= 0) {
      var bp = built.bodies[state.follow].group.position;
      orbit.target.copy(bp);
      orbit.update();
    }
    overlays.update(view.frame, state.stickSlip);
    renderer.render(built.scene, camera);
    if (!test) plot.draw(state.t);
    scrub.value = String(view.frame);
    clock.textContent = "t = " + state.t.toFixed(4) + " s   frame " + (view.frame + 1) + " / " + frames +
      (state.playing ? "   playing" : "   paused") + "   x" + state.speed;
    renderTimes.push(performance.now() - r0);
    if (renderTimes.length > 240) renderTimes.shift();
    ++renders;
    if (test || built.bodies.length <= 50 || renders % 30 === 0 || !state.playing) writeStatus();
  }

  function seek(t) { state.t = Math.max(T[0], Math.min(T[frames - 1], t)); reanchor(); render(); }
  function stepFrame(d) {
    state.playing = false;
    var k = locate(state.t)[0];
    var exact = T[k] === state.t;
    k = d > 0 ? Math.min(k + 1, frames - 1) : Math.max(exact ? k - 1 : k, 0);
    seek(T[k]);
  }

  // While playing, replay time runs with the clock from where play (or a speed change)
  // anchored it, whatever the frame rate; pausing reads it once more.
  var anchor = { t: state.t, clock: performance.now() };
  function reanchor() { anchor = { t: state.t, clock: performance.now() }; }
  function advance() {
    if (!state.playing) return;
    state.t = anchor.t + (performance.now() - anchor.clock) / 1000 * state.speed;
    if (state.t >= T[frames - 1]) { state.t = T[frames - 1]; state.playing = false; }
  }
  function tick(stamp) {
    if (lastStamp !== null) {
      frameTimes.push(stamp - lastStamp);
      if (frameTimes.length > 240) frameTimes.shift();
    }
    lastStamp = stamp;
    if (state.playing) { advance(); render(); }
    requestAnimationFrame(tick);
  }

  function stats(a) {
    if (!a.length) return null;
    var s = a.slice().sort(function (x, y) { return x - y; });
    var mean = a.reduce(function (x, y) { return x + y; }, 0) / a.length;
    return { mean: +mean.toFixed(3), p95: +s[Math.floor(0.95 * (s.length - 1))].toFixed(3), count: a.length };
  }

  var actions = [];
  var bench = null;
  // bench=N: N frames across the run rendered back to back, each waited for (a one-pixel
  // read makes the GPU finish), for the cost of a frame of this scene in this browser.
  function runBench(n) {
    var gl = renderer.getContext(), px = new Uint8Array(4), times = [];
    for (var i = 0; i < n; ++i) {
      var r0 = performance.now();
      seek(T[0] + (T[frames - 1] - T[0]) * i / Math.max(n - 1, 1));
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
      times.push(performance.now() - r0);
    }
    bench = stats(times);
  }
  function writeStatus() {
    var w = renderer.domElement.width, h = renderer.domElement.height;
    var screen = {}, colours = {};
    function pixel(v) {
      var p = v.clone().project(camera);
      return [+((p.x + 1) / 2 * w).toFixed(2), +((1 - p.y) / 2 * h).toFixed(2)];
    }
    built.bodies.forEach(function (b) {
      screen[b.name] = pixel(b.group.position);
      colours[b.name] = "#" + b.baseColour.getHexString();
    });
    var legendBox = legend ? legend.getBoundingClientRect() : { left: 0, top: 0, right: 0, bottom: 0 };
    statusEl.textContent = JSON.stringify({
      ready: true, errors: window.TRIBO_ERRORS, bodies: built.bodies.length,
      names: built.bodies.map(function (b) { return b.name; }),
      time: state.t, frame: view.frame, frames: frames, rows: meta.rows, stride: meta.stride,
      playing: state.playing, speed: state.speed, orientation: hasOrientation,
      canvas: [w, h], window: [window.innerWidth, window.innerHeight],
      camera: { eye: camera.position.toArray(), target: orbit.target.toArray(), fov: camera.fov },
      screen: screen, colours: colours, actions: actions,
      elements: elements.counts, drawn: elements.describe(pixel),
      legend: legendEntries, legend_rect: [legendBox.left, legendBox.top, legendBox.right, legendBox.bottom],
      plot: plot.axes, coil_radius: elements.coilRadius,
      spring_colour: "#" + new THREE.Color(TriboView.colours.spring).getHexString(),
      joint_colour: "#" + new THREE.Color(TriboView.colours.joint).getHexString(),
      belt_colour: "#" + new THREE.Color(TriboView.colours.belt).getHexString(),
      frame_ms: stats(frameTimes), render_ms: stats(renderTimes), bench: bench
    });
  }

  // Controls.
  function byId(id) { return document.getElementById(id); }
  byId("play").addEventListener("click", function () {
    if (state.t >= T[frames - 1]) state.t = T[0];
    state.playing = true; reanchor(); render();
  });
  byId("pause").addEventListener("click", function () { advance(); state.playing = false; render(); });
  byId("step").addEventListener("click", function () { stepFrame(1); });
  byId("back").addEventListener("click", function () { stepFrame(-1); });
  scrub.addEventListener("input", function () { state.playing = false; seek(T[+scrub.value]); });
  var speed = byId("speed");
  [0.01, 0.1, 0.25, 0.5, 1, 2, 5, 10, 50].forEach(function (s) {
    var o = document.createElement("option"); o.value = String(s); o.textContent = "x" + s; speed.appendChild(o);
  });
  speed.value = "1";
  speed.addEventListener("change", function () { advance(); state.speed = +speed.value; reanchor(); render(); });
  var follow = byId("follow"), trails = byId("trails"), channels = byId("channels");
  built.bodies.forEach(function (b, i) {
    var o = document.createElement("option"); o.value = String(i); o.textContent = b.name; follow.appendChild(o);
    if (pos[i]) { o = document.createElement("option"); o.value = String(i); o.textContent = b.name; trails.appendChild(o); }
  });
  meta.columns.forEach(function (c, k) {
    if (k === 0) return;
    var o = document.createElement("option"); o.value = String(k); o.textContent = c; channels.appendChild(o);
  });
  follow.addEventListener("change", function () { state.follow = follow.value === "" ? -1 : +follow.value; render(); });
  function selected(sel) {
    return Array.prototype.filter.call(sel.options, function (o) { return o.selected; }).map(function (o) { return +o.value; });
  }
  trails.addEventListener("change", function () { overlays.setTrails(selected(trails)); render(); });
  channels.addEventListener("change", function () { plot.choose(selected(channels)); render(); });
  byId("forces").addEventListener("change", function () { overlays.showForces(byId("forces").checked); render(); });
  byId("stickslip").addEventListener("change", function () { state.stickSlip = byId("stickslip").checked; render(); });
  window.addEventListener("keydown", function (e) {
    if (e.target.tagName === "SELECT" || e.target.tagName === "INPUT") return;
    if (e.key === " ") { byId(state.playing ? "pause" : "play").click(); e.preventDefault(); }
    if (e.key === "ArrowRight") stepFrame(1);
    if (e.key === "ArrowLeft") stepFrame(-1);
  });
  window.addEventListener("resize", function () {
    renderer.setSize(width(), height());
    camera.aspect = width() / height();
    camera.updateProjectionMatrix();
    render();
  });

  // Title and notes.
  byId("title").textContent = meta.scene_path + (meta.status ? "  (" + meta.status + ")" : "");
  var notes = ["holds " + frames + " frames of " + meta.rows + " recorded rows" +
               (meta.stride > 1 ? " (one in " + meta.stride + "; cap " + meta.frame_cap + " frames)" : "")];
  if (!hasOrientation) notes.push("no orientation recorded: bodies keep their initial orientation " +
                                  "(add orientation to output.channels, or run with --view)");
  if (overlays.hasForces) notes.push("force arrows: magnitudes recorded; normal drawn along +z" +
                                     (overlays.hasFriction ? ", friction against the motion relative to the moving surface" : ""));
  else { byId("forces").disabled = true; byId("stickslip").disabled = true; }
  byId("notes").innerHTML = "";
  notes.concat(built.notes).forEach(function (n) { var d = document.createElement("div"); d.textContent = n; byId("notes").appendChild(d); });

  // The legend: what each colour and marker means, for what this scene has.
  var legend = byId("legend"), legendEntries = [];
  function hex(c) { return "#" + new THREE.Color(c).getHexString(); }
  function legendEntry(key, symbol, colours, label) {
    var d = document.createElement("div");
    d.className = "entry";
    d.setAttribute("data-key", key);
    colours.forEach(function (c) {
      var sw = document.createElement("span");
      sw.className = "swatch";
      sw.setAttribute("data-colour", hex(c));
      sw.style.color = hex(c);
      sw.textContent = symbol;
      d.appendChild(sw);
    });
    d.appendChild(document.createTextNode(" " + label));
    legend.appendChild(d);
    legendEntries.push({ key: key, colours: colours.map(hex), label: label });
  }
  var C = TriboView.colours;
  var bodyColours = [];
  built.bodies.forEach(function (b, i) {
    // Only bodies drawn in their colour (a half-space is a textured plane).
    var gs = data.scene.bodies[i].geometries;
    if (gs.length && gs.every(function (g) { return g.shape === "halfspace"; })) return;
    var c = hex(b.baseColour);
    if (bodyColours.indexOf(c) < 0 && bodyColours.length < 8) bodyColours.push(c);
  });
  legendEntry("body", "\u25a0", bodyColours, built.bodies.length > 1 ? "bodies (each its own colour)" : "body");
  if (overlays.hasStickSlip) {
    legendEntry("sticking", "\u25a0", [C.sticking], "sticking: in contact, slip below the stick speed (stick/slip on)");
    legendEntry("slipping", "\u25a0", [C.slipping], "slipping: in contact, slip above it (stick/slip on)");
  }
  if (overlays.hasForces) {
    legendEntry("normal_force", "\u2191", [C.normal], "normal force (forces on)");
    if (overlays.hasFriction) legendEntry("friction_force", "\u2192", [C.friction], "friction force (forces on)");
  }
  if (elements.counts.springs)
    legendEntry("spring", "\u223f", [C.spring], "spring between its anchors (dots)");
  if (elements.counts.joints)
    legendEntry("joint", "\u25c6", [C.joint], "joint: anchor and axis");
  if (elements.counts.belt_arrows)
    legendEntry("belt", "\u27a4", [C.belt], "direction the surface (belt) moves");

  // URL hash settings.
  function setSelect(sel, names) {
    var wanted = names.split(",");
    Array.prototype.forEach.call(sel.options, function (o) { o.selected = wanted.indexOf(o.textContent) >= 0; });
    sel.dispatchEvent(new Event("change"));
  }
  if (hash.speed) { state.speed = +hash.speed; speed.value = hash.speed; }
  if (hash.follow) setSelect(follow, hash.follow);
  if (hash.trails) setSelect(trails, hash.trails);
  if (hash.plot) setSelect(channels, hash.plot);
  else if (meta.observed && columnIndex[meta.observed] !== undefined) setSelect(channels, meta.observed);
  if ("forces" in hash) byId("forces").click();
  if ("stickslip" in hash) byId("stickslip").click();
  if (hash.t) state.t = Math.max(T[0], Math.min(T[frames - 1], +hash.t));
  reanchor();
  render();
  if (hash.bench) { state.playing = false; runBench(+hash.bench); }
  writeStatus();

  // Scripted clicks for tests: click=play,pause,step,back,scrub:FRAME,wait, clickdelay ms apart;
  // each action logs the time, frame and playing state just after it.
  if (hash.click) {
    var delay = hash.clickdelay ? +hash.clickdelay : 300;
    var script = hash.click.split(",");
    // Each action is timed from the one before, so that the delays hold however late a
    // timer fires.
    var next = function (n) {
      if (n >= script.length) return;
      setTimeout(function () {
        var a = script[n];
        if (a === "wait") {
          // nothing: records the status a moment after the previous action
        } else if (a.indexOf("scrub:") === 0) {
          scrub.value = a.slice(6);
          scrub.dispatchEvent(new Event("input"));
        } else {
          byId(a).click();
        }
        actions.push({ action: a, time: state.t, frame: view.frame, playing: state.playing,
                       clock: +performance.now().toFixed(1) });
        writeStatus();
        next(n + 1);
      }, delay);
    };
    next(0);
  }
  requestAnimationFrame(tick);
})();
