// Description of one rigid body in the model (immutable once built).
//
// A dynamic body obeys Newton-Euler: m a = F, I_W dw/dt = T - w x I_W w (I_W = R I_B R^T,
// inertia about the centre of mass, which is the body origin). A kinematic body moves with
// a prescribed constant velocity, whatever acts on it. Either may carry a surface velocity
// (body frame): its surface slides past contacts while its geometry stays put (a belt).
// Not here: state (core/state.hpp), geometry (Model::geometries).
#pragma once

#include <string>

#include "core/math.hpp"

namespace tribo {

// Typed body index; kWorld is the fixed world frame.
struct BodyIndex {
  int value = -1;
  static constexpr int kWorldValue = -1;
  static BodyIndex world() { return {kWorldValue}; }
  bool isWorld() const { return value == kWorldValue; }
  bool operator==(const BodyIndex&) const = default;
};

enum class BodyKind { kDynamic, kKinematic };

struct Body {
  std::string name;
  BodyKind kind = BodyKind::kDynamic;
  double mass = 1.0;                     // [kg]
  Mat3 inertia = Mat3::Identity();       // about the origin, body frame [kg m^2]
  Vec3 position = Vec3::Zero();          // initial, world [m]
  Quat orientation = Quat::Identity();   // initial, body to world
  Vec3 velocity = Vec3::Zero();          // initial (or prescribed), world [m/s]
  Vec3 angular_velocity = Vec3::Zero();  // initial (or prescribed), world [rad/s]
  Vec3 surface_velocity = Vec3::Zero();  // each geometry's frame [m/s] (surfaceVelocityOf)
};

}  // namespace tribo
