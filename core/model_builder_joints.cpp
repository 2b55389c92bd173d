// ModelBuilder: joints, what acts on their coordinates, couplings, and the joint checks of
// build() (derived limit gains, redundant constraints). See core/model_builder.hpp.
#include <cmath>
#include <sstream>
#include <utility>

#include "core/constraint_rank.hpp"
#include "core/constraint_rows.hpp"
#include "core/joint_forces.hpp"
#include "core/model_builder.hpp"
#include "core/number_text.hpp"

namespace tribo {

namespace {

// Orthonormal frame whose third column is `axis` and whose first is `reference` made normal
// to it (any normal when reference is zero).
Mat3 jointFrame(const Vec3& axis, const Vec3& reference) {
  const Vec3 z = axis.normalized();
  Vec3 helper = reference;
  if (helper.norm() < 1e-12) helper = std::abs(z.x()) > 0.9 ? Vec3::UnitY() : Vec3::UnitX();
  const Vec3 x = (helper - helper.dot(z) * z).normalized();
  Mat3 r;
  r.col(0) = x;
  r.col(1) = z.cross(x);
  r.col(2) = z;
  return r;
}

std::string jointWho(const std::string& name) { return "joint '" + name + "'"; }

}  // namespace

int ModelBuilder::pushJoint(Joint joint) {
  const std::string who = jointWho(joint.name);
  if (joint.name.empty()) throw ModelError("joint name must be non-empty");
  if (findJoint(joint.name)) throw ModelError(who + ": a joint of that name already exists");
  const Body c = checkedBody(joint.child, who + " child");
  checkedBody(joint.parent, who + " parent");
  if (joint.child.isWorld() || c.kind != BodyKind::kDynamic)
    throw ModelError(who + ": the child must be a dynamic body");
  if (joint.parent == joint.child) throw ModelError(who + ": parent and child are the same body");
  joint_index_.emplace(joint.name, static_cast<int>(model_.joints.size()));
  model_.joints.push_back(std::move(joint));
  return static_cast<int>(model_.joints.size()) - 1;
}

int ModelBuilder::addJoint(const std::string& name, JointType type, BodyIndex parent,
                           BodyIndex child, const Vec3& anchor_world, const Vec3& axis_world) {
  return addJoint(name, type, parent, child, anchor_world, axis_world, Vec3::Zero());
}

int ModelBuilder::addJoint(const std::string& name, JointType type, BodyIndex parent,
                           BodyIndex child, const Vec3& anchor_world, const Vec3& axis_world,
                           const Vec3& reference_world) {
  const std::string who = jointWho(name);
  const Body p = checkedBody(parent, who + " parent");
  const Body c = checkedBody(child, who + " child");
  if (!anchor_world.allFinite() || !axis_world.allFinite() || axis_world.norm() < 1e-12)
    throw ModelError(who + ": anchor must be finite and axis non-zero");
  if (!reference_world.allFinite()) throw ModelError(who + ": second axis (axis2) must be finite");
  const double ref = reference_world.norm();
  if (type == JointType::kUniversal) {
    if (ref < 1e-12)
      throw ModelError(who + ": a universal joint needs its second axis (axis2), normal to axis");
    const double cosine = std::abs(axis_world.normalized().dot(reference_world / ref));
    if (cosine > 1e-9)
      throw ModelError(who + ": axis2 must be normal to axis (cosine of the angle between them " +
                       numberText(cosine) + ")");
  } else if (ref > 0.0 && axis_world.normalized().cross(reference_world / ref).norm() < 1e-6) {
    throw ModelError(who + ": axis2 (the zero-angle reference) must not be parallel to axis");
  }
  const Mat3 axes_world = jointFrame(axis_world, reference_world);
  Joint j;
  j.name = name;
  j.type = type;
  j.parent = parent;
  j.child = child;
  const Mat3 rp = p.orientation.toRotationMatrix();
  const Mat3 rc = c.orientation.toRotationMatrix();
  j.anchor_in_parent = rp.transpose() * (anchor_world - p.position);
  j.axes_in_parent = rp.transpose() * axes_world;
  j.anchor_in_child = rc.transpose() * (anchor_world - c.position);
  j.axes_in_child = rc.transpose() * axes_world;
  return pushJoint(std::move(j));
}

int ModelBuilder::addJointInFrames(const std::string& name, JointType type, BodyIndex parent,
                                   BodyIndex child, const Eigen::Isometry3d& joint_in_parent,
                                   const Eigen::Isometry3d& joint_in_child,
                                   const Vec3& axis_in_joint) {
  const std::string who = jointWho(name);
  if (!joint_in_parent.matrix().allFinite() || !joint_in_child.matrix().allFinite())
    throw ModelError(who + ": joint frames must be finite");
  if (!axis_in_joint.allFinite() || axis_in_joint.norm() < 1e-12)
    throw ModelError(who + ": axis must be finite and non-zero");
  for (const auto* frame : {&joint_in_parent, &joint_in_child})
    if ((frame->linear().transpose() * frame->linear() - Mat3::Identity()).norm() > 1e-9)
      throw ModelError(who + ": joint frame rotations must be orthonormal");
  const Mat3 axes = jointFrame(axis_in_joint, Vec3::Zero());
  Joint j;
  j.name = name;
  j.type = type;
  j.parent = parent;
  j.child = child;
  j.anchor_in_parent = joint_in_parent.translation();
  j.axes_in_parent = joint_in_parent.linear() * axes;
  j.anchor_in_child = joint_in_child.translation();
  j.axes_in_child = joint_in_child.linear() * axes;
  return pushJoint(std::move(j));
}

Joint& ModelBuilder::checkedJoint(int joint, const std::string& what, bool scalar_coordinate) {
  if (joint < 0 || joint >= static_cast<int>(model_.joints.size()))
    throw ModelError(what + ": joint index " + std::to_string(joint) + " out of range");
  Joint& j = model_.joints[joint];
  if (scalar_coordinate && !hasScalarCoordinate(j.type))
    throw ModelError(jointWho(j.name) + ": " + what +
                     " needs a revolute or prismatic joint (this one is " + jointTypeName(j.type) +
                     ")");
  return j;
}

void ModelBuilder::setJointLimit(int joint, const JointLimit& limit) {
  Joint& j = checkedJoint(joint, "a limit", true);
  const std::string who = jointWho(j.name) + " limit";
  if (!std::isfinite(limit.lower) || !std::isfinite(limit.upper) || limit.lower > limit.upper)
    throw ModelError(who + ": expected finite lower <= upper (got " + numberText(limit.lower) +
                     ", " + numberText(limit.upper) + ")");
  if (!std::isfinite(limit.stiffness) || limit.stiffness < 0.0 || !std::isfinite(limit.damping) ||
      limit.damping < 0.0)
    throw ModelError(who + ": stiffness and damping must be >= 0");
  j.elements.limit = limit;
}

void ModelBuilder::setJointSpring(int joint, const JointSpring& spring) {
  Joint& j = checkedJoint(joint, "a spring", true);
  if (!std::isfinite(spring.stiffness) || spring.stiffness < 0.0 ||
      !std::isfinite(spring.reference))
    throw ModelError(jointWho(j.name) + " spring: stiffness must be >= 0 (got " +
                     numberText(spring.stiffness) + ") and the reference finite");
  j.elements.spring = spring;
}

void ModelBuilder::setJointDamping(int joint, double damping) {
  Joint& j = checkedJoint(joint, "damping", true);
  if (!std::isfinite(damping) || damping < 0.0)
    throw ModelError(jointWho(j.name) + ": damping must be >= 0 (got " + numberText(damping) + ")");
  j.elements.damping = damping;
}

void ModelBuilder::setJointEffort(int joint, double effort) {
  Joint& j = checkedJoint(joint, "an effort", true);
  if (!std::isfinite(effort))
    throw ModelError(jointWho(j.name) + ": effort must be finite (got " + numberText(effort) + ")");
  j.elements.effort = effort;
}

void ModelBuilder::setJointFriction(int joint, const JointFriction& friction) {
  Joint& j = checkedJoint(joint, "friction", true);
  const std::string who = jointWho(j.name) + " friction";
  if (!friction.law) throw ModelError(who + ": no friction law");
  if (friction.law->stateful())
    throw ModelError(who + ": law " + std::string(friction.law->name()) +
                     " keeps contact anchors; joint friction takes memoryless laws and laws "
                     "with internal state (" +
                     [] {
                       std::string names;
                       for (const auto& n : friction::knownDynamicFrictionLaws())
                         names += (names.empty() ? "" : ", ") + n;
                       return names;
                     }() +
                     ")");
  if (!std::isfinite(friction.radius) || friction.radius <= 0.0)
    throw ModelError(who + ": radius must be > 0 (got " + numberText(friction.radius) + ")");
  if (friction.load == JointFrictionLoad::kConstant &&
      (!std::isfinite(friction.normal_force) || friction.normal_force < 0.0))
    throw ModelError(who + ": normal_force must be >= 0 (got " + numberText(friction.normal_force) +
                     ")");
  j.elements.friction = friction;
}

void ModelBuilder::setJointDrive(int joint, const JointDrive& drive) {
  Joint& j = checkedJoint(joint, "a drive", true);
  const DriveFunction& f = drive.function;
  if (!std::isfinite(f.constant) || !std::isfinite(f.slope) || !std::isfinite(f.amplitude) ||
      !std::isfinite(f.frequency) || !std::isfinite(f.phase))
    throw ModelError(jointWho(j.name) + " drive: its function's values must be finite");
  if (j.elements.actuator)
    throw ModelError(jointWho(j.name) + " drive: the joint has actuator '" +
                     j.elements.actuator->name +
                     "' (a drive prescribes the motion; the actuator's effort would do nothing)");
  j.elements.drive = drive;
}

void ModelBuilder::setJointRating(int joint, double effort, double velocity) {
  Joint& j = checkedJoint(joint, "a rating", true);
  auto check = [&](double v, const char* what) {
    if (std::isnan(v) || v <= 0.0)
      throw ModelError(jointWho(j.name) + ": rated " + what + " must be > 0 (got " + numberText(v) +
                       ")");
  };
  check(effort, "effort");
  check(velocity, "velocity");
  j.elements.rated_effort = effort;
  j.elements.rated_velocity = velocity;
}

void ModelBuilder::setJointActuator(int joint, JointActuator actuator) {
  Joint& j = checkedJoint(joint, "an actuator", true);
  const std::string who = "actuator '" + actuator.name + "' on " + jointWho(j.name);
  if (actuator.name.empty()) throw ModelError("actuator on " + jointWho(j.name) + ": empty name");
  for (const Joint& other : model_.joints)
    if (other.elements.actuator && other.elements.actuator->name == actuator.name)
      throw ModelError(who + ": an actuator of that name is on joint '" + other.name + "'");
  if (j.elements.actuator)
    throw ModelError(who + ": the joint already has actuator '" + j.elements.actuator->name + "'");
  if (j.elements.drive)
    throw ModelError(who +
                     ": the joint has a drive (its motion is prescribed; the actuator's "
                     "effort would do nothing)");
  auto gain = [&](double v, const char* what) {
    if (!std::isfinite(v) || v < 0.0)
      throw ModelError(who + ": " + what + " must be finite and >= 0 (got " + numberText(v) + ")");
  };
  gain(actuator.kp, "kp");
  gain(actuator.kd, "kd");
  switch (actuator.kind) {
    case ActuatorKind::kMotor:
      if (actuator.kp != 0.0 || actuator.kd != 0.0)
        throw ModelError(who + ": a motor takes no gains (its effort is the signal)");
      break;
    case ActuatorKind::kPositionServo:
      if (actuator.kp == 0.0 && actuator.kd == 0.0)
        throw ModelError(who + ": a position servo needs kp > 0 or kd > 0");
      break;
    case ActuatorKind::kVelocityServo:
      if (actuator.kp != 0.0)
        throw ModelError(who + ": a velocity servo takes kd only (tau = kd (target - rate))");
      if (actuator.kd == 0.0) throw ModelError(who + ": a velocity servo needs kd > 0");
      break;
  }
  auto limit = [&](double& v, double rated, const char* what) {
    if (std::isnan(v) || v <= 0.0)
      throw ModelError(who + ": " + what + " must be > 0 (got " + numberText(v) + ")");
    if (std::isinf(v)) v = rated;
  };
  limit(actuator.max_effort, j.elements.rated_effort, "effort limit");
  limit(actuator.max_velocity, j.elements.rated_velocity, "velocity limit");
  j.elements.actuator = std::move(actuator);
}

int ModelBuilder::addJointCoupling(const std::string& name, int leader, int follower,
                                   double multiplier, double offset) {
  const std::string who = "coupling '" + name + "'";
  const Joint& l = checkedJoint(leader, who + " leader", true);
  const Joint& f = checkedJoint(follower, who + " follower", true);
  if (leader == follower) throw ModelError(who + ": leader and follower are the same joint");
  if (!std::isfinite(multiplier) || !std::isfinite(offset))
    throw ModelError(who + ": multiplier and offset must be finite");
  for (const JointCoupling& c : model_.couplings)
    if (c.follower == follower)
      throw ModelError(who + ": joint '" + f.name + "' already follows joint '" +
                       model_.joints[c.leader].name + "'");
  (void)l;
  model_.couplings.push_back({name, leader, follower, multiplier, offset});
  return static_cast<int>(model_.couplings.size()) - 1;
}

std::optional<int> ModelBuilder::findJoint(const std::string& name) const {
  if (const auto it = joint_index_.find(name); it != joint_index_.end()) return it->second;
  return std::nullopt;
}

void ModelBuilder::finishJoints(Model& model) const {
  // Limit gains left at 0: a critically damped stop whose frequency is 0.5 / time_step on
  // the coordinate's inertia as the stability estimate takes it (core/joint_forces.hpp: the
  // child about or along the axis, reduced with a free parent's), so the explicit integrators
  // stay well inside their limits (rk4 at about 5.6 steps, semi-implicit Euler at about 1.7).
  // Outboard bodies only lower the frequency.
  const double omega = 0.5 / model.options.time_step;
  const std::vector<int> joint_of_child = jointOfChild(model);
  for (std::size_t ji = 0; ji < model.joints.size(); ++ji) {
    Joint& j = model.joints[ji];
    if (!j.elements.limit || j.elements.limit->stiffness > 0.0) continue;
    double inertia = coordinateInertia(model, static_cast<int>(ji), joint_of_child);
    if (!(inertia > 0.0) || !std::isfinite(inertia)) {  // no dynamic body on either side
      const Body& c = model.bodies[j.child.value];
      inertia = c.mass;
      if (isAngular(j.type)) {
        const Mat3 r = c.orientation.toRotationMatrix();
        const Vec3 axis = r * j.axes_in_child.col(2);
        const Vec3 arm = -(r * j.anchor_in_child);  // centre of mass from the anchor
        inertia = axis.dot(r * c.inertia * r.transpose() * axis) +
                  c.mass * (arm - arm.dot(axis) * axis).squaredNorm();
      }
    }
    JointLimit& l = *j.elements.limit;
    l.stiffness = inertia * omega * omega;
    if (l.damping == 0.0) l.damping = 2.0 * inertia * omega;
  }

  if (!needsRankCheck(model)) return;
  const std::vector<ConstraintRow> rows = constraintRows(model, true);
  const std::vector<int> redundant = findRedundantRows(model, rows);
  if (redundant.empty()) return;
  std::ostringstream list;
  int listed = 0;
  for (int r : redundant) {
    const ConstraintRow& row = rows[r];
    const Joint& j = model.joints[row.joint];
    if (row.equation == ConstraintRow::kDriveEquation)
      throw ModelError(jointWho(j.name) +
                       ": its drive prescribes a motion the other constraints already fix");
    if (row.equation == ConstraintRow::kCouplingEquation)
      throw ModelError("coupling '" + model.couplings[row.coupling].name +
                       "': it prescribes a motion the other constraints already fix");
    if (listed < 6)
      list << (listed ? "; " : "") << jointWho(j.name) << " "
           << equationName(jointEquations(j.type)[row.equation]);
    ++listed;
  }
  if (listed > 6) list << "; and " << listed - 6 << " more";
  if (model.options.constraints.redundant == RedundancyPolicy::kError)
    throw ModelError(
        "redundant constraints at the initial configuration (" + std::to_string(listed) +
        " equations depend on the ones before them, as in a planar loop of revolute joints): " +
        list.str() +
        ". Use joints with fewer equations (spherical, universal, cylindrical, planar) or set "
        "simulation.constraints.redundant: remove to drop them");
  for (int r : redundant) model.joints[rows[r].joint].dropped_equations |= 1u << rows[r].equation;
}

}  // namespace tribo
