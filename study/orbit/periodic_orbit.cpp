#include "study/orbit/periodic_orbit.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "core/integrator.hpp"
#include "core/simulator.hpp"
#include "study/orbit/forcing.hpp"
#include "study/orbit/krylov.hpp"
#include "study/orbit/orbit_coordinates.hpp"
#include "study/orbit/picard.hpp"
#include "study/orbit/shooting.hpp"

namespace tribo::study {

using shooting::Flow;

namespace {

// For a Newton iteration that stalled on an adaptive integrator's flow: its error control
// makes the flow smooth only to about rtol, so a residual stuck near rtol asks for a tighter
// rtol (or a looser --tolerance); empty otherwise.
std::string adaptiveHint(const Model& model, double tolerance, double residual) {
  const double rtol = model.options.relative_tolerance;
  if (!isAdaptive(model.options.integrator) || !(residual < 1e3 * rtol)) return "";
  return "; with " + integratorName(model.options.integrator) +
         " the flow is accurate to "
         "about its rtol (" +
         shooting::messageNumber(rtol) + "), above the tolerance (" +
         shooting::messageNumber(tolerance) + "): set simulation.rtol near " +
         shooting::messageNumber(0.1 * tolerance) + " or raise --tolerance";
}

// An autonomous orbit whose amplitude is below this fraction of the settling run's is an
// equilibrium Newton found instead (the same bound continuation uses, orbit_branch.cpp).
constexpr double kEquilibrium = 1e-6;

// A multiplier other than the trivial one closer to the unit circle than the flow can tell
// (ten times the trivial one's error, at least 1e-6) leaves the orbit's stability undecided:
// the orbit lies in a family (a conservative motion, a state the dynamics leave free), and
// "stable" would be a guess. Such an orbit is reported neutral, not stable.
void markNeutral(OrbitResult& r) {
  r.neutral = shooting::undecidedStability(r.multipliers, r.trivial, r.trivial_error);
  if (r.neutral) r.stable = false;
}

unsigned threadsOf(const OrbitSpec& spec) {
  return std::max(1u, spec.threads ? spec.threads : std::thread::hardware_concurrency());
}

// Relative accuracy GMRES solves Newton's step to, and the products it may spend on one step.
constexpr double kGmresTolerance = 1e-8;
constexpr int kGmresMostProducts = 400;
// Arnoldi's tolerance on the leading multipliers.
constexpr double kArnoldiTolerance = 1e-8;

bool useKrylov(const OrbitSpec& spec, Eigen::Index unknowns) {
  if (spec.solver == OrbitSolver::kAuto) return unknowns >= kKrylovFromUnknowns;
  return spec.solver == OrbitSolver::kKrylov;
}

// Each unknown's scale: its size, with the finite differences' floor.
Eigen::VectorXd scalesOf(const Eigen::VectorXd& y, const Eigen::VectorXd& floor) {
  return y.cwiseAbs().cwiseMax(floor);
}

// The leading multipliers by Arnoldi on D^-1 M D (the same eigenvalues as the monodromy M;
// D the unknowns' scales), each product a central difference of two flows.
shooting::Floquet leadingFloquet(const Flow& flow, const Eigen::VectorXd& y, double T,
                                 const Eigen::VectorXd& scale, const OrbitSpec& spec,
                                 bool autonomous, OrbitResult& r) {
  const Eigen::Index n = y.size();
  const Eigen::Index count = std::min<Eigen::Index>(spec.leading_multipliers, n - 2);
  const krylov::Product monodromy = [&](const Eigen::VectorXd& u) {
    const double size = u.cwiseAbs().maxCoeff();
    if (size == 0.0) return Eigen::VectorXd(Eigen::VectorXd::Zero(n));
    const double eps = spec.fd_step / size;
    const Eigen::VectorXd v = scale.cwiseProduct(u);
    return Eigen::VectorXd(
        ((flow(y + eps * v, T) - flow(y - eps * v, T)) / (2 * eps)).cwiseQuotient(scale));
  };
  try {
    const krylov::Leading leading =
        krylov::leadingEigenvalues(monodromy, n, count, kArnoldiTolerance);
    r.krylov_products += leading.products;
    return shooting::classify(leading.values, autonomous);
  } catch (const std::runtime_error& e) {
    throw OrbitError(std::string("the orbit converged, but its multipliers did not: ") + e.what() +
                     " (--solver dense computes all of them)");
  }
}

// Newton's step dz with J dz = -F by GMRES on the scaled system (rows and columns by the
// unknowns' scales, so that metres, radians and bristle deflections weigh alike).
// `apply(v)` is J v.
Eigen::VectorXd krylovStep(const krylov::Product& apply, const Eigen::VectorXd& F,
                           const Eigen::VectorXd& column_scale, const Eigen::VectorXd& row_scale,
                           OrbitResult& r) {
  const krylov::Product scaled = [&](const Eigen::VectorXd& u) {
    return Eigen::VectorXd(apply(column_scale.cwiseProduct(u)).cwiseQuotient(row_scale));
  };
  const krylov::Solution sol =
      krylov::gmres(scaled, -F.cwiseQuotient(row_scale), kGmresTolerance, kGmresMostProducts);
  r.krylov_products += sol.products;
  if (!sol.converged)
    throw OrbitError("GMRES did not solve Newton's step in " + std::to_string(sol.products) +
                     " products (relative error " + std::to_string(sol.error) +
                     "): --solver dense factorizes the whole Jacobian instead");
  return column_scale.cwiseProduct(sol.x);
}

// The observed coordinate over one period from y (r.t, r.x) and its extremes.
void sampleOrbit(const Flow& flow, const OrbitCoordinates& coords, const Eigen::VectorXd& y,
                 double T, int body, int axis, OrbitResult& r) {
  shooting::SampledPeriod p = shooting::samplePeriod(flow, coords, y, T, body, axis, r.forced);
  r.t = std::move(p.t);
  r.x = std::move(p.x);
  r.x_max = p.x_max;
  r.x_min = p.x_min;
  r.amplitude_pp = r.x_max - r.x_min;
}

// The forced orbit: unknowns the state at a whole number of forcing periods, the period fixed
// (periodic_orbit.hpp).
void forcedOrbit(const io::Scene& scene, const OrbitSpec& spec, int body, int axis,
                 OrbitResult& r) {
  const Model& model = *scene.model;
  r.forced = true;
  r.forcing = nonAutonomous(model);
  r.forcing_period = forcingPeriod(model, spec.period);
  r.periods = spec.periods;
  const double T = spec.periods * r.forcing_period;
  const double settle = spec.settle > 0.0 ? spec.settle : model.options.duration;
  const double cycles = std::max(1.0, std::ceil(settle / T - 1e-9));
  if (cycles > 1e7)
    throw OrbitError("the settling run of " + std::to_string(settle) + " s holds more than 1e7 " +
                     "periods of " + std::to_string(T) + " s: give a shorter --settle");
  // The settling run: whole periods, so that its end has the forcing's phase at t = 0; the
  // last period's extremes are the guess's amplitude, and how far it returns to its start
  // tells a response that repeats from one that does not.
  const auto b = static_cast<std::size_t>(body);
  double lo = 1e300, hi = -1e300;
  State before_last = Simulator(scene.model).state();
  if (cycles > 1.0) before_last = shooting::advance(scene.model, before_last, (cycles - 1.0) * T);
  const State settled =
      shooting::advance(scene.model, before_last, T, [&](double, const State& st) {
        lo = std::min(lo, st.bodies[b].position[axis]);
        hi = std::max(hi, st.bodies[b].position[axis]);
      });
  r.guess_period = T;
  r.guess_amplitude_pp = hi - lo;
  r.guess_seconds = cycles * T;
  const OrbitCoordinates coords(model, settled);
  const Flow flow(scene.model, coords);
  const Eigen::Index n = coords.size();
  r.coordinates = coords.names();
  Eigen::VectorXd y = coords.toVector(settled);
  std::string settled_return = "unknown: contacts came or went";
  try {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g",
                  (y - coords.toVector(before_last)).norm() / (1.0 + y.norm()));
    settled_return = text;
  } catch (const std::runtime_error&) {
  }
  const Eigen::VectorXd floor = shooting::fdFloor(y, settled.friction_values.size());
  const bool krylov = useKrylov(spec, n);
  r.solver = krylov ? "krylov" : "dense";
  Eigen::MatrixXd monodromy(krylov ? 0 : n, krylov ? 0 : n);
  if (spec.return_map)
    r.picard_iterations = shooting::picardForced(flow, y, T, spec.tolerance).iterations;
  // Newton's step, least squares: the joints' constraints make M - I singular in the
  // directions they remove.
  auto denseStep = [&](const Eigen::VectorXd& F) {
    return Eigen::VectorXd(
        shooting::closingJacobian(monodromy, nullptr, 0).colPivHouseholderQr().solve(-F));
  };
  bool converged = false;
  for (int it = 0;; ++it) {
    const Eigen::VectorXd end = flow(y, T);
    const Eigen::VectorXd F = end - y;
    r.residual = F.norm() / (1.0 + y.norm());
    r.iterations = it;
    if (r.residual <= spec.tolerance) {
      r.flows_to_converge = flow.count();
      r.periods_to_converge = flow.integrated() / T;
    }
    if (!krylov)
      shooting::parallelColumns(n, threadsOf(spec), [&](Eigen::Index j) {
        const double d = spec.fd_step * std::max(std::abs(y[j]), floor[j]);
        Eigen::VectorXd up = y, down = y;
        up[j] += d;
        down[j] -= d;
        monodromy.col(j) = (flow(up, T) - flow(down, T)) / (2 * d);
      });
    if (r.residual <= spec.tolerance) {
      converged = true;
      if (!krylov) {
        // One more step with the monodromy at hand, kept if it lowers the residual (as for
        // the autonomous orbit).
        const Eigen::VectorXd y2 = y + denseStep(F);
        if (y2.allFinite()) {
          if (const double res2 = (flow(y2, T) - y2).norm() / (1.0 + y2.norm());
              res2 < r.residual) {
            y = y2;
            r.residual = res2;
          }
        }
      }
      break;
    }
    if (it == spec.max_iterations) break;
    if (krylov) {
      // (M - I) v by a forward difference of the flow: one flow per product.
      const Eigen::VectorXd scale = scalesOf(y, floor);
      const krylov::Product apply = [&](const Eigen::VectorXd& v) {
        const double size = v.cwiseQuotient(scale).cwiseAbs().maxCoeff();
        if (size == 0.0) return Eigen::VectorXd(Eigen::VectorXd::Zero(n));
        const double eps = spec.fd_step / size;
        return Eigen::VectorXd((flow(y + eps * v, T) - end) / eps - v);
      };
      y += krylovStep(apply, F, scale, scale, r);
    } else {
      y += denseStep(F);
    }
    if (!y.allFinite())
      throw OrbitError(
          "Newton's iteration left the orbit: start from a run closer to it (a "
          "longer --settle)");
  }
  if (!converged)
    throw OrbitError("Newton's iteration did not converge in " +
                     std::to_string(spec.max_iterations) + " iterations (residual " +
                     std::to_string(r.residual) +
                     "; the settling run's last period returned "
                     "to within " +
                     settled_return +
                     " of its start): the response may not repeat with this period (a "
                     "subharmonic wants --periods, a quasi-periodic or chaotic one has none; a "
                     "longer --settle brings the guess closer)" +
                     adaptiveHint(model, spec.tolerance, r.residual));
  r.period = T;
  r.start = y;
  if (!krylov) r.monodromy = monodromy;
  shooting::Floquet f = krylov ? leadingFloquet(flow, y, T, scalesOf(y, floor), spec, false, r)
                               : shooting::floquet(monodromy, false);
  r.multipliers = std::move(f.multipliers);
  r.stable = f.stable;
  r.largest_multiplier = f.largest;
  markNeutral(r);
  r.reference = settled;
  sampleOrbit(flow, coords, y, T, body, axis, r);
  r.flows = flow.count();
}

}  // namespace

OrbitResult findPeriodicOrbit(const io::Scene& scene, const OrbitSpec& given) {
  OrbitSpec spec = given;
  spec.fd_step = shooting::fdStepFor(*scene.model, given.fd_step);
  const auto wall = std::chrono::steady_clock::now();
  const Model& model = *scene.model;
  const io::SummarySpec& watched = scene.output.summary;
  const int body = shooting::observedBody(scene);
  const int axis = watched.coordinate;
  OrbitResult r;
  r.observed = watched.body + "." + std::string(1, "xyz"[axis]);
  if (spec.periods < 1) throw OrbitError("periods must be >= 1");
  if (!nonAutonomous(model).empty()) {
    forcedOrbit(scene, spec, body, axis, r);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count();
    return r;
  }
  if (spec.period > 0.0 || spec.periods != 1)
    throw OrbitError(
        "--period and --periods apply to forced scenes; this one is autonomous (no input "
        "varies in time), its orbit's period is an unknown");

  const double settle = spec.settle > 0.0 ? spec.settle : model.options.duration;
  const shooting::Guess guess = shooting::settledGuess(scene.model, body, axis, settle);
  r.guess_period = guess.period;
  r.guess_amplitude_pp = guess.amplitude_pp;
  r.guess_seconds = guess.seconds;
  const OrbitCoordinates coords(model, guess.state);
  const Flow flow(scene.model, coords);
  const Eigen::Index n = coords.size();
  const Eigen::Index phase = coords.velocityIndex(body, axis);
  r.coordinates = coords.names();

  Eigen::VectorXd y = coords.toVector(guess.state);
  double T = guess.period;
  const unsigned threads = threadsOf(spec);

  // The finite-difference steps: relative to each unknown, with a floor per kind (1 cm, 1 cm/s
  // and 10 mrad for bodies; the largest friction state for those).
  const Eigen::VectorXd floor = shooting::fdFloor(y, guess.state.friction_values.size());

  const bool krylov = useKrylov(spec, n);
  r.solver = krylov ? "krylov" : "dense";
  Eigen::MatrixXd monodromy(krylov ? 0 : n, krylov ? 0 : n);
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

  // Return-map iterations first: a stick-slip orbit converges in two or three of them
  // (study/orbit/picard.hpp); Newton's method takes over where they do not shrink the
  // residual fast.
  double picard_residual = INFINITY;
  if (spec.return_map) {
    const shooting::PicardOutcome o =
        shooting::picardAutonomous(flow, y, T, phase, model.options.time_step, spec.tolerance);
    r.picard_iterations = o.iterations;
    picard_residual = o.residual;
  }
  // Newton's step from the dense Jacobian (the monodromy less I, the T column, the phase row),
  // least squares: the joints' constraints make it singular in the directions they remove.
  auto denseStep = [&](const Eigen::VectorXd& F) {
    return Eigen::VectorXd(
        shooting::closingJacobian(monodromy, &along, phase).colPivHouseholderQr().solve(-F));
  };
  bool converged = false;
  try {
    for (int it = 0;; ++it) {
      const Eigen::VectorXd end = flow(y, T);
      Eigen::VectorXd F(n + 1);
      F.head(n) = end - y;
      F[n] = y[phase];
      r.residual = F.norm() / (1.0 + y.norm());
      r.iterations = it;
      if (r.residual <= spec.tolerance) {
        r.flows_to_converge = flow.count();
        r.periods_to_converge = flow.integrated() / T;
      }
      if (!krylov) jacobian();  // also the monodromy at the final point
      if (r.residual <= spec.tolerance) {
        converged = true;
        if (!krylov) {
          // One more step with the Jacobian at hand (the multipliers' anyway), kept if it
          // lowers the residual: return-map iterations stop at the tolerance.
          const Eigen::VectorXd dz = denseStep(F);
          const Eigen::VectorXd y2 = y + dz.head(n);
          const double T2 = T + dz[n];
          if (y2.allFinite() && T2 > 0.0) {
            Eigen::VectorXd F2(n + 1);
            F2.head(n) = flow(y2, T2) - y2;
            F2[n] = y2[phase];
            if (const double res2 = F2.norm() / (1.0 + y2.norm()); res2 < r.residual) {
              y = y2;
              T = T2;
              r.residual = res2;
            }
          }
        }
        break;
      }
      if (it == spec.max_iterations) break;
      Eigen::VectorXd dz;
      if (krylov) {
        // J (v, v_T) = ((phi_{T + eps v_T}(y + eps v) - phi_T(y)) / eps - v, v_phase): one flow
        // per product.
        Eigen::VectorXd scale(n + 1);
        scale << scalesOf(y, floor), T;
        Eigen::VectorXd row_scale = scale;
        row_scale[n] = scale[phase];
        const krylov::Product apply = [&](const Eigen::VectorXd& v) {
          Eigen::VectorXd out(n + 1);
          const double size = v.cwiseQuotient(scale).cwiseAbs().maxCoeff();
          if (size == 0.0) return Eigen::VectorXd(Eigen::VectorXd::Zero(n + 1));
          const double eps = spec.fd_step / size;
          out.head(n) = (flow(y + eps * v.head(n), T + eps * v[n]) - end) / eps - v.head(n);
          out[n] = v[phase];
          return out;
        };
        dz = krylovStep(apply, F, scale, row_scale, r);
      } else {
        dz = denseStep(F);
      }
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
                       "finite differences are too coarse for it" +
                       adaptiveHint(model, spec.tolerance, r.residual));
  } catch (const OrbitError& e) {
    // Return-map iterations that stalled close to the tolerance and a Newton's method that
    // then failed: the sign of an orbit in a family (a second multiplier at 1, as of a
    // conservative motion), where the iterations stop contracting and Newton's system is
    // singular. Say so, and what accepts the orbit they reached.
    if (!(picard_residual <= 1e3 * spec.tolerance)) throw;
    throw OrbitError(std::string(e.what()) + "; the return-map iterations had come within " +
                     shooting::messageNumber(picard_residual) +
                     " and stalled: the orbit may be one of a family (a second multiplier at "
                     "1, as of a conservative motion), which leaves Newton's system singular; "
                     "--tolerance " +
                     shooting::messageNumber(2 * picard_residual) +
                     " accepts the orbit they reached");
  }

  r.period = T;
  r.start = y;
  if (!krylov) {
    r.monodromy = monodromy;
    r.period_column = along;
  }
  shooting::Floquet f = krylov ? leadingFloquet(flow, y, T, scalesOf(y, floor), spec, true, r)
                               : shooting::floquet(monodromy);
  r.multipliers = std::move(f.multipliers);
  r.trivial = f.trivial;
  r.trivial_error = f.trivial_error;
  r.stable = f.stable;
  r.largest_multiplier = f.largest;
  markNeutral(r);
  r.reference = guess.state;

  // One period sampled at the step, from the orbit's start (a maximum of x).
  sampleOrbit(flow, coords, y, T, body, axis, r);
  // An equilibrium closes on itself for any T: a settling run whose oscillation was decaying
  // leads Newton onto it, and its "orbit" is a point (its "trivial" multiplier is then no
  // check at all). Refused where the amplitude is below kEquilibrium of the settling run's,
  // or within a hundred times Newton's tolerance of nothing (a settling run that had already
  // decayed to rounding gives a guess of that size too).
  const double size = 1.0 + std::max(std::abs(r.x_max), std::abs(r.x_min));
  if (!(r.amplitude_pp > kEquilibrium * r.guess_amplitude_pp) ||
      !(r.amplitude_pp > 100.0 * spec.tolerance * size))
    throw OrbitError("the orbit found is an equilibrium (amplitude " +
                     shooting::messageNumber(r.amplitude_pp) + " in " + r.observed +
                     " against the settling run's " +
                     shooting::messageNumber(r.guess_amplitude_pp) +
                     "): the oscillation decays here; a limit cycle needs other settings, or a "
                     "longer --settle if the run had not yet reached one");
  r.flows = flow.count();
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
  j["neutral"] = r.neutral;
  j["largest_multiplier"] = r.largest_multiplier;
  j["forced"] = r.forced;
  if (r.forced) {
    j["forcing"] = r.forcing;
    j["forcing_period"] = r.forcing_period;
    j["periods"] = r.periods;
  }
  nlohmann::ordered_json mu = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < r.multipliers.size(); ++i)
    mu.push_back({{"re", r.multipliers[i].real()},
                  {"im", r.multipliers[i].imag()},
                  {"modulus", std::abs(r.multipliers[i])},
                  {"trivial", static_cast<int>(i) == r.trivial}});
  j["multipliers"] = mu;
  if (!r.forced) j["trivial_multiplier_error"] = r.trivial_error;
  j["newton"] = {{"iterations", r.iterations},
                 {"residual", r.residual},
                 {"tolerance", spec.tolerance},
                 {"fd_step", shooting::fdStepFor(*scene.model, spec.fd_step)},
                 {"solver", r.solver},
                 {"picard_iterations", r.picard_iterations},
                 {"flows", r.flows},
                 {"flows_to_converge", r.flows_to_converge},
                 {"periods_to_converge", r.periods_to_converge},
                 {"krylov_products", r.krylov_products}};
  j["guess"] = {{"settle", spec.settle > 0.0 ? spec.settle : scene.model->options.duration},
                {"settled_after", r.guess_seconds},
                {"period", r.guess_period},
                {"amplitude_pp", r.guess_amplitude_pp}};
  j["integrator"] = integratorName(scene.model->options.integrator);
  j["time_step"] = scene.model->options.time_step;
  if (r.step_check) {
    const StepCheck& c = *r.step_check;
    nlohmann::ordered_json check = {{"setting", c.setting},     {"value", c.value},
                                    {"converged", c.converged}, {"iterations", c.iterations},
                                    {"residual", c.residual},   {"tolerance", c.tolerance},
                                    {"flows", c.flows}};
    if (c.converged) {
      check["period"] = c.period;
      check["amplitude_pp"] = c.amplitude_pp;
      check["period_change"] = c.period_change;
      check["amplitude_change"] = c.amplitude_change;
      check["relative_period_change"] = c.relative_period_change;
      check["relative_amplitude_change"] = c.relative_amplitude_change;
    } else {
      check["why"] = c.why;
    }
    j["step_check"] = check;
  }
  nlohmann::ordered_json start = nlohmann::ordered_json::object();
  for (std::size_t i = 0; i < r.coordinates.size(); ++i)
    start[r.coordinates[i]] = r.start[static_cast<Eigen::Index>(i)];
  j["start"] = start;
  j["seconds"] = r.seconds;
  return j.dump(2);
}

}  // namespace tribo::study
