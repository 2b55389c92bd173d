#include "box_grid_scene.hpp"

#include <cstdio>

namespace tribo::bench {

std::string boxGridYaml(int n, bool box_ground) {
  const double pitch = 0.25, size = 0.2, mass = 8.0, k = 6.0e5;
  const double z0 = size / 2 - mass * 9.81 / (4 * k);
  char line[256];
  std::string text;
  std::snprintf(line, sizeof line, "# %d x %d boxes of 0.2 m, 8 kg, at a 0.25 m pitch on %s.\n", n,
                n, box_ground ? "a kinematic box" : "a half-space");
  text += line;
  text += R"(parameters:
  k: 6.0e5
  c: 1000.0
  mu: 0.5
  dt: 1.0e-3
  duration: 1.0
  integrator: semi_implicit_euler
simulation: {duration: $duration, time_step: $dt, integrator: $integrator, gravity: [0, 0, -9.81]}
friction_laws:
  coulomb: {mu: $mu, regularization: tanh, v_eps: 0.01}
materials:
  - {name: ground_box, normal: {law: linear, stiffness: $k, damping: $c}, friction: coulomb,
     default: true}
bodies:
)";
  const double span = (n - 1) * pitch, centre = span / 2, side = span + size + 1.0;
  if (box_ground)
    std::snprintf(line, sizeof line,
                  "  - {name: ground, kind: kinematic, position: [%.6g, %.6g, -0.1], geometry: "
                  "[{name: floor, shape: box, size: [%.6g, %.6g, 0.2]}]}\n",
                  centre, centre, side, side);
  else
    std::snprintf(line, sizeof line,
                  "  - {name: ground, kind: kinematic, geometry: [{name: floor, shape: "
                  "halfspace}]}\n");
  text += line;
  // One entry for all the boxes (bodies[].pattern): copy (i, j) is box_i_j_0 at
  // (i pitch, j pitch, z0), as the body-by-body text had it, in the same order.
  std::snprintf(line, sizeof line,
                "  - {name: box, mass: 8.0, position: [0, 0, %.17g], geometry: [{name: s, shape: "
                "box, size: [0.2, 0.2, 0.2]}], pattern: {grid: [%d, %d, 1], spacing: [%.17g, "
                "%.17g, 0]}}\n",
                z0, n, n, pitch, pitch);
  text += line;
  return text;
}

}  // namespace tribo::bench
