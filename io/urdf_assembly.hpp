// Turns a URDF robot's link tree into rigid bodies at a given configuration: forward
// kinematics from joint positions, and lumping of links joined by fixed joints into one
// body (masses added, centre of mass averaged, inertias moved to the common centre with the
// parallel-axis theorem: I = sum_i R_i I_i R_i^T + m_i (|d_i|^2 1 - d_i d_i^T)).
//   revolute/continuous: T_child = T_parent * origin * Rot(axis, q)
//   prismatic:           T_child = T_parent * origin * Trans(axis q)
//   fixed, floating, planar at q = 0: T_child = T_parent * origin
// Not here: making model bodies and joints (io/urdf_model.hpp), collision shapes.
#pragma once

#include <Eigen/Geometry>
#include <map>
#include <string>
#include <vector>

#include "io/urdf_robot.hpp"

namespace tribo::io {

// Links rigidly joined (through fixed joints) form one body, named after its top link.
struct UrdfBodyGroup {
  std::string name;        // the top link's name
  int top_link = -1;       // index into UrdfRobot::links
  std::vector<int> links;  // every link of the group, top first
  int parent_joint = -1;   // the movable joint above the group (index into joints), -1 at the root
  double mass = 0.0;       // [kg]
  Eigen::Vector3d com = Eigen::Vector3d::Zero();      // in the top link frame [m]
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // about the com, top link axes
};

struct UrdfAssembly {
  std::vector<Eigen::Isometry3d> link_world;  // per link: its frame in the world
  std::vector<int> group_of_link;             // per link: index into groups
  std::vector<UrdfBodyGroup> groups;          // root group first, parents before children
};

// `base` places the root link frame in the world; `positions` gives joint positions by
// joint name [rad or m] (others 0). Throws std::invalid_argument for a position of an
// unknown or fixed joint.
UrdfAssembly assembleUrdf(const UrdfRobot& robot, const Eigen::Isometry3d& base,
                          const std::map<std::string, double>& positions = {});

}  // namespace tribo::io
