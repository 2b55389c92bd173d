#include "io/urdf_assembly.hpp"

#include <stdexcept>

namespace tribo::io {

namespace {

Eigen::Isometry3d jointMotion(const UrdfJoint& j, double q) {
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  if (j.type == "revolute" || j.type == "continuous")
    m.linear() = Eigen::AngleAxisd(q, j.axis).toRotationMatrix();
  else if (j.type == "prismatic")
    m.translation() = q * j.axis;
  return m;
}

}  // namespace

UrdfAssembly assembleUrdf(const UrdfRobot& robot, const Eigen::Isometry3d& base,
                          const std::map<std::string, double>& positions) {
  // Joints by name and by child link: every look-up below is a map's, so assembling is
  // O(n log n) in the links, whatever the shape of the tree.
  std::map<std::string, int> joint_by_name, joint_by_child;
  for (std::size_t k = 0; k < robot.joints.size(); ++k) {
    joint_by_name.emplace(robot.joints[k].name, static_cast<int>(k));
    joint_by_child[robot.joints[k].child] = static_cast<int>(k);  // the last, as before
  }
  for (const auto& [name, q] : positions) {
    const auto named = joint_by_name.find(name);
    const UrdfJoint* j = named == joint_by_name.end() ? nullptr : &robot.joints[named->second];
    if (!j)
      throw std::invalid_argument("no joint named '" + name + "' in robot '" + robot.name + "'");
    if (j->type == "fixed")
      throw std::invalid_argument("joint '" + name + "' is fixed: it has no position to set");
    if (j->type == "floating" || j->type == "planar")
      throw std::invalid_argument("joint '" + name + "' is " + j->type +
                                  ": set its pose through the body, not a single position");
  }
  std::map<std::string, int> link_index;
  for (std::size_t i = 0; i < robot.links.size(); ++i)
    link_index[robot.links[i].name] = static_cast<int>(i);

  UrdfAssembly a;
  const std::size_t n = robot.links.size();
  a.link_world.assign(n, Eigen::Isometry3d::Identity());
  a.group_of_link.assign(n, -1);
  // Links are stored parents first, so one pass places every link and group.
  for (std::size_t i = 0; i < n; ++i) {
    const UrdfLink& link = robot.links[i];
    const auto above = joint_by_child.find(link.name);
    const int joint_index = above == joint_by_child.end() ? -1 : above->second;
    const UrdfJoint* joint = joint_index < 0 ? nullptr : &robot.joints[joint_index];
    if (!joint) {
      a.link_world[i] = base;
    } else {
      const int parent = link_index.at(joint->parent);
      const auto it = positions.find(joint->name);
      a.link_world[i] = a.link_world[parent] * joint->origin *
                        jointMotion(*joint, it == positions.end() ? 0.0 : it->second);
      if (joint->type == "fixed") {
        a.group_of_link[i] = a.group_of_link[parent];
        a.groups[a.group_of_link[i]].links.push_back(static_cast<int>(i));
        continue;
      }
    }
    UrdfBodyGroup g;
    g.name = link.name;
    g.top_link = static_cast<int>(i);
    g.links = {static_cast<int>(i)};
    g.parent_joint = joint_index;
    a.group_of_link[i] = static_cast<int>(a.groups.size());
    a.groups.push_back(g);
  }
  // Lumped inertial properties, in the top link frame.
  for (UrdfBodyGroup& g : a.groups) {
    const Eigen::Isometry3d top_inv = a.link_world[g.top_link].inverse();
    Eigen::Vector3d moment = Eigen::Vector3d::Zero();
    for (int li : g.links) {
      const UrdfLink& l = robot.links[li];
      if (!l.has_inertial || !(l.mass > 0.0)) continue;
      const Eigen::Isometry3d frame = top_inv * a.link_world[li] * l.inertial_origin;
      g.mass += l.mass;
      moment += l.mass * frame.translation();
    }
    if (g.mass <= 0.0) continue;
    g.com = moment / g.mass;
    for (int li : g.links) {
      const UrdfLink& l = robot.links[li];
      if (!l.has_inertial || !(l.mass > 0.0)) continue;
      const Eigen::Isometry3d frame = top_inv * a.link_world[li] * l.inertial_origin;
      const Eigen::Matrix3d r = frame.linear();
      const Eigen::Vector3d d = frame.translation() - g.com;
      g.inertia += r * l.inertia * r.transpose() +
                   l.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
    }
  }
  return a;
}

}  // namespace tribo::io
