// A run restarted from a copy of its State continues bit for bit (fixed-step methods: the
// State is all a run needs). Shared by the scene tests of stateful friction.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "core/simulator.hpp"

namespace tribo::test {

// Runs `model` to `t_save`, copies the state into a second simulator, steps both `steps`
// times and expects identical friction states, positions and velocities. The saved state
// must hold friction records: `records` of them when given (> 0).
inline void expectRestartContinuesBitForBit(const std::shared_ptr<const Model>& model,
                                            double t_save, int steps, const std::string& label,
                                            std::size_t records = 0) {
  Simulator a(model);
  while (a.state().time < t_save) ASSERT_TRUE(a.step().ok) << label;
  const State saved = a.state();
  ASSERT_FALSE(saved.friction_states.empty()) << label;
  if (records > 0) {
    ASSERT_EQ(saved.friction_states.size(), records) << label;
  }
  Simulator b(model);
  b.setState(saved);
  for (int i = 0; i < steps; ++i) {
    ASSERT_TRUE(a.step().ok) << label;
    ASSERT_TRUE(b.step().ok) << label;
  }
  EXPECT_EQ(a.state().friction_values, b.state().friction_values) << label;
  for (std::size_t i = 0; i < a.state().bodies.size(); ++i) {
    EXPECT_EQ(a.state().bodies[i].position, b.state().bodies[i].position) << label;
    EXPECT_EQ(a.state().bodies[i].velocity, b.state().bodies[i].velocity) << label;
  }
}

}  // namespace tribo::test
