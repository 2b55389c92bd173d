// Reads a URDF file through urdfdom into a UrdfRobot (io/urdf_robot.hpp), adding what
// urdfdom leaves out: the line of each element for messages, <gazebo> contact tags, and
// capsule collisions (urdfdom 3 drops every collision of a link after one it does not
// know). Collision mesh references are resolved with PackagePaths. The model checks run
// here too (io/urdf_checks.hpp) and land in UrdfRobot::issues.
// Errors that leave nothing to simulate (unreadable or empty file, not XML, malformed XML,
// unknown joint type, missing link, no single root) throw UrdfError "FILE:LINE: what,
// expected what"; everything else is an issue, so `tribo info` can show all findings at once.
// Lenient by default, as Drake, Gazebo and PyBullet are where urdfdom refuses: a revolute or
// prismatic joint without <limit> loads as unlimited, and a parent link named `world` that is
// not declared is the world frame (each said in a note). UrdfReadOptions::strict keeps
// urdfdom's refusal. A collision <sphere radius="0"> is kept: a contact point.
// Not here: turning the robot into bodies (io/urdf_model.hpp).
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

struct UrdfReadOptions {
  bool strict = false;  // refuse what urdfdom refuses (no lenient repairs)
};

UrdfRobot readUrdf(const std::string& path, const PackagePaths& packages = {},
                   const UrdfReadOptions& options = {});

// True when the file's first element is <robot> (after an XML declaration, comments and a
// byte-order mark), whatever its name ends with: how `tribo run` tells a URDF from a scene.
bool looksLikeUrdf(const std::string& path);

// The same from XML text; `name_for_errors` stands for the file name in messages and in
// UrdfRobot::path, and relative mesh references resolve against its folder.
UrdfRobot readUrdfFromString(const std::string& xml, const std::string& name_for_errors,
                             const PackagePaths& packages = {},
                             const UrdfReadOptions& options = {});

}  // namespace tribo::io
