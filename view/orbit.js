// Orbit camera for the replay page: z is up; left drag turns the camera around its target,
// right drag (or shift + left drag) pans, the wheel zooms. The camera is stated as eye and
// target (the URL's camera= parameter) and kept as azimuth, elevation and distance.
// Not here: following a body (page.js moves the target), rendering.
var TriboView = window.TriboView || {};
window.TriboView = TriboView;

TriboView.Orbit = function (camera, element, onChange) {
  var self = this;
  this.camera = camera;
  this.target = new THREE.Vector3();
  this.azimuth = 0;
  this.elevation = 0.4;
  this.distance = 5;
  this.onChange = onChange;

  this.set = function (eye, target) {
    self.target.copy(target);
    var d = new THREE.Vector3().subVectors(eye, target);
    self.distance = Math.max(d.length(), 1e-6);
    self.azimuth = Math.atan2(d.y, d.x);
    self.elevation = Math.asin(Math.max(-1, Math.min(1, d.z / self.distance)));
    self.update();
  };
  this.eye = function () {
    var c = Math.cos(self.elevation);
    return new THREE.Vector3(c * Math.cos(self.azimuth), c * Math.sin(self.azimuth),
                             Math.sin(self.elevation)).multiplyScalar(self.distance).add(self.target);
  };
  this.update = function () {
    camera.up.set(0, 0, 1);
    camera.position.copy(self.eye());
    camera.lookAt(self.target);
    camera.updateMatrixWorld();
  };

  var drag = null;
  element.addEventListener("contextmenu", function (e) { e.preventDefault(); });
  element.addEventListener("mousedown", function (e) {
    drag = { x: e.clientX, y: e.clientY, pan: e.button === 2 || e.shiftKey };
  });
  window.addEventListener("mouseup", function () { drag = null; });
  window.addEventListener("mousemove", function (e) {
    if (!drag) return;
    var dx = e.clientX - drag.x, dy = e.clientY - drag.y;
    drag.x = e.clientX;
    drag.y = e.clientY;
    if (drag.pan) {
      // Move the target in the view plane by the distance the pointer covers at its depth.
      var h = element.clientHeight || 1;
      var perPixel = 2 * self.distance * Math.tan(camera.fov * Math.PI / 360) / h;
      var right = new THREE.Vector3().setFromMatrixColumn(camera.matrixWorld, 0);
      var up = new THREE.Vector3().setFromMatrixColumn(camera.matrixWorld, 1);
      self.target.addScaledVector(right, -dx * perPixel).addScaledVector(up, dy * perPixel);
    } else {
      self.azimuth -= dx * 0.008;
      self.elevation = Math.max(-1.55, Math.min(1.55, self.elevation + dy * 0.008));
    }
    self.update();
    if (self.onChange) self.onChange();
  });
  element.addEventListener("wheel", function (e) {
    e.preventDefault();
    self.distance *= Math.exp(0.001 * e.deltaY);
    self.update();
    if (self.onChange) self.onChange();
  }, { passive: false });
};
