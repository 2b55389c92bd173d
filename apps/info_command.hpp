// `tribo info FILE.urdf [--package-path DIR ...]`: prints a URDF robot's link tree with
// joint types and masses, the total mass, joint counts by type, and the model checks.
// Exit status 0 when the robot can be simulated, 2 when the file or a check is an error.
#pragma once

#include <string>
#include <vector>

namespace tribo::app {

int runInfo(const std::vector<std::string>& args);

}  // namespace tribo::app
