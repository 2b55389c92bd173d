#include "peer_scene.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace tribo::peers {

namespace {

PeerShape shapeOf(const Geometry& g) {
  PeerShape s;
  s.pose = g.local_pose;
  switch (g.shape.type) {
    case contact::ShapeType::kBox:
      s.kind = PeerShape::Kind::kBox;
      s.half_extents = g.shape.half_extents;
      break;
    case contact::ShapeType::kSphere:
      s.kind = PeerShape::Kind::kSphere;
      s.radius = g.shape.radius;
      break;
    case contact::ShapeType::kHalfSpace:
      s.kind = PeerShape::Kind::kHalfSpace;
      break;
    default:
      throw std::invalid_argument("peers: geometry '" + g.name +
                                  "' is not a box, sphere or half-space");
  }
  return s;
}

}  // namespace

PeerScene peerSceneFrom(const Model& model, double mu, long steps) {
  PeerScene scene;
  scene.gravity = model.options.gravity;
  scene.dt = model.options.time_step;
  scene.mu = mu;
  scene.steps = steps;
  for (const Body& b : model.bodies) {
    PeerBody p;
    p.name = b.name;
    p.dynamic = b.kind == BodyKind::kDynamic;
    p.mass = b.mass;
    p.position = b.position;
    p.orientation = b.orientation;
    if (p.dynamic) {
      const Mat3 off = b.inertia - Mat3(b.inertia.diagonal().asDiagonal());
      if (off.norm() > 1e-12 * b.inertia.norm())
        throw std::invalid_argument("peers: body '" + b.name + "' has a non-diagonal inertia");
      p.inertia = b.inertia.diagonal();
    }
    if (!b.velocity.isZero() || !b.angular_velocity.isZero() || !b.surface_velocity.isZero())
      throw std::invalid_argument("peers: body '" + b.name + "' does not start at rest");
    scene.bodies.push_back(std::move(p));
  }
  for (const Geometry& g : model.geometries) {
    if (g.body.isWorld()) throw std::invalid_argument("peers: geometry on the world");
    scene.bodies[static_cast<std::size_t>(g.body.value)].shapes.push_back(shapeOf(g));
  }
  for (const PeerBody& p : scene.bodies) {
    if (!p.dynamic) continue;
    if (p.shapes.size() != 1 || !p.shapes[0].pose.isApprox(Eigen::Isometry3d::Identity()) ||
        p.shapes[0].kind == PeerShape::Kind::kHalfSpace)
      throw std::invalid_argument("peers: dynamic body '" + p.name +
                                  "' needs one box or sphere at its centre");
  }
  if (!model.joints.empty() || !model.springs.empty())
    throw std::invalid_argument("peers: joints and springs are not carried over");
  return scene;
}

double horizontalDrift(const PeerScene& scene, const std::vector<Eigen::Vector3d>& positions) {
  double drift = 0.0;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b)
    if (scene.bodies[b].dynamic)
      drift = std::max(drift, (positions[b] - scene.bodies[b].position).head<2>().norm());
  return drift;
}

double BeltSpec::exactX(double t) const {
  const double w = std::sqrt(spring / mass);
  return mu * mass * g / spring * (1.0 - std::cos(w * t));
}

}  // namespace tribo::peers
