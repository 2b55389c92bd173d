#include "io/scene_signal.hpp"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/number_text.hpp"
#include "io/scene_keys.hpp"
#include "io/signal_table_file.hpp"
#include "io/time_expression.hpp"

namespace tribo::io::scene_detail {

namespace {

double optional(const Map& m, const char* key, double fallback) {
  const auto v = m.get(key);
  return v ? v->number() : fallback;
}

using Points = std::vector<std::pair<double, double>>;

Signal tableSignal(const Value& at, Points points, bool cubic) {
  return guarded(at, [&] {
    return cubic ? Signal::cubicTable(std::move(points)) : Signal::table(std::move(points));
  });
}

Points inlinePoints(const Value& v) {
  Points points;
  for (const Value& p : v.items("[t, v] points")) {
    const auto tv = p.numbers({2}, "a point [t, v]");
    points.emplace_back(tv[0], tv[1]);
  }
  return points;
}

// {table: [[t, v], ...]} or {table: {points | file, [column], [interpolation]}}.
Signal readTable(const Value& body) {
  if (!body.node().IsMap()) return tableSignal(body, inlinePoints(body), false);
  const Map m(body, scene_keys::kTableSignal);
  const auto points = m.get("points");
  const auto file = m.get("file");
  const auto column = m.get("column");
  if (points.has_value() == file.has_value())
    body.fail("expected one of 'points' and 'file', found " +
              std::string(points ? "both" : "neither"));
  if (column && !file) column->fail("'column' selects a column of a 'file'; there is none");
  bool cubic = false;
  if (const auto how = m.get("interpolation"))
    cubic = how->choice(scene_keys::kInterpolations) == 1;
  if (points) return tableSignal(*points, inlinePoints(*points), cubic);
  SignalTableColumn which;
  if (column) {
    const std::string text = column->text();
    if (const auto n = parseNumber(text)) {
      which.position = column->integer(2);
    } else {
      which.name = text;
    }
  }
  const std::string given = file->text();
  std::filesystem::path path = given;
  if (path.is_relative()) path = std::filesystem::path(body.file()).parent_path() / path;
  const std::string shown = "table file '" + given + "': ";
  Points read;
  try {
    read = readSignalTableFile(path.string(), which);
  } catch (const SceneError& e) {
    file->fail(shown + e.what());
  }
  try {
    return cubic ? Signal::cubicTable(std::move(read)) : Signal::table(std::move(read));
  } catch (const std::invalid_argument& e) {
    file->fail(shown + path.string() + ": " + e.what());
  }
}

// {expression: "text"} or {expression: {value, [derivative], [time_scale], [breakpoints]}}.
Signal readExpression(const Value& body) {
  const auto compile = [](const Value& v) {
    return TimeExpression(v.text(), v.parameters(), v.where(), v.path());
  };
  if (!body.node().IsMap()) return Signal::function(compile(body));
  const Map m(body, scene_keys::kExpressionSignal);
  TimeExpression value = compile(m.required("value"));
  std::function<double(double)> derivative;
  if (const auto d = m.get("derivative")) derivative = compile(*d);
  const double time_scale = m.get("time_scale") ? m.get("time_scale")->positive() : 1e-3;
  std::vector<double> breakpoints;
  if (const auto b = m.get("breakpoints")) {
    for (const Value& item : b->items("a sequence of times [s]")) {
      breakpoints.push_back(item.number());
      if (breakpoints.size() > 1 && !(breakpoints.back() > breakpoints[breakpoints.size() - 2]))
        item.fail("breakpoints must increase strictly: " + item.text() + " follows " +
                  numberText(breakpoints[breakpoints.size() - 2]));
    }
  }
  return guarded(body, [&] {
    return Signal::function(std::move(value), std::move(derivative), std::move(breakpoints),
                            time_scale);
  });
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
  if (kind == "table") return readTable(body);
  if (kind == "expression") return readExpression(body);
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
