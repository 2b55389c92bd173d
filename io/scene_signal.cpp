#include "io/scene_signal.hpp"

#include <string>
#include <utility>
#include <vector>

#include "io/scene_keys.hpp"

namespace tribo::io::scene_detail {

namespace {

double optional(const Map& m, const char* key, double fallback) {
  const auto v = m.get(key);
  return v ? v->number() : fallback;
}

}  // namespace

Signal readSignal(const Value& v) {
  if (!v.node().IsMap()) return guarded(v, [&] { return Signal::constant(v.number()); });
  const Map m(v, scene_keys::kSignal);
  if (m.entries().size() != 1)
    v.fail("expected a number or a mapping with one signal kind (" + joined(scene_keys::kSignal) +
           "), found " + std::to_string(m.entries().size()) + " keys");
  const auto& [kind, body] = m.entries().front();
  if (kind == "ramp") {
    const Map r(body, scene_keys::kRampSignal);
    const double rate = r.required("rate").number();
    return guarded(body, [&] {
      return Signal::ramp(rate, optional(r, "start", 0.0), optional(r, "initial", 0.0));
    });
  }
  if (kind == "step") {
    const Map s(body, scene_keys::kStepSignal);
    const double time = s.required("time").number();
    const double before = s.required("before").number();
    const double after = s.required("after").number();
    return guarded(body, [&] { return Signal::step(time, before, after); });
  }
  if (kind == "smooth_step") {
    const Map s(body, scene_keys::kSmoothStepSignal);
    const double start = s.required("start").number();
    const double end = s.required("end").number();
    const double before = s.required("before").number();
    const double after = s.required("after").number();
    return guarded(body, [&] { return Signal::smoothStep(start, before, end, after); });
  }
  if (kind == "table") {
    std::vector<std::pair<double, double>> points;
    for (const Value& p : body.items("[t, v] points")) {
      const auto tv = p.numbers({2}, "a point [t, v]");
      points.emplace_back(tv[0], tv[1]);
    }
    return guarded(body, [&] { return Signal::table(std::move(points)); });
  }
  // sines (the key table admits no other)
  std::vector<Signal::Sine> terms;
  for (const Value& item : body.items("sine terms {amplitude, frequency, ...}")) {
    const Map s(item, scene_keys::kSineTerm);
    Signal::Sine term;
    term.amplitude = s.required("amplitude").number();
    term.frequency = s.required("frequency").number();
    term.phase = optional(s, "phase", 0.0);
    term.offset = optional(s, "offset", 0.0);
    terms.push_back(term);
  }
  return guarded(body, [&] { return Signal::sines(std::move(terms)); });
}

std::array<Signal, 3> readSignals3(const Value& v) {
  if (!v.node().IsSequence() || v.node().size() != 3)
    v.fail("expected 3 components [x, y, z] (each a number or a signal), found " + v.found());
  const std::vector<Value> items = v.items("components");
  return {readSignal(items[0]), readSignal(items[1]), readSignal(items[2])};
}

}  // namespace tribo::io::scene_detail
