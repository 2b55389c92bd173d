// A runnable scene from a URDF file alone, for `tribo run ROBOT.urdf`: the robot dropped on
// a ground plane under gravity. Its settings are parameters that --set overrides:
//   duration 1 [s], dt 1e-3 [s], integrator rk4, drop 0.05 [m] (gap between the lowest
//   collision point and the ground at t = 0), mu 0.8 (coulomb, tanh with v_eps 1e-3),
//   stiffness [N/m per contact point] (default: the robot's weight on 8 points at 1 mm
//   depth), damping [N s/m per point] (default: critical for that mass on 8 points),
//   base auto|fixed|floating (auto: a massless root is welded to the world).
// Links with <gazebo> mu1/kp/kd get those as their ground contact (kd as damping).
// Not here: scene files with several robots (io/scene_loader.hpp).
#pragma once

#include <string>
#include <vector>

#include "io/scene_loader.hpp"

namespace tribo::io {

// Throws SceneError (unknown --set name, bad value) or UrdfError.
Scene sceneFromUrdf(const std::string& path, const std::vector<std::string>& package_paths,
                    const std::vector<std::string>& overrides);

}  // namespace tribo::io
