// The time-series panel: chosen recorded channels over the whole run on one canvas, with a
// time axis (ticks, "t [s]") and a value axis (ticks, the first channel's name and unit
// from the page's data); channels of that unit share the axis, a channel of another unit
// is scaled to its own range (written beside its name). A cursor marks the replay time; a
// click on the plot moves the replay to that time. The axes drawn last are kept in
// `axes` (labels, tick values and pixels) for the status. Not here: the replay itself.
var TriboView = window.TriboView || {};
window.TriboView = TriboView;

// About `count` round tick values (steps of 1, 2 or 5 times a power of ten) in [lo, hi].
TriboView.niceTicks = function (lo, hi, count) {
  if (!(hi > lo)) return { step: 0, values: [lo] };
  var raw = (hi - lo) / count, mag = Math.pow(10, Math.floor(Math.log10(raw))), f = raw / mag;
  var step = (f < 1.5 ? 1 : f < 3 ? 2 : f < 7 ? 5 : 10) * mag;
  var values = [];
  for (var k = Math.ceil(lo / step - 1e-9); k * step <= hi + 1e-9 * step; ++k) values.push(k * step);
  return { step: step, values: values };
};

// A tick value as text, to the step's last digit.
TriboView.tickText = function (v, step) {
  if (!step) return String(+v.toPrecision(4));
  if (Math.abs(v) < 1e-9 * step) v = 0;
  var a = Math.max(Math.abs(v), step);
  if (a >= 1e5 || step < 1e-4) {
    var digits = Math.max(0, Math.floor(Math.log10(a) + 1e-9) - Math.floor(Math.log10(step) + 1e-9));
    return v === 0 ? "0" : v.toExponential(Math.min(digits, 6));
  }
  return v.toFixed(Math.max(0, -Math.floor(Math.log10(step) + 1e-9)));
};

// Writes text at (x, y) on `ctx` (rotated a quarter turn anticlockwise when `up`) and pushes
// {name, text, box} onto `list`, box its bounding box in canvas pixels from the font's
// measured glyph extents (the sweep and branch pages report their labels' boxes for tests).
TriboView.label = function (ctx, list, name, text, x, y, align, up) {
  ctx.textAlign = align;
  var m = ctx.measureText(text);
  var l = m.actualBoundingBoxLeft, r = m.actualBoundingBoxRight;
  var a = m.actualBoundingBoxAscent, d = m.actualBoundingBoxDescent;
  if (up) {
    ctx.save(); ctx.translate(x, y); ctx.rotate(-Math.PI / 2); ctx.fillText(text, 0, 0); ctx.restore();
    list.push({ name: name, text: text, box: [x - a, y - r, x + d, y + l] });
  } else {
    ctx.fillText(text, x, y);
    list.push({ name: name, text: text, box: [x - l, y - a, x + r, y + d] });
  }
  ctx.textAlign = "left";
};

TriboView.Plot = function (canvas, view, onSeek) {
  var self = this;
  var colours = ["#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f", "#edc948"];
  var chosen = [];
  var t = view.series[0];
  var t0 = t[0], t1 = t[t.length - 1] > t0 ? t[t.length - 1] : t0 + 1;
  var units = view.data.meta.units || [];
  var left = 64, right = 10;
  this.axes = null;

  this.choose = function (columns) { chosen = columns.slice(0, colours.length); };

  function range(s) {
    var lo = Infinity, hi = -Infinity;
    s.forEach(function (v) { if (v !== null) { lo = Math.min(lo, v); hi = Math.max(hi, v); } });
    return [lo, hi];
  }

  this.draw = function (time) {
    var w = canvas.clientWidth, h = canvas.clientHeight;
    if (!w || !h) return;
    if (canvas.width !== w || canvas.height !== h) { canvas.width = w; canvas.height = h; }
    var g = canvas.getContext("2d");
    g.clearRect(0, 0, w, h);
    var x1 = w - right, top = 22, bottom = h - 34;
    function x(tt) { return left + (tt - t0) / (t1 - t0) * (x1 - left); }
    g.font = "11px sans-serif";
    g.textBaseline = "alphabetic";

    // The value axis: the first chosen channel's unit; every channel of that unit on it.
    var unit = chosen.length ? units[chosen[0]] || "" : "";
    var shared = chosen.filter(function (c) { return (units[c] || "") === unit; });
    var lo = Infinity, hi = -Infinity;
    shared.forEach(function (c) { var r = range(view.series[c]); lo = Math.min(lo, r[0]); hi = Math.max(hi, r[1]); });
    if (!(hi >= lo)) { lo = 0; hi = 1; }
    if (hi === lo) { lo -= 0.5 * (Math.abs(lo) || 1); hi += 0.5 * (Math.abs(hi) || 1); }
    var pad = 0.04 * (hi - lo);
    lo -= pad; hi += pad;
    function y(v) { return bottom - (v - lo) / (hi - lo) * (bottom - top); }

    var axes = { x_label: "t [s]", y_label: "", x_ticks: [], y_ticks: [], channels: [], shared: [] };
    // Grid, ticks and their values.
    g.strokeStyle = "#3a3f48";
    g.fillStyle = "#aaa";
    g.lineWidth = 1;
    var xt = TriboView.niceTicks(t0, t1, Math.max(2, Math.floor((x1 - left) / 90)));
    g.textAlign = "center";
    xt.values.forEach(function (v) {
      var px = x(v);
      g.beginPath(); g.moveTo(px, top); g.lineTo(px, bottom + 4); g.stroke();
      var text = TriboView.tickText(v, xt.step);
      var half = g.measureText(text).width / 2;  // kept inside the canvas at the ends
      g.fillText(text, Math.max(half + 1, Math.min(w - half - 1, px)), bottom + 15);
      axes.x_ticks.push({ value: v, text: text, px: +px.toFixed(2) });
    });
    if (chosen.length) {
      var yt = TriboView.niceTicks(lo, hi, Math.max(2, Math.floor((bottom - top) / 28)));
      g.textAlign = "right";
      yt.values.forEach(function (v) {
        var py = y(v);
        g.beginPath(); g.moveTo(left - 4, py); g.lineTo(x1, py); g.stroke();
        var text = TriboView.tickText(v, yt.step);
        g.fillText(text, left - 6, py + 4);
        axes.y_ticks.push({ value: v, text: text, py: +py.toFixed(2) });
      });
    }
    g.strokeStyle = "#888";
    g.beginPath(); g.moveTo(left, top); g.lineTo(left, bottom); g.lineTo(x1, bottom); g.stroke();

    // Axis labels.
    g.textAlign = "center";
    g.fillStyle = "#ccc";
    g.fillText(axes.x_label, (left + x1) / 2, h - 4);
    if (chosen.length) {
      var name = view.data.meta.columns[chosen[0]];
      var label = unit ? (shared.length === 1 ? name + " [" + unit + "]" : "[" + unit + "]") : name;
      if (g.measureText(label).width > bottom - top && unit) label = "[" + unit + "]";
      axes.y_label = label;
      g.save();
      g.translate(12, (top + bottom) / 2);
      g.rotate(-Math.PI / 2);
      g.fillText(label, 0, 0);
      g.restore();
    }

    // The channels; their names (with their own range when off the axis) above the plot.
    g.textAlign = "left";
    var nameX = left;
    chosen.forEach(function (c, k) {
      var s = view.series[c];
      var r = range(s);
      if (!(r[1] >= r[0])) return;
      var own = shared.indexOf(c) < 0;
      var span = r[1] > r[0] ? r[1] - r[0] : 1;
      function yOf(v) { return own ? bottom - (v - r[0]) / span * (bottom - top) : y(v); }
      g.strokeStyle = g.fillStyle = colours[k];
      g.beginPath();
      var step = Math.max(1, Math.floor(s.length / (2 * (x1 - left))));
      var started = false;
      for (var i = 0; i < s.length; i += step) {
        if (s[i] === null) { started = false; continue; }
        if (started) g.lineTo(x(t[i]), yOf(s[i])); else g.moveTo(x(t[i]), yOf(s[i]));
        started = true;
      }
      g.stroke();
      var u = units[c] ? " " + units[c] : "";
      var text = view.data.meta.columns[c] + (own ? " [" + r[0].toPrecision(4) + ", " + r[1].toPrecision(4) + "]" + u +
                                              " (own scale)" : "");
      g.fillText(text, nameX, 13);
      nameX += g.measureText(text).width + 18;
      axes.channels.push(view.data.meta.columns[c]);
      if (!own) axes.shared.push(view.data.meta.columns[c]);
    });

    g.strokeStyle = "#fff";
    g.beginPath();
    g.moveTo(x(time), top);
    g.lineTo(x(time), bottom);
    g.stroke();
    axes.canvas = [w, h];
    axes.box = [left, top, x1, bottom];
    self.axes = axes;
  };

  canvas.addEventListener("click", function (e) {
    var r = canvas.getBoundingClientRect();
    var f = (e.clientX - r.left - left) / (r.width - left - right);
    onSeek(t0 + Math.max(0, Math.min(1, f)) * (t1 - t0));
  });
};
