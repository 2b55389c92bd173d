// Switchable overlays of the replay page: trails of chosen bodies (their recorded origin
// path up to the current frame), force arrows at a body from the per-body channels
// (NAME.normal_force drawn along +z, the usual contact normal against a floor or belt;
// NAME.friction_force drawn horizontally against the body's motion relative to the moving
// surface: the channels give magnitudes, so both directions are assumptions the page
// states), stick/slip colouring (NAME.slip below the run's stick speed while NAME.normal_force
// > 0: blue stuck, orange slipping) and the hover tooltip. Not here: the replay (page.js).
var TriboView = window.TriboView || {};
window.TriboView = TriboView;

TriboView.Overlays = function (view) {
  var self = this;
  var trails = {};
  var arrows = [];

  // Trail of body i: every frame's origin, drawn up to the current frame.
  this.setTrails = function (indices) {
    Object.keys(trails).forEach(function (k) { view.scene.remove(trails[k]); });
    trails = {};
    indices.forEach(function (i) {
      var p = view.pos[i];
      if (!p) return;
      var n = view.frames;
      var xyz = new Float32Array(3 * n);
      for (var f = 0; f < n; ++f) {
        xyz[3 * f] = view.series[p[0]][f];
        xyz[3 * f + 1] = view.series[p[1]][f];
        xyz[3 * f + 2] = view.series[p[2]][f];
      }
      var g = new THREE.BufferGeometry();
      g.setAttribute("position", new THREE.BufferAttribute(xyz, 3));
      var line = new THREE.Line(g, new THREE.LineBasicMaterial({ color: 0xffffff }));
      line.frustumCulled = false;
      trails[i] = line;
      view.scene.add(line);
    });
  };

  function column(name) { return view.columnIndex[name]; }
  function maxOf(c) {
    var m = 0;
    view.series[c].forEach(function (v) { if (v !== null && Math.abs(v) > m) m = Math.abs(v); });
    return m;
  }

  // Arrows for bodies that recorded forces; the largest is 0.3 of the scene's size.
  var forceBodies = [];
  var movingSurface = [0, 0, 0];
  view.data.scene.bodies.forEach(function (b) {
    if (b.surface_velocity.some(function (v) { return v !== 0; })) movingSurface = b.surface_velocity;
  });
  view.data.scene.bodies.forEach(function (b, i) {
    var n = column(b.name + ".normal_force"), fr = column(b.name + ".friction_force");
    if (b.kind !== "dynamic" || (n === undefined && fr === undefined)) return;  // belts are driven
    forceBodies.push({ i: i, normal: n, friction: fr, vx: column(b.name + ".vx"),
                       vy: column(b.name + ".vy"), slip: column(b.name + ".slip") });
  });
  var forceMax = 1e-12;
  forceBodies.forEach(function (f) {
    if (f.normal !== undefined) forceMax = Math.max(forceMax, maxOf(f.normal));
    if (f.friction !== undefined) forceMax = Math.max(forceMax, maxOf(f.friction));
  });
  this.hasForces = forceBodies.length > 0;
  this.hasFriction = forceBodies.some(function (f) { return f.friction !== undefined; });
  this.hasStickSlip = forceBodies.some(function (f) { return f.slip !== undefined && f.normal !== undefined; });

  this.showForces = function (on) {
    arrows.forEach(function (a) { view.scene.remove(a.arrow); });
    arrows = [];
    if (!on) return;
    forceBodies.forEach(function (f) {
      if (f.normal !== undefined)
        arrows.push({ f: f, kind: "normal", arrow: new THREE.ArrowHelper(new THREE.Vector3(0, 0, 1),
                      new THREE.Vector3(), 1, TriboView.colours.normal) });
      if (f.friction !== undefined)
        arrows.push({ f: f, kind: "friction", arrow: new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0),
                      new THREE.Vector3(), 1, TriboView.colours.friction) });
    });
    arrows.forEach(function (a) { view.scene.add(a.arrow); });
  };

  this.update = function (frame, stickSlip) {
    Object.keys(trails).forEach(function (k) { trails[k].geometry.setDrawRange(0, frame + 1); });
    var scale = 0.3 * view.extent / forceMax;
    arrows.forEach(function (a) {
      var f = a.f, body = view.bodies[f.i].group;
      var value = view.series[a.kind === "normal" ? f.normal : f.friction][frame] || 0;
      a.arrow.position.copy(body.position);
      a.arrow.visible = Math.abs(value) * scale > 1e-6 * view.extent;
      if (!a.arrow.visible) return;
      if (a.kind === "friction") {
        var rx = movingSurface[0] - (f.vx !== undefined ? view.series[f.vx][frame] : 0);
        var ry = movingSurface[1] - (f.vy !== undefined ? view.series[f.vy][frame] : 0);
        var len = Math.hypot(rx, ry);
        a.arrow.setDirection(len > 0 ? new THREE.Vector3(rx / len, ry / len, 0) : new THREE.Vector3(1, 0, 0));
      }
      var l = Math.abs(value) * scale;
      a.arrow.setLength(l, 0.2 * l, 0.1 * l);
    });
    forceBodies.forEach(function (f) {
      var b = view.bodies[f.i];
      if (!b.material.color) return;
      if (!stickSlip || f.slip === undefined || f.normal === undefined) {
        b.material.color.copy(b.baseColour);
        return;
      }
      var inContact = (view.series[f.normal][frame] || 0) > 0;
      var stuck = Math.abs(view.series[f.slip][frame] || 0) < view.data.meta.stick_speed;
      b.material.color.set(!inContact ? b.baseColour : stuck ? TriboView.colours.sticking : TriboView.colours.slipping);
    });
  };

  // Tooltip: the body under the pointer, its name and every recorded value at this frame.
  var raycaster = new THREE.Raycaster();
  var tooltip = document.getElementById("tooltip");
  view.renderer.domElement.addEventListener("mousemove", function (e) {
    var r = view.renderer.domElement.getBoundingClientRect();
    var ndc = new THREE.Vector2((e.clientX - r.left) / r.width * 2 - 1, -(e.clientY - r.top) / r.height * 2 + 1);
    raycaster.setFromCamera(ndc, view.camera);
    var hits = raycaster.intersectObjects(view.bodies.map(function (b) { return b.group; }), true);
    var hit = hits.find(function (h) { return h.object.userData.body !== undefined; });
    if (!hit) { tooltip.style.display = "none"; return; }
    var b = view.data.scene.bodies[hit.object.userData.body];
    var lines = [b.name];
    view.data.meta.columns.forEach(function (c, k) {
      if (c.indexOf(b.name + ".") === 0) {
        var v = view.series[k][view.frame];
        lines.push(c.slice(b.name.length + 1) + " = " + (v === null ? "-" : Number(v).toPrecision(6)));
      }
    });
    tooltip.textContent = lines.join("\n");
    tooltip.style.left = (e.clientX + 14) + "px";
    tooltip.style.top = (e.clientY + 14) + "px";
    tooltip.style.display = "block";
  });
};
