#include "core/joint_forces.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace tribo {

namespace {
constexpr int kMaxFrictionIterations = 20;
constexpr double kFrictionTolerance = 1e-12;
}  // namespace

std::vector<int> jointOfChild(const Model& model) {
  std::vector<int> table(model.bodies.size(), -1);
  for (std::size_t k = 0; k < model.joints.size(); ++k)
    if (const BodyIndex c = model.joints[k].child; !c.isWorld())
      table[static_cast<std::size_t>(c.value)] = static_cast<int>(k);
  return table;
}

double coordinateInertia(const Model& model, int joint, std::span<const int> joint_of_child) {
  const Joint& j = model.joints[joint];
  const bool angular = jointCoordinate(j).angular;
  const auto dynamic = [&](BodyIndex b) {
    return !b.isWorld() && model.bodies[b.value].kind == BodyKind::kDynamic;
  };
  // A body's inertia about (revolute) or along (prismatic) the world axis through the world
  // point `anchor`.
  auto about = [&](BodyIndex b, const Vec3& anchor, const Vec3& axis) {
    const Body& body = model.bodies[b.value];
    if (!angular) return body.mass;
    const Mat3 r = body.orientation.normalized().toRotationMatrix();
    const Vec3 offset = body.position - anchor;
    const double d2 = (offset - offset.dot(axis) * axis).squaredNorm();
    return axis.dot(r * body.inertia * r.transpose() * axis) + body.mass * d2;
  };
  auto pose = [&](BodyIndex b, const Vec3& local_point, const Vec3& local_axis) {
    if (b.isWorld()) return std::pair<Vec3, Vec3>(local_point, local_axis);
    const Body& body = model.bodies[b.value];
    const Mat3 r = body.orientation.normalized().toRotationMatrix();
    return std::pair<Vec3, Vec3>(body.position + r * local_point, r * local_axis);
  };
  const auto [anchor, axis] = pose(j.child, j.anchor_in_child, j.axes_in_child.col(2));
  if (!dynamic(j.child)) {
    if (!dynamic(j.parent)) return std::numeric_limits<double>::infinity();
    return about(j.parent, anchor, axis);
  }
  const double c = about(j.child, anchor, axis);
  if (!dynamic(j.parent)) return c;
  // The parent gives way when it is free, or turns (slides) on a joint of its own along a
  // parallel axis (a chain of fingers): then the pair's reduced inertia.
  const int below_index = joint_of_child[static_cast<std::size_t>(j.parent.value)];
  const Joint* below =
      below_index >= 0 ? &model.joints[static_cast<std::size_t>(below_index)] : nullptr;
  double p = std::numeric_limits<double>::infinity();
  if (!below) {
    p = angular ? about(j.parent, model.bodies[j.parent.value].position, axis)
                : model.bodies[j.parent.value].mass;
  } else if (below->type == j.type) {
    const auto [a2, axis2] = pose(j.parent, below->anchor_in_child, below->axes_in_child.col(2));
    if (std::abs(axis2.dot(axis)) > 0.99) {
      p = about(j.parent, a2, axis2);
    } else if (angular && dynamic(below->parent)) {
      // Three revolute joints in series (a gimbal, as URDF writes a ball joint through two
      // massless links): turning the middle joint swings this axis around the middle axis, and
      // where it lines up with the first joint's axis (gimbal lock) the parent and the middle
      // link turn together about it against the first joint alone. That happens when both
      // axes make the same angle with the middle one. The parent then gives way as in a chain
      // of fingers, whatever the pose at the start: near lock a damper on this joint acts on
      // the two links' own inertia, and sized for the child's it would make the step unstable.
      const int first_index = joint_of_child[static_cast<std::size_t>(below->parent.value)];
      if (first_index >= 0 && model.joints[static_cast<std::size_t>(first_index)].type == j.type) {
        const Joint& first = model.joints[static_cast<std::size_t>(first_index)];
        const Vec3 axis1 =
            pose(below->parent, first.anchor_in_child, first.axes_in_child.col(2)).second;
        if (std::abs(std::abs(axis1.dot(axis2)) - std::abs(axis.dot(axis2))) < 0.01)
          p = about(j.parent, anchor, axis);
      }
    }
  }
  return std::isinf(p) ? c : p * c / (p + c);
}

std::vector<int> jointFrictionStateOffsets(const Model& model) {
  std::vector<int> offsets(model.joints.size(), -1);
  int next = 0;
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    const Joint& joint = model.joints[j];
    const auto& f = joint.elements.friction;
    if (!hasScalarCoordinate(joint.type) || !f) continue;
    if (const friction::DynamicFrictionLaw* law = f->law->dynamic()) {
      offsets[j] = next;
      next += law->stateSize();
    }
  }
  return offsets;
}

JointForces::JointForces(const Model& model) {
  const std::vector<int> offsets = jointFrictionStateOffsets(model);
  const std::vector<int> joint_of_child = jointOfChild(model);
  const IntegratorType integrator = model.options.integrator;
  const bool fixed_step =
      integrator == IntegratorType::kRk4 || integrator == IntegratorType::kSemiImplicitEuler;
  for (int j = 0; j < static_cast<int>(model.joints.size()); ++j) {
    const Joint& joint = model.joints[j];
    if (!hasScalarCoordinate(joint.type) || !joint.elements.hasForces()) continue;
    Entry e;
    e.joint = j;
    e.coordinate = jointCoordinate(joint);
    e.elements = &joint.elements;
    if (const auto& a = joint.elements.actuator)
      e.target = SignalMemo(a->target, a->kind == ActuatorKind::kPositionServo);
    if (fixed_step && model.options.time_step > 0.0)
      e.max_slope = kDissipativeSlopeShare * coordinateInertia(model, j, joint_of_child) /
                    model.options.time_step;
    const auto& f = joint.elements.friction;
    if (f && (e.dynamic = f->law->dynamic()) != nullptr) {
      e.state = offsets[static_cast<std::size_t>(j)];
      joint_state_size_ += e.dynamic->stateSize();
    }
    entries_.push_back(e);
    if (f && f->load == JointFrictionLoad::kReaction)
      reaction_.push_back(static_cast<int>(entries_.size()) - 1);
  }
  delta_.assign(model.bodies.size(), {});
}

void JointForces::addGeneralized(const Entry& e, double tau, std::vector<Wrench>& out) const {
  const BodyIndex p = e.coordinate.parent, c = e.coordinate.child;
  if (!p.isWorld()) {
    out[p.value].force += tau * e.value.j_parent.head<3>().transpose();
    out[p.value].torque += tau * e.value.j_parent.tail<3>().transpose();
  }
  out[c.value].force += tau * e.value.j_child.head<3>().transpose();
  out[c.value].torque += tau * e.value.j_child.tail<3>().transpose();
}

double limitCoordinate(const JointLimit& limit, double q, bool angular) {
  if (!angular) return q;
  const double middle = 0.5 * (limit.lower + limit.upper);
  return middle + wrapAngle(q - middle);
}

void JointForces::noteHeld(const Entry& e, double tau, double held, Workspace& ws) {
  const double change = std::abs(tau - held);
  if (change > ws.joint_held_change) {
    ws.joint_held_change = change;
    ws.joint_held = e.joint;
  }
}

double JointForces::frictionTorque(const Entry& e, double load, Workspace& ws) const {
  const JointFriction& f = *e.elements->friction;
  const double r = e.coordinate.angular ? f.radius : 1.0;
  const Vec3 slip(r * e.value.rate, 0.0, 0.0);
  if (e.dynamic != nullptr) {  // the rate does not depend on the load: written once
    e.dynamic->rate(e.z, slip, load, e.z_rate);
    return r * e.dynamic->force(e.z, e.z_rate, slip, load, nullptr).x();
  }
  // Damping and friction share one slope budget (core/joint_forces.hpp).
  const double budget = e.max_slope - std::min(e.elements->damping, e.max_slope);
  const double tau = r * friction::tangentialForce(*f.law, slip, load).x();
  const double held = capped(tau, e.value.rate, budget);
  if (held != tau) noteHeld(e, tau, held, ws);
  return held;
}

void JointForces::accumulate(const State& state, Workspace& ws) {
  ws.joint_held_change = 0.0;
  ws.joint_held = -1;
  if (entries_.empty()) return;  // ws.joint_wrench stays as Dynamics made it: zero
  for (auto& w : ws.joint_wrench) w.setZero();
  const MotionView motion(state, ws.rotation);
  for (Entry& e : entries_) {
    const BodyMotion p = motion(e.coordinate.parent);
    evaluateCoordinate(e.coordinate, p, motion(e.coordinate.child), e.value);
    e.axis = p.rotation * e.coordinate.z_parent;
    e.reaction_torque = 0.0;
    if (e.dynamic != nullptr) {
      e.z = &state.friction_values[static_cast<std::size_t>(e.state)];
      e.z_rate = &ws.friction_state_rate[static_cast<std::size_t>(e.state)];
      e.load = e.elements->friction->normal_force;
      std::fill(e.z_rate, e.z_rate + e.dynamic->stateSize(), 0.0);
    }
    const JointElements& el = *e.elements;
    const double q = e.value.q, rate = e.value.rate;
    const double damper = -el.damping * rate, held_damper = capped(damper, rate, e.max_slope);
    if (held_damper != damper) noteHeld(e, damper, held_damper, ws);
    double tau = el.effort + held_damper;
    if (el.spring) {
      const double stretch = q - el.spring->reference;
      tau -= el.spring->stiffness * (e.coordinate.angular ? wrapAngle(stretch) : stretch);
    }
    if (el.limit) {
      const JointLimit& l = *el.limit;
      const double ql = limitCoordinate(l, e.value.q, e.coordinate.angular);
      if (ql > l.upper) tau -= std::max(0.0, l.stiffness * (ql - l.upper) + l.damping * rate);
      if (ql < l.lower) tau += std::max(0.0, l.stiffness * (l.lower - ql) - l.damping * rate);
    }
    if (el.actuator) {
      // actuatorEffort with the signal sampled through the memo, or the command.
      const SignalMemo::Sample target =
          std::isnan(e.command) ? e.target.at(state.time) : SignalMemo::Sample{e.command, 0.0};
      const ActuatorOutput out = actuatorEffortFor(*el.actuator, target.value, target.derivative, q,
                                                   rate, e.coordinate.angular);
      ws.actuator_output[static_cast<std::size_t>(e.joint)] = out;
      tau += out.effort;
    }
    if (el.friction) {
      // Reaction-load friction is added after the solve (applyReactionFriction).
      const double friction = el.friction->load == JointFrictionLoad::kConstant
                                  ? frictionTorque(e, el.friction->normal_force, ws)
                                  : 0.0;
      ws.joint_friction[static_cast<std::size_t>(e.joint)] = friction;
      tau += friction;
    }
    addGeneralized(e, tau, ws.joint_wrench);
  }
}

bool JointForces::setActuatorCommand(int joint, double command) {
  for (Entry& e : entries_)
    if (e.joint == joint && e.elements->actuator) {
      e.command = command;
      return true;
    }
  return false;
}

int JointForces::applyReactionFriction(ConstraintSolver& solver, Workspace& ws) {
  ws.joint_friction_converged = true;
  if (reaction_.empty()) return 0;
  int iterations = 0;
  for (; iterations < kMaxFrictionIterations; ++iterations) {
    for (auto& w : delta_) w.setZero();
    double change = 0.0, largest = 0.0;
    for (int index : reaction_) {
      Entry& e = entries_[index];
      const Vec3 f = solver.reactionForce(e.joint);
      const double load = e.coordinate.angular ? f.norm() : (f - f.dot(e.axis) * e.axis).norm();
      e.load = load;
      const double tau = frictionTorque(e, load, ws);
      const double d = tau - e.reaction_torque;
      e.reaction_torque = tau;
      ws.joint_friction[static_cast<std::size_t>(e.joint)] = tau;
      change = std::max(change, std::abs(d));
      largest = std::max(largest, std::abs(tau));
      if (d != 0.0) {
        addGeneralized(e, d, delta_);
        addGeneralized(e, d, ws.joint_wrench);
      }
    }
    if (change == 0.0) break;
    solver.addForcesAndResolve(delta_, ws);
    if (change <= kFrictionTolerance * (1.0 + largest)) {
      ++iterations;
      return iterations;
    }
  }
  ws.joint_friction_converged = iterations < kMaxFrictionIterations;
  return iterations;
}

void JointForces::initialJointStates(double* z) const {
  for (const Entry& e : entries_)
    if (e.dynamic != nullptr) e.dynamic->initialState(z + e.state);
}

void JointForces::stepStates(State& state, double h) const {
  for (const Entry& e : entries_) {
    if (e.dynamic == nullptr) continue;
    const double r = e.coordinate.angular ? e.elements->friction->radius : 1.0;
    e.dynamic->stableStep(&state.friction_values[static_cast<std::size_t>(e.state)],
                          Vec3(r * e.value.rate, 0.0, 0.0), e.load, h);
  }
}

}  // namespace tribo
