// The applied-load part of the assemble stage (core/dynamics.hpp): each of the model's
// loads (core/applied_load.hpp, whose header has the equations) at the state's time into
// Workspace::load_wrench (per body) and Workspace::load_force (per load).
// What it saves over evaluating every load in full: its signals are sampled through a memo
// (core/signal_memo.hpp: once per distinct time, constants once), a force or torque whose
// components are all the constant 0 adds nothing, a force at the body origin adds no moment,
// and only loaded bodies' wrenches are zeroed. A load commanded from outside (setCommand) or
// perturbed (setOffset) takes the full path. The sums are those of the full evaluation, bit
// for bit (a zero added to a sum that starts at +0 changes no bit; a non-finite force may
// leave a different non-finite torque, which the guards stop either way).
// Not here: the loads' power in the energy account (core/energy.hpp), reading them (io/).
#pragma once

#include <optional>
#include <vector>

#include "core/model.hpp"
#include "core/signal_memo.hpp"
#include "core/state.hpp"
#include "core/workspace.hpp"

namespace tribo {

class AppliedLoads {
 public:
  explicit AppliedLoads(const Model& model);

  bool empty() const { return entries_.empty(); }
  // The loads at state.time, the bodies at `state` with their rotations in ws.rotation.
  void accumulate(const State& state, Workspace& ws);
  // Added to load i's force and torque (in its frame) from now on (Dynamics::setLoadOffset).
  void setOffset(std::size_t load, const Vec3& force, const Vec3& torque);
  // Load i's force and/or torque (in its frame) held at these values in place of its signals
  // from now on: a command from outside the model (a controller; Simulator::setLoadCommand).
  // std::nullopt gives that part back to its signals.
  void setCommand(std::size_t load, const std::optional<Vec3>& force,
                  const std::optional<Vec3>& torque);

 private:
  struct Entry {
    const AppliedLoad* load = nullptr;
    SignalVectorMemo force, torque;
    bool at_origin = false;  // point == 0: no moment
  };
  std::vector<Entry> entries_;
  std::vector<int> loaded_bodies_;  // each body with a load, once
  std::vector<Wrench> offsets_;     // per load (empty: none ever set)
  struct Command {
    std::optional<Vec3> force, torque;
  };
  std::vector<Command> commands_;  // per load (empty: none ever given)
};

}  // namespace tribo
