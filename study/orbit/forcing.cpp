#include "study/orbit/forcing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/prescribed_motion.hpp"
#include "study/orbit/periodic_orbit.hpp"

namespace tribo::study {

namespace {

constexpr double kWhole = 1e-9;  // relative tolerance of "a whole number of periods"
constexpr int kMostCycles = 64;  // q at most in P = q / f_min

bool whole(double x) { return std::abs(x - std::round(x)) <= kWhole * std::max(1.0, x); }

// The smallest P = q / f_min (q <= 64) that holds a whole number of cycles of every frequency,
// or -1.
double commonPeriod(const std::vector<double>& frequencies) {
  const double f_min = *std::min_element(frequencies.begin(), frequencies.end());
  for (int q = 1; q <= kMostCycles; ++q) {
    const double P = q / f_min;
    if (std::all_of(frequencies.begin(), frequencies.end(), [&](double f) { return whole(P * f); }))
      return P;
  }
  return -1.0;
}

std::string axisName(std::size_t i) { return std::string(1, "xyz"[i]); }

TimeInput ofSignal(std::string name, const Signal& s) {
  TimeInput in{std::move(name), 0.0, {}, &s};
  switch (s.kind()) {
    case Signal::Kind::kConstant:
      break;
    case Signal::Kind::kSines:
      for (const Signal::Sine& term : s.sineTerms())
        if (term.amplitude != 0.0 && term.frequency > 0.0) in.frequencies.push_back(term.frequency);
      if (!in.frequencies.empty()) in.period = commonPeriod(in.frequencies);
      break;
    case Signal::Kind::kRamp:
      // Constant when its rate is 0 (then value(0) is the constant everywhere).
      if (s.derivative(0.0) != 0.0 || s.value(0.0) != s.value(1.0)) in.period = -1.0;
      break;
    case Signal::Kind::kStep:
    case Signal::Kind::kSmoothStep:
    case Signal::Kind::kTable:
    case Signal::Kind::kCubicTable:
    case Signal::Kind::kFunction:
      in.period = -1.0;
      break;
  }
  return in;
}

}  // namespace

std::vector<TimeInput> timeInputs(const Model& m) {
  std::vector<TimeInput> all;
  auto add = [&](TimeInput in) {
    if (in.period != 0.0) all.push_back(std::move(in));
  };
  for (const AppliedLoad& load : m.loads)
    for (std::size_t i = 0; i < 3; ++i) {
      add(ofSignal("load '" + load.name + "' force " + axisName(i), load.force[i]));
      add(ofSignal("load '" + load.name + "' torque " + axisName(i), load.torque[i]));
    }
  for (const Joint& j : m.joints) {
    if (j.elements.actuator)
      add(ofSignal("joint '" + j.name + "' actuator target", j.elements.actuator->target));
    if (const auto& drive = j.elements.drive) {
      const std::string name = "joint '" + j.name + "' drive";
      if (drive->signal) {
        add(ofSignal(name, *drive->signal));
      } else {
        const DriveFunction& f = drive->function;
        TimeInput in{name, 0.0, {}, nullptr};
        if (f.slope != 0.0)
          in.period = -1.0;
        else if (f.amplitude != 0.0 && f.frequency != 0.0) {
          in.frequencies.push_back(std::abs(f.frequency) / (2 * std::numbers::pi));
          in.period = 1.0 / in.frequencies.back();
        }
        // A velocity drive of constant rate turns the joint steadily: constant in time here.
        add(std::move(in));
      }
    }
  }
  for (const Body& b : m.bodies) {
    if (b.surface_velocity_signal)
      for (std::size_t i = 0; i < 3; ++i)
        add(ofSignal("body '" + b.name + "' surface velocity " + axisName(i),
                     (*b.surface_velocity_signal)[i]));
    if (b.motion) {
      for (std::size_t i = 0; i < 3; ++i)
        add(ofSignal("body '" + b.name + "' motion velocity " + axisName(i),
                     b.motion->velocity[i]));
      add(ofSignal("body '" + b.name + "' motion spin rate", b.motion->spin_rate));
    }
  }
  return all;
}

std::string nonAutonomous(const Model& m) {
  const std::vector<TimeInput> inputs = timeInputs(m);
  if (inputs.empty()) return "";
  return inputs.front().name + " varies in time" +
         (inputs.size() > 1 ? " (and " + std::to_string(inputs.size() - 1) + " more inputs)" : "");
}

double forcingPeriod(const Model& m, double given) {
  const std::vector<TimeInput> inputs = timeInputs(m);
  if (inputs.empty())
    throw OrbitError(
        "the scene has no input that varies in time: its orbits are autonomous, with a "
        "period of their own (no --period)");
  if (given > 0.0) {
    for (const TimeInput& in : inputs) {
      if (in.period > 0.0) {
        if (!whole(given / in.period))
          throw OrbitError("--period " + std::to_string(given) + " s is not a whole number of " +
                           in.name + "'s periods (" + std::to_string(in.period) + " s)");
        continue;
      }
      if (!in.signal)
        throw OrbitError(in.name + " does not repeat (its slope is not 0): it has no period");
      // Repeats with `given`? 64 samples over one period from t = 0.
      double scale = 0.0, worst = 0.0;
      for (int i = 0; i < 64; ++i) {
        const double t = given * i / 64.0;
        const double a = in.signal->value(t), b = in.signal->value(t + given);
        scale = std::max({scale, std::abs(a), std::abs(b)});
        worst = std::max(worst, std::abs(a - b));
      }
      if (worst > kWhole * std::max(scale, 1e-300))
        throw OrbitError(in.name + " does not repeat with --period " + std::to_string(given) +
                         " s: its values one period apart differ by up to " +
                         std::to_string(worst) + " (of " + std::to_string(scale) + ")");
    }
    return given;
  }
  std::vector<double> frequencies;
  for (const TimeInput& in : inputs) {
    if (in.period < 0.0 && !in.frequencies.empty())
      throw OrbitError(in.name + "'s frequencies have no common period within " +
                       std::to_string(kMostCycles) +
                       " cycles of the lowest: give the forcing's period with --period");
    if (in.period < 0.0)
      throw OrbitError(in.name +
                       " varies in time with no period known (only sines and sine drives have "
                       "one): give the forcing's period with --period");
    frequencies.insert(frequencies.end(), in.frequencies.begin(), in.frequencies.end());
  }
  const double P = commonPeriod(frequencies);
  if (P < 0.0)
    throw OrbitError("the inputs' frequencies have no common period within " +
                     std::to_string(kMostCycles) +
                     " cycles of the lowest: give the forcing's period with --period");
  return P;
}

}  // namespace tribo::study
