// Bullet's runs of bench/peers (peer_engines.hpp): each PeerBody a btRigidBody (fixed ones with
// mass 0, one object per shape), btBoxShape / btSphereShape / btStaticPlaneShape. Friction: a
// pair's coefficient is the product of its two objects' (Bullet's rule), so every object gets
// sqrt(mu) and every pair mu.
#include <btBulletDynamicsCommon.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "peer_engines.hpp"

namespace tribo::peers {

namespace {

btVector3 bt(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
btTransform bt(const Eigen::Isometry3d& t) {
  const Eigen::Quaterniond q(t.linear());
  return btTransform(btQuaternion(q.x(), q.y(), q.z(), q.w()),
                     bt(Eigen::Vector3d(t.translation())));
}

// A world and everything it owns.
struct World {
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &config};
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btDefaultMotionState>> states;
  std::vector<std::unique_ptr<btRigidBody>> bodies;

  ~World() {
    for (auto& b : bodies) world.removeRigidBody(b.get());
  }

  btCollisionShape* shape(const PeerShape& s) {
    switch (s.kind) {
      case PeerShape::Kind::kBox:
        shapes.push_back(std::make_unique<btBoxShape>(bt(s.half_extents)));
        break;
      case PeerShape::Kind::kSphere:
        shapes.push_back(std::make_unique<btSphereShape>(s.radius));
        break;
      case PeerShape::Kind::kHalfSpace:
        shapes.push_back(std::make_unique<btStaticPlaneShape>(btVector3(0, 0, 1), 0));
        break;
    }
    return shapes.back().get();
  }

  btRigidBody* add(btCollisionShape* shape, const btTransform& pose, double mass,
                   const btVector3& inertia, double friction) {
    states.push_back(std::make_unique<btDefaultMotionState>(pose));
    btRigidBody::btRigidBodyConstructionInfo info(mass, states.back().get(), shape, inertia);
    info.m_friction = friction;
    info.m_restitution = 0;
    bodies.push_back(std::make_unique<btRigidBody>(info));
    btRigidBody* body = bodies.back().get();
    body->setActivationState(DISABLE_DEACTIVATION);
    world.addRigidBody(body);
    return body;
  }

  // Deepest contact and the number of contact points now (the manifolds' points, touching or
  // within Bullet's contact threshold).
  void contacts(PeerRun& run) {
    run.penetration = 0;
    run.points = 0;
    for (int i = 0; i < dispatcher.getNumManifolds(); ++i) {
      const btPersistentManifold* m = dispatcher.getManifoldByIndexInternal(i);
      for (int k = 0; k < m->getNumContacts(); ++k) {
        run.points += 1;
        run.penetration = std::max(run.penetration, -m->getContactPoint(k).getDistance());
      }
    }
  }
};

}  // namespace

std::string bulletVersion() { return std::to_string(btGetVersion()); }

PeerRun runBullet(const PeerScene& scene) {
  World w;
  w.world.setGravity(bt(scene.gravity));
  const double friction = std::sqrt(scene.mu);
  std::vector<btRigidBody*> dynamic(scene.bodies.size(), nullptr);
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const PeerBody& p = scene.bodies[b];
    Eigen::Isometry3d body_pose = Eigen::Isometry3d::Identity();
    body_pose.linear() = p.orientation.toRotationMatrix();
    body_pose.translation() = p.position;
    if (p.dynamic)
      dynamic[b] = w.add(w.shape(p.shapes[0]), bt(body_pose), p.mass, bt(p.inertia), friction);
    else
      for (const PeerShape& s : p.shapes)
        w.add(w.shape(s), bt(body_pose * s.pose), 0.0, btVector3(0, 0, 0), friction);
  }
  PeerRun run;
  run.steps = scene.steps;
  const StepTimer timer;
  for (long i = 0; i < scene.steps; ++i) w.world.stepSimulation(scene.dt, 1, scene.dt);
  timer.stop(run);
  w.contacts(run);
  std::vector<Eigen::Vector3d> positions(scene.bodies.size());
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    positions[b] = scene.bodies[b].position;
    if (dynamic[b]) {
      const btVector3& o = dynamic[b]->getWorldTransform().getOrigin();
      positions[b] = {o.x(), o.y(), o.z()};
      run.max_speed = std::max(run.max_speed, double(dynamic[b]->getLinearVelocity().length()));
      if (!std::isfinite(positions[b].norm())) run.error = "diverged";
    }
  }
  run.drift = horizontalDrift(scene, positions);
  return run;
}

// The belt: a long kinematic box moved at v_b (Bullet takes a kinematic body's velocity from its
// motion state's change over the step), the block free along x and z only (linear factor 1 0 1,
// no rotation), the spring a force -k x applied before every step.
PeerRun runBulletBelt(const BeltSpec& belt) {
  World w;
  w.world.setGravity(btVector3(0, 0, -belt.g));
  const double friction = std::sqrt(belt.mu);
  const Eigen::Vector3d belt_half(50.0, 1.0, 0.05);
  btTransform belt_pose(btQuaternion::getIdentity(), btVector3(0, 0, -belt_half.z()));
  PeerShape belt_shape;
  belt_shape.half_extents = belt_half;
  btRigidBody* belt_body = w.add(w.shape(belt_shape), belt_pose, 0.0, btVector3(0, 0, 0), friction);
  belt_body->setCollisionFlags(belt_body->getCollisionFlags() |
                               btCollisionObject::CF_KINEMATIC_OBJECT);
  PeerShape box_shape;
  box_shape.half_extents = belt.half_extents;
  const btTransform box_pose(btQuaternion::getIdentity(), btVector3(0, 0, belt.half_extents.z()));
  btRigidBody* box = w.add(w.shape(box_shape), box_pose, belt.mass, btVector3(1, 1, 1), friction);
  box->setLinearFactor(btVector3(1, 0, 1));
  box->setAngularFactor(btVector3(0, 0, 0));
  PeerRun run;
  run.steps = belt.steps;
  const StepTimer timer;
  for (long i = 0; i < belt.steps; ++i) {
    belt_pose.setOrigin(
        btVector3(belt.belt_speed * belt.dt * static_cast<double>(i + 1), 0, -belt_half.z()));
    belt_body->getMotionState()->setWorldTransform(belt_pose);
    box->applyCentralForce(
        btVector3(-belt.spring * box->getWorldTransform().getOrigin().x(), 0, 0));
    w.world.stepSimulation(belt.dt, 1, belt.dt);
  }
  timer.stop(run);
  w.contacts(run);
  const double x = box->getWorldTransform().getOrigin().x();
  run.belt_error = std::abs(x - belt.exactX(belt.dt * static_cast<double>(belt.steps)));
  if (!std::isfinite(x)) run.error = "diverged";
  return run;
}

}  // namespace tribo::peers
