#include "io/urdf_scene.hpp"

#include <cmath>
#include <map>
#include <sstream>

#include "contact/primitive_contacts.hpp"
#include "core/number_text.hpp"
#include "core/stability.hpp"
#include "friction/friction_law.hpp"
#include "io/run_settings_check.hpp"
#include "io/scene_parameters.hpp"
#include "io/urdf_model.hpp"
#include "io/urdf_reader.hpp"
#include "io/utf8_check.hpp"

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

// Contact points of the moving `geometries` (of `model`, at its initial pose) below the
// plane z = level, at most 8 per geometry as in the collision detector: with `level` the
// lowest point plus the target depth, the points that carry the robot as it lands.
int supportPoints(const Model& model, const std::vector<int>& geometries, double level) {
  Eigen::Isometry3d plane = Eigen::Isometry3d::Identity();
  plane.translation().z() = level;
  std::vector<contact::ContactPoint> out;
  for (int gi : geometries) {
    const Geometry& g = model.geometries[gi];
    Eigen::Isometry3d pose = g.local_pose;
    if (!g.body.isWorld()) {
      const Body& b = model.bodies[g.body.value];
      Eigen::Isometry3d body = Eigen::Isometry3d::Identity();
      body.linear() = b.orientation.normalized().toRotationMatrix();
      body.translation() = b.position;
      pose = body * g.local_pose;
      if (b.kind != BodyKind::kDynamic) continue;
    } else {
      continue;  // welded to the world: carries nothing
    }
    contact::halfSpaceContacts(g.shape, pose, plane, 0, 8, out);
  }
  return static_cast<int>(out.size());
}

}  // namespace

namespace {

// The automatic step is accepted within this share of the stable step estimated at it.
constexpr double kAutoStepShare = 0.9;

const std::map<std::string, std::string>& defaultSettings() {
  static const std::map<std::string, std::string> settings{
      {"duration", "1"},       {"dt", "auto"},        {"integrator", "auto"}, {"drop", "0.05"},
      {"mu", "0.8"},           {"stiffness", "auto"}, {"damping", "auto"},    {"base", "auto"},
      {"penetration", "1e-3"}, {"min_dt", "1e-5"}};
  return settings;
}

}  // namespace

const std::vector<std::string>& urdfSceneSettings() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const auto& [name, value] : defaultSettings()) out.push_back(name);
    return out;
  }();
  return names;
}

Scene sceneFromUrdf(const std::string& path, const std::vector<std::string>& package_paths,
                    const std::vector<std::string>& overrides, const UrdfReadOptions& read,
                    const RunSettings& run) {
  if (run.integrator || run.time_step || run.duration || run.relative_tolerance ||
      run.absolute_tolerance || run.event_location || run.output_interval)
    throw SceneError(path + ": a URDF run takes its integrator, step and duration as --set " +
                     "integrator=, dt=, duration= (its run settings take threads only)");
  std::map<std::string, std::string> settings = defaultSettings();
  if (const std::size_t bad = firstBadUtf8(path); bad != std::string::npos)
    throw SceneError("URDF file path '" + printableText(path) + "': expected UTF-8 text, found " +
                     badUtf8Reason(path, bad));
  for (const std::string& o : overrides) {
    if (const std::size_t bad = firstBadUtf8(o); bad != std::string::npos)
      throw SceneError(path + ": --set " + printableText(o) + ": expected UTF-8 text, found " +
                       badUtf8Reason(o, bad));
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
  // A setting that must be > 0 (or >= 0 when `zero`), checked where it is read.
  auto checked = [&](const std::string& name, const char* field, bool zero = false) {
    const double v = number(name);
    requireRunSetting(zero ? v >= 0.0 : v > 0.0, path, name, field, zero ? ">= 0" : "> 0", v);
    return v;
  };
  const double duration = checked("duration", "duration");
  const double floor = checked("min_dt", "min_dt");
  const double depth = checked("penetration", "penetration");
  const double mu = checked("mu", "mu", true);
  const bool auto_k = settings["stiffness"] == "auto", auto_c = settings["damping"] == "auto";
  if (!auto_k) checked("stiffness", "stiffness");
  if (!auto_c) checked("damping", "damping", true);
  const bool auto_dt = settings["dt"] == "auto";
  if (!auto_dt) checked("dt", "time_step");
  const bool auto_integrator = settings["integrator"] == "auto";
  IntegratorType integrator = IntegratorType::kRk4;
  if (!auto_integrator) {
    try {
      integrator = integratorFromName(settings["integrator"]);
    } catch (const std::exception& e) {
      throw SceneError(path + ": run setting 'integrator': " + e.what());
    }
  }

  const UrdfRobot robot = readUrdf(path, PackagePaths::withEnvironment(package_paths), read);
  std::vector<std::string> notes;
  for (const UrdfIssue& i : robot.issues)
    if (i.severity != UrdfIssue::Severity::kError) notes.push_back(i.where + ": " + i.message);
  ModelBuilder builder;
  builder.options().duration = duration;
  // Until the step is chosen: one no longer than the run, so the probe models build.
  builder.options().time_step = std::min(1e-3, duration);
  builder.options().integrator = integrator;
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
  const double drop = number("drop");
  // What the model refuses in the robot (an error finding of the reader, a mesh that does
  // not load, a joint the builder refuses) is the URDF's: a UrdfError naming the file.
  auto add = [&](ModelBuilder& into) {
    try {
      return addUrdfRobot(into, robot, placement);
    } catch (const ModelError& e) {
      throw UrdfError(path + ": " + e.what());
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      throw UrdfError(what.rfind(path + ": ", 0) == 0 ? what : path + ": " + what);
    }
  };
  {
    ModelBuilder probe;
    const double lowest = add(probe).lowest_point;
    placement.base.translation().z() = drop - lowest;
  }
  const UrdfModelResult added = add(builder);
  for (const std::string& n : added.notes) notes.push_back(n);
  const int ground = builder.addGeometry("ground", BodyIndex::world(), contact::Shape::halfSpace());
  builder.setGeometrySurface(ground, "ground");

  // Contact stiffness per point: the weight the ground carries (every moving body's) shared
  // by the points within `penetration` of the lowest at the initial pose (a wheel on its rim
  // touches at 2, a box foot at 4, a mesh at up to 8), each at that depth: k = W / (n d).
  // Damping: critical for the link's own body on 4 points (so light links are not
  // overdamped, which would bound the explicit step far below what the stiffness needs).
  const double g = builder.options().gravity.norm();
  double moving = 0.0;
  for (const Body& b : builder.bodies()) moving += b.kind == BodyKind::kDynamic ? b.mass : 0.0;
  const int points = supportPoints(*builder.build(), added.geometries, drop + depth);
  const double weight = std::max(moving, 1e-6) * g;
  const double k = auto_k ? weight / (std::max(points, 1) * depth) : number("stiffness");
  for (const auto& surface : added.surfaces) {
    const double m = surface.body_mass > 0.0 ? surface.body_mass : moving;
    const contact::Material base_material =
        groundMaterial(mu, k, auto_c ? 2.0 * std::sqrt(k * m / 4.0) : number("damping"));
    builder.addSurfacePairMaterial(
        surface.name, "ground",
        builder.addMaterial(withGazeboTags(base_material, surface.contact, m, auto_c)));
  }
  builder.setDefaultMaterial(builder.addMaterial(groundMaterial(
      mu, k, auto_c ? 2.0 * std::sqrt(k * std::max(moving, 1e-6) / 8.0) : number("damping"))));

  // dt auto: half the a-priori stable step of the stiffest element, at most 1 ms, and a whole
  // fraction 1 ms / n so that rows fall every 1 ms. Default joint-limit gains follow the step
  // (ModelBuilder::build), so the step is checked again at its own gains and taken
  // smaller until it is within 0.9 of its estimate. Below the floor min_dt the explicit run
  // would take too long: said before the run, and an automatic integrator becomes bdf
  // (implicit: no step limit; dt is then its output interval).
  if (auto_dt) {
    StabilityLimit limit = estimateStableStep(*builder.build()).limit;
    const double interval = std::min(1e-3, duration);
    double n = std::max(1.0, std::ceil(interval / (0.5 * limit.max_step) - 1e-9));
    double step = interval / n;
    bool within = false;
    for (int tries = 0; tries < 16; ++tries, n += 1.0) {
      step = interval / n;
      if (step < floor) break;
      builder.options().time_step = step;
      limit = estimateStableStep(*builder.build()).limit;
      if ((within = step <= kAutoStepShare * limit.max_step)) break;
    }
    const double needed = within ? step : std::min(step, 0.5 * limit.max_step);
    builder.options().time_step = needed;
    if (needed < floor && builder.options().integrator != IntegratorType::kBdf) {
      std::ostringstream why;
      why << "the stable step of " << integratorName(builder.options().integrator) << " is "
          << limit.max_step << " s, set by " << limit.element << ": a step of " << needed
          << " s is below min_dt = " << floor << " s ("
          << std::llround(builder.options().duration / needed) << " steps for the run); ";
      if (auto_integrator) {
        builder.options().integrator = IntegratorType::kBdf;
        builder.options().time_step = std::min(1e-3, duration);
        why << "running with bdf instead (implicit, no step limit; --set integrator=rk4 --set "
               "dt=... forces the explicit run)";
      } else {
        builder.options().time_step = std::min(floor, duration);
        why << "running at min_dt, which may diverge (use --set integrator=bdf, or stiffen the "
               "link's mass or soften that element)";
      }
      notes.push_back(why.str());
    }
  } else {
    builder.options().time_step = number("dt");
  }
  if (run.threads) builder.options().threads = *run.threads;
  checkRunOptions(builder.options(), path, RunSettingKeys::urdf());

  Scene scene;
  scene.path = path;
  try {
    scene.model = builder.build();
  } catch (const ModelError& e) {  // the checks above leave none foreseen
    throw SceneError(path + ": " + e.what());
  }
  scene.output.interval = std::max(1e-3, builder.options().time_step);
  for (const auto& b : scene.model->bodies) {
    if (b.kind == BodyKind::kDynamic) {
      scene.output.summary.body = b.name;
      scene.output.summary.coordinate = 2;
      break;
    }
  }
  settings["stiffness"] = numberText(k);
  settings["dt"] = numberText(builder.options().time_step);
  settings["integrator"] = integratorName(builder.options().integrator);
  settings["support_points"] = std::to_string(points);
  for (const auto& [name, value] : settings) scene.parameters.emplace_back(name, value);
  scene.notes = notes;
  return scene;
}

}  // namespace tribo::io
