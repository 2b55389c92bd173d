// A robot as read from a URDF file, in Tribo's own types: links (mass, inertial frame,
// inertia, collision geometry, Gazebo contact parameters) and joints (type, frames, axis,
// limits, dynamics, mimic), plus the checks' findings. Produced by io/urdf_reader.hpp; turned
// into bodies and joints elsewhere. Visual geometry is not kept (it does not simulate).
// Conventions are URDF's: a joint's origin places the child link frame in the parent link
// frame at zero joint position; the axis is in that frame; inertia is about the centre of
// mass, in the inertial frame; lengths in m, masses in kg, angles in rad.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

namespace tribo::io {

struct UrdfCollision {
  enum class Kind { kBox, kSphere, kCylinder, kCapsule, kMesh } kind = Kind::kBox;
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();  // in the link frame
  Eigen::Vector3d size = Eigen::Vector3d::Zero();            // box: full edge lengths
  double radius = 0.0;                                       // sphere, cylinder, capsule
  double length = 0.0;                                       // cylinder, capsule (along z)
  std::string mesh_uri;                                      // as written
  std::string mesh_path;                                     // resolved file (empty if not a mesh)
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();           // mesh
};

// <gazebo reference="LINK"> contact parameters (ODE-style): friction coefficients mu1 and
// mu2, contact stiffness kp [N/m] and damping kd [N s/m]; unset when absent.
struct GazeboContact {
  std::optional<double> mu1, mu2, kp, kd;
};

struct UrdfLink {
  std::string name;
  int line = 0;  // of its <link> element, 0 if unknown
  bool has_inertial = false;
  double mass = 0.0;
  Eigen::Isometry3d inertial_origin = Eigen::Isometry3d::Identity();  // in the link frame
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // about the COM, inertial frame
  std::vector<UrdfCollision> collisions;
  GazeboContact contact;
};

struct UrdfJoint {
  std::string name;
  int line = 0;
  std::string type;  // fixed, revolute, continuous, prismatic, floating, planar
  std::string parent, child;
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();  // child frame in parent frame
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();           // in the joint frame, unit
  bool has_limits = false;
  double lower = 0.0, upper = 0.0, effort = 0.0, velocity = 0.0;
  double damping = 0.0, friction = 0.0;  // <dynamics>
  std::optional<std::string> mimic_joint;
  double mimic_multiplier = 1.0, mimic_offset = 0.0;
};

struct UrdfIssue {
  // note: something read leniently or repaired (said, not a problem); warning: dubious data
  // the model changes to simulate; error: refused.
  enum class Severity { kNote, kWarning, kError } severity = Severity::kWarning;
  std::string where;  // "link 'x'" or "joint 'y'"
  std::string message;
};

struct UrdfRobot {
  std::string name;
  std::string path;
  std::string root;               // root link name
  std::vector<UrdfLink> links;    // parents before children, root first
  std::vector<UrdfJoint> joints;  // in the order of their child links
  std::vector<UrdfIssue> issues;

  double totalMass() const;
  const UrdfLink* findLink(const std::string& name) const;
  const UrdfJoint* parentJoint(const std::string& link) const;
  bool hasErrors() const;
};

}  // namespace tribo::io
