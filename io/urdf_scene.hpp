// A runnable scene from a URDF file alone, for `tribo run ROBOT.urdf`: the robot dropped on
// a ground plane under gravity. Its settings are parameters that --set overrides, chosen
// for the robot when `auto`:
//   duration 1 [s]; drop 0.05 [m] (gap between the lowest collision point and the ground at
//   t = 0); mu 0.8 (coulomb, tanh with v_eps 1e-2); base auto|fixed|floating (auto: a
//   massless root is welded to the world);
//   stiffness [N/m per contact point], auto: k = W / (n d), W the weight of every moving
//   body (massless links' stand-in masses included), n the contact points within d of the
//   lowest at the initial pose (reported as support_points), d = penetration (1e-3 m): the
//   robot resting as it starts sinks d;
//   damping [N s/m per point], auto: critical for each link's body on 4 points;
//   dt [s], auto: half the a-priori stable step (core/stability.hpp: contacts, springs,
//   joint springs, limits, dampers and friction on the coordinate's inertia), at most 1 ms;
//   integrator auto: rk4, or bdf when the step rk4 needs is below min_dt (1e-5 s), said in a
//   note naming the element; with an integrator given, a step below min_dt runs at min_dt,
//   with the same note.
// Links with <gazebo> mu1/kp/kd get those as their ground contact (kd as damping). The notes
// carry the reader's notes and warnings (io/urdf_reader.hpp) and the model's
// (io/urdf_model.hpp), so `tribo info` and `tribo run` say the same.
// Not here: scene files with several robots (io/scene_loader.hpp).
#pragma once

#include <string>
#include <vector>

#include "io/scene_loader.hpp"
#include "io/urdf_reader.hpp"

namespace tribo::io {

// The names --set may give a URDF run (the settings above), sorted.
const std::vector<std::string>& urdfSceneSettings();

// `run.threads` replaces the run's threads of one force evaluation (default 1); the other run
// settings of a URDF run are the --set names above, and giving them in `run` is a SceneError.
// Throws SceneError (unknown --set name, bad value) or UrdfError.
Scene sceneFromUrdf(const std::string& path, const std::vector<std::string>& package_paths,
                    const std::vector<std::string>& overrides, const UrdfReadOptions& read = {},
                    const RunSettings& run = {});

}  // namespace tribo::io
