// The branch page's script: the bifurcation diagram of `tribo orbit --continue`'s branch (each
// orbit's peak-to-peak amplitude against the continued parameter; stable orbits joined by solid
// lines, unstable ones by dashed lines, split where the stability changes; steady sliding on
// the parameter axis, solid where its growth rate is negative and dashed where it is positive,
// split where it changes sign; the located events and the Hopf start marked and labelled;
// after a branch switch, the branch switched from in grey),
// and the chosen point's orbit replayed: the observed coordinate over one period with a marker
// running along it in time and the located extremes dotted. Clicking a point chooses it,
// hovering shows its values, left and right arrows choose the previous and next point along
// the branch. Uses TriboView.niceTicks, tickText and label (plot.js). Writes #tribo-status (errors,
// the points drawn and their pixels, the events, the labels and their boxes, the chosen point,
// the replay's ranges and marker, the actions) for tests. URL hash: point=K (chosen first),
// click=K,right,left,wait (a click on point K's dot, an arrow key, or the replay drawn and its
// marker logged; clickdelay ms apart, 200; each logs the page's clock). Not here: a run's
// replay (page.js), the sweep page (sweep.js).
(function () {
  var data = window.TRIBO_DATA, meta = data.meta, points = data.points, orbits = data.orbits;
  var statusEl = document.getElementById("tribo-status");
  var diagram = document.getElementById("diagram"), g = diagram.getContext("2d");
  var replay = document.getElementById("replay"), rg = replay.getContext("2d");
  var infoEl = document.getElementById("point-info"), tooltip = document.getElementById("tooltip");
  var hash = {};
  location.hash.replace(/^#/, "").split("&").forEach(function (kv) {
    var i = kv.indexOf("=");
    if (kv) hash[decodeURIComponent(i < 0 ? kv : kv.slice(0, i))] = i < 0 ? "" : decodeURIComponent(kv.slice(i + 1));
  });
  var colours = { stable: "#5b9bd5", unstable: "#e15759", undecided: "#9e9e9e", primary: "#8c8c8c", steadyStable: "#59a14f",
                  steadyUnstable: "#f28e2b", event: "#edc948", chosen: "#ffffff", text: "#ddd" };
  var DASH = [7, 5];

  function value(v) { return v === null || v === undefined ? NaN : v; }
  // A number to `digits` significant digits, in exponent form when very small or large.
  function shown(v, digits) {
    if (!isFinite(v)) return "n/a";
    var a = Math.abs(v);
    if (a !== 0 && (a < 1e-3 || a >= 1e7)) return v.toExponential(digits - 1).replace(/\.?0+e/, "e");
    return String(+v.toPrecision(digits));
  }
  function clamp(v, lo, hi) { return Math.max(lo, Math.min(hi, v)); }

  // Title, notes and a legend of the line styles and colours.
  document.getElementById("title").textContent = "branch of " + meta.scene + " in " + meta.parameter +
    ": " + points.length + " points, " + meta.status;
  var notes = [];
  if (meta.stop_reason) notes.push(meta.stop_reason);
  if (meta.hopf) notes.push("started at a Hopf point of steady sliding, " + meta.parameter + " = " +
                            shown(meta.hopf.parameter, 8));
  var primary = data.primary || [];
  if (meta.switch && meta.switch.found)
    notes.push("switched from the grey branch (" + primary.length + " points) at its " +
               meta.switch.at.replace("_", " ") + ", " + meta.parameter + " = " +
               shown(meta.switch.parameter, 8));
  if (!meta.steady_growth) notes.push("branch.csv has no steady sliding growth rates: the axis is bare");
  if (meta.orbit_samples < meta.orbit_rows)
    notes.push("orbits decimated: " + meta.orbit_samples + " of " + meta.orbit_rows + " samples held");
  notes.push("click a point to replay its orbit; left/right arrows: previous/next point");
  document.getElementById("notes").textContent = notes.join("; ");
  var legend = document.getElementById("legend-line");
  [["stable", "\u2014 stable orbit"], ["unstable", "- - unstable orbit"],
   ["steadyStable", "\u2014 steady sliding stable (amplitude 0)"], ["steadyUnstable", "- - steady sliding unstable"],
   ["event", "\u25c6 event"], ["primary", "\u2014 branch switched from"]].forEach(function (entry) {
    if (!meta.steady_growth && entry[0].indexOf("steady") === 0) return;
    if (entry[0] === "primary" && primary.length === 0) return;
    var s = document.createElement("span");
    s.style.color = colours[entry[0]];
    s.style.marginRight = "14px";
    s.textContent = entry[1];
    legend.appendChild(s);
  });

  // Where each event is drawn: at its parameter (the middle of its two points' when it could
  // not be interpolated) and the amplitude interpolated between those points; a Hopf point on
  // the axis, where the orbits shrink onto steady sliding.
  var events = data.events.map(function (e) {
    var a = points[e.between[0]], b = points[e.between[1]];
    var p = e.parameter === null ? (a.parameter + b.parameter) / 2 : e.parameter;
    var amplitude;
    if (e.kind === "hopf") amplitude = 0;
    else if (b.parameter !== a.parameter)
      amplitude = a.amplitude_pp + clamp((p - a.parameter) / (b.parameter - a.parameter), 0, 1) *
                                   (b.amplitude_pp - a.amplitude_pp);
    else amplitude = (a.amplitude_pp + b.amplitude_pp) / 2;
    return { kind: e.kind, parameter: p, amplitude: amplitude, between: e.between };
  });
  if (meta.hopf) events.push({ kind: "hopf (start)", parameter: meta.hopf.parameter, amplitude: 0, between: null });

  // The diagram's ranges: every point, event and the Hopf start; amplitude from a little below 0
  // (so that steady sliding's line stands clear of the frame).
  var plo = Infinity, phi = -Infinity, amax = 0;
  points.concat(primary).forEach(function (p) {
    if (isFinite(p.parameter)) { plo = Math.min(plo, p.parameter); phi = Math.max(phi, p.parameter); }
    if (isFinite(p.amplitude_pp)) amax = Math.max(amax, p.amplitude_pp);
  });
  events.forEach(function (e) {
    if (isFinite(e.parameter)) { plo = Math.min(plo, e.parameter); phi = Math.max(phi, e.parameter); }
  });
  if (!(phi > plo)) { var half = 0.5 * (Math.abs(plo) || 1); plo -= half; phi += half; }
  var ppad = 0.04 * (phi - plo);
  plo -= ppad; phi += ppad;
  if (!(amax > 0)) amax = 1;
  var alo = -0.04 * amax, ahi = 1.12 * amax;

  var chosen = hash.point !== undefined ? clamp(Math.round(+hash.point) || 0, 0, points.length - 1) : 0;
  var hovered = -1;
  var drawn = [], labels = [], segments = {}, axes = {}, eventsDrawn = [];
  var actions = [];
  var box = { left: 72, right: 20, top: 26, bottom: 46 };

  function fitCanvases() {
    var w = clamp(window.innerWidth - 24, 420, 900);
    var panel = document.getElementById("branch-panel");
    diagram.width = w;
    diagram.height = clamp(window.innerHeight - panel.offsetHeight - 200 - 60, 260, 420);
    replay.width = w;
    replay.height = 200;
  }

  var label = TriboView.label;

  // The largest font size (12 px down to 8 px) at which `text` is at most `room` wide.
  function fit(ctx, text, room) {
    for (var size = 12; size > 8; --size) {
      ctx.font = size + "px sans-serif";
      if (ctx.measureText(text).width <= room) return;
    }
    ctx.font = "8px sans-serif";
  }

  // A frame with round ticks and their values, the axes' names; returns the pixel mappings.
  function frame(ctx, list, w, h, xlo, xhi, ylo, yhi, xName, yName, prefix) {
    var x0 = box.left, x1 = w - box.right, y0 = box.top, y1 = h - box.bottom;
    function X(v) { return x0 + (v - xlo) / (xhi - xlo) * (x1 - x0); }
    function Y(v) { return y1 - (v - ylo) / (yhi - ylo) * (y1 - y0); }
    ctx.font = "11px sans-serif";
    ctx.lineWidth = 1;
    ctx.setLineDash([]);
    ctx.strokeStyle = "#3a3f48";
    ctx.fillStyle = "#aaa";
    var out = { x_label: xName, y_label: yName, x_ticks: [], y_ticks: [] };
    var xt = TriboView.niceTicks(xlo, xhi, Math.max(2, Math.floor((x1 - x0) / 90)));
    xt.values.forEach(function (v) {
      var px = X(v);
      ctx.beginPath(); ctx.moveTo(px, y0); ctx.lineTo(px, y1 + 4); ctx.stroke();
      var text = TriboView.tickText(v, xt.step);
      var halfWidth = ctx.measureText(text).width / 2;
      ctx.textAlign = "center";
      ctx.fillText(text, clamp(px, halfWidth + 1, w - halfWidth - 1), y1 + 15);
      out.x_ticks.push({ value: v, text: text, px: +px.toFixed(2) });
    });
    var yt = TriboView.niceTicks(ylo, yhi, Math.max(2, Math.floor((y1 - y0) / 30)));
    ctx.textAlign = "right";
    yt.values.forEach(function (v) {
      var py = Y(v);
      ctx.beginPath(); ctx.moveTo(x0 - 4, py); ctx.lineTo(x1, py); ctx.stroke();
      var text = TriboView.tickText(v, yt.step);
      ctx.fillText(text, x0 - 6, py + 4);
      out.y_ticks.push({ value: v, text: text, py: +py.toFixed(2) });
    });
    ctx.strokeStyle = "#888";
    ctx.beginPath(); ctx.moveTo(x0, y0); ctx.lineTo(x0, y1); ctx.lineTo(x1, y1); ctx.stroke();
    ctx.fillStyle = "#ccc";
    var xMid = (x0 + x1) / 2, yMid = (y0 + y1) / 2;  // labels centred there, fitted to the canvas
    fit(ctx, xName, 2 * Math.min(xMid, w - xMid) - 4);
    label(ctx, list, prefix + "x_axis", xName, xMid, h - 8, "center");
    fit(ctx, yName, 2 * Math.min(yMid, h - yMid) - 4);
    label(ctx, list, prefix + "y_axis", yName, 14, yMid, "center", true);
    ctx.font = "12px sans-serif";
    out.box = [x0, y0, x1, y1];
    out.x_range = [xlo, xhi];
    out.y_range = [ylo, yhi];
    return { X: X, Y: Y, axes: out };
  }

  function line(ctx, xa, ya, xb, yb, colour, dashed, width) {
    ctx.strokeStyle = colour;
    ctx.lineWidth = width;
    ctx.setLineDash(dashed ? DASH : []);
    ctx.beginPath(); ctx.moveTo(xa, ya); ctx.lineTo(xb, yb); ctx.stroke();
    ctx.setLineDash([]);
  }

  function diamond(ctx, x, y, size, colour) {
    ctx.fillStyle = colour;
    ctx.beginPath();
    ctx.moveTo(x, y - size); ctx.lineTo(x + size, y); ctx.lineTo(x, y + size); ctx.lineTo(x - size, y);
    ctx.closePath(); ctx.fill();
  }

  function drawDiagram() {
    var w = diagram.width, h = diagram.height;
    g.clearRect(0, 0, w, h);
    labels = [];
    var f = frame(g, labels, w, h, plo, phi, alo, ahi, meta.parameter, "peak to peak of " + meta.observed, "");
    var X = f.X, Y = f.Y;
    axes = f.axes;
    segments = { orbit_solid: 0, orbit_dashed: 0, steady_solid: 0, steady_dashed: 0,
                 primary_solid: 0, primary_dashed: 0 };

    // The branch switched from (grey, dashed where unstable), under everything else; its
    // points are not chosen (their orbits are not in this folder).
    for (var j = 0; j + 1 < primary.length; ++j) {
      var pa = primary[j], pb = primary[j + 1], both = pa.stable && pb.stable;
      line(g, X(pa.parameter), Y(pa.amplitude_pp), X(pb.parameter), Y(pb.amplitude_pp), colours.primary, !both, 2);
      segments[both ? "primary_solid" : "primary_dashed"] += 1;
    }
    primary.forEach(function (pt) {
      g.fillStyle = g.strokeStyle = colours.primary;
      g.lineWidth = 1.5;
      g.beginPath(); g.arc(X(pt.parameter), Y(pt.amplitude_pp), 3, 0, 2 * Math.PI);
      if (pt.stable) g.fill(); else g.stroke();
    });

    // Steady sliding on the axis, by parameter (it is a function of the parameter alone).
    if (meta.steady_growth) {
      var steady = points.filter(function (p) { return isFinite(value(p.steady_growth_rate)); })
        .sort(function (a, b) { return a.parameter - b.parameter; });
      for (var s = 0; s + 1 < steady.length; ++s) {
        var a = steady[s], b = steady[s + 1], ga = a.steady_growth_rate, gb = b.steady_growth_rate;
        var split = (ga < 0) !== (gb < 0) ? ga / (ga - gb) : 1;  // where the rate crosses 0
        var pm = a.parameter + split * (b.parameter - a.parameter);
        line(g, X(a.parameter), Y(0), X(pm), Y(0), ga < 0 ? colours.steadyStable : colours.steadyUnstable, ga >= 0, 3);
        segments[ga < 0 ? "steady_solid" : "steady_dashed"] += 1;
        if (split < 1) {
          line(g, X(pm), Y(0), X(b.parameter), Y(0), gb < 0 ? colours.steadyStable : colours.steadyUnstable, gb >= 0, 3);
          segments[gb < 0 ? "steady_solid" : "steady_dashed"] += 1;
        }
      }
      steady.forEach(function (p) {
        var stable = p.steady_growth_rate < 0;
        g.fillStyle = g.strokeStyle = stable ? colours.steadyStable : colours.steadyUnstable;
        g.lineWidth = 1.5;
        if (stable) g.fillRect(X(p.parameter) - 3, Y(0) - 3, 6, 6);
        else g.strokeRect(X(p.parameter) - 3, Y(0) - 3, 6, 6);
      });
    }

    // The orbits, point to point along the branch; a pair of different stability split where
    // an event between them is located (else halfway).
    function style(pt) { return pt.stable ? colours.stable : colours.unstable; }
    for (var i = 0; i + 1 < points.length; ++i) {
      var p = points[i], q = points[i + 1];
      if (p.stable === q.stable) {
        line(g, X(p.parameter), Y(p.amplitude_pp), X(q.parameter), Y(q.amplitude_pp), style(p), !p.stable, 2);
        segments[p.stable ? "orbit_solid" : "orbit_dashed"] += 1;
        continue;
      }
      var u = 0.5;
      data.events.forEach(function (e) {
        if (e.between[1] !== i + 1 || e.parameter === null || q.parameter === p.parameter) return;
        if (["stability_change", "period_doubling", "torus", "fold"].indexOf(e.kind) < 0) return;
        u = clamp((e.parameter - p.parameter) / (q.parameter - p.parameter), 0, 1);
      });
      var mx = X(p.parameter + u * (q.parameter - p.parameter)), my = Y(p.amplitude_pp + u * (q.amplitude_pp - p.amplitude_pp));
      line(g, X(p.parameter), Y(p.amplitude_pp), mx, my, style(p), !p.stable, 2);
      line(g, mx, my, X(q.parameter), Y(q.amplitude_pp), style(q), !q.stable, 2);
      segments[p.stable ? "orbit_solid" : "orbit_dashed"] += 1;
      segments[q.stable ? "orbit_solid" : "orbit_dashed"] += 1;
    }

    // Events: a diamond each, under the points.
    eventsDrawn = [];
    events.forEach(function (e) {
      if (!isFinite(e.parameter) || !isFinite(e.amplitude)) return;
      var x = X(e.parameter), y = Y(e.amplitude);
      diamond(g, x, y, 6, colours.event);
      eventsDrawn.push({ kind: e.kind, parameter: e.parameter, amplitude: e.amplitude, between: e.between,
                         x: +x.toFixed(2), y: +y.toFixed(2) });
    });

    // The points: filled when stable, rings when not (grey when the stability is undecided);
    // the chosen one circled in white.
    drawn = [];
    points.forEach(function (pt, k) {
      if (!isFinite(pt.parameter) || !isFinite(pt.amplitude_pp)) return;
      var x = X(pt.parameter), y = Y(pt.amplitude_pp);
      g.fillStyle = g.strokeStyle = pt.undecided ? colours.undecided : pt.stable ? colours.stable : colours.unstable;
      g.lineWidth = 2;
      g.beginPath(); g.arc(x, y, 4, 0, 2 * Math.PI);
      if (pt.stable) g.fill(); else g.stroke();
      if (k === hovered && k !== chosen) {
        g.strokeStyle = "#999"; g.lineWidth = 1;
        g.beginPath(); g.arc(x, y, 7, 0, 2 * Math.PI); g.stroke();
      }
      drawn.push({ index: k, x: +x.toFixed(2), y: +y.toFixed(2), stable: pt.stable,
                   parameter: pt.parameter, amplitude_pp: pt.amplitude_pp });
    });
    var c = drawn.filter(function (d) { return d.index === chosen; })[0];
    if (c) {
      g.strokeStyle = colours.chosen; g.lineWidth = 2;
      g.beginPath(); g.arc(c.x, c.y, 8, 0, 2 * Math.PI); g.stroke();
    }

    // The events' kinds: above each diamond, moved up past the points, the diamonds and the
    // labels already placed (below the diamond when there is no room above), inside the canvas.
    g.font = "12px sans-serif";
    var placed = drawn.map(function (d) { return [d.x - 9, d.y - 9, d.x + 9, d.y + 9]; })
      .concat(eventsDrawn.map(function (e) { return [e.x - 7, e.y - 7, e.x + 7, e.y + 7]; }));
    function overlaps(b) {
      return placed.some(function (o) { return b[0] < o[2] && o[0] < b[2] && b[1] < o[3] && o[1] < b[3]; });
    }
    eventsDrawn.forEach(function (e, k) {
      var m = g.measureText(e.kind), halfWidth = m.width / 2 + 1;
      var lx = clamp(e.x, halfWidth + 2, w - halfWidth - 2);
      var asc = m.actualBoundingBoxAscent, desc = m.actualBoundingBoxDescent;
      var boxAt = function (yy) { return [lx - halfWidth, yy - asc - 1, lx + halfWidth, yy + desc + 1]; };
      var ly = e.y - 10;
      while (overlaps(boxAt(ly)) && ly - asc > 2) ly -= 7;
      if (ly - asc <= 2) {
        ly = e.y + 10 + asc;
        while (overlaps(boxAt(ly)) && ly + desc < h - 2) ly += 7;
        ly = Math.min(ly, h - 2 - desc);
      }
      var b = boxAt(ly);
      placed.push(b);
      if (b[1] > e.y + 8 || b[3] < e.y - 12) {  // moved off its diamond: a thin line leads back
        g.strokeStyle = colours.event; g.lineWidth = 1; g.setLineDash([1, 2]);
        g.beginPath(); g.moveTo(lx, b[1] > e.y ? b[1] : b[3]); g.lineTo(e.x, e.y); g.stroke();
        g.setLineDash([]);
      }
      g.fillStyle = colours.event;
      label(g, labels, "event" + k, e.kind, lx, ly, "center");
    });
  }

  // The chosen orbit over one period, with a marker at time `tm` and the located extremes.
  var replayState = { point: -1, samples: 0, t_range: null, x_range: null, sample_range: null, marker: null, frames: 0 };
  var replayLabels = [];
  function drawReplay(tm) {
    var w = replay.width, h = replay.height, o = orbits[chosen], p = points[chosen];
    rg.clearRect(0, 0, w, h);
    replayLabels = [];
    var n = o.t.length, t0 = o.t[0], t1 = o.t[n - 1] > t0 ? o.t[n - 1] : t0 + 1;
    var slo = Infinity, shi = -Infinity;
    o.x.forEach(function (v) { slo = Math.min(slo, v); shi = Math.max(shi, v); });
    var lo = slo, hi = shi;
    if (isFinite(value(p.x_min))) lo = Math.min(lo, p.x_min);
    if (isFinite(value(p.x_max))) hi = Math.max(hi, p.x_max);
    var pad = hi > lo ? 0.08 * (hi - lo) : 0.5 * (Math.abs(lo) || 1);
    var f = frame(rg, replayLabels, w, h, t0, t1, lo - pad, hi + pad, "t [s]", meta.observed, "replay_");
    var X = f.X, Y = f.Y;
    // The located extremes (x_min refined between samples), dotted.
    [p.x_min, p.x_max].forEach(function (v) {
      if (!isFinite(value(v))) return;
      rg.strokeStyle = "#888"; rg.lineWidth = 1; rg.setLineDash([2, 3]);
      rg.beginPath(); rg.moveTo(X(t0), Y(v)); rg.lineTo(X(t1), Y(v)); rg.stroke();
      rg.setLineDash([]);
    });
    rg.strokeStyle = p.stable ? colours.stable : colours.unstable;
    rg.lineWidth = 2;
    rg.setLineDash(p.stable ? [] : DASH);
    rg.beginPath();
    var step = Math.max(1, Math.floor(n / (2 * (f.axes.box[2] - f.axes.box[0]))));
    for (var i = 0; i < n; i += step) {
      if (i) rg.lineTo(X(o.t[i]), Y(o.x[i])); else rg.moveTo(X(o.t[i]), Y(o.x[i]));
    }
    rg.lineTo(X(o.t[n - 1]), Y(o.x[n - 1]));
    rg.stroke();
    rg.setLineDash([]);
    // The marker: x at tm, interpolated between the samples around it.
    var k = 0, j = n - 1;
    while (j - k > 1) { var mid = (k + j) >> 1; if (o.t[mid] <= tm) k = mid; else j = mid; }
    var u = o.t[j] > o.t[k] ? clamp((tm - o.t[k]) / (o.t[j] - o.t[k]), 0, 1) : 0;
    var xm = o.x[k] + u * (o.x[j] - o.x[k]);
    rg.strokeStyle = "#666"; rg.lineWidth = 1;
    rg.beginPath(); rg.moveTo(X(tm), f.axes.box[1]); rg.lineTo(X(tm), f.axes.box[3]); rg.stroke();
    rg.fillStyle = colours.chosen;
    rg.beginPath(); rg.arc(X(tm), Y(xm), 5, 0, 2 * Math.PI); rg.fill();
    rg.fillStyle = "#ccc";
    var title = "point " + chosen + ": " + meta.observed + " over one period, peak to peak " +
                shown(p.amplitude_pp, 10);
    fit(rg, title, w - f.axes.box[0] - 4);
    label(rg, replayLabels, "replay_title", title, f.axes.box[0], 14, "left");
    replayState.point = chosen;
    replayState.samples = n;
    replayState.t_range = [t0, o.t[n - 1]];
    replayState.x_range = [lo, hi];
    replayState.sample_range = [slo, shi];
    replayState.marker = { t: tm, x: xm };
    replayState.axes = f.axes;
  }

  function pointText(k) {
    var p = points[k];
    var parts = ["point " + k + " of " + points.length, meta.parameter + " = " + shown(p.parameter, 10),
                 "period " + shown(p.period, 10) + " s", "amplitude " + shown(p.amplitude_pp, 10) + " (peak to peak of " + meta.observed + ")",
                 "largest multiplier " + shown(p.largest_multiplier, 4),
                 p.undecided ? "stability undecided (a multiplier on the unit circle within the flow's accuracy)" : p.stable ? "stable" : "unstable"];
    if (isFinite(value(p.stick_fraction))) parts.push("stick fraction " + shown(100 * p.stick_fraction, 3) + " %");
    if (isFinite(value(p.steady_growth_rate)))
      parts.push("steady sliding " + (p.steady_growth_rate < 0 ? "stable" : "unstable") + " (growth rate " +
                 shown(p.steady_growth_rate, 4) + " 1/s)");
    if (p.event) parts.push("events before it: " + p.event.split(";").join(", "));
    return parts.join("   ");
  }

  function writeStatus() {
    var rect = diagram.getBoundingClientRect(), rrect = replay.getBoundingClientRect();
    var p = points[chosen];
    function boxes(list, r) {
      return list.map(function (l) {
        return { name: l.name, text: l.text, canvas_box: l.box.map(function (v) { return +v.toFixed(2); }),
                 page_box: [l.box[0] + r.left, l.box[1] + r.top, l.box[2] + r.left, l.box[3] + r.top].map(function (v) { return +v.toFixed(2); }) };
      });
    }
    statusEl.textContent = JSON.stringify({
      ready: true, errors: window.TRIBO_ERRORS, kind: "branch", parameter: meta.parameter, observed: meta.observed,
      points: points.length, drawn_points: drawn, segments: segments, events: eventsDrawn, axes: axes,
      offset: [rect.left, rect.top], replay_offset: [rrect.left, rrect.top],
      canvas: [diagram.width, diagram.height], replay_canvas: [replay.width, replay.height],
      window: [window.innerWidth, window.innerHeight],
      labels: boxes(labels, rect), replay_labels: boxes(replayLabels, rrect),
      selected: { index: chosen, parameter: p.parameter, period: p.period, amplitude_pp: p.amplitude_pp,
                  largest_multiplier: p.largest_multiplier, stable: p.stable, text: infoEl.textContent },
      replay: replayState, actions: actions
    });
  }

  // The replay runs one period in `loop` seconds: the period itself when it lies between 1.5
  // and 6 s, else the nearer of the two; it starts when a point is chosen.
  var started = 0;
  function replayTime(now) {
    var o = orbits[chosen], t0 = o.t[0], t1 = o.t[o.t.length - 1];
    var period = t1 > t0 ? t1 - t0 : 1, loop = clamp(period, 1.5, 6);
    replayState.seconds_per_period = loop;
    return t0 + ((((now - started) / 1000 / loop) % 1) + 1) % 1 * period;
  }
  function tick(now) {
    drawReplay(replayTime(now));
    replayState.frames += 1;
    writeStatus();
    requestAnimationFrame(tick);
  }

  function choose(k, how) {
    chosen = clamp(k, 0, points.length - 1);
    infoEl.textContent = pointText(chosen);
    started = performance.now();
    replayState.frames = 0;
    drawDiagram();
    var o = orbits[chosen];
    drawReplay(o.t[0]);
    if (how) actions.push({ action: how, selected: chosen, period: points[chosen].period, clock: started });
    writeStatus();
  }

  function pointAt(e) {
    var rect = diagram.getBoundingClientRect(), x = e.clientX - rect.left, y = e.clientY - rect.top;
    var best = -1, bd = 12;
    drawn.forEach(function (d) {
      var dist = Math.hypot(d.x - x, d.y - y);
      if (dist < bd) { bd = dist; best = d.index; }
    });
    return best;
  }
  diagram.addEventListener("click", function (e) {
    var k = pointAt(e);
    if (k >= 0) choose(k, "click:" + k);
  });
  diagram.addEventListener("mousemove", function (e) {
    var k = pointAt(e);
    if (k !== hovered) { hovered = k; drawDiagram(); }
    if (k < 0) { tooltip.style.display = "none"; return; }
    tooltip.textContent = pointText(k).split("   ").join("\n") + (k === chosen ? "" : "\n(click: replay)");
    tooltip.style.left = (e.clientX + 14) + "px";
    tooltip.style.top = (e.clientY + 14) + "px";
    tooltip.style.display = "block";
  });
  diagram.addEventListener("mouseleave", function () {
    tooltip.style.display = "none";
    if (hovered >= 0) { hovered = -1; drawDiagram(); }
  });
  window.addEventListener("keydown", function (e) {
    if (e.key === "ArrowRight") { choose(chosen + 1, "key:right"); e.preventDefault(); }
    if (e.key === "ArrowLeft") { choose(chosen - 1, "key:left"); e.preventDefault(); }
  });
  window.addEventListener("resize", function () { fitCanvases(); choose(chosen); });

  fitCanvases();
  choose(chosen);

  // Scripted actions for tests: click=K (a click on point K's dot), right, left (arrow keys),
  // wait (the replay drawn at the clock's time); clickdelay ms apart.
  if (hash.click) {
    var delay = hash.clickdelay ? +hash.clickdelay : 200;
    var script = hash.click.split(",");
    var next = function (n) {
      if (n >= script.length) return;
      setTimeout(function () {
        var a = script[n];
        if (a === "right" || a === "left") {
          window.dispatchEvent(new KeyboardEvent("keydown", { key: a === "right" ? "ArrowRight" : "ArrowLeft", bubbles: true }));
        } else if (a !== "wait") {
          var d = drawn.filter(function (p) { return p.index === +a; })[0];
          var rect = diagram.getBoundingClientRect();
          if (d) diagram.dispatchEvent(new MouseEvent("click", { clientX: rect.left + d.x, clientY: rect.top + d.y, bubbles: true }));
          else actions.push({ action: "click:" + a, selected: chosen, missing: true });
        } else {  // the replay drawn now, its marker logged with the clock
          var now = performance.now();
          drawReplay(replayTime(now));
          actions.push({ action: "wait", selected: chosen, clock: now, marker: replayState.marker });
        }
        writeStatus();
        next(n + 1);
      }, delay);
    };
    next(0);
  }
  requestAnimationFrame(tick);
})();
