// The scene reader: one parsed scene document turned into a Scene, section by section, in
// the order load() reads them (parameters and overrides first, so that every "$name" after
// them reads the overridden value; friction laws before the joint references and materials
// that select them; materials before the robots' Gazebo tags and the contacts). Each
// section's reader fills the ModelBuilder and refuses what it cannot take with a SceneError
// at the offending value (io/scene_value.hpp). Its member functions are defined by section:
//   io/scene_reader.cpp     load(), run settings, parameters, simulation, output
//   io/scene_bodies.cpp     bodies, geometry, robots, Gazebo tags, body names
//   io/scene_joints.cpp     joints, joint references, constraint options, springs,
//                           bushings, torsional springs
//   io/scene_loads.cpp      applied loads (their signals: io/scene_signal.hpp)
//   io/scene_actuators.cpp  joint actuators (motors, servos)
//   io/scene_materials.cpp  friction laws, materials, normal laws, contacts
// Internal to io/ (it includes yaml-cpp): io/scene_loader.cpp uses it; nothing outside io/
// includes it.
// Not here: the format itself (docs/scene-format.md), the accepted keys
// (io/scene_keys.hpp), YAML parsing and the public entry points (io/scene_loader.hpp).
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "contact/contact_force.hpp"
#include "contact/shape.hpp"
#include "core/model_builder.hpp"
#include "friction/friction_law.hpp"
#include "io/scene_loader.hpp"
#include "io/scene_parameters.hpp"
#include "io/scene_value.hpp"
#include "io/urdf_model.hpp"

namespace tribo::io::scene_detail {

struct GeometrySpec {
  Value at;
  std::string name;
  contact::Shape shape;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  std::string surface = {};
  std::uint32_t group = 1;
  std::uint32_t mask = 0xffffffffu;
};

// A robot link surface whose Gazebo tags still need their materials (after materials:).
struct GazeboSurface {
  Value at;
  UrdfModelResult::Surface surface;
};

struct LawEntry {
  Value at;
  friction::LawSpec spec;
  std::shared_ptr<const friction::FrictionLaw> law;  // built when a material selects it
};

class Loader {
 public:
  Loader(std::string file, const YAML::Node& root, std::vector<std::string> package_paths,
         const UserLaws& user_laws)
      : file_(std::move(file)),
        root_(root),
        package_paths_(std::move(package_paths)),
        user_laws_(user_laws) {}

  Scene load(const std::vector<std::string>& overrides, const RunSettings& settings);

 private:
  // io/scene_reader.cpp
  void noteSurfaceVelocityOffTheSurface(const Model& model);
  void applyRunSettings(const RunSettings& r, OutputSpec& output);
  void readParameters(const Value& v);
  void readSimulation(const Value& v);
  OutputSpec readOutput(const Value& v);

  // io/scene_bodies.cpp
  void readBody(const Value& v);
  void readMotion(const Map& m, Body& body);
  struct PatternCopy {
    std::string suffix;          // "_i_j_k"
    Vec3 offset = Vec3::Zero();  // from the entry's position [m]
  };
  static constexpr double kMaxPatternBodies = 1e6;  // bodies one pattern entry may make
  std::vector<PatternCopy> readPattern(const Value& v);
  GeometrySpec readGeometry(const Value& v);
  void readRobot(const Value& v);
  void applyGazeboTags();
  BodyIndex body(const Value& v) const;

  // io/scene_joints.cpp
  void readConstraintOptions(const Value& v, ConstraintOptions& c);
  void readJoint(const Value& v);
  void readJointReferences();
  void readSpring(const Value& v);
  void readBushing(const Value& v);
  void readTorsionalSpring(const Value& v);

  // io/scene_loads.cpp
  void readLoad(const Value& v);
  // io/scene_actuators.cpp
  void readActuator(const Value& v);

  // io/scene_materials.cpp
  std::shared_ptr<const friction::FrictionLaw> frictionLaw(const Value& name);
  std::shared_ptr<const friction::FrictionLaw> tabulatedLaw(const LawEntry& law,
                                                            const Value& selected_by);
  void readFrictionLaws(const Value& v);
  void readMaterial(const Value& v);
  contact::NormalLaw readNormalLaw(const Value& v);
  contact::Anisotropy readAnisotropy(const Value& v);
  std::shared_ptr<const friction::ElasticStickLaw> readAngularStick(const Value& v, bool spinning);
  void readContact(const Value& v);

  std::string file_;
  std::optional<Value> summary_channel_;  // output.summary.channel, checked after the build
  YAML::Node root_;
  ParameterTable params_;
  ModelBuilder builder_;
  Keys geometry_names_;
  Keys law_names_;  // in file order, for messages
  std::map<std::string, LawEntry> laws_;
  std::map<std::string, int> materials_;
  std::vector<std::pair<int, Value>> pending_friction_;  // joint index, its friction block
  std::vector<std::pair<int, Value>> pending_mimic_;     // joint index, its mimic block
  std::string default_material_;  // name of the material marked default, if any
  std::map<std::string, contact::Material> material_values_;     // by name
  std::set<std::pair<std::string, std::string>> surface_pairs_;  // given a material, sorted
  std::set<std::string> body_surfaces_;  // surfaces of the bodies: section's geometry
  std::vector<GazeboSurface> gazebo_surfaces_;
  std::vector<std::string> package_paths_;  // --package-path folders
  const UserLaws& user_laws_;
  bool uses_user_law_ = false;  // a material's friction is one of user_laws_
  std::vector<std::string> notes_;
};

}  // namespace tribo::io::scene_detail
