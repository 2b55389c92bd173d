// The keys of a scene file, one table per section, and the option words the loader accepts
// where a word is expected: the one list the scene reader (io/scene_reader.hpp) checks each
// mapping against, and the one list the fuzzing dictionary is generated from
// (tools/scene_dictionary.cpp), so a key the loader accepts is fuzzed the day it exists
// (tests/io/scene_keys_test.cpp checks the committed fuzz/dictionaries/scene.dict holds them
// all), and documented (tests/io/scene_format_doc_test.cpp checks docs/scene-format.md lists
// each section's keys exactly).
// Not here: what a key means (docs/scene-format.md), vocabularies owned by
// other modules (friction laws and their keys: friction/law_keys.hpp; normal laws,
// shapes, joint types, integrators: contact/ and core/; output channel groups:
// io/output_channels.hpp).
#pragma once

#include <string>
#include <vector>

namespace tribo::io::scene_keys {

using List = std::vector<std::string>;

inline const List kTop{"parameters", "simulation", "bodies",        "robots",
                       "joints",     "springs",    "bushings",      "torsional_springs",
                       "loads",      "actuators",  "friction_laws", "materials",
                       "contacts",   "output"};
inline const List kSimulation{"duration",  "time_step",      "integrator",  "gravity",
                              "baumgarte", "collision",      "rtol",        "atol",
                              "max_step",  "event_location", "constraints", "threads"};
inline const List kBaumgarte{"alpha", "beta"};
inline const List kCollision{
    "broadphase",          "closed_form_box_halfspace", "closed_form_primitives",
    "polyhedron_manifold", "max_points_per_pair",       "joined_bodies_collide",
    "match_radius",        "query_time_limit"};
inline const List kConstraints{"projection",       "tolerance",     "iterations",
                               "project_initial",  "redundant",     "solver",
                               "sparse_threshold", "drift_warning", "drift_stop"};
inline const List kBody{"name",        "kind",   "mass",     "inertia",          "position",
                        "orientation", "rpy",    "velocity", "angular_velocity", "surface_velocity",
                        "geometry",    "pattern"};
inline const List kBodyPattern{"grid", "spacing", "jitter", "seed"};
inline const List kGeometry{
    "name",    "shape",           "size",           "radius",   "length",      "file", "scale",
    "surface", "collision_group", "collision_mask", "position", "orientation", "rpy"};
inline const List kRobot{"file",          "prefix",         "position",        "orientation",
                         "rpy",           "base",           "joint_positions", "joint_velocities",
                         "package_paths", "collision_group"};
inline const List kJoint{"name",  "type",   "parent",  "child",  "anchor",   "axis",  "axis2",
                         "limit", "spring", "damping", "effort", "friction", "drive", "mimic"};
inline const List kJointLimit{"lower", "upper", "stiffness", "damping"};
inline const List kJointSpring{"stiffness", "reference"};
inline const List kJointDrive{"mode",      "constant", "slope", "amplitude",
                              "frequency", "phase",    "signal"};
inline const List kJointFriction{"law", "load", "normal_force", "radius"};
inline const List kJointMimic{"joint", "multiplier", "offset"};
inline const List kSpring{"name",    "a",         "point_a", "b",
                          "point_b", "stiffness", "damping", "rest_length"};
inline const List kBushing{"name",
                           "a",
                           "b",
                           "frame_a",
                           "frame_b",
                           "stiffness",
                           "damping",
                           "rotational_stiffness",
                           "rotational_damping"};
inline const List kFrame{"position", "orientation", "rpy"};
inline const List kTorsionalSpring{"name", "a", "b", "axis", "stiffness", "damping", "rest_angle"};
inline const List kLoad{"name", "body", "force", "torque", "frame", "point"};
inline const List kActuator{"name", "joint", "type",         "target",
                            "kp",   "kd",    "effort_limit", "velocity_limit"};
// A signal mapping's one key, its kind (io/scene_signal.hpp), and each kind's keys.
inline const List kSignal{"ramp", "step", "smooth_step", "table", "sines", "expression"};
inline const List kRampSignal{"rate", "start", "initial"};
inline const List kStepSignal{"time", "before", "after"};
inline const List kSmoothStepSignal{"start", "end", "before", "after"};
inline const List kSineTerm{"amplitude", "frequency", "phase", "offset"};
inline const List kTableSignal{"points", "file", "column", "interpolation"};
inline const List kExpressionSignal{"value", "derivative", "time_scale", "breakpoints"};
inline const List kInterpolations{"linear", "cubic"};
inline const List kMaterial{"name",    "normal",   "friction", "anisotropy",
                            "rolling", "spinning", "surfaces", "default"};
inline const List kRolling{"length", "stiffness", "damping", "stick_speed"};
inline const List kSpinning{"mu", "radius", "stiffness", "damping", "stick_speed"};
inline const List kAnisotropy{"frame", "axis", "ratio", "backward"};
inline const List kFrameSides{"a", "b"};
inline const List kNormal{"law",       "stiffness",   "damping",     "exponent",
                          "max_depth", "restitution", "impact_speed"};
inline const List kContact{"a", "b", "material"};
inline const List kOutput{"interval", "digits", "channels", "summary"};
inline const List kSummary{"body", "coordinate", "channel", "stick_speed", "last_cycles"};
inline const List kTabulatedLaw{"file"};

// Words where the loader expects one of a few (Value::choice and the like).
inline const List kBodyKinds{"dynamic", "kinematic"};
inline const List kShapes{"box",  "sphere",    "cylinder",    "capsule",
                          "cone", "halfspace", "convex_mesh", "mesh"};
inline const List kRobotBases{"auto", "fixed", "floating"};
inline const List kRedundancyPolicies{"error", "remove"};
inline const List kDriveModes{"position", "velocity"};
inline const List kJointFrictionLoads{"reaction", "constant"};
inline const List kSummaryCoordinates{"x", "y", "z"};
inline const List kLoadFrames{"world", "body"};
inline const List kActuatorTypes{"motor", "position", "velocity"};
inline const List kOtherWords{"true", "false", "world", "auto", "tabulated"};

// Every table above with the section it belongs to, for generators and tests.
struct Section {
  const char* where;  // "bodies[]", "simulation.collision", "(words) shape", ...
  const List* words;
};
inline const std::vector<Section>& sections() {
  static const std::vector<Section> all{{"(top level)", &kTop},
                                        {"simulation", &kSimulation},
                                        {"simulation.baumgarte", &kBaumgarte},
                                        {"simulation.collision", &kCollision},
                                        {"simulation.constraints", &kConstraints},
                                        {"bodies[]", &kBody},
                                        {"bodies[].geometry[]", &kGeometry},
                                        {"bodies[].pattern", &kBodyPattern},
                                        {"robots[]", &kRobot},
                                        {"joints[]", &kJoint},
                                        {"joints[].limit", &kJointLimit},
                                        {"joints[].spring", &kJointSpring},
                                        {"joints[].drive", &kJointDrive},
                                        {"joints[].friction", &kJointFriction},
                                        {"joints[].mimic", &kJointMimic},
                                        {"springs[]", &kSpring},
                                        {"bushings[]", &kBushing},
                                        {"bushings[].frame_a / frame_b", &kFrame},
                                        {"torsional_springs[]", &kTorsionalSpring},
                                        {"loads[]", &kLoad},
                                        {"actuators[]", &kActuator},
                                        {"loads[] signal", &kSignal},
                                        {"loads[] signal.ramp", &kRampSignal},
                                        {"loads[] signal.step", &kStepSignal},
                                        {"loads[] signal.smooth_step", &kSmoothStepSignal},
                                        {"loads[] signal.sines[]", &kSineTerm},
                                        {"loads[] signal.table", &kTableSignal},
                                        {"loads[] signal.expression", &kExpressionSignal},
                                        {"materials[]", &kMaterial},
                                        {"materials[].normal", &kNormal},
                                        {"materials[].anisotropy", &kAnisotropy},
                                        {"materials[].rolling", &kRolling},
                                        {"materials[].spinning", &kSpinning},
                                        {"contacts[]", &kContact},
                                        {"output", &kOutput},
                                        {"output.summary", &kSummary},
                                        {"friction_laws.tabulated", &kTabulatedLaw},
                                        {"(words) body kind", &kBodyKinds},
                                        {"(words) shape", &kShapes},
                                        {"(words) robot base", &kRobotBases},
                                        {"(words) constraints.redundant", &kRedundancyPolicies},
                                        {"(words) drive mode", &kDriveModes},
                                        {"(words) joint friction load", &kJointFrictionLoads},
                                        {"(words) summary coordinate", &kSummaryCoordinates},
                                        {"(words) load frame", &kLoadFrames},
                                        {"(words) actuator type", &kActuatorTypes},
                                        {"(words) table interpolation", &kInterpolations},
                                        {"(words) other", &kOtherWords}};
  return all;
}

}  // namespace tribo::io::scene_keys
