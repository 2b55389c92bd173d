#include "io/urdf_scene.hpp"

#include <cmath>
#include <map>

#include "core/stability.hpp"
#include "friction/friction_law.hpp"
#include "io/scene_parameters.hpp"
#include "io/urdf_model.hpp"
#include "io/urdf_reader.hpp"

namespace tribo::io {

namespace {

contact::Material groundMaterial(double mu, double stiffness, double damping) {
  contact::Material m;
  m.normal.type = contact::NormalLawType::kLinear;
  m.normal.stiffness = stiffness;
  m.normal.damping = damping;
  m.friction = urdfCoulomb(mu);
  return m;
}

}  // namespace

Scene sceneFromUrdf(const std::string& path, const std::vector<std::string>& package_paths,
                    const std::vector<std::string>& overrides) {
  std::map<std::string, std::string> settings{
      {"duration", "1"}, {"dt", "auto"},        {"integrator", "rk4"}, {"drop", "0.05"},
      {"mu", "0.8"},     {"stiffness", "auto"}, {"damping", "auto"},   {"base", "auto"}};
  for (const std::string& o : overrides) {
    const auto eq = o.find('=');
    const std::string name = o.substr(0, eq);
    if (eq == std::string::npos || !settings.count(name)) {
      std::string known;
      for (const auto& [k, v] : settings) known += (known.empty() ? "" : ", ") + k;
      throw SceneError(path + ": --set " + o + ": unknown setting for a URDF run (known: " + known +
                       ")");
    }
    settings[name] = o.substr(eq + 1);
  }
  auto number = [&](const std::string& name) {
    const auto v = parseNumber(settings[name]);
    if (!v)
      throw SceneError(path + ": --set " + name + ": expected a number, got '" + settings[name] +
                       "'");
    return *v;
  };

  const UrdfRobot robot = readUrdf(path, PackagePaths::withEnvironment(package_paths));
  ModelBuilder builder;
  builder.options().duration = number("duration");
  builder.options().integrator = integratorFromName(settings["integrator"]);
  builder.options().collision.broadphase = true;

  UrdfPlacement placement;
  const std::string& base = settings["base"];
  if (base == "fixed")
    placement.base_mode = UrdfPlacement::Base::kFixed;
  else if (base == "floating")
    placement.base_mode = UrdfPlacement::Base::kFloating;
  else if (base != "auto")
    throw SceneError(path + ": --set base: expected auto, fixed or floating, got '" + base + "'");

  // Place it once to find its lowest point, then again lifted to `drop` above the ground.
  {
    ModelBuilder probe;
    const double lowest = addUrdfRobot(probe, robot, placement).lowest_point;
    placement.base.translation().z() = number("drop") - lowest;
  }
  const UrdfModelResult added = addUrdfRobot(builder, robot, placement);
  const int ground = builder.addGeometry("ground", BodyIndex::world(), contact::Shape::halfSpace());
  builder.setGeometrySurface(ground, "ground");

  // Contact per link: a stiffness that carries the robot's weight on 8 points at 1 mm, and a
  // damping critical for the link's own body on 4 points (so light links are not overdamped,
  // which would bound the explicit step far below what the stiffness needs).
  const double mass = std::max(robot.totalMass(), 1e-3);
  const double g = builder.options().gravity.norm();
  constexpr double kPoints = 8.0, kDepth = 1e-3;
  const bool auto_k = settings["stiffness"] == "auto", auto_c = settings["damping"] == "auto";
  const double k = auto_k ? mass * g / (kPoints * kDepth) : number("stiffness");
  for (const auto& surface : added.surfaces) {
    const double m = surface.body_mass > 0.0 ? surface.body_mass : mass;
    const contact::Material base =
        groundMaterial(number("mu"), k, auto_c ? 2.0 * std::sqrt(k * m / 4.0) : number("damping"));
    builder.addSurfacePairMaterial(
        surface.name, "ground",
        builder.addMaterial(withGazeboTags(base, surface.contact, m, auto_c)));
  }
  builder.setDefaultMaterial(builder.addMaterial(groundMaterial(
      number("mu"), k, auto_c ? 2.0 * std::sqrt(k * mass / kPoints) : number("damping"))));

  // dt auto: half the a-priori stable step of the stiffest element, at most 1 ms.
  if (settings["dt"] == "auto") {
    builder.options().time_step = 1e-3;
    const double limit = estimateStableStep(*builder.build()).limit.max_step;
    builder.options().time_step = std::min(1e-3, 0.5 * limit);
  } else {
    builder.options().time_step = number("dt");
  }

  Scene scene;
  scene.path = path;
  scene.model = builder.build();
  scene.output.interval = std::max(1e-3, builder.options().time_step);
  for (const auto& b : scene.model->bodies) {
    if (b.kind == BodyKind::kDynamic) {
      scene.output.summary.body = b.name;
      scene.output.summary.coordinate = 2;
      break;
    }
  }
  settings["stiffness"] = std::to_string(k);
  settings["dt"] = std::to_string(builder.options().time_step);
  for (const auto& [name, value] : settings) scene.parameters.emplace_back(name, value);
  scene.notes = added.notes;
  return scene;
}

}  // namespace tribo::io
