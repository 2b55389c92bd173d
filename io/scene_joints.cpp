// Scene reader (io/scene_reader.hpp): joints and what acts on their coordinates, the joint
// references resolved once everything is read (friction laws, mimic leaders), constraint
// options, and the force elements: springs, bushings, torsional springs.
#include <optional>
#include <string>
#include <vector>

#include "io/scene_keys.hpp"
#include "io/scene_reader.hpp"
#include "io/scene_signal.hpp"

namespace tribo::io::scene_detail {

namespace {

// A bushing frame {[position], [orientation | rpy]} in its body's frame (identity when
// absent).
void readFrame(const std::optional<Value>& v, Vec3& position, Quat& rotation) {
  if (!v) return;
  const Map m(*v, scene_keys::kFrame);
  position = m.vec3("position", Vec3::Zero());
  rotation = orientation(m);
}

// Three gains >= 0, each checked at its own item; zero when absent.
Vec3 gains(const Map& m, const std::string& key) {
  const auto v = m.get(key);
  if (!v) return Vec3::Zero();
  const std::string what = "3 numbers >= 0 [x, y, z] (per axis of frame A)";
  v->numbers({3}, what);  // the length first
  const std::vector<Value> items = v->items(what);
  return {items[0].nonNegative(), items[1].nonNegative(), items[2].nonNegative()};
}

}  // namespace

void Loader::readConstraintOptions(const Value& v, ConstraintOptions& c) {
  const Map m(v, scene_keys::kConstraints);
  if (auto x = m.get("projection")) c.projection = x->flag();
  if (auto x = m.get("tolerance")) c.projection_tolerance = x->positive();
  if (auto x = m.get("iterations")) c.projection_iterations = x->integer(1);
  if (auto x = m.get("project_initial")) c.project_initial = x->flag();
  if (auto x = m.get("redundant"))
    c.redundant = x->choice(scene_keys::kRedundancyPolicies) == 0 ? RedundancyPolicy::kError
                                                                  : RedundancyPolicy::kRemove;
  if (auto x = m.get("solver"))
    c.solver = guarded(*x, [&] { return constraintSolverFromName(x->text()); });
  if (auto x = m.get("sparse_threshold")) c.sparse_threshold = x->integer(1);
  if (auto x = m.get("drift_warning")) c.drift_warning = x->positive();
  if (auto x = m.get("drift_stop")) c.drift_stop = x->positive();
}

void Loader::readJoint(const Value& v) {
  const Map m(v, scene_keys::kJoint);
  const std::string name = m.required("name").text();
  const Value type_value = m.required("type");
  const JointType type = guarded(type_value, [&] { return jointTypeFromName(type_value.text()); });
  const auto parent_value = m.get("parent");
  const BodyIndex parent = parent_value ? body(*parent_value) : BodyIndex::world();
  const BodyIndex child = body(m.required("child"));
  const Vec3 child_position =
      child.isWorld() ? Vec3::Zero() : builder_.bodies()[child.value].position;
  const Vec3 anchor = m.vec3("anchor", child_position);
  const Vec3 axis = m.vec3("axis", Vec3::UnitZ());
  const Vec3 axis2 = m.vec3("axis2", Vec3::Zero());
  const int joint =
      guarded(v, [&] { return builder_.addJoint(name, type, parent, child, anchor, axis, axis2); });
  if (auto x = m.get("limit")) {
    const Map l(*x, scene_keys::kJointLimit);
    JointLimit limit{l.required("lower").number(), l.required("upper").number(), 0.0, 0.0};
    if (auto k = l.get("stiffness")) limit.stiffness = k->nonNegative();
    if (auto c = l.get("damping")) limit.damping = c->nonNegative();
    guarded(*x, [&] { builder_.setJointLimit(joint, limit); });
  }
  if (auto x = m.get("spring")) {
    const Map sp(*x, scene_keys::kJointSpring);
    const auto reference = sp.get("reference");
    const JointSpring spring{sp.required("stiffness").number(),
                             reference ? reference->number() : 0.0};
    guarded(*x, [&] { builder_.setJointSpring(joint, spring); });
  }
  if (auto x = m.get("damping")) guarded(*x, [&] { builder_.setJointDamping(joint, x->number()); });
  if (auto x = m.get("effort")) guarded(*x, [&] { builder_.setJointEffort(joint, x->number()); });
  if (auto x = m.get("drive")) {
    const Map d(*x, scene_keys::kJointDrive);
    JointDrive drive;
    if (auto mode = d.get("mode"))
      drive.mode =
          mode->choice(scene_keys::kDriveModes) == 0 ? DriveMode::kPosition : DriveMode::kVelocity;
    auto number = [&](const char* key) {
      const auto n = d.get(key);
      return n ? n->number() : 0.0;
    };
    if (auto signal = d.get("signal")) {
      for (const char* key : {"constant", "slope", "amplitude", "frequency", "phase"})
        if (d.get(key))
          signal->fail(std::string("a drive takes either `signal` or the function's keys "
                                   "(constant, slope, amplitude, frequency, phase), not both; "
                                   "found `") +
                       key + "` too");
      drive.signal = readSignal(*signal);
    } else {
      drive.function = {number("constant"), number("slope"), number("amplitude"),
                        number("frequency"), number("phase")};
    }
    guarded(*x, [&] { builder_.setJointDrive(joint, drive); });
  }
  // Friction names a law and mimic a joint, possibly defined later: resolved once all
  // joints and laws are read (readJointReferences).
  if (auto x = m.get("friction")) pending_friction_.emplace_back(joint, *x);
  if (auto x = m.get("mimic")) pending_mimic_.emplace_back(joint, *x);
}

void Loader::readJointReferences() {
  for (const auto& [joint, v] : pending_friction_) {
    const Map f(v, scene_keys::kJointFriction);
    JointFriction friction;
    friction.law = frictionLaw(f.required("law"));
    if (auto x = f.get("load"))
      friction.load = x->choice(scene_keys::kJointFrictionLoads) == 0
                          ? JointFrictionLoad::kReaction
                          : JointFrictionLoad::kConstant;
    if (auto x = f.get("normal_force")) {
      if (friction.load != JointFrictionLoad::kConstant)
        x->fail("normal_force applies to load: constant only");
      friction.normal_force = x->nonNegative();
    } else if (friction.load == JointFrictionLoad::kConstant) {
      v.fail("missing required key 'normal_force' (needed by load: constant)");
    }
    if (auto x = f.get("radius")) friction.radius = x->positive();
    guarded(v, [&, joint = joint] { builder_.setJointFriction(joint, friction); });
  }
  for (const auto& [joint, v] : pending_mimic_) {
    const Map mm(v, scene_keys::kJointMimic);
    const Value leader_value = mm.required("joint");
    const auto leader = builder_.findJoint(leader_value.text());
    if (!leader) {
      Keys known;
      for (const Joint& j : builder_.joints()) known.push_back(j.name);
      leader_value.fail("unknown joint '" + leader_value.text() +
                        "' (known joints: " + joined(known) + ")");
    }
    const auto multiplier = mm.get("multiplier");
    const auto offset = mm.get("offset");
    const std::string name = builder_.joints()[joint].name + " mimics " + leader_value.text();
    guarded(v, [&, joint = joint] {
      return builder_.addJointCoupling(name, *leader, joint,
                                       multiplier ? multiplier->number() : 1.0,
                                       offset ? offset->number() : 0.0);
    });
  }
}

void Loader::readSpring(const Value& v) {
  const Map m(v, scene_keys::kSpring);
  const std::string name = m.required("name").text();
  const BodyIndex a = body(m.required("a"));
  const BodyIndex b = body(m.required("b"));
  const Vec3 pa = m.required("point_a").vec3();
  const Vec3 pb = m.required("point_b").vec3();
  const double k = m.required("stiffness").number();
  const auto damping = m.get("damping");
  const auto rest = m.get("rest_length");
  const double c = damping ? damping->number() : 0.0;
  const double l0 = rest ? rest->nonNegative() : -1.0;  // < 0: the initial distance
  guarded(v, [&] { builder_.addSpring(name, a, pa, b, pb, k, c, l0); });
}

void Loader::readBushing(const Value& v) {
  const Map m(v, scene_keys::kBushing);
  Bushing bushing;
  bushing.name = m.required("name").text();
  bushing.body_a = body(m.required("a"));
  bushing.body_b = body(m.required("b"));
  readFrame(m.get("frame_a"), bushing.position_a, bushing.orientation_a);
  readFrame(m.get("frame_b"), bushing.position_b, bushing.orientation_b);
  bushing.stiffness = gains(m, "stiffness");
  bushing.damping = gains(m, "damping");
  bushing.rotational_stiffness = gains(m, "rotational_stiffness");
  bushing.rotational_damping = gains(m, "rotational_damping");
  guarded(v, [&] { builder_.addBushing(bushing); });
}

void Loader::readTorsionalSpring(const Value& v) {
  const Map m(v, scene_keys::kTorsionalSpring);
  const std::string name = m.required("name").text();
  const BodyIndex a = body(m.required("a"));
  const BodyIndex b = body(m.required("b"));
  const Value axis_value = m.required("axis");
  const Vec3 axis = axis_value.vec3("3 numbers [x, y, z] (the axis, world)");
  if (!(axis.norm() > 0.0))
    axis_value.fail("expected a non-zero axis, found " + axis_value.found());
  const double k = m.required("stiffness").nonNegative();
  const auto damping = m.get("damping");
  const auto rest = m.get("rest_angle");
  const double c = damping ? damping->nonNegative() : 0.0;
  const double rest_angle = rest ? rest->number() : 0.0;
  guarded(v, [&] { builder_.addTorsionalSpring(name, a, b, axis, k, c, rest_angle); });
}

}  // namespace tribo::io::scene_detail
