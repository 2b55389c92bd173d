// The time-series panel: chosen recorded channels over the whole run on one canvas (each
// scaled to its own range, its min and max written beside its name) and a cursor at the
// replay time; a click on the plot moves replay to that time. Not here: the replay itself.
var TriboView = window.TriboView || {};
window.TriboView = TriboView;

TriboView.Plot = function (canvas, view, onSeek) {
  var colours = ["#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f", "#edc948"];
  var chosen = [];
  var t = view.series[0];
  var t0 = t[0], t1 = t[t.length - 1] > t0 ? t[t.length - 1] : t0 + 1;

  this.choose = function (columns) { chosen = columns.slice(0, colours.length); };

  this.draw = function (time) {
    var w = canvas.clientWidth, h = canvas.clientHeight;
    if (!w || !h) return;
    if (canvas.width !== w || canvas.height !== h) { canvas.width = w; canvas.height = h; }
    var g = canvas.getContext("2d");
    g.clearRect(0, 0, w, h);
    var left = 10, right = w - 10, top = 18, bottom = h - 16;
    function x(tt) { return left + (tt - t0) / (t1 - t0) * (right - left); }
    g.font = "11px sans-serif";
    chosen.forEach(function (c, k) {
      var s = view.series[c];
      var lo = Infinity, hi = -Infinity;
      s.forEach(function (v) { if (v !== null) { lo = Math.min(lo, v); hi = Math.max(hi, v); } });
      if (!(hi >= lo)) return;
      var span = hi > lo ? hi - lo : 1;
      g.strokeStyle = g.fillStyle = colours[k];
      g.beginPath();
      var step = Math.max(1, Math.floor(s.length / (2 * (right - left))));
      for (var i = 0; i < s.length; i += step) {
        if (s[i] === null) continue;
        var y = bottom - (s[i] - lo) / span * (bottom - top);
        if (i === 0) g.moveTo(x(t[i]), y); else g.lineTo(x(t[i]), y);
      }
      g.stroke();
      g.fillText(view.data.meta.columns[c] + " [" + lo.toPrecision(4) + ", " + hi.toPrecision(4) + "]",
                 left + k * 230, 12);
    });
    g.fillStyle = "#aaa";
    g.fillText(t0.toPrecision(4) + " s", left, h - 3);
    g.fillText(t1.toPrecision(4) + " s", right - 50, h - 3);
    g.strokeStyle = "#fff";
    g.beginPath();
    g.moveTo(x(time), top);
    g.lineTo(x(time), bottom);
    g.stroke();
  };

  canvas.addEventListener("click", function (e) {
    var r = canvas.getBoundingClientRect();
    var f = (e.clientX - r.left - 10) / (r.width - 20);
    onSeek(t0 + Math.max(0, Math.min(1, f)) * (t1 - t0));
  });
};
