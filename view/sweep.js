// The sweep page's script: one chosen result of results.csv over the swept parameters, as a
// heat map for two axes (a colour scale whose brightness rises with the value; failed or
// empty points grey) or a line for one; with more axes, the first two at the others' first
// values. Hovering a point shows its row; clicking opens its replay page when the sweep
// kept its trajectory. Writes #tribo-status (errors, points, each drawn cell's centre and
// value, each label's text and bounding box) for tests. URL hash: metric=NAME. The canvas
// fits the window and its margins fit the labels' measured sizes, so that no label is cut.
// Uses TriboView.label (plot.js, embedded before it). Not here: a run's replay (page.js).
(function () {
  var data = window.TRIBO_DATA, meta = data.meta;
  var statusEl = document.getElementById("tribo-status");
  var canvas = document.getElementById("map"), g = canvas.getContext("2d");
  var hash = {};
  location.hash.replace(/^#/, "").split("&").forEach(function (kv) {
    var i = kv.indexOf("=");
    if (kv) hash[decodeURIComponent(i < 0 ? kv : kv.slice(0, i))] = i < 0 ? "" : decodeURIComponent(kv.slice(i + 1));
  });
  var col = {};
  meta.columns.forEach(function (c, k) { col[c] = k; });
  var axes = meta.axes;
  var skip = { point: 1, status: 1, warnings: 1, message: 1 };
  axes.forEach(function (a) { skip[a.name] = 1; });
  var metric = document.getElementById("metric");
  meta.columns.forEach(function (c) {
    if (skip[c]) return;
    var o = document.createElement("option"); o.value = o.textContent = c; metric.appendChild(o);
  });
  metric.value = hash.metric && col[hash.metric] !== undefined ? hash.metric : "amplitude_pp";
  document.getElementById("title").textContent = "sweep of " + meta.scene + "  (" + data.rows.length + " points)";
  var notes = [];
  if (axes.length > 2) notes.push("axes after the second held at their first values");
  var linkedCount = Object.keys(data.linked).length;
  notes.push(linkedCount ? linkedCount + " points link to their replay (click)" :
             "no point kept its trajectory (tribo sweep --keep-trajectories)");
  if (meta.kept > linkedCount) notes.push((meta.kept - linkedCount) + " kept points without a page: tribo view SWEEP_DIR/points/N");
  document.getElementById("notes").textContent = "  " + notes.join("; ");

  // Colour scale from dark blue through teal and green to yellow: brightness rises with value.
  var stops = [[0.0, [40, 20, 90]], [0.35, [30, 110, 140]], [0.7, [60, 180, 90]], [1.0, [250, 230, 40]]];
  function colour(u) {
    for (var i = 1; i < stops.length; ++i) {
      if (u <= stops[i][0]) {
        var a = stops[i - 1], b = stops[i], f = (u - a[0]) / (b[0] - a[0]);
        return "rgb(" + [0, 1, 2].map(function (k) { return Math.round(a[1][k] + f * (b[1][k] - a[1][k])); }).join(",") + ")";
      }
    }
    return "rgb(250,230,40)";
  }
  function value(row) {
    var v = parseFloat(row[col[metric.value]]);
    return row[col.status] === "complete" && isFinite(v) ? v : null;
  }
  // The canvas fits the window (at most 900 x 560), so that nothing drawn falls outside it.
  var panel = document.getElementById("sweep-panel");
  canvas.width = Math.max(420, Math.min(900, window.innerWidth - 24));
  canvas.height = Math.max(300, Math.min(560, window.innerHeight - panel.offsetHeight - 16));
  var cells = [], labels = [];
  // Writes text at (x, y) and records its box in `labels` (TriboView.label, plot.js).
  function label(name, text, x, y, align, up) {
    TriboView.label(g, labels, name, text, x, y, align, up);
  }
  // The largest font size (12 px down to 8 px) at which `text` is at most `room` wide.
  function fit(text, room) {
    for (var size = 12; size > 8; --size) {
      g.font = size + "px sans-serif";
      if (g.measureText(text).width <= room) return;
    }
    g.font = "8px sans-serif";
  }
  function draw() {
    var w = canvas.width, h = canvas.height, top = 20, bottom = h - 50, left = 70;
    g.clearRect(0, 0, w, h);
    g.font = "12px sans-serif";
    labels = [];
    var shown = data.rows.filter(function (r) {
      for (var k = 2; k < axes.length; ++k) if (r[col[axes[k].name]] !== axes[k].values[0]) return false;
      return true;
    });
    var vals = shown.map(value).filter(function (v) { return v !== null; });
    var lo = Math.min.apply(null, vals), hi = Math.max.apply(null, vals);
    var span = hi > lo ? hi - lo : 1;
    var hiText = hi.toPrecision(4), loText = lo.toPrecision(4);
    // Right of the map: a gap, the colour bar, its values and its label (the result's name,
    // written upwards): the margin is what they measure.
    var valueWidth = Math.max(g.measureText(hiText).width, g.measureText(loText).width);
    var right = axes.length === 1 ? w - 20 : w - (20 + 20 + 6 + valueWidth + 10 + 16 + 8);
    cells = [];
    var ax = axes[0], nx = ax.values.length;
    if (axes.length === 1) {
      g.strokeStyle = "#f28e2b"; g.beginPath();
      var started = false;
      shown.forEach(function (r) {
        var i = ax.values.indexOf(r[col[ax.name]]), v = value(r);
        var x = left + (nx > 1 ? i / (nx - 1) : 0.5) * (right - left);
        if (v === null) { started = false; return; }
        var y = bottom - (v - lo) / span * (bottom - top);
        if (started) g.lineTo(x, y); else g.moveTo(x, y);
        started = true;
        cells.push({ point: r[0], x: x, y: y, value: v, row: r });
      });
      g.stroke();
      g.fillStyle = "#f28e2b";
      cells.forEach(function (c) { g.beginPath(); g.arc(c.x, c.y, 4, 0, 7); g.fill(); });
      g.fillStyle = "#ddd";
      label("value_high", hiText, 4, top + 4, "left");
      label("value_low", loText, 4, bottom, "left");
      var lineLabel = ax.name + ": " + ax.values[0] + " .. " + ax.values[nx - 1];
      fit(lineLabel, right - left);
      label("x_axis", lineLabel, left, h - 20, "left");
      g.font = "12px sans-serif";
      label("y_axis", metric.value, left - 40, (top + bottom) / 2, "center", true);
    } else {
      var ay = axes[1], ny = ay.values.length;
      var cw = (right - left) / nx, ch = (bottom - top) / ny;
      shown.forEach(function (r) {
        var i = ax.values.indexOf(r[col[ax.name]]), j = ay.values.indexOf(r[col[ay.name]]);
        var v = value(r);
        var x0 = left + i * cw, y0 = bottom - (j + 1) * ch;
        g.fillStyle = v === null ? "#777" : colour((v - lo) / span);
        g.fillRect(x0, y0, Math.ceil(cw), Math.ceil(ch));
        cells.push({ point: r[0], x: x0 + cw / 2, y: y0 + ch / 2, w: cw, h: ch, value: v, row: r });
      });
      g.fillStyle = "#ddd";
      var xText = ax.name + " " + ax.values[0] + " .. " + ax.values[nx - 1] + "  (right)";
      fit(xText, right - left);
      label("x_axis", xText, (left + right) / 2, bottom + 30, "center");
      var yText = ay.name + " " + ay.values[0] + " .. " + ay.values[ny - 1] + "  (up)";
      fit(yText, bottom - top);
      label("y_axis", yText, left - 24, (top + bottom) / 2, "center", true);
      g.font = "12px sans-serif";
      var barX = right + 20;
      for (var s = 0; s <= 10; ++s) {  // colour bar
        g.fillStyle = colour(s / 10);
        g.fillRect(barX, bottom - (s + 1) * (bottom - top) / 11, 20, (bottom - top) / 11 + 1);
      }
      g.fillStyle = "#ddd";
      label("bar_high", hiText, barX + 26, top + 10, "left");
      label("bar_low", loText, barX + 26, bottom, "left");
      fit(metric.value, bottom - top);
      label("bar", metric.value, barX + 26 + valueWidth + 10 + 12, (top + bottom) / 2, "center", true);
      g.font = "12px sans-serif";
    }
    cells.forEach(function (c) {  // a white dot marks a point with a replay page
      if (!data.linked[c.point]) return;
      g.fillStyle = "#fff"; g.fillRect(c.x - 1.5, c.y - 1.5, 3, 3);
    });
    statusEl.textContent = JSON.stringify({
      ready: true, errors: window.TRIBO_ERRORS, kind: "sweep", metric: metric.value,
      points: data.rows.length, linked: linkedCount, range: [lo, hi],
      offset: [canvas.getBoundingClientRect().left, canvas.getBoundingClientRect().top],
      canvas: [canvas.width, canvas.height], window: [window.innerWidth, window.innerHeight],
      labels: labels.map(function (l) {
        var r = canvas.getBoundingClientRect();
        return { name: l.name, text: l.text, canvas_box: l.box.map(function (v) { return +v.toFixed(2); }),
                 page_box: [l.box[0] + r.left, l.box[1] + r.top, l.box[2] + r.left, l.box[3] + r.top].map(function (v) { return +v.toFixed(2); }) };
      }),
      cells: cells.map(function (c) { return { point: c.point, x: c.x, y: c.y, value: c.value }; })
    });
  }
  function cellAt(e) {
    var r = canvas.getBoundingClientRect(), x = e.clientX - r.left, y = e.clientY - r.top;
    var best = null, bd = Infinity;
    cells.forEach(function (c) {
      var d = Math.hypot(c.x - x, c.y - y);
      if (d < bd && (c.w ? Math.abs(c.x - x) <= c.w / 2 && Math.abs(c.y - y) <= c.h / 2 : d < 10)) { bd = d; best = c; }
    });
    return best;
  }
  var tooltip = document.getElementById("tooltip");
  canvas.addEventListener("mousemove", function (e) {
    var c = cellAt(e);
    if (!c) { tooltip.style.display = "none"; return; }
    tooltip.textContent = meta.columns.map(function (n, k) { return n + " = " + c.row[k]; })
      .filter(function (t, k) { return c.row[k] !== ""; }).join("\n") +
      (data.linked[c.point] ? "\n(click: replay)" : "");
    tooltip.style.left = (e.clientX + 14) + "px";
    tooltip.style.top = (e.clientY + 14) + "px";
    tooltip.style.display = "block";
  });
  canvas.addEventListener("click", function (e) {
    var c = cellAt(e);
    if (c && data.linked[c.point]) window.location.href = data.linked[c.point];
  });
  metric.addEventListener("change", draw);
  draw();
})();
