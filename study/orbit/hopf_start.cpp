#include "study/orbit/hopf_start.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <string>
#include <unordered_map>

#include "study/orbit/periodic_orbit.hpp"
#include "study/orbit/shooting.hpp"

namespace tribo::study {
namespace {

struct Sample {
  double p = 0, growth = 0;
  ModesResult modes;
  const Mode* mode = nullptr;  // the leading oscillatory one, in modes
};

// Steady sliding's leading oscillatory mode at p.
Sample sampleAt(const std::function<io::Scene(double)>& sceneAt, double p) {
  Sample s;
  s.p = p;
  try {
    s.modes = analyzeModes(sceneAt(p));
  } catch (const std::exception& e) {
    throw OrbitError(
        "no Hopf point to start from: the modes analysis of steady sliding failed at " +
        shooting::messageNumber(p) + ": " + e.what());
  }
  for (const Mode& m : s.modes.modes)
    if (m.frequency > 0.0 && (!s.mode || m.growth_rate > s.mode->growth_rate)) s.mode = &m;
  if (!s.mode)
    throw OrbitError("no Hopf point to start from: steady sliding has no oscillatory mode at " +
                     shooting::messageNumber(p));
  s.growth = s.mode->growth_rate;
  return s;
}

}  // namespace

HopfPoint locateHopf(const std::function<io::Scene(double)>& sceneAt, double from, double to,
                     int samples) {
  HopfPoint h;
  samples = std::max(samples, 1);
  Sample lo = sampleAt(sceneAt, from);
  ++h.analyses;
  const double first_growth = lo.growth;
  Sample hi;
  bool bracketed = false;
  for (int i = 1; i <= samples && !bracketed; ++i) {
    hi = sampleAt(sceneAt, from + (to - from) * i / samples);
    ++h.analyses;
    if ((lo.growth > 0.0) != (hi.growth > 0.0)) {
      bracketed = true;
    } else {
      lo = std::move(hi);
      hi = Sample{};
    }
  }
  if (!bracketed)
    throw OrbitError(
        "no Hopf point between " + shooting::messageNumber(from) + " and " +
        shooting::messageNumber(to) +
        ": the growth rate of steady sliding's leading oscillatory mode keeps its sign (" +
        shooting::messageNumber(first_growth) + " 1/s at " + shooting::messageNumber(from) + ", " +
        shooting::messageNumber(lo.growth) + " 1/s at " + shooting::messageNumber(lo.p) +
        "); widen the range or start from an orbit");
  // Bisection: sigma(p) is smooth but its slope is not known, and 40 to 50 analyses of a
  // small scene cost milliseconds.
  const bool rising = hi.growth > 0.0;
  double a = lo.p, b = hi.p;
  Sample best = std::abs(lo.growth) < std::abs(hi.growth) ? std::move(lo) : std::move(hi);
  while (std::abs(b - a) > 1e-12 * std::max(1.0, std::abs(a))) {
    const double mid = 0.5 * (a + b);
    if (mid == a || mid == b) break;
    Sample s = sampleAt(sceneAt, mid);
    ++h.analyses;
    ((s.growth > 0.0) == rising ? b : a) = mid;
    if (std::abs(s.growth) <= std::abs(best.growth)) best = std::move(s);
  }
  h.parameter = best.p;
  h.omega = std::abs(best.mode->eigenvalue.imag());
  h.steady = best.modes.steady.state;
  h.shape = best.mode->shape;
  // A pair reported with omega < 0 has the conjugate shape: the phases change sign.
  if (best.mode->eigenvalue.imag() < 0.0)
    for (ShapeEntry& e : h.shape) e.phase_deg = -e.phase_deg;
  return h;
}

Eigen::VectorXd hopfDirection(const HopfPoint& hopf, const Model& model,
                              const OrbitCoordinates& coords, int body, int axis) {
  static const char* kAxes[] = {"x", "y", "z"};
  const std::string observed =
      model.bodies[static_cast<std::size_t>(body)].name + "." + kAxes[axis];
  const auto obs = std::find_if(hopf.shape.begin(), hopf.shape.end(),
                                [&](const ShapeEntry& e) { return e.coordinate == observed; });
  if (obs == hopf.shape.end() || !(obs->magnitude > 1e-9))
    throw OrbitError("the Hopf mode leaves the observed coordinate " + observed +
                     " at rest: observe a coordinate the mode moves (output.summary)");
  const double deg = std::numbers::pi / 180.0;
  Eigen::VectorXd e = Eigen::VectorXd::Zero(coords.size());
  // Each entry "BODY.c" once: c in x y z (translation, world) or rx ry rz (rotation vector,
  // world as the modes analysis takes it; the orbit's is in the body's reference frame), at
  // the mode's phase relative to the observed coordinate's.
  std::unordered_map<std::string, int> dynamic;  // name -> body index, dynamic bodies only
  for (std::size_t b = 0; b < model.bodies.size(); ++b)
    if (coords.positionIndex(static_cast<int>(b), 0) >= 0)
      dynamic.emplace(model.bodies[b].name, static_cast<int>(b));
  for (const ShapeEntry& s : hopf.shape) {
    const std::size_t dot = s.coordinate.rfind('.');
    const auto it =
        dot == std::string::npos ? dynamic.end() : dynamic.find(s.coordinate.substr(0, dot));
    if (it == dynamic.end()) continue;
    const std::string which = s.coordinate.substr(dot + 1);
    const bool rotation = which.size() == 2 && which[0] == 'r';
    const int k = which.back() - 'x';
    if (k < 0 || k > 2 || which.size() != (rotation ? 2u : 1u)) continue;
    const double phase = (s.phase_deg - obs->phase_deg) * deg;
    const double amp = s.magnitude / obs->magnitude;
    const Eigen::Index p = coords.positionIndex(it->second, 0) + (rotation ? 3 : 0);
    const Eigen::Index v = coords.velocityIndex(it->second, 0) + (rotation ? 3 : 0);
    e[p + k] = amp * std::cos(phase);
    e[v + k] = -hopf.omega * amp * std::sin(phase);
  }
  // The rotation entries from world axes into each body's reference frame.
  for (const auto& entry : dynamic) {
    const int b = entry.second;
    const Eigen::Index p = coords.positionIndex(b, 0) + 3;
    const Eigen::Matrix3d R0 =
        hopf.steady.bodies[static_cast<std::size_t>(b)].orientation.toRotationMatrix();
    e.segment<3>(p) = (R0.transpose() * e.segment<3>(p)).eval();
  }
  return e;
}

}  // namespace tribo::study
