// The model: the immutable description of a scene, built and validated once by
// ModelBuilder. Bodies, collision geometries, joints, force elements, contact materials
// and pairs, and the simulation options (every speed-for-accuracy trade is one of them).
// Not here: anything that changes during a run (core/state.hpp, core/dynamics.hpp).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "contact/collision_detector.hpp"
#include "contact/contact_force.hpp"
#include "contact/shape.hpp"
#include "core/body.hpp"
#include "core/force_element.hpp"
#include "core/joint.hpp"

namespace tribo {

enum class IntegratorType { kSemiImplicitEuler, kRk4 };

// Scene names "semi_implicit_euler", "rk4"; throws std::invalid_argument otherwise.
IntegratorType integratorFromName(const std::string& name);
std::string integratorName(IntegratorType type);

struct SimulationOptions {
  Vec3 gravity{0.0, 0.0, -9.81};  // [m/s^2]
  IntegratorType integrator = IntegratorType::kRk4;
  double time_step = 1e-3;   // [s]; see README for the measured speed/accuracy trade
  double duration = 10.0;    // [s]
  // Baumgarte stabilization: Phi'' + 2 alpha Phi' + beta^2 Phi = 0 [1/s].
  double baumgarte_alpha = 20.0;
  double baumgarte_beta = 20.0;
  contact::CollisionOptions collision;
};

struct Geometry {
  std::string name;
  BodyIndex body = BodyIndex::world();
  contact::Shape shape;
  Eigen::Isometry3d local_pose = Eigen::Isometry3d::Identity();  // in the body frame
};

struct ContactPair {
  int geometry_a = -1;  // normal and friction forces are reported on B
  int geometry_b = -1;
  int material = -1;
};

struct Model {
  std::vector<Body> bodies;
  std::vector<Geometry> geometries;
  std::vector<Joint> joints;
  std::vector<SpringDamper> springs;
  std::vector<contact::Material> materials;
  std::vector<ContactPair> contact_pairs;
  SimulationOptions options;

  std::optional<BodyIndex> findBody(const std::string& name) const;
  int dynamicBodyCount() const;
};

}  // namespace tribo
