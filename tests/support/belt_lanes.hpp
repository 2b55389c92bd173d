// The scene text of n copies of the paper's belt oscillator (scenes/belt.yaml: a 10 kg box,
// 300 N/m to a wall, roh_yoo friction on a belt at 1.5 m/s, RK4 at 1 ms) side by side in
// lanes 0.4 m apart, each box on its own planar joint, neighbours joined by bushings of
// `coupling` N/m along the belt that are relaxed when they move together: 12 n orbit unknowns
// whose in-phase motion is the single belt's stick-slip cycle (the bushings then carry no
// force). Shared by the Krylov shooting tests (tests/study/krylov_orbit_test.cpp) and the orbit
// bench (bench/scenes/orbit_bench.cpp). The summary observes box0.x. Not here: expectations.
#pragma once

#include <sstream>
#include <string>

namespace tribo::test {

inline std::string beltLanes(int n, double coupling = 1000.0) {
  const double z0 = 0.05 - 10.0 * 9.81 / (4 * 2.5e5);  // the boxes' static depth on 4 corners
  std::ostringstream y;
  y.precision(17);
  y << "simulation: {duration: 30, time_step: 0.001, integrator: rk4, gravity: [0, 0, -9.81]}\n"
       "bodies:\n  - {name: belt, kind: kinematic, surface_velocity: [1.5, 0, 0],\n"
       "     geometry: [{name: surface, shape: halfspace}]}\n";
  for (int i = 0; i < n; ++i)
    y << "  - {name: box" << i << ", mass: 10, position: [0, " << 0.4 * i << ", " << z0
      << "], geometry: [{name: g" << i << ", shape: box, size: [0.2, 0.2, 0.1]}]}\n";
  y << "joints:\n";
  for (int i = 0; i < n; ++i)
    y << "  - {name: lane" << i << ", type: planar_translation, parent: world, child: box" << i
      << ", anchor: [0, " << 0.4 * i << ", " << z0 << "], axis: [0, 1, 0]}\n";
  y << "springs:\n";
  for (int i = 0; i < n; ++i)
    y << "  - {name: wall" << i << ", a: world, point_a: [-100, " << 0.4 * i << ", " << z0
      << "], b: box" << i << ", point_b: [0, " << 0.4 * i << ", " << z0
      << "], stiffness: 300, rest_length: 100}\n";
  if (n > 1) y << "bushings:\n";
  for (int i = 1; i < n; ++i)
    y << "  - {name: link" << i << ", a: box" << i - 1 << ", b: box" << i
      << ", frame_b: {position: [0, -0.4, 0]}, stiffness: [" << coupling << ", 0, 0]}\n";
  y << "friction_laws:\n"
       "  roh_yoo: {mu_s: 0.35, mu_k: 0.3, v_s: 0.01, a: 1.5, beta: 0.3333333333333333}\n"
       "materials:\n  - {name: belt_box, normal: {law: linear, stiffness: 2.5e5, damping: 1.5e3},"
       " friction: roh_yoo}\ncontacts:\n";
  for (int i = 0; i < n; ++i) y << "  - {a: surface, b: g" << i << ", material: belt_box}\n";
  y << "output: {summary: {body: box0, coordinate: x, stick_speed: 0.01, last_cycles: 3}}\n";
  return y.str();
}

}  // namespace tribo::test
