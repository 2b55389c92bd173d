#include "io/urdf_model.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>

#include "contact/shape_inertia.hpp"
#include "core/number_text.hpp"
#include "friction/friction_law.hpp"
#include "io/mesh_loader.hpp"
#include "io/urdf_assembly.hpp"

namespace tribo::io {

namespace {

// Raises principal moments so the tensor is positive definite and obeys the triangle
// inequality; returns true if it changed anything.
bool regularizeInertia(double mass, Eigen::Matrix3d& inertia) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (inertia + inertia.transpose()));
  Eigen::Vector3d p = eig.eigenvalues();
  const double floor = mass * 1e-6;  // 1 mm radius of gyration
  const double largest = std::max(p.maxCoeff(), floor);
  const bool valid = p.minCoeff() > 0.0 && p(0) + p(1) >= p(2) * (1.0 - 1e-9);
  if (valid) return false;
  for (int i = 0; i < 3; ++i) p(i) = std::max({p(i), 0.5 * largest, floor});
  inertia = eig.eigenvectors() * p.asDiagonal() * eig.eigenvectors().transpose();
  return true;
}

contact::Shape shapeOf(const UrdfCollision& c, const std::string& link) {
  switch (c.kind) {
    case UrdfCollision::Kind::kBox:
      return contact::Shape::box(0.5 * c.size);
    case UrdfCollision::Kind::kSphere:
      return contact::Shape::sphere(c.radius);
    case UrdfCollision::Kind::kCylinder:
      return contact::Shape::cylinder(c.radius, 0.5 * c.length);
    case UrdfCollision::Kind::kCapsule:
      return contact::Shape::capsule(c.radius, 0.5 * c.length);
    case UrdfCollision::Kind::kMesh:
      if (c.mesh_path.empty())
        throw std::invalid_argument("link '" + link + "': collision mesh '" + c.mesh_uri +
                                    "' was not found");
      try {  // as the link's other geometry errors: naming the link
        return contact::Shape::triangleMesh(loadMesh(c.mesh_path, c.scale));
      } catch (const contact::MeshError& e) {
        throw std::invalid_argument("link '" + link + "': collision " + e.what());
      }
  }
  throw std::invalid_argument("link '" + link + "': unsupported collision geometry");
}

// The inertia (about the centre of mass, inertial frame) of a link that has a mass and no
// inertia: its collision solids sharing the mass by volume (a mesh that is not a closed solid
// by its bounding box), moved to the centre of mass with the parallel-axis theorem; without a
// solid, a sphere of that mass at the density of water. Sets `what` to say which.
Eigen::Matrix3d inertiaFromGeometry(const UrdfLink& l, std::string& what) {
  struct Part {
    contact::MassProperties unit;  // for unit mass
    Eigen::Isometry3d pose;        // geometry frame in the link frame
  };
  std::vector<Part> parts;
  double volume = 0.0;
  for (const UrdfCollision& c : l.collisions) {
    contact::Shape shape = shapeOf(c, l.name);
    if (shape.isPoint()) continue;
    contact::MassProperties unit;
    try {
      unit = contact::solidMassProperties(shape, 1.0);
    } catch (const std::invalid_argument&) {  // an open mesh: its bounding box
      Eigen::Vector3d lo, hi;
      for (int i = 0; i < 3; ++i) {
        hi(i) = shape.support(Eigen::Vector3d::Unit(i));
        lo(i) = -shape.support(-Eigen::Vector3d::Unit(i));
      }
      const contact::Shape box = contact::Shape::box(0.5 * (hi - lo));
      unit = contact::solidMassProperties(box, 1.0);
      unit.centroid = 0.5 * (hi + lo);
    }
    if (!(unit.volume > 0.0)) continue;
    volume += unit.volume;
    parts.push_back({unit, c.origin});
  }
  const Eigen::Vector3d com = l.inertial_origin.translation();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  if (parts.empty()) {
    const double radius = std::cbrt(3.0 * l.mass / (4.0 * M_PI * 1000.0));
    what = "a sphere of that mass at the density of water (radius " + numberText(radius) + " m)";
    return Eigen::Matrix3d::Identity() * (0.4 * l.mass * radius * radius);
  }
  for (const Part& p : parts) {
    const double m = l.mass * p.unit.volume / volume;
    const Eigen::Matrix3d r = p.pose.linear();
    const Eigen::Vector3d d = p.pose * p.unit.centroid - com;
    inertia += m * (r * p.unit.inertia * r.transpose()) +
               m * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  }
  what = "its collision geometry at that mass";
  const Eigen::Matrix3d in = l.inertial_origin.linear();
  return in.transpose() * inertia * in;
}

JointType jointTypeOf(const UrdfJoint& j) {
  if (j.type == "revolute" || j.type == "continuous") return JointType::kRevolute;
  if (j.type == "prismatic") return JointType::kPrismatic;
  if (j.type == "planar") return JointType::kPlanar;
  return JointType::kFree;
}

}  // namespace

UrdfModelResult addUrdfRobot(ModelBuilder& builder, const UrdfRobot& read,
                             const UrdfPlacement& placement) {
  if (read.hasErrors()) {
    for (const auto& i : read.issues)
      if (i.severity == UrdfIssue::Severity::kError)
        throw std::invalid_argument(read.path + ": " + i.where + ": " + i.message);
  }
  UrdfModelResult result;
  // A link with a mass and no inertia gets one from its geometry (never a silently tiny one).
  UrdfRobot robot = read;
  for (UrdfLink& l : robot.links) {
    if (!l.has_inertial || !(l.mass > 0.0) || !l.inertia.isZero(0.0)) continue;
    std::string what;
    l.inertia = inertiaFromGeometry(l, what);
    const Eigen::Vector3d p =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(l.inertia).eigenvalues();
    result.notes.push_back("link '" + l.name + "' has mass " + numberText(l.mass) +
                           " kg and no inertia: given the inertia of " + what +
                           " (principal moments " + numberText(p(0)) + ", " + numberText(p(1)) +
                           ", " + numberText(p(2)) + " kg m^2)");
  }
  // Joints whose range excludes 0 start at the nearest limit unless a position is given.
  std::map<std::string, double> positions = placement.joint_positions;
  for (const auto& j : robot.joints) {
    if (!j.has_limits || positions.count(j.name)) continue;
    if (j.type != "revolute" && j.type != "prismatic") continue;
    if (0.0 < j.lower || 0.0 > j.upper) {
      positions[j.name] = 0.0 < j.lower ? j.lower : j.upper;
      result.notes.push_back("joint '" + j.name + "' starts at " + numberText(positions[j.name]) +
                             ", the end of its range nearest 0");
    }
  }
  const UrdfAssembly a = assembleUrdf(robot, placement.base, positions);
  const std::string& pre = placement.prefix;

  double massive_total = 0.0;
  int massive_count = 0;
  for (const auto& g : a.groups)
    if (g.mass > 0.0) massive_total += g.mass, ++massive_count;
  const double stand_in_mass = massive_count ? 1e-3 * massive_total / massive_count : 1e-3;

  // Body frames (origin at the group's centre of mass, axes of its top link), parents first;
  // the root may be welded to the world.
  std::vector<bool> welded(a.groups.size(), false);
  std::vector<Eigen::Isometry3d> body_pose(a.groups.size(), Eigen::Isometry3d::Identity());
  std::vector<int> parent_group(a.groups.size(), -1);
  std::vector<Eigen::Isometry3d> joint_world(a.groups.size(), Eigen::Isometry3d::Identity());
  std::map<std::string, int> link_index;
  for (std::size_t li = 0; li < robot.links.size(); ++li)
    link_index.emplace(robot.links[li].name, static_cast<int>(li));
  for (std::size_t gi = 0; gi < a.groups.size(); ++gi) {
    const UrdfBodyGroup& g = a.groups[gi];
    const Eigen::Isometry3d& top = a.link_world[g.top_link];
    if (gi == 0)
      // A root link named "world" is the world frame itself (the Gazebo convention).
      welded[gi] = placement.base_mode == UrdfPlacement::Base::kFixed ||
                   (placement.base_mode == UrdfPlacement::Base::kAuto &&
                    (g.mass <= 0.0 || robot.links[g.top_link].name == "world"));
    if (!welded[gi]) {
      body_pose[gi].linear() = top.linear();
      body_pose[gi].translation() = top * g.com;
    }
    if (g.parent_joint >= 0) {
      const UrdfJoint& j = robot.joints[g.parent_joint];
      const int parent_link = link_index.at(j.parent);
      parent_group[gi] = a.group_of_link[parent_link];
      joint_world[gi] = a.link_world[parent_link] * j.origin;
    }
  }

  // Velocities from joint rates, parents first: w_c = w_p + a qdot (revolute), and
  // v_c = v_p + w_p x (p_j - x_p) + a qdot (prismatic) + w_c x (x_c - p_j).
  std::vector<Eigen::Vector3d> lin(a.groups.size(), Eigen::Vector3d::Zero());
  std::vector<Eigen::Vector3d> ang(a.groups.size(), Eigen::Vector3d::Zero());
  for (std::size_t gi = 1; gi < a.groups.size(); ++gi) {
    const UrdfJoint& j = robot.joints[a.groups[gi].parent_joint];
    const int pg = parent_group[gi];
    const Eigen::Vector3d axis_world = joint_world[gi].linear() * j.axis;
    const Eigen::Vector3d pj = joint_world[gi].translation();
    const auto rate = placement.joint_velocities.find(j.name);
    const double qdot = rate == placement.joint_velocities.end() ? 0.0 : rate->second;
    const bool turns = j.type == "revolute" || j.type == "continuous";
    ang[gi] = ang[pg] + (turns ? Eigen::Vector3d(axis_world * qdot) : Eigen::Vector3d::Zero());
    lin[gi] =
        lin[pg] + ang[pg].cross(pj - body_pose[pg].translation()) +
        (j.type == "prismatic" ? Eigen::Vector3d(axis_world * qdot) : Eigen::Vector3d::Zero()) +
        ang[gi].cross(body_pose[gi].translation() - pj);
  }
  std::set<std::string> movable;
  for (const auto& j : robot.joints)
    if (j.type != "fixed") movable.insert(j.name);
  for (const auto& [name, rate] : placement.joint_velocities) {
    if (!movable.count(name))
      throw std::invalid_argument("no movable joint named '" + name + "' in robot '" + robot.name +
                                  "' (joint velocity given)");
  }

  std::vector<BodyIndex> body_of_group(a.groups.size(), BodyIndex::world());
  for (std::size_t gi = 0; gi < a.groups.size(); ++gi) {
    const UrdfBodyGroup& g = a.groups[gi];
    if (welded[gi]) {
      result.notes.push_back("link '" + g.name + "' (root) is welded to the world" +
                             (g.mass <= 0.0       ? std::string(": it has no mass")
                              : g.name == "world" ? std::string(": it is named world")
                                                  : std::string()));
      continue;
    }
    Body b;
    b.name = pre + g.name;
    b.mass = g.mass;
    b.inertia = g.inertia;
    if (g.mass <= 0.0) {
      b.mass = stand_in_mass;
      b.inertia = Eigen::Matrix3d::Identity() * (0.4 * b.mass * 0.05 * 0.05);
      result.notes.push_back("link '" + g.name + "' has no mass but moves: given " +
                             numberText(b.mass) + " kg and a 5 cm sphere's inertia");
    } else if (regularizeInertia(b.mass, b.inertia)) {
      result.notes.push_back("link '" + g.name +
                             "': inertia raised to be positive definite and obey the triangle "
                             "inequality");
    }
    b.position = body_pose[gi].translation();
    b.orientation = Eigen::Quaterniond(body_pose[gi].linear());
    b.velocity = lin[gi];
    b.angular_velocity = ang[gi];
    body_of_group[gi] = builder.addBody(b);
  }

  // Joints: the URDF joint frame is the child link frame at zero position.
  std::map<std::string, int> joint_index;
  for (std::size_t gi = 1; gi < a.groups.size(); ++gi) {
    const UrdfBodyGroup& g = a.groups[gi];
    const UrdfJoint& j = robot.joints[g.parent_joint];
    if (body_of_group[gi].isWorld() || j.type == "floating") continue;  // free: no joint
    const int pg = parent_group[gi];
    const Eigen::Isometry3d in_parent = body_pose[pg].inverse() * joint_world[gi];
    const Eigen::Isometry3d in_child = body_pose[gi].inverse() * a.link_world[g.top_link];
    const int index = builder.addJointInFrames(pre + j.name, jointTypeOf(j), body_of_group[pg],
                                               body_of_group[gi], in_parent, in_child, j.axis);
    joint_index[j.name] = index;
    const bool scalar = j.type == "revolute" || j.type == "prismatic" || j.type == "continuous";
    if (!scalar) continue;
    if (j.type != "continuous" && j.has_limits && j.upper >= j.lower)
      builder.setJointLimit(index, JointLimit{j.lower, j.upper, 0.0, 0.0});
    if (j.has_limits) {
      // <limit effort velocity>: the defaults of an actuator's saturation (a value of 0, which
      // some files write for "not given", or one that is not finite rates nothing).
      auto rated = [](double v) {
        return std::isfinite(v) && v > 0.0 ? v : std::numeric_limits<double>::infinity();
      };
      builder.setJointRating(index, rated(j.effort), rated(j.velocity));
    }
    if (j.damping > 0.0) builder.setJointDamping(index, j.damping);
    if (j.friction > 0.0) {
      JointFriction f;
      f.law = friction::makeFrictionLaw(
          {"coulomb", {{"mu", 1.0}, {"v_eps", 1e-3}}, {{"regularization", "tanh"}}});
      f.load = JointFrictionLoad::kConstant;
      f.normal_force = j.friction;
      f.radius = 1.0;
      builder.setJointFriction(index, f);
    }
  }
  for (const auto& j : robot.joints) {
    if (!j.mimic_joint) continue;
    const auto leader = joint_index.find(*j.mimic_joint);
    const auto follower = joint_index.find(j.name);
    if (leader == joint_index.end() || follower == joint_index.end()) {
      result.notes.push_back("joint '" + j.name + "' mimics '" + *j.mimic_joint +
                             "', which is not a simulated joint: mimic ignored");
      continue;
    }
    builder.addJointCoupling(pre + j.name + "_mimic", leader->second, follower->second,
                             j.mimic_multiplier, j.mimic_offset);
  }

  // Collision geometry, with the link's surface (Gazebo tags give it its own material).
  result.lowest_point = std::numeric_limits<double>::infinity();
  for (std::size_t li = 0; li < robot.links.size(); ++li) {
    const UrdfLink& l = robot.links[li];
    const int gi = a.group_of_link[li];
    int k = 0;
    for (const UrdfCollision& c : l.collisions) {
      const contact::Shape shape = shapeOf(c, l.name);
      const Eigen::Isometry3d world = a.link_world[li] * c.origin;
      const std::string name = pre + l.name + (k ? "_collision" + std::to_string(k) : "_collision");
      ++k;
      const int geo =
          builder.addGeometry(name, body_of_group[gi], shape, body_pose[gi].inverse() * world);
      builder.setGeometrySurface(geo, pre + l.name);
      // No self-collision (as in Gazebo and PyBullet by default): the robot's geometries
      // share one group bit and leave it out of their mask.
      builder.setCollisionFilter(geo, placement.collision_group, ~placement.collision_group);
      if (result.surfaces.empty() || result.surfaces.back().name != pre + l.name) {
        const BodyIndex body = body_of_group[gi];
        result.surfaces.push_back(
            {pre + l.name, body.isWorld() ? 0.0 : builder.bodies()[body.value].mass, l.contact});
      }
      result.geometries.push_back(geo);
      result.lowest_point =
          std::min(result.lowest_point,
                   world.translation().z() -
                       shape.support(-(world.linear().transpose() * Eigen::Vector3d::UnitZ())));
    }
  }
  if (!std::isfinite(result.lowest_point)) result.lowest_point = placement.base.translation().z();
  return result;
}

std::shared_ptr<const friction::FrictionLaw> urdfCoulomb(double mu) {
  return friction::makeFrictionLaw(
      {"coulomb", {{"mu", mu}, {"v_eps", 1e-2}}, {{"regularization", "tanh"}}});
}

contact::Material withGazeboTags(contact::Material base, const GazeboContact& tags,
                                 double body_mass, bool critical_without_kd) {
  if (tags.mu1) base.friction = urdfCoulomb(*tags.mu1);
  if (tags.kp || tags.kd) {
    const double k = tags.kp.value_or(base.normal.stiffness);
    const double c = tags.kd                          ? *tags.kd
                     : tags.kp && critical_without_kd ? 2.0 * std::sqrt(k * body_mass / 4.0)
                                                      : base.normal.damping;
    base.normal = contact::NormalLaw{};
    base.normal.type = contact::NormalLawType::kLinear;
    base.normal.stiffness = k;
    base.normal.damping = c;
    base.normal.validate();
  }
  return base;
}

}  // namespace tribo::io
