// A belt whose surface is tilted by its geometry's pose (`rpy` on the half-space, as
// scenes/incline.yaml tilts a slope) moves along the tilted plane: a box resting on it sees
// the full belt speed v_b as slip, in the plane, for tilts about either horizontal axis and
// several speeds (before, the surface velocity stayed horizontal in the body frame and the
// box saw v_b cos(theta)). A belt turned as a whole body (body `rpy`) gives the same slip:
// the two ways of tilting agree.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "core/dynamics.hpp"
#include "io/scene_loader.hpp"

namespace tribo {
namespace {

// A 1 x 1 x 0.1 m box whose bottom face lies 1e-4 m inside a half-space tilted by
// (roll, pitch), the belt surface moving at v_b along the geometry's x.
std::string scene(double roll, double pitch, double v_b, bool tilt_body) {
  const double c = std::cos(pitch), s = std::sin(pitch), cr = std::cos(roll), sr = std::sin(roll);
  // The plane's normal, R_x(roll) R_y(pitch) z; the box's centre 0.05 - 1e-4 along it, the
  // box turned the same way.
  const double nx = s, ny = -sr * c, nz = cr * c;
  const double d = 0.05 - 1e-4;
  char text[2048];
  const std::string tilt = "rpy: [" + std::to_string(roll) + ", " + std::to_string(pitch) + ", 0]";
  std::snprintf(text, sizeof text, R"(
simulation: {duration: 0.01, time_step: 0.001, gravity: [0, 0, 0]}
bodies:
  - name: belt
    kind: kinematic
    surface_velocity: [%.17g, 0, 0]
    %s
    geometry:
      - {name: surface, shape: halfspace%s}
  - name: box
    mass: 1
    position: [%.17g, %.17g, %.17g]
    %s
    geometry:
      - {name: box_shape, shape: box, size: [1, 1, 0.1]}
friction_laws:
  coulomb: {mu: 0.3}
materials:
  - {name: m, normal: {law: linear, stiffness: 1.0e5}, friction: coulomb}
contacts:
  - {a: surface, b: box_shape, material: m}
)",
                v_b, tilt_body ? tilt.c_str() : "", tilt_body ? "" : (", " + tilt).c_str(), d * nx,
                d * ny, d * nz, tilt.c_str());
  return text;
}

TEST(TiltedBelt, SurfaceMovesAlongItsTiltedPlane) {
  for (const double roll : {0.0, 0.3})
    for (const double pitch : {0.0, 10 * M_PI / 180, -0.5})
      for (const double v_b : {0.01, 1.5, 30.0})
        for (const bool tilt_body : {false, true}) {
          const io::Scene sc =
              io::loadSceneFromString(scene(roll, pitch, v_b, tilt_body), "tilted.yaml");
          Dynamics dynamics(sc.model);
          const Workspace& ws = dynamics.evaluate(dynamics.initialState());
          ASSERT_EQ(ws.contacts.size(), 4u);
          for (const auto& c : ws.contacts) {
            // Box at rest: slip of the box relative to the belt is minus the surface's.
            EXPECT_NEAR(c.slip.norm(), v_b, 1e-12 * v_b) << roll << " " << pitch;
            EXPECT_NEAR(c.slip.dot(c.point.normal), 0.0, 1e-12 * v_b);
          }
        }
}

// The rule's guard: a surface velocity with a part along the half-space's normal (its
// geometry's z) is noted when the scene loads; tangent ones, tilted or not, are not.
TEST(TiltedBelt, SurfaceVelocityOffTheSurfaceIsNoted) {
  auto notes = [](const std::string& yaml) {
    std::string all;
    for (const std::string& n : io::loadSceneFromString(yaml, "belt.yaml").notes) all += n + "\n";
    return all;
  };
  for (const double v : {1e-3, 1.5, 40.0}) {
    for (const bool tilt_body : {false, true}) {
      EXPECT_EQ(notes(scene(0.1, 0.17, v, tilt_body)), "") << v;
      std::string off = scene(0.1, 0.17, v, tilt_body);
      const std::string from = "surface_velocity: [";
      const auto at = off.find(from);
      const auto end = off.find(']', at);
      off.replace(at, end - at + 1,
                  from + std::to_string(v) + ", 0, " + std::to_string(0.1 * v) + "]");
      const std::string text = notes(off);
      EXPECT_NE(text.find("bodies.belt.surface_velocity"), std::string::npos) << text;
      EXPECT_NE(text.find("not tangent to the surface of half-space 'surface'"), std::string::npos)
          << text;
    }
  }
}

}  // namespace
}  // namespace tribo
