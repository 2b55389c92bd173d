// Reads a URDF file through urdfdom into a UrdfRobot (io/urdf_robot.hpp), adding what
// urdfdom leaves out: the line of each element for messages, <gazebo> contact tags, and
// capsule collisions (urdfdom 3 drops every collision of a link after one it does not
// know). Collision mesh references are resolved with PackagePaths. The model checks run
// here too (io/urdf_checks.hpp) and land in UrdfRobot::issues.
// Errors that leave nothing to simulate (unreadable file, malformed XML, unknown joint
// type, missing link, no single root) throw UrdfError "FILE:LINE: what, expected what";
// everything else is an issue, so `tribo info` can show all findings at once.
#pragma once

#include <stdexcept>
#include <string>

#include "io/package_paths.hpp"
#include "io/urdf_robot.hpp"

namespace tribo::io {

class UrdfError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

UrdfRobot readUrdf(const std::string& path, const PackagePaths& packages = {});

// The same from XML text; `name_for_errors` stands for the file name in messages and in
// UrdfRobot::path, and relative mesh references resolve against its folder.
UrdfRobot readUrdfFromString(const std::string& xml, const std::string& name_for_errors,
                             const PackagePaths& packages = {});

}  // namespace tribo::io
