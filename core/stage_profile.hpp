// Wall time per stage of the step, measured only when asked (Simulator::setProfiling /
// Dynamics::setProfiling), in the manner of Box2D's b2Profile. The stages are those of
// Dynamics::evaluate, in pipeline order, plus the advance of stateful friction after a step:
//   poses -> detect -> contact kinematics -> normal force -> friction -> assemble ->
//   unconstrained accelerations -> constraints (solve and joint reaction friction)
//   [-> friction states, once per step]
// Seconds are summed over every evaluation since profiling was switched on (an integrator
// makes 1-4 or more per step), read from std::chrono::steady_clock with one clock read per
// stage boundary (StageClock). Off (the default), nothing is timed and no clock is read.
// `fcl` is the part of `detect` spent inside FCL's narrowphase; `step`
// is whole Simulator::step calls, so step minus the stages is the integrator's own work,
// the divergence checks and the energy guard (an evaluation asked for by Simulator::current
// outside a step is in its stages but not in `step`).
// Not here: counts of contacts or integrator work (StepStats, core/simulator.hpp).
#pragma once

#include <array>
#include <chrono>
#include <cstddef>
#include <string_view>

namespace tribo {

enum class Stage : int {
  kPoses,              // rotations, world inertias, geometry poses
  kDetect,             // collision detection (broadphase, narrowphase)
  kContactKinematics,  // depth rate, slip
  kNormalForce,        // penalty normal force
  kFriction,           // friction laws (stateful ones: anchor lookup and state view)
  kAssemble,           // contact, spring and joint-force wrenches on the bodies
  kAccelerations,      // unconstrained accelerations: forces, gravity, gyroscopic terms
  kConstraints,        // constraint solve and joint friction under reaction load
  kFrictionStates,     // friction memory before and after a step (core/friction_states.hpp)
  kCount
};

inline constexpr std::size_t kStageCount = static_cast<std::size_t>(Stage::kCount);

// Snake-case name of a stage, e.g. "contact_kinematics" (for counters and output).
constexpr std::string_view stageName(Stage stage) {
  constexpr std::string_view kNames[kStageCount] = {
      "poses",    "detect",        "contact_kinematics", "normal_force",   "friction",
      "assemble", "accelerations", "constraints",        "friction_states"};
  return kNames[static_cast<std::size_t>(stage)];
}

struct StageProfile {
  std::array<double, kStageCount> seconds{};  // per stage, indexed by Stage [s]
  long evaluations = 0;                       // Dynamics::evaluate calls timed
  double fcl = 0.0;                           // inside FCL, part of seconds[kDetect] [s]
  double step = 0.0;                          // whole Simulator::step calls [s]

  double& operator[](Stage s) { return seconds[static_cast<std::size_t>(s)]; }
  double operator[](Stage s) const { return seconds[static_cast<std::size_t>(s)]; }
  // Sum over the stages [s].
  double total() const {
    double sum = 0.0;
    for (double s : seconds) sum += s;
    return sum;
  }
};

// Lap timer over a StageProfile: each lap() charges the time since the previous lap (or
// construction) to a stage. With a null profile it does nothing and reads no clock.
class StageClock {
 public:
  using Clock = std::chrono::steady_clock;
  explicit StageClock(StageProfile* profile) : profile_(profile) {
    if (profile_ != nullptr) last_ = Clock::now();
  }
  void lap(Stage stage) {
    if (profile_ == nullptr) return;
    const Clock::time_point now = Clock::now();
    (*profile_)[stage] += std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }

 private:
  StageProfile* profile_;
  Clock::time_point last_{};
};

}  // namespace tribo
