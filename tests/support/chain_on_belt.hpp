// The scene text of a chain of n boxes (1 kg, 0.2 x 0.2 x 0.1 m, each on a planar joint)
// pressed on a belt at 1.5 m/s by their weight, joined in a row by springs of 300 N/m and tied
// to a wall at the first: n coupled belt oscillators, 2n coordinates (x and z per box), 4n
// contact points. law: roh_yoo (memoryless: 4n states in A) or lugre (plus 12 bristle states
// per box). spring_damping [N s/m] on the springs between boxes (none by default) damps the
// modes by how much neighbours move against each other, so the in-phase modes lead and the
// growth rates no longer tie. Shared by the modes bench (bench/scenes/modes_bench.cpp) and the
// sparse-solver tests. Not here: expectations about its modes.
#pragma once

#include <sstream>
#include <string>

namespace tribo::test {

inline std::string chainOnBelt(int n, const std::string& law, double spring_damping = 0.0) {
  std::ostringstream y;
  y << "simulation: {duration: 1, time_step: 0.001, integrator: rk4, gravity: [0, 0, -9.81]}\n"
       "bodies:\n  - {name: belt, kind: kinematic, surface_velocity: [1.5, 0, 0],\n"
       "     geometry: [{name: surface, shape: halfspace}]}\n";
  for (int i = 0; i < n; ++i)
    y << "  - {name: b" << i << ", mass: 1, position: [" << 0.3 * i << ", 0, 0.0499],"
      << " geometry: [{name: g" << i << ", shape: box, size: [0.2, 0.2, 0.1]}]}\n";
  y << "joints:\n";
  for (int i = 0; i < n; ++i)
    y << "  - {name: j" << i << ", type: planar_translation, parent: world, child: b" << i
      << ", anchor: [" << 0.3 * i << ", 0, 0.0499], axis: [0, 1, 0]}\n";
  y << "springs:\n  - {name: s0, a: world, point_a: [-0.3, 0, 0.0499], b: b0,"
       " point_b: [0, 0, 0.0499], stiffness: 300}\n";
  for (int i = 1; i < n; ++i)
    y << "  - {name: s" << i << ", a: b" << i - 1 << ", point_a: [" << 0.3 * (i - 1)
      << ", 0, 0.0499], b: b" << i << ", point_b: [" << 0.3 * i
      << ", 0, 0.0499], stiffness: 300, damping: " << spring_damping << "}\n";
  y << "friction_laws:\n  roh_yoo: {mu_s: 0.35, mu_k: 0.3, v_s: 0.01, a: 1.5, beta: 0.3333}\n"
       "  lugre: {sigma0: 1.0e4, sigma1: 30, sigma2: 0, mu_c: 0.3, mu_s: 0.35, v_s: 0.01}\n"
       "materials:\n  - {name: belt_box, normal: {law: linear, stiffness: 2.5e5, damping: 1.5e3},"
       " friction: "
    << law << "}\ncontacts:\n";
  for (int i = 0; i < n; ++i) y << "  - {a: surface, b: g" << i << ", material: belt_box}\n";
  return y.str();
}

}  // namespace tribo::test
