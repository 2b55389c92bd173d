#include "core/integrator.hpp"

#include <vector>

#include "core/prescribed_motion.hpp"
#include "core/stage_threads.hpp"
#include "core/sundials_integrators.hpp"

namespace tribo {

namespace {

// f(b) for every body b, split across the threads the scene's evaluation uses when its bodies
// pay for them (core/stage_threads.hpp). Each body's update reads and writes only its own
// entries, so the state is the same bit for bit for any number of threads.
template <class F>
void forEachBody(const Dynamics& dynamics, std::size_t bodies, F&& f) {
  contact::parallelFor(bodies, stageThreads(bodies, dynamics.threads()), f);
}

class SemiImplicitEuler final : public Integrator {
 public:
  IntegratorStatus step(Dynamics& dynamics, State& state, double h,
                        bool start_is_evaluated) override {
    if (!start_is_evaluated) ++counters_.evaluations;
    const Workspace& ws = start_is_evaluated ? dynamics.workspace() : dynamics.evaluate(state);
    forEachBody(dynamics, state.bodies.size(), [&](std::size_t b) {
      BodyState& s = state.bodies[b];
      s.velocity += h * ws.linear_acceleration[b];
      s.angular_velocity += h * ws.angular_acceleration[b];
      s.position += h * s.velocity;
      s.orientation = rotateBy(s.angular_velocity, h, s.orientation);
    });
    if (dynamics.frictionMemory().dynamic()) dynamics.stepFrictionMemory(state, h);
    state.time += h;
    ++counters_.steps;
    return {};
  }
  int evaluationsPerStep() const override { return 1; }
};

class RungeKutta4 final : public Integrator {
 public:
  explicit RungeKutta4(std::size_t n) : stage_(), rates_(4, std::vector<Rate>(n)), z_rates_(4) {}

  IntegratorStatus step(Dynamics& dynamics, State& state, double h,
                        bool start_is_evaluated) override {
    static constexpr double kStageTime[4] = {0.0, 0.5, 0.5, 1.0};
    static constexpr double kWeight[4] = {1.0 / 6.0, 2.0 / 6.0, 2.0 / 6.0, 1.0 / 6.0};
    stage_ = state;
    for (int k = 0; k < 4; ++k) {
      if (k > 0) {
        makeStage(dynamics, state, rates_[k - 1], z_rates_[k - 1], kStageTime[k] * h);
        // Kinematic bodies along signals at the stage's time exactly, not to the stage's
        // order (their velocity's curvature would err by h^2 v'' / 8 in the slip).
        placePrescribedBodies(dynamics.model().bodies, dynamics.prescribedBodies(), stage_);
      }
      const State& at = k == 0 ? state : stage_;
      const bool reuse = k == 0 && start_is_evaluated;
      if (!reuse) ++counters_.evaluations;
      const Workspace& ws = reuse ? dynamics.workspace() : dynamics.evaluate(at);
      std::vector<Rate>& rate = rates_[k];
      forEachBody(dynamics, at.bodies.size(), [&](std::size_t b) {
        const BodyState& s = at.bodies[b];
        rate[b] = {s.velocity, quaternionRate(s.angular_velocity, s.orientation),
                   ws.linear_acceleration[b], ws.angular_acceleration[b]};
      });
      // Dynamic friction states: their records are those of `state` in every stage.
      z_rates_[k].assign(ws.friction_state_rate.begin(), ws.friction_state_rate.end());
    }
    z_sum_.resize(z_rates_[0].size());
    for (std::size_t i = 0; i < z_sum_.size(); ++i)
      z_sum_[i] = kWeight[0] * z_rates_[0][i] + kWeight[1] * z_rates_[1][i] +
                  kWeight[2] * z_rates_[2][i] + kWeight[3] * z_rates_[3][i];
    addRates(state, z_sum_, h, state);
    forEachBody(dynamics, state.bodies.size(), [&](std::size_t b) {
      BodyState& s = state.bodies[b];
      Rate sum{};
      for (int k = 0; k < 4; ++k) {
        sum.dp += kWeight[k] * rates_[k][b].dp;
        sum.dq += kWeight[k] * rates_[k][b].dq;
        sum.dv += kWeight[k] * rates_[k][b].dv;
        sum.dw += kWeight[k] * rates_[k][b].dw;
      }
      s.position += h * sum.dp;
      s.orientation.coeffs() += h * sum.dq;
      s.orientation.normalize();
      s.velocity += h * sum.dv;
      s.angular_velocity += h * sum.dw;
    });
    state.time += h;
    ++counters_.steps;
    return {};
  }
  int evaluationsPerStep() const override { return 4; }

 private:
  struct Rate {
    Vec3 dp = Vec3::Zero();
    Eigen::Vector4d dq = Eigen::Vector4d::Zero();
    Vec3 dv = Vec3::Zero();
    Vec3 dw = Vec3::Zero();
  };

  void makeStage(const Dynamics& dynamics, const State& base, const std::vector<Rate>& rate,
                 const std::vector<double>& z_rate, double dt) {
    stage_.time = base.time + dt;
    addRates(base, z_rate, dt, stage_);
    forEachBody(dynamics, base.bodies.size(), [&](std::size_t b) {
      const BodyState& s = base.bodies[b];
      BodyState& o = stage_.bodies[b];
      o.position = s.position + dt * rate[b].dp;
      o.orientation.coeffs() = s.orientation.coeffs() + dt * rate[b].dq;
      o.orientation.normalize();
      o.velocity = s.velocity + dt * rate[b].dv;
      o.angular_velocity = s.angular_velocity + dt * rate[b].dw;
    });
  }

  State stage_;
  std::vector<std::vector<Rate>> rates_;
  std::vector<std::vector<double>> z_rates_;  // per stage, dz/dt of the friction states
  std::vector<double> z_sum_;                 // their weighted sum
};

}  // namespace

bool isAdaptive(IntegratorType type) {
  return type == IntegratorType::kDopri5 || type == IntegratorType::kBdf;
}

std::unique_ptr<Integrator> makeIntegrator(IntegratorType type, const Model& model) {
  switch (type) {
    case IntegratorType::kRk4:
      return std::make_unique<RungeKutta4>(model.bodies.size());
    case IntegratorType::kDopri5:
      return makeArkodeDopri5(model);
    case IntegratorType::kBdf:
      return makeCvodeBdf(model);
    case IntegratorType::kSemiImplicitEuler:
      break;
  }
  return std::make_unique<SemiImplicitEuler>();
}

}  // namespace tribo
