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
#include "study/orbit/orbit_coordinates.hpp"
#include "study/orbit/shooting.hpp"

namespace tribo::study {

using shooting::Flow;

OrbitResult findPeriodicOrbit(const io::Scene& scene, const OrbitSpec& spec) {
  const auto wall = std::chrono::steady_clock::now();
  const Model& model = *scene.model;
  const io::SummarySpec& watched = scene.output.summary;
  const int body = shooting::shootableBody(scene);
  const int axis = watched.coordinate;
  OrbitResult r;
  r.observed = watched.body + "." + std::string(1, "xyz"[axis]);

  const double settle = spec.settle > 0.0 ? spec.settle : model.options.duration;
  const shooting::Guess guess = shooting::settledGuess(scene.model, body, axis, settle);
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
  const Eigen::VectorXd floor = shooting::fdFloor(y, guess.state.friction_values.size());

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
    shooting::parallelColumns(n + 1, threads, column);
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
  shooting::Floquet f = shooting::floquet(monodromy);
  r.multipliers = std::move(f.multipliers);
  r.trivial = f.trivial;
  r.trivial_error = f.trivial_error;
  r.stable = f.stable;
  r.reference = guess.state;

  // One period sampled at the step, from the orbit's start (a maximum of x).
  const auto b = static_cast<std::size_t>(body);
  r.t.push_back(0.0);
  r.x.push_back(coords.fromVector(y).bodies[b].position[axis]);
  flow(y, T, [&](double t, const State& s) {
    r.t.push_back(t);
    r.x.push_back(s.bodies[b].position[axis]);
  });
  r.x_max = r.x.front();
  r.x_min = shooting::refinedMinimum(r.x);
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
