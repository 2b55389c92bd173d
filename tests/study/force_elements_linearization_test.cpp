// study/modes/linearization differentiates the whole evaluation, so bushings and torsional springs
// enter the linearized stiffness with no code of their own: a body on a bushing to the world
// (gains all different, frame A turned) plus a torsional spring about frame A's z has the
// squared frequencies k_i / m and k_ri / I_i, about z (k_rz + k_t) / I_z, as the eigenvalues
// of -K; light and stiff (1e-3 kg, 1e6 N/m) as well as ordinary.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cstdio>

#include "core/model_builder.hpp"
#include "study/modes/linearization.hpp"

namespace tribo::study {
namespace {

TEST(ForceElementsLinearization, EigenvaluesAreTheClosedFormSquaredFrequencies) {
  struct Case {
    double mass;
    Vec3 inertia, k, kr;
    double kt;
  };
  for (const Case& c :
       {Case{2.0, {0.03, 0.05, 0.07}, {100, 400, 900}, {3, 7, 13}, 5.0},
        Case{1e-3, {1e-7, 2e-7, 2.5e-7}, {1e6, 2e6, 5e6}, {0.01, 0.03, 0.05}, 0.02}}) {
    const Quat frame(Eigen::AngleAxisd(0.7, Vec3(1, -2, 0.5).normalized()));
    ModelBuilder b;
    Body body;
    body.name = "block";
    body.mass = c.mass;
    body.inertia = c.inertia.asDiagonal();
    body.position = Vec3(0.3, -1.2, 2.0);
    body.orientation = frame;  // principal axes along frame A's
    const BodyIndex i = b.addBody(body);
    Bushing bushing;
    bushing.name = "mount";
    bushing.body_b = i;
    bushing.position_a = body.position;
    bushing.orientation_a = frame;
    bushing.stiffness = c.k;
    bushing.rotational_stiffness = c.kr;
    b.addBushing(bushing);
    b.addTorsionalSpring("torsion", BodyIndex::world(), i, frame * Vec3::UnitZ(), c.kt, 0.0, 0.0);
    b.options().gravity = Vec3::Zero();
    const auto model = b.build();
    Dynamics dynamics(model);
    const State at = dynamics.initialState();
    const ReducedCoordinates coords(*model, at);
    const Linearization lin = linearize(dynamics, coords, at, DifferenceSteps{}, false, 0.0);
    Eigen::VectorXd got = Eigen::EigenSolver<Eigen::MatrixXd>(-lin.stiffness).eigenvalues().real();
    std::sort(got.data(), got.data() + got.size());
    std::vector<double> expected;
    for (int a = 0; a < 3; ++a) {
      expected.push_back(c.k[a] / c.mass);
      expected.push_back((c.kr[a] + (a == 2 ? c.kt : 0.0)) / c.inertia[a]);
    }
    std::sort(expected.begin(), expected.end());
    for (int a = 0; a < 6; ++a) {
      std::printf("m %g: eigenvalue %.10g, expected %.10g\n", c.mass, got[a], expected[a]);
      // Central differences at h = 1e-7 of a linear force: only rounding, eps |x| / h with
      // positions of ~2 m: 2e-16 x 2 / 1e-7 = 4e-9 relative; 1e-6 asked.
      EXPECT_NEAR(got[a], expected[a], 1e-6 * expected[a]) << a;
    }
  }
}

}  // namespace
}  // namespace tribo::study
