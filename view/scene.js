// The scene's geometry as three.js objects: one group per body holding its geometries at
// their local poses (box, sphere, cylinder, capsule, cone, meshes), half-spaces as large
// checkered planes whose texture slides with the body's surface velocity (a belt), and
// lights; the page's colours (bodies, contact states, springs, joints, surface arrows,
// forces). In test mode every body is drawn in one flat colour of its own and the planes
// in dark grey, so a screenshot can be searched for a body's pixels.
// Not here: moving the bodies (page.js), overlays (overlays.js), springs, joints and surface
// arrows (elements.js).
var TriboView = window.TriboView || {};
window.TriboView = TriboView;

// Flat colour of body i in test mode: hues spread by the golden ratio, full saturation.
TriboView.testColour = function (i) {
  return new THREE.Color().setHSL((i * 0.618033988749895 + 0.05) % 1, 1.0, 0.5);
};

// Body colours, chosen away from the contact-state colours below (no blue, no orange), so
// that a body's own colour never reads as sticking or slipping.
TriboView.palette = [0x59a14f, 0xb07aa1, 0x76b7b2, 0x9c755f, 0xff9da7, 0xbab0ac, 0x8cd17d,
                     0xd37295];

// What the page draws in which colour (the legend lists them): contact states (the
// stick/slip overlay), springs and their anchors, joints, the direction a surface moves,
// force arrows.
TriboView.colours = {
  sticking: 0x3366ff, slipping: 0xff8800, spring: 0xf2f2f2, joint: 0xffe14d, belt: 0xb6ff2e,
  normal: 0x66ccff, friction: 0xff6666
};

TriboView.checkerTexture = function () {
  var c = document.createElement("canvas");
  c.width = c.height = 64;
  var g = c.getContext("2d");
  g.fillStyle = "#5b6270"; g.fillRect(0, 0, 64, 64);
  g.fillStyle = "#454b57"; g.fillRect(0, 0, 32, 32); g.fillRect(32, 32, 32, 32);
  g.fillStyle = "#c9a227"; g.fillRect(0, 0, 4, 64);  // a stripe across x shows motion along x
  var t = new THREE.CanvasTexture(c);
  t.wrapS = t.wrapT = THREE.RepeatWrapping;
  t.anisotropy = 4;
  return t;
};

TriboView.shapeObject = function (g, material, extent) {
  var obj;
  var s = g.shape;
  if (s === "box") {
    var h = g.half_extents;
    obj = new THREE.Mesh(new THREE.BoxBufferGeometry(2 * h[0], 2 * h[1], 2 * h[2]), material);
  } else if (s === "sphere") {
    var r = g.radius > 0 ? g.radius : 0.01 * extent;  // a contact point: a small dot
    obj = new THREE.Mesh(new THREE.SphereBufferGeometry(r, 24, 16), material);
  } else if (s === "cylinder" || s === "cone") {
    var geo = s === "cylinder" ?
      new THREE.CylinderBufferGeometry(g.radius, g.radius, 2 * g.half_length, 32) :
      new THREE.ConeBufferGeometry(g.radius, 2 * g.half_length, 32);
    geo.rotateX(Math.PI / 2);  // three's axis y (apex +y) to the engine's z (apex +z)
    obj = new THREE.Mesh(geo, material);
  } else if (s === "capsule") {
    obj = new THREE.Group();
    var body = new THREE.CylinderBufferGeometry(g.radius, g.radius, 2 * g.half_length, 32, 1, true);
    body.rotateX(Math.PI / 2);
    obj.add(new THREE.Mesh(body, material));
    [-1, 1].forEach(function (side) {
      var cap = new THREE.Mesh(new THREE.SphereBufferGeometry(g.radius, 24, 16), material);
      cap.position.set(0, 0, side * g.half_length);
      obj.add(cap);
    });
  } else if (s === "convex_mesh" || s === "mesh") {
    var bg = new THREE.BufferGeometry();
    bg.setAttribute("position", new THREE.Float32BufferAttribute(g.vertices, 3));
    bg.setIndex(g.triangles);
    bg.computeVertexNormals();
    var m = material.clone();
    m.side = THREE.DoubleSide;
    obj = new THREE.Mesh(bg, m);
  } else {
    return null;
  }
  obj.position.fromArray(g.position);
  var q = g.quaternion;
  obj.quaternion.set(q[1], q[2], q[3], q[0]);
  return obj;
};

// Returns {scene, bodies: [{name, group, material, baseColour}], planes: [{texture, velocity,
// period}], extent, notes}.
TriboView.buildScene = function (data, extent, test) {
  var scene = new THREE.Scene();
  scene.background = new THREE.Color(test ? 0x000000 : 0x1b1d22);
  if (!test) {
    scene.add(new THREE.HemisphereLight(0xffffff, 0x404050, 0.75));
    var sun = new THREE.DirectionalLight(0xffffff, 0.6);
    sun.position.set(1, -2, 3);
    scene.add(sun);
  }
  var out = { scene: scene, bodies: [], planes: [], notes: [] };
  var planeSize = Math.max(20 * extent, 4);
  var period = Math.max(extent / 4, 0.05);  // checker period [m]

  function plane(parent, g, velocity) {
    var mat;
    var texture = null;
    if (test) {
      mat = new THREE.MeshBasicMaterial({ color: 0x202020 });
    } else {
      texture = TriboView.checkerTexture();
      texture.repeat.set(planeSize / period, planeSize / period);
      mat = new THREE.MeshLambertMaterial({ map: texture });
    }
    var mesh = new THREE.Mesh(new THREE.PlaneBufferGeometry(planeSize, planeSize), mat);
    mesh.position.fromArray(g.position);
    var q = g.quaternion;
    mesh.quaternion.set(q[1], q[2], q[3], q[0]);
    parent.add(mesh);
    if (texture) out.planes.push({ texture: texture, velocity: velocity, period: period });
  }

  var hasPlane = false;
  data.scene.world.forEach(function (g) {
    if (g.shape === "halfspace") { plane(scene, g, [0, 0, 0]); hasPlane = true; return; }
    var obj = TriboView.shapeObject(g, new THREE.MeshLambertMaterial({ color: 0x777777 }), extent);
    if (obj) scene.add(obj);
  });
  data.scene.bodies.forEach(function (b, i) {
    var group = new THREE.Group();
    var colour = test ? TriboView.testColour(i) : new THREE.Color(TriboView.palette[i % 10]);
    var material = test ? new THREE.MeshBasicMaterial({ color: colour })
                        : new THREE.MeshLambertMaterial({ color: colour });
    b.geometries.forEach(function (g) {
      if (g.note) out.notes.push(b.name + ": " + g.note);
      if (g.shape === "halfspace") { plane(group, g, b.surface_velocity); hasPlane = true; return; }
      var obj = TriboView.shapeObject(g, material, extent);
      if (obj) {
        obj.userData.body = i;
        obj.traverse(function (o) { o.userData.body = i; });
        group.add(obj);
      }
    });
    if (b.geometries.length === 0) {  // nothing to draw (a URDF link without collision): a marker
      var marker = new THREE.Mesh(new THREE.SphereBufferGeometry(0.04 * extent, 16, 12), material);
      marker.userData.body = i;
      group.add(marker);
      out.notes.push(b.name + ": no geometry; drawn as a small sphere at its origin");
    }
    group.position.fromArray(b.position);
    var q = b.quaternion;
    group.quaternion.set(q[1], q[2], q[3], q[0]);
    scene.add(group);
    out.bodies.push({ name: b.name, group: group, material: material, baseColour: colour.clone() });
  });
  if (!test && !hasPlane) {  // no ground drawn: a grid in the plane z = 0 for reference
    var grid = new THREE.GridHelper(planeSize, Math.round(planeSize / Math.max(extent, 0.1)),
                                    0x888888, 0x3a3f48);
    grid.rotateX(Math.PI / 2);  // into the x-y plane
    scene.add(grid);
  }
  return out;
};

// Slides the plane textures to time t: a point of the surface moves by velocity * t.
TriboView.movePlanes = function (planes, t) {
  planes.forEach(function (p) {
    p.texture.offset.set(-p.velocity[0] * t / p.period, -p.velocity[1] * t / p.period);
  });
};
