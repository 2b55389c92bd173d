// Scene reader (io/scene_reader.hpp): the order of sections, run settings, parameters,
// simulation, output.
#include "io/scene_reader.hpp"

#include <algorithm>
#include <cmath>

#include "core/number_text.hpp"
#include "core/thread_count.hpp"
#include "io/output_channels.hpp"
#include "io/run_settings_check.hpp"
#include "io/scene_keys.hpp"

namespace tribo::io::scene_detail {

namespace {

// A scene whose geometries could touch but that gives no contact at all: no `contacts:` list
// and no material that is the default or names surface pairs, so every body passes through
// every other. Said before the run (empty when some contact is modelled, or when no two
// geometries on different bodies, one of them moving, exist).
std::string noContactNote(const Model& model) {
  if (model.automatic_contacts || !model.contact_pairs.empty()) return {};
  const Geometry* moving = nullptr;
  for (const Geometry& g : model.geometries)
    if (!g.body.isWorld() && model.bodies[g.body.value].kind == BodyKind::kDynamic) {
      moving = &g;
      break;
    }
  if (moving == nullptr) return {};
  for (const Geometry& g : model.geometries) {
    if (&g == moving || (!g.body.isWorld() && g.body.value == moving->body.value)) continue;
    return "no contact is modelled: the scene lists no contacts: and no material is "
           "`default: true` or names `surfaces:`, so geometry '" +
           moving->name + "' passes through '" + g.name +
           "' and every other (add `default: true` to a material, or list the pairs under "
           "contacts:)";
  }
  return {};
}

}  // namespace

Scene Loader::load(const std::vector<std::string>& overrides, const RunSettings& settings) {
  const Value root(file_, params_, root_, "");
  const Map m(root, scene_keys::kTop);
  if (auto p = m.get("parameters")) readParameters(*p);
  params_.applyOverrides(overrides, file_);
  if (auto s = m.get("simulation")) readSimulation(*s);
  const auto robots = m.get("robots");
  if (auto b = robots ? m.get("bodies") : m.required("bodies"))
    for (const Value& v : b->items("bodies", robots.has_value())) readBody(v);
  if (robots)
    for (const Value& v : robots->items("robots")) readRobot(v);
  if (auto j = m.get("joints"))
    for (const Value& v : j->items("joints", true)) readJoint(v);
  if (auto s = m.get("springs"))
    for (const Value& v : s->items("springs", true)) readSpring(v);
  if (auto s = m.get("bushings"))
    for (const Value& v : s->items("bushings", true)) readBushing(v);
  if (auto s = m.get("torsional_springs"))
    for (const Value& v : s->items("torsional_springs", true)) readTorsionalSpring(v);
  if (auto s = m.get("loads"))
    for (const Value& v : s->items("loads", true)) readLoad(v);
  if (auto s = m.get("actuators"))
    for (const Value& v : s->items("actuators", true)) readActuator(v);
  if (auto f = m.get("friction_laws")) readFrictionLaws(*f);
  readJointReferences();
  if (auto mat = m.get("materials"))
    for (const Value& v : mat->items("materials", true)) readMaterial(v);
  applyGazeboTags();
  if (auto c = m.get("contacts"))
    for (const Value& v : c->items("contacts", true)) readContact(v);
  Scene scene;
  if (auto o = m.get("output")) scene.output = readOutput(*o);
  applyRunSettings(settings, scene.output);
  checkRunOptions(builder_.options(), file_);
  scene.path = file_;
  try {
    scene.model = std::move(builder_).build();  // the builder is done: no copy of the model
  } catch (const ModelError& e) {
    throw SceneError({file_}, "", e.what());
  }
  if (summary_channel_) {
    const std::vector<std::string> columns = channelColumns(*scene.model, scene.output.channels);
    if (std::find(columns.begin() + 1, columns.end(), scene.output.summary.channel) ==
        columns.end())
      summary_channel_->fail(
          "no recorded channel '" + scene.output.summary.channel +
          "' (output.channels: " + joined(scene.output.channels) +
          "; e.g. BODY.yaw needs rpy, JOINT.q needs joints, A/B.normal_force needs pairs, "
          "A/B.z.x needs friction_states)");
  }
  noteSurfaceVelocityOffTheSurface(*scene.model);
  if (std::string note = noContactNote(*scene.model); !note.empty()) notes_.push_back(note);
  scene.parameters = params_.values();
  scene.notes = notes_;
  return scene;
}

// A half-space's surface is its geometry's z = 0 plane: a body's surface_velocity (in each
// geometry's frame) with a part along that z would push material through the surface,
// which the contact ignores (it uses the tangential part only through the slip).
void Loader::noteSurfaceVelocityOffTheSurface(const Model& model) {
  for (const Geometry& g : model.geometries) {
    if (g.body.isWorld() || g.shape.type != contact::ShapeType::kHalfSpace) continue;
    const Vec3& v = model.bodies[g.body.value].surface_velocity;
    if (std::abs(v.z()) <= 1e-9 * v.norm()) continue;
    notes_.push_back("bodies." + model.bodies[g.body.value].name + ".surface_velocity [" +
                     numberText(v.x()) + ", " + numberText(v.y()) + ", " + numberText(v.z()) +
                     "] is not tangent to the surface of half-space '" + g.name +
                     "' (its z must be 0: the velocity is read in the geometry's " +
                     "frame, whose z is the surface normal)");
  }
}

void Loader::applyRunSettings(const RunSettings& r, OutputSpec& output) {
  SimulationOptions& o = builder_.options();
  if (r.integrator) o.integrator = *r.integrator;
  if (r.time_step) o.time_step = *r.time_step;
  if (r.duration) o.duration = *r.duration;
  if (r.relative_tolerance) o.relative_tolerance = *r.relative_tolerance;
  if (r.absolute_tolerance) o.absolute_tolerance = *r.absolute_tolerance;
  if (r.event_location) o.event_location = *r.event_location;
  if (r.threads) o.threads = *r.threads;
  // A law the caller defined (in Python: it takes the GIL for each call) runs on the
  // calling thread alone.
  if (uses_user_law_) o.threads = 1;
  if (r.output_interval) {
    if (!(*r.output_interval > 0.0) || !std::isfinite(*r.output_interval))
      throw SceneError({file_}, "output.interval",
                       "expected a number > 0, found " + numberText(*r.output_interval));
    output.interval = *r.output_interval;
  }
}

void Loader::readParameters(const Value& v) {
  const Map table(v, {});
  for (const auto& [name, value] : table.entries()) {
    if (!value.node().IsScalar())
      value.fail("expected a number or a string, found " + value.found());
    params_.add(name, value.node().Scalar(), value.where());
  }
}

void Loader::readSimulation(const Value& v) {
  const Map m(v, scene_keys::kSimulation);
  SimulationOptions& o = builder_.options();
  if (auto x = m.get("duration")) o.duration = x->positive();
  if (auto x = m.get("time_step")) o.time_step = x->positive();
  if (auto x = m.get("integrator"))
    o.integrator = guarded(*x, [&] { return integratorFromName(x->text()); });
  if (auto x = m.get("rtol")) {
    o.relative_tolerance = x->positive();
    if (!(o.relative_tolerance < 1.0)) x->fail("expected a number in (0, 1), found " + x->found());
  }
  if (auto x = m.get("atol")) o.absolute_tolerance = x->positive();
  if (auto x = m.get("max_step")) o.max_internal_step = x->nonNegative();
  if (auto x = m.get("event_location")) o.event_location = x->flag();
  if (auto x = m.get("threads")) {
    if (x->node().IsScalar() && x->text() == "auto") {
      o.threads = kAutoThreads;
    } else {
      try {
        o.threads = x->integer(1);
      } catch (const SceneError&) {
        x->fail("expected auto or a whole number >= 1, found " + x->found());
      }
    }
  }
  o.gravity = m.vec3("gravity", o.gravity);
  if (auto x = m.get("baumgarte")) {
    const Map b(*x, scene_keys::kBaumgarte);
    if (auto a = b.get("alpha")) o.baumgarte_alpha = a->nonNegative();
    if (auto a = b.get("beta")) o.baumgarte_beta = a->nonNegative();
  }
  if (auto x = m.get("constraints")) readConstraintOptions(*x, o.constraints);
  if (auto x = m.get("collision")) {
    const Map c(*x, scene_keys::kCollision);
    if (auto a = c.get("broadphase")) o.collision.broadphase = a->flag();
    if (auto a = c.get("closed_form_box_halfspace"))
      o.collision.closed_form_box_halfspace = a->flag();
    if (auto a = c.get("max_points_per_pair")) o.collision.max_points_per_pair = a->integer(1);
    if (auto a = c.get("closed_form_primitives")) o.collision.closed_form_primitives = a->flag();
    if (auto a = c.get("polyhedron_manifold")) o.collision.polyhedron_manifold = a->flag();
    if (auto a = c.get("joined_bodies_collide")) o.collision.joined_bodies_collide = a->flag();
    if (auto a = c.get("match_radius")) o.collision.match_radius = a->positive();
    if (auto a = c.get("query_time_limit")) o.collision.query_time_limit = a->nonNegative();
  }
}

OutputSpec Loader::readOutput(const Value& v) {
  const Map m(v, scene_keys::kOutput);
  OutputSpec out;
  if (auto x = m.get("interval")) out.interval = x->positive();
  if (auto x = m.get("digits")) {
    out.digits = x->integer(1);
    if (out.digits > 17) x->fail("expected a whole number from 1 to 17, found " + x->text());
  }
  if (auto x = m.get("channels")) {
    out.channels.clear();
    for (const Value& g : x->items("channels")) {
      const std::string name = g.text();
      if (!hasGroup(knownChannelGroups(), name))
        g.fail("unknown channel group '" + name + "' (known: " + joined(knownChannelGroups()) +
               ")");
      if (hasGroup(out.channels, name)) g.fail("channel group '" + name + "' is listed twice");
      out.channels.push_back(name);
    }
  }
  if (auto x = m.get("summary")) {
    const Map s(*x, scene_keys::kSummary);
    const auto b = s.get("body");
    const auto channel = s.get("channel");
    if (!b && !channel) s.required("body");  // the message names what is missing
    if (b) {
      if (body(*b).isWorld()) b->fail("expected a body of the scene, found 'world'");
      out.summary.body = b->text();
    }
    if (channel) {
      if (s.get("coordinate")) channel->fail("give either channel or coordinate, not both");
      out.summary.channel = channel->text();
      summary_channel_.emplace(*channel);  // checked once the model is built
    }
    if (auto c = s.get("coordinate"))
      out.summary.coordinate = c->choice(scene_keys::kSummaryCoordinates);
    if (!out.summary.body.empty() && !hasGroup(out.channels, "contact"))
      out.channels.push_back("contact");  // the summary's stuck fraction reads it
    if (out.summary.channel.empty() && !hasGroup(out.channels, "position"))
      out.channels.push_back("position");
    if (auto c = s.get("stick_speed")) out.summary.stick_speed = c->nonNegative();
    if (auto c = s.get("last_cycles")) out.summary.last_cycles = c->integer(1);
  }
  return out;
}

}  // namespace tribo::io::scene_detail
