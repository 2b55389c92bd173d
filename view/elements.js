// The model's elements besides bodies, drawn on the replay page: each spring (a spring-damper
// or a bushing) as a coil between its two attachment points, moved every frame with the
// bodies' poses, its ends as small spheres (an end on the world stays where it is); each
// joint (not a free one) as a small marker at its anchor on the child with its axis as a
// short line through it; each moving surface (a belt) as an arrow along its direction of
// motion, carried by its body. Anchors and joint markers are drawn over the bodies (they
// are often inside one). Colours: TriboView.colours (scene.js). Not here: bodies and planes
// (scene.js), the replay (page.js).
var TriboView = window.TriboView || {};
window.TriboView = TriboView;

// A coil of unit length along +z, `turns` turns of radius `radius`, with straight leads
// from the axis at both ends, each `lead` of the length.
TriboView.coilGeometry = function (radius, turns, lead) {
  var perTurn = 12, n = turns * perTurn, xyz = [0, 0, 0];
  for (var i = 0; i <= n; ++i) {
    var a = 2 * Math.PI * i / perTurn;
    xyz.push(radius * Math.cos(a), radius * Math.sin(a), lead + (1 - 2 * lead) * i / n);
  }
  xyz.push(0, 0, 1);
  var g = new THREE.BufferGeometry();
  g.setAttribute("position", new THREE.Float32BufferAttribute(xyz, 3));
  return g;
};

// view: {scene, bodies (page bodies with .group), extent}; data: the page's data.
TriboView.Elements = function (data, view) {
  var colours = TriboView.colours, extent = view.extent, bodies = view.bodies;
  var springs = [], joints = [], arrows = [];
  var anchorCount = 0;
  var overMaterial = function (colour) {
    return new THREE.MeshBasicMaterial({ color: colour, depthTest: false, transparent: true });
  };
  var anchorGeometry = new THREE.SphereBufferGeometry(0.012 * extent, 12, 8);
  var anchorMaterial = overMaterial(colours.spring);
  var coilMaterial = new THREE.LineBasicMaterial({ color: colours.spring });
  var coilRadius = 0.03 * extent;

  function parentOf(index) { return index < 0 ? view.scene : bodies[index].group; }
  // A point fixed in body `index` (world: -1) in world coordinates, from the body's pose now.
  function worldPoint(index, local, out) {
    out.fromArray(local);
    if (index < 0) return out;
    var g = bodies[index].group;
    return out.applyQuaternion(g.quaternion).add(g.position);
  }
  function addAnchor(index, local) {
    var m = new THREE.Mesh(anchorGeometry, anchorMaterial);
    m.position.fromArray(local);
    m.renderOrder = 10;
    parentOf(index).add(m);
    ++anchorCount;
  }

  var a = new THREE.Vector3(), b = new THREE.Vector3();
  (data.scene.springs || []).forEach(function (s) {
    worldPoint(s.a, s.point_a, a);
    worldPoint(s.b, s.point_b, b);
    var length = a.distanceTo(b);
    var turns = Math.max(8, Math.min(2000, Math.round(length / (4 * coilRadius))));
    var lead = length > 0 ? Math.min(0.1, 2 * coilRadius / length) : 0.1;
    var coil = new THREE.Line(TriboView.coilGeometry(coilRadius, turns, lead), coilMaterial);
    coil.frustumCulled = false;  // its bounding box is the unit coil's, not the scaled one
    view.scene.add(coil);
    addAnchor(s.a, s.point_a);
    addAnchor(s.b, s.point_b);
    springs.push({ name: s.name, kind: s.kind, a: s.a, pa: s.point_a, b: s.b, pb: s.point_b,
                   coil: coil, ends: [new THREE.Vector3(), new THREE.Vector3()] });
  });

  var markerGeometry = new THREE.OctahedronBufferGeometry(0.025 * extent);
  var markerMaterial = overMaterial(colours.joint);
  var axisMaterial = new THREE.LineBasicMaterial({ color: colours.joint, depthTest: false, transparent: true });
  (data.scene.joints || []).forEach(function (j) {
    if (j.type === "free") return;  // no constraint to show
    var group = new THREE.Group();
    group.position.fromArray(j.anchor_in_child);
    var marker = new THREE.Mesh(markerGeometry, markerMaterial);
    marker.renderOrder = 10;
    group.add(marker);
    var half = new THREE.Vector3().fromArray(j.axis_in_child).normalize().multiplyScalar(0.15 * extent);
    var g = new THREE.BufferGeometry().setFromPoints([half.clone().negate(), half]);
    var axis = new THREE.Line(g, axisMaterial);
    axis.renderOrder = 10;
    group.add(axis);
    parentOf(j.child).add(group);
    joints.push({ name: j.name, type: j.type, child: j.child, anchor: j.anchor_in_child, group: group });
  });

  // A moving surface's arrow: beside a plane's origin (towards the default camera, -y of
  // the motion), else on top of the geometry, pointing along the motion.
  data.scene.bodies.forEach(function (body, i) {
    body.geometries.forEach(function (g) {
      var v = g.surface_velocity;
      if (!v || (v[0] === 0 && v[1] === 0 && v[2] === 0)) return;
      var dir = new THREE.Vector3().fromArray(v).normalize();
      var q = new THREE.Quaternion(g.quaternion[1], g.quaternion[2], g.quaternion[3], g.quaternion[0]);
      var normal = new THREE.Vector3(0, 0, 1).applyQuaternion(q);
      var length = 0.4 * extent;
      var start = new THREE.Vector3().fromArray(g.position);
      if (g.shape === "halfspace") {
        var side = new THREE.Vector3().crossVectors(normal, dir);
        if (side.lengthSq() < 1e-12) side.set(0, 1, 0);
        start.addScaledVector(side.normalize(), -0.4 * extent);
        start.addScaledVector(normal, 0.005 * extent);
      } else {
        var top = g.half_extents ? g.half_extents[2] : (g.radius || 0) + (g.half_length || 0);
        start.addScaledVector(normal, top + 0.03 * extent);
      }
      start.addScaledVector(dir, -0.5 * length);
      var arrow = new THREE.ArrowHelper(dir, start, length, colours.belt, 0.25 * length, 0.12 * length);
      bodies[i].group.add(arrow);
      arrows.push({ body: i, geometry: g.name, start: start.clone(), dir: dir, length: length, arrow: arrow });
    });
  });

  this.coilRadius = coilRadius;
  this.counts = { springs: springs.length, anchors: anchorCount, joints: joints.length, belt_arrows: arrows.length };

  // Places the coils between their ends at the bodies' current poses.
  var zAxis = new THREE.Vector3(0, 0, 1), d = new THREE.Vector3();
  this.update = function () {
    springs.forEach(function (s) {
      worldPoint(s.a, s.pa, s.ends[0]);
      worldPoint(s.b, s.pb, s.ends[1]);
      d.subVectors(s.ends[1], s.ends[0]);
      var length = d.length();
      s.coil.visible = length > 1e-9 * extent;
      if (!s.coil.visible) return;
      s.coil.position.copy(s.ends[0]);
      s.coil.quaternion.setFromUnitVectors(zAxis, d.divideScalar(length));
      s.coil.scale.set(1, 1, length);
    });
  };

  // For the status: world and screen positions (project: world Vector3 -> [px, py]).
  this.describe = function (project) {
    var p = new THREE.Vector3();
    function world(index, local) { return worldPoint(index, local, p).toArray().map(function (x) { return +x.toFixed(6); }); }
    return {
      springs: springs.map(function (s) {
        return { name: s.name, kind: s.kind, a: world(s.a, s.pa), b: world(s.b, s.pb),
                 screen_a: project(worldPoint(s.a, s.pa, p)), screen_b: project(worldPoint(s.b, s.pb, p)) };
      }),
      joints: joints.map(function (j) {
        return { name: j.name, type: j.type, anchor: world(j.child, j.anchor),
                 screen: project(worldPoint(j.child, j.anchor, p)) };
      }),
      belt_arrows: arrows.map(function (r) {
        var e = r.start.clone().addScaledVector(r.dir, r.length);
        return { body: bodies[r.body].name, geometry: r.geometry,
                 start: world(r.body, r.start.toArray()), end: world(r.body, e.toArray()),
                 screen_start: project(worldPoint(r.body, r.start.toArray(), p)),
                 screen_end: project(worldPoint(r.body, e.toArray(), p)) };
      })
    };
  };
};
