#include "chute_scene.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

namespace tribo::bench {

std::string chuteYaml(int nx, int ny, int nz, double duration) {
  const double g = 9.81, angle = 26.0 * std::numbers::pi / 180.0;
  std::ostringstream y;
  y.precision(17);
  y << "parameters: {k: 1.5e5, c: 35.0, mu: 0.4, dt: 1.0e-3}\n"
    << "simulation:\n  duration: " << duration
    << "\n  time_step: $dt\n  integrator: semi_implicit_euler\n"
    << "  gravity: [" << g * std::sin(angle) << ", 0, " << -g * std::cos(angle) << "]\n"
    << "friction_laws:\n  coulomb: {mu: $mu, regularization: tanh, v_eps: 0.01}\n"
    << "materials:\n  - name: rubber\n    normal: {law: linear, stiffness: $k, damping: $c}\n"
    << "    friction: coulomb\n    default: true\n"
    << "bodies:\n  - name: chute\n    kind: kinematic\n"
    << "    geometry: [{name: floor, shape: halfspace}]\n"
    << "  - {name: s, mass: 0.5, position: [0, 0, 0.0525], geometry: [{name: g, shape: sphere, "
       "radius: 0.05}], pattern: {grid: ["
    << nx << ", " << ny << ", " << nz
    << "], spacing: [0.105, 0.105, 0.105], jitter: 0.002, seed: 1}}\n";
  return y.str();
}

}  // namespace tribo::bench
