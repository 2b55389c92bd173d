#include "study/orbit/periodic_orbit.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "core/simulator.hpp"
#include "core/thread_count.hpp"
#include "study/orbit/orbit_coordinates.hpp"

namespace tribo::study {

namespace {

// Why the scene's motion depends on the time itself (so its orbits are forced ones), or empty.
std::string nonAutonomous(const Model& m) {
  if (!m.loads.empty()) return "it has applied loads";
  for (const Body& b : m.bodies) {
    if (b.kind == BodyKind::kKinematic &&
        (b.velocity.norm() > 0.0 || b.angular_velocity.norm() > 0.0))
      return "kinematic body '" + b.name + "' moves";
    if (b.surface_velocity_signal) return "body '" + b.name + "' has a surface velocity signal";
  }
  for (const Joint& j : m.joints) {
    if (j.elements.drive) return "joint '" + j.name + "' is driven";
    if (j.elements.actuator) return "joint '" + j.name + "' has an actuator";
  }
  return "";
}

// The flow of the scene's integrator: from y over T, with the last step shortened.
class Flow {
 public:
  Flow(std::shared_ptr<const Model> model, const OrbitCoordinates& coords)
      : model_(std::move(model)), coords_(coords), h_(model_->options.time_step) {}

  // y at T; `sample(t, state)` after each step if given. Throws OrbitError for a failed step.
  Eigen::VectorXd operator()(const Eigen::VectorXd& y, double T,
                             const std::function<void(double, const State&)>& sample = {}) const {
    long n = static_cast<long>(std::floor(T / h_));
    double rest = T - static_cast<double>(n) * h_;
    if (rest > h_ * (1 - 1e-9)) ++n, rest = 0.0;
    if (rest < h_ * 1e-9) rest = 0.0;
    Simulator sim(model_);
    State start = coords_.fromVector(y);
    const double t0 = start.time;
    sim.setState(start);
    for (long i = 0; i < n; ++i) {
      check(sim.step(), T);
      if (sample) sample(sim.state().time - t0, sim.state());
    }
    State end = sim.state();
    if (rest > 0.0) {
      auto last = std::make_shared<Model>(*model_);
      last->options.time_step = rest;
      Simulator tail(last);
      tail.setState(end);
      check(tail.step(), T);
      end = tail.state();
      if (sample) sample(T, end);
    }
    return coords_.toVector(end);
  }

 private:
  static void check(const StepStatus& s, double T) {
    if (!s.ok)
      throw OrbitError("a step of the shooting flow (period " + std::to_string(T) +
                       " s) failed: " + s.message);
  }
  std::shared_ptr<const Model> model_;
  const OrbitCoordinates& coords_;
  double h_;
};

// The last two maxima of the observed coordinate in a run of `seconds`: the state at the
// last one and the time between them (linear in the velocity's zero crossing).
struct Guess {
  State state;
  double period = 0, amplitude_pp = 0;
};

Guess settledGuess(const std::shared_ptr<const Model>& model, int body, int axis, double seconds) {
  Simulator sim(model);
  const auto b = static_cast<std::size_t>(body);
  std::vector<double> crossings;
  std::optional<State> last_state;
  double prev_v = sim.state().bodies[b].velocity[axis];
  double lo = 1e300, hi = -1e300, lo_prev = 1e300, hi_prev = -1e300;
  const double h = model->options.time_step;
  const long steps = static_cast<long>(std::ceil(seconds / h));
  for (long i = 0; i < steps; ++i) {
    const double t_prev = sim.state().time;
    const StepStatus s = sim.step();
    if (!s.ok) throw OrbitError("the settling run failed: " + s.message);
    const BodyState& now = sim.state().bodies[b];
    const double v = now.velocity[axis];
    lo = std::min(lo, now.position[axis]);
    hi = std::max(hi, now.position[axis]);
    if (prev_v > 0.0 && v <= 0.0) {
      crossings.push_back(t_prev + (sim.state().time - t_prev) * prev_v / (prev_v - v));
      last_state = sim.state();
      lo_prev = lo, hi_prev = hi;
      lo = 1e300, hi = -1e300;
    }
    prev_v = v;
  }
  if (crossings.size() < 3)
    throw OrbitError("the observed coordinate has " + std::to_string(crossings.size()) +
                     " maxima in the settling run of " + std::to_string(seconds) +
                     " s, fewer than 3: no oscillation to shoot for (steady sliding is stable "
                     "here, or give a longer --settle)");
  Guess g;
  g.state = *last_state;
  g.period = crossings.back() - crossings[crossings.size() - 2];
  g.amplitude_pp = hi_prev - lo_prev;
  return g;
}

// The smallest value of x by a parabola through the smallest sample and its neighbours.
double refinedMinimum(const std::vector<double>& x) {
  const auto it = std::min_element(x.begin(), x.end());
  const auto i = static_cast<std::size_t>(it - x.begin());
  if (i == 0 || i + 1 >= x.size()) return *it;
  const double a = x[i - 1], b = x[i], c = x[i + 1], d = a - 2 * b + c;
  if (d <= 0.0) return b;
  return b - (a - c) * (a - c) / (8.0 * d);
}

}  // namespace

OrbitResult findPeriodicOrbit(const io::Scene& scene, const OrbitSpec& spec) {
  const auto wall = std::chrono::steady_clock::now();
  const Model& model = *scene.model;
  const io::SummarySpec& watched = scene.output.summary;
  if (watched.body.empty() || !watched.channel.empty())
    throw OrbitError(
        "the scene's summary observes no body coordinate (output.summary.body and "
        "coordinate): the orbit's phase is taken where that coordinate peaks");
  const auto body_it = std::find_if(model.bodies.begin(), model.bodies.end(),
                                    [&](const Body& b) { return b.name == watched.body; });
  if (body_it == model.bodies.end() || body_it->kind != BodyKind::kDynamic)
    throw OrbitError("the observed body '" + watched.body + "' is not a dynamic body");
  if (const std::string why = nonAutonomous(model); !why.empty())
    throw OrbitError("the scene is not autonomous (" + why +
                     "): its orbits are forced, with the forcing's period, which shooting for a "
                     "free period does not handle");
  const IntegratorType integrator = model.options.integrator;
  if (integrator != IntegratorType::kRk4 && integrator != IntegratorType::kSemiImplicitEuler)
    throw OrbitError("shooting needs a fixed-step integrator (rk4 or semi_implicit_euler), not " +
                     integratorName(integrator));
  const int body = static_cast<int>(body_it - model.bodies.begin());
  const int axis = watched.coordinate;
  OrbitResult r;
  r.observed = watched.body + "." + std::string(1, "xyz"[axis]);

  const double settle = spec.settle > 0.0 ? spec.settle : model.options.duration;
  const Guess guess = settledGuess(scene.model, body, axis, settle);
  r.guess_period = guess.period;
  r.guess_amplitude_pp = guess.amplitude_pp;
  const OrbitCoordinates coords(model, guess.state);
  const Flow flow(scene.model, coords);
  const Eigen::Index n = coords.size();
  const Eigen::Index phase = coords.velocityIndex(body, axis);
  r.coordinates = coords.names();

  Eigen::VectorXd y = coords.toVector(guess.state);
  double T = guess.period;
  const unsigned threads =
      std::max(1u, spec.threads ? spec.threads : std::thread::hardware_concurrency());

  // The finite-difference steps: relative to each unknown, with a floor per kind (1 cm, 1 cm/s
  // and 10 mrad for bodies; the largest friction state for those).
  Eigen::VectorXd floor = Eigen::VectorXd::Constant(n, 1e-2);
  const Eigen::Index bodies_end = n - static_cast<Eigen::Index>(guess.state.friction_values.size());
  if (bodies_end < n)
    floor.tail(n - bodies_end)
        .setConstant(std::max(1e-12, y.tail(n - bodies_end).cwiseAbs().maxCoeff()));

  Eigen::MatrixXd monodromy(n, n);
  Eigen::VectorXd along(n);
  auto jacobian = [&] {
    // Column j < n: d phi / d y_j; column n: d phi / d T. Columns split over the threads.
    auto column = [&](Eigen::Index j) {
      // Central differences: second order, so the trivial multiplier's error shows the
      // flow's accuracy rather than the difference's.
      if (j < n) {
        const double d = spec.fd_step * std::max(std::abs(y[j]), floor[j]);
        Eigen::VectorXd up = y, down = y;
        up[j] += d;
        down[j] -= d;
        monodromy.col(j) = (flow(up, T) - flow(down, T)) / (2 * d);
      } else {
        const double d = spec.fd_step * T;
        along = (flow(y, T + d) - flow(y, T - d)) / (2 * d);
      }
    };
    std::vector<std::thread> pool;
    std::vector<std::exception_ptr> errors(threads);
    for (unsigned w = 1; w < threads; ++w)
      pool.emplace_back([&, w] {
        const ScopedThreadLimit one_each(1);  // the columns share the cores
        try {
          for (Eigen::Index j = w; j <= n; j += threads) column(j);
        } catch (...) {
          errors[w] = std::current_exception();
        }
      });
    try {
      const ScopedThreadLimit one_each(threads > 1 ? 1 : 0);
      for (Eigen::Index j = 0; j <= n; j += threads) column(j);
    } catch (...) {
      errors[0] = std::current_exception();
    }
    for (auto& t : pool) t.join();
    for (auto& e : errors)
      if (e) std::rethrow_exception(e);
  };

  bool converged = false;
  for (int it = 0;; ++it) {
    const Eigen::VectorXd end = flow(y, T);
    Eigen::VectorXd F(n + 1);
    F.head(n) = end - y;
    F[n] = y[phase];
    r.residual = F.norm() / (1.0 + y.norm());
    r.iterations = it;
    jacobian();  // also the monodromy at the final point
    if (r.residual <= spec.tolerance) {
      converged = true;
      break;
    }
    if (it == spec.max_iterations) break;
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n + 1, n + 1);
    J.topLeftCorner(n, n) = monodromy - Eigen::MatrixXd::Identity(n, n);
    J.topRightCorner(n, 1) = along;
    J(n, phase) = 1.0;
    Eigen::VectorXd dz = J.colPivHouseholderQr().solve(-F);
    // A damped step: the period changes by at most a quarter of itself.
    const double scale = std::min(1.0, 0.25 * T / std::max(std::abs(dz[n]), 1e-300));
    y += scale * dz.head(n);
    T += scale * dz[n];
    if (!(T > 0.0) || !y.allFinite())
      throw OrbitError("Newton's iteration left the orbit (period " + std::to_string(T) +
                       " s): start from a run closer to it (a longer --settle)");
  }
  if (!converged)
    throw OrbitError("Newton's iteration did not converge in " +
                     std::to_string(spec.max_iterations) + " iterations (residual " +
                     std::to_string(r.residual) +
                     "): the orbit may not be isolated, or the "
                     "finite differences are too coarse for it");

  r.period = T;
  r.start = y;
  Eigen::EigenSolver<Eigen::MatrixXd> eig(monodromy, false);
  for (Eigen::Index i = 0; i < eig.eigenvalues().size(); ++i)
    r.multipliers.push_back(eig.eigenvalues()[i]);
  std::sort(r.multipliers.begin(), r.multipliers.end(),
            [](auto a, auto b) { return std::abs(a) > std::abs(b); });
  double nearest = 1e300;
  for (std::size_t i = 0; i < r.multipliers.size(); ++i)
    if (std::abs(r.multipliers[i] - 1.0) < nearest)
      nearest = std::abs(r.multipliers[i] - 1.0), r.trivial = static_cast<int>(i);
  r.trivial_error = nearest;
  r.stable = true;
  for (std::size_t i = 0; i < r.multipliers.size(); ++i)
    if (static_cast<int>(i) != r.trivial && std::abs(r.multipliers[i]) >= 1.0) r.stable = false;

  // One period sampled at the step, from the orbit's start (a maximum of x).
  const auto b = static_cast<std::size_t>(body);
  r.t.push_back(0.0);
  r.x.push_back(coords.fromVector(y).bodies[b].position[axis]);
  flow(y, T, [&](double t, const State& s) {
    r.t.push_back(t);
    r.x.push_back(s.bodies[b].position[axis]);
  });
  r.x_max = r.x.front();
  r.x_min = refinedMinimum(r.x);
  r.amplitude_pp = r.x_max - r.x_min;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count();
  return r;
}

std::string orbitJsonText(const io::Scene& scene, const OrbitSpec& spec, const OrbitResult& r) {
  nlohmann::ordered_json j;
  j["scene"] = scene.path;
  nlohmann::ordered_json params = nlohmann::ordered_json::object();
  for (const auto& [name, value] : scene.parameters) params[name] = value;
  j["parameters"] = params;
  j["observed"] = r.observed;
  j["period"] = r.period;
  j["frequency_hz"] = 1.0 / r.period;
  j["amplitude_pp"] = r.amplitude_pp;
  j["x_max"] = r.x_max;
  j["x_min"] = r.x_min;
  j["stable"] = r.stable;
  nlohmann::ordered_json mu = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < r.multipliers.size(); ++i)
    mu.push_back({{"re", r.multipliers[i].real()},
                  {"im", r.multipliers[i].imag()},
                  {"modulus", std::abs(r.multipliers[i])},
                  {"trivial", static_cast<int>(i) == r.trivial}});
  j["multipliers"] = mu;
  j["trivial_multiplier_error"] = r.trivial_error;
  j["newton"] = {{"iterations", r.iterations},
                 {"residual", r.residual},
                 {"tolerance", spec.tolerance},
                 {"fd_step", spec.fd_step}};
  j["guess"] = {{"settle", spec.settle > 0.0 ? spec.settle : scene.model->options.duration},
                {"period", r.guess_period},
                {"amplitude_pp", r.guess_amplitude_pp}};
  j["integrator"] = integratorName(scene.model->options.integrator);
  j["time_step"] = scene.model->options.time_step;
  nlohmann::ordered_json start = nlohmann::ordered_json::object();
  for (std::size_t i = 0; i < r.coordinates.size(); ++i)
    start[r.coordinates[i]] = r.start[static_cast<Eigen::Index>(i)];
  j["start"] = start;
  j["seconds"] = r.seconds;
  return j.dump(2);
}

}  // namespace tribo::study
