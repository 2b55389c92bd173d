// The model: the immutable description of a scene, built and validated once by
// ModelBuilder. Bodies, collision geometries, joints, force elements, applied loads,
// contact materials and pairs, and the simulation options (every speed-for-accuracy trade is one of
// them). Not here: anything that changes during a run (core/state.hpp, core/dynamics.hpp).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "contact/collision_detector.hpp"
#include "contact/contact_force.hpp"
#include "contact/shape.hpp"
#include "core/applied_load.hpp"
#include "core/automatic_contacts.hpp"
#include "core/body.hpp"
#include "core/bushing.hpp"
#include "core/constraint_options.hpp"
#include "core/contact_pair.hpp"
#include "core/force_element.hpp"
#include "core/joint.hpp"
#include "core/thread_count.hpp"
#include "core/torsional_spring.hpp"
#include "friction/name_table.hpp"

namespace tribo {

// Fixed-step explicit (semi_implicit_euler, rk4: hand-written, the fast path) and adaptive
// with error control from SUNDIALS (dopri5: ARKODE explicit Dormand-Prince 5(4); bdf: CVODE
// variable-order BDF, implicit, for very stiff contacts). See core/integrator.hpp.
enum class IntegratorType { kSemiImplicitEuler, kRk4, kDopri5, kBdf };

// Scene names "semi_implicit_euler", "rk4", "dopri5", "bdf".
inline constexpr NameTable<IntegratorType, 4> kIntegratorNames{
    "integrator",
    {{{IntegratorType::kSemiImplicitEuler, "semi_implicit_euler"},
      {IntegratorType::kRk4, "rk4"},
      {IntegratorType::kDopri5, "dopri5"},
      {IntegratorType::kBdf, "bdf"}}}};
// Throws std::invalid_argument naming the known names for any other.
inline IntegratorType integratorFromName(const std::string& name) {
  return kIntegratorNames.fromName(name);
}
inline std::string integratorName(IntegratorType type) { return kIntegratorNames.name(type); }

struct SimulationOptions {
  Vec3 gravity{0.0, 0.0, -9.81};  // [m/s^2]
  IntegratorType integrator = IntegratorType::kRk4;
  double time_step = 1e-3;  // [s]; see README for the measured speed/accuracy trade
  double duration = 10.0;   // [s]
  // Baumgarte stabilization: Phi'' + 2 alpha Phi' + beta^2 Phi = 0 [1/s].
  double baumgarte_alpha = 20.0;
  double baumgarte_beta = 20.0;
  ConstraintOptions constraints;  // projection, redundancy, solver (constraint_options.hpp)
  contact::CollisionOptions collision;
  // Adaptive integrators (dopri5, bdf) only: time_step is then the communication interval
  // (outputs and divergence checks) and the integrator picks its internal steps so that the
  // local error stays below relative_tolerance |y| + absolute_tolerance per component.
  double relative_tolerance = 1e-6;  // [-]
  double absolute_tolerance = 1e-9;  // [m, m/s, rad/s, -]
  double max_internal_step = 0.0;    // [s]; 0: no limit
  bool event_location = true;        // stop and restart at friction regime changes
  // Threads of one force evaluation (core/thread_count.hpp): kAutoThreads (0) or >= 1. The
  // results do not depend on it; small scenes use one whatever it says.
  int threads = 1;
};

struct Geometry {
  std::string name;
  BodyIndex body = BodyIndex::world();
  contact::Shape shape;
  Eigen::Isometry3d local_pose = Eigen::Isometry3d::Identity();  // in the body frame
  // Automatic contacts only: the surface material it is made of (selects the contact
  // material by surface pair), and collision filtering: geometries g, h may collide when
  // (g.group & h.mask) != 0 and (h.group & g.mask) != 0.
  std::string surface;
  std::uint32_t collision_group = 1;
  std::uint32_t collision_mask = 0xffffffffu;
};

// Automatic contacts: the contact material between two surface materials (either order).
struct SurfacePairMaterial {
  std::string surface_a, surface_b;
  int material = -1;
};

struct Model {
  std::vector<Body> bodies;
  std::vector<Geometry> geometries;
  std::vector<Joint> joints;
  std::vector<JointCoupling> couplings;  // mimic constraints between joint coordinates
  std::vector<SpringDamper> springs;
  std::vector<Bushing> bushings;
  std::vector<TorsionalSpring> torsional_springs;
  std::vector<AppliedLoad> loads;  // time-driven forces and torques on dynamic bodies
  std::vector<contact::Material> materials;
  std::vector<ContactPair> contact_pairs;  // listed contacts; pair id = index
  // True when the scene listed no contacts: every two geometries that may touch do, by the
  // rule in `automatic` (core/automatic_contacts.hpp), applied on demand to the pairs the
  // broadphase reports; contact_pairs stays empty and pair ids are g * n + h.
  bool automatic_contacts = false;
  AutomaticContacts automatic;
  // Scalar joint constraint equations kept after redundancy removal (set by the builder).
  int constraint_equations = 0;
  SimulationOptions options;

  std::optional<BodyIndex> findBody(const std::string& name) const;
  // The joint carrying the actuator named `name` (core/joint_actuator.hpp).
  std::optional<int> findActuator(const std::string& name) const;
  // The index of the load named `name` in `loads`.
  std::optional<std::size_t> findLoad(const std::string& name) const;
  int dynamicBodyCount() const;
  // The pair a contact point's `pair` id names (listed or automatic).
  ContactPair contactPair(int id) const {
    return automatic_contacts ? automaticPair(*this, id)
                              : contact_pairs[static_cast<std::size_t>(id)];
  }
};

// The world velocity of geometry `g`'s surface: its body's surface velocity at the
// evaluation's time (`body_surface`, per body: Workspace::surface_velocity) read in the
// geometry's own frame (local_pose), so a belt surface tilted by its geometry's pose moves
// along the tilted plane; zero for the world, and for all when `body_surface` is empty (no
// body has a surface velocity). `body_rotation`: body to world rotations.
inline Vec3 surfaceVelocityOf(const Model& model, const std::vector<Mat3>& body_rotation,
                              const std::vector<Vec3>& body_surface, int g) {
  const Geometry& geometry = model.geometries[static_cast<std::size_t>(g)];
  if (geometry.body.isWorld() || body_surface.empty()) return Vec3::Zero();
  const Vec3& v = body_surface[static_cast<std::size_t>(geometry.body.value)];
  if (v.squaredNorm() == 0.0) return Vec3::Zero();
  return body_rotation[geometry.body.value] * (geometry.local_pose.linear() * v);
}

}  // namespace tribo
