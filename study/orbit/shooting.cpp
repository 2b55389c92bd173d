#include "study/orbit/shooting.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <optional>
#include <thread>

#include "core/integrator.hpp"
#include "core/simulator.hpp"
#include "core/thread_count.hpp"
#include "study/orbit/forcing.hpp"
#include "study/orbit/periodic_orbit.hpp"

namespace tribo::study::shooting {

namespace {

void check(const StepStatus& s, double T) {
  if (!s.ok)
    throw OrbitError("a step of the shooting flow (period " + std::to_string(T) +
                     " s) failed: " + s.message);
}

}  // namespace

int observedBody(const io::Scene& scene) {
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
  return static_cast<int>(body_it - model.bodies.begin());
}

int shootableBody(const io::Scene& scene) {
  const int body = observedBody(scene);
  if (const std::string why = nonAutonomous(*scene.model); !why.empty())
    throw OrbitError("the scene is not autonomous (" + why +
                     "): its orbits are forced, with the forcing's period; `tribo orbit` "
                     "without --continue finds one, continuation follows autonomous orbits only");
  return body;
}

double fdStepFor(const Model& model, double fd_step) {
  if (!isAdaptive(model.options.integrator)) return fd_step;
  return std::max(fd_step, std::cbrt(model.options.relative_tolerance));
}

State advance(const std::shared_ptr<const Model>& model, const State& start, double T,
              const std::function<void(double, const State&)>& sample,
              const std::function<void(const Workspace&)>& contacts) {
  const double h = model->options.time_step;
  long n = static_cast<long>(std::floor(T / h));
  double rest = T - static_cast<double>(n) * h;
  if (rest > h * (1 - 1e-9)) ++n, rest = 0.0;
  if (rest < h * 1e-9) rest = 0.0;
  Simulator sim(model);
  const double t0 = start.time;
  sim.setState(start);
  for (long i = 0; i < n; ++i) {
    check(sim.step(), T);
    if (sample) sample(sim.state().time - t0, sim.state());
    if (contacts) contacts(sim.current());
  }
  if (rest == 0.0) return sim.state();
  auto last = std::make_shared<Model>(*model);
  last->options.time_step = rest;
  Simulator tail(last);
  tail.setState(sim.state());
  check(tail.step(), T);
  if (sample) sample(T, tail.state());
  if (contacts) contacts(tail.current());
  return tail.state();
}

Flow::Flow(std::shared_ptr<const Model> model, const OrbitCoordinates& coords)
    : model_(std::move(model)), coords_(coords) {}

Eigen::VectorXd Flow::operator()(const Eigen::VectorXd& y, double T,
                                 const std::function<void(double, const State&)>& sample,
                                 const std::function<void(const Workspace&)>& contacts) const {
  ++count_;
  integrated_.fetch_add(T);
  return coords_.toVector(advance(model_, coords_.fromVector(y), T, sample, contacts));
}

Guess settledGuess(const std::shared_ptr<const Model>& model, int body, int axis, double seconds,
                   const State* start) {
  Simulator sim(model);
  if (start != nullptr) sim.setState(*start);
  const auto b = static_cast<std::size_t>(body);
  // Per maximum: when (the velocity's zero crossing), its peak, and the coordinate's extremes
  // over the interval that ended there.
  std::vector<double> crossings, peaks, lows, highs;
  std::optional<State> last_state;
  double prev_v = sim.state().bodies[b].velocity[axis];
  double prev_x = sim.state().bodies[b].position[axis];
  double lo = 1e300, hi = -1e300;
  // The coordinate may peak more than once a cycle (a pendulum swinging past the horizontal):
  // the cycle is the smallest lag m of maxima after which peak and time repeat.
  // repeated[m]: successive cycles of m maxima like the one before.
  std::vector<int> repeated(kMostPeaksPerCycle + 1, 0);
  int settled_lag = 0;
  // The amplitude over the last m intervals.
  auto amplitudeOver = [&](std::size_t m) {
    const std::size_t k = crossings.size();
    double a = 1e300, z = -1e300;
    for (std::size_t i = k - m; i < k; ++i) a = std::min(a, lows[i]), z = std::max(z, highs[i]);
    return z - a;
  };
  const double h = model->options.time_step;
  const long steps = static_cast<long>(std::ceil(seconds / h));
  for (long i = 0; i < steps && settled_lag == 0; ++i) {
    const double t_prev = sim.state().time;
    const StepStatus s = sim.step();
    if (!s.ok) throw OrbitError("the settling run failed: " + s.message);
    const BodyState& now = sim.state().bodies[b];
    const double v = now.velocity[axis];
    lo = std::min(lo, now.position[axis]);
    hi = std::max(hi, now.position[axis]);
    if (prev_v > 0.0 && v <= 0.0) {
      const double dt = sim.state().time - t_prev;
      crossings.push_back(t_prev + dt * prev_v / (prev_v - v));
      // The peak of the parabola whose slope goes linearly from prev_v to v over the step.
      peaks.push_back(prev_x + 0.5 * prev_v * prev_v * dt / (prev_v - v));
      lows.push_back(lo);
      highs.push_back(hi);
      last_state = sim.state();
      lo = 1e300, hi = -1e300;
      const std::size_t k = crossings.size();
      for (std::size_t m = 1; m <= kMostPeaksPerCycle && 2 * m + 1 <= k; ++m) {
        const double period = crossings[k - 1] - crossings[k - 1 - m];
        const double before = crossings[k - 1 - m] - crossings[k - 1 - 2 * m];
        const bool same =
            std::abs(peaks[k - 1] - peaks[k - 1 - m]) <= kSettledTolerance * amplitudeOver(m) &&
            std::abs(period - before) <= kSettledTolerance * period;
        repeated[m] = same ? repeated[m] + 1 : 0;
        if (repeated[m] >= kSettledCycles) {
          settled_lag = static_cast<int>(m);
          break;
        }
      }
    }
    prev_v = v;
    prev_x = now.position[axis];
  }
  if (crossings.size() < 3)
    throw OrbitError("the observed coordinate has " + std::to_string(crossings.size()) +
                     " maxima in the settling run of " + std::to_string(seconds) +
                     " s, fewer than 3: no oscillation to shoot for (steady sliding is stable "
                     "here, or give a longer --settle)");
  // Not settled to kSettledTolerance: the smallest lag whose last peak repeats to 1e-3 of the
  // amplitude, one maximum a cycle if none does.
  const std::size_t k = crossings.size();
  std::size_t lag = static_cast<std::size_t>(settled_lag);
  for (std::size_t m = 1; lag == 0 && m <= kMostPeaksPerCycle && m + 1 <= k; ++m)
    if (std::abs(peaks[k - 1] - peaks[k - 1 - m]) <= 1e-3 * amplitudeOver(m)) lag = m;
  if (lag == 0) lag = 1;
  Guess g;
  g.state = *last_state;
  g.period = crossings[k - 1] - crossings[k - 1 - lag];
  g.amplitude_pp = amplitudeOver(lag);
  g.peaks_per_cycle = static_cast<int>(lag);
  g.seconds = sim.state().time;
  return g;
}

Eigen::VectorXd fdFloor(const Eigen::VectorXd& y, std::size_t friction_count) {
  const Eigen::Index n = y.size();
  Eigen::VectorXd floor = Eigen::VectorXd::Constant(n, 1e-2);
  const Eigen::Index bodies_end = n - static_cast<Eigen::Index>(friction_count);
  if (bodies_end < n)
    floor.tail(n - bodies_end)
        .setConstant(std::max(1e-12, y.tail(n - bodies_end).cwiseAbs().maxCoeff()));
  return floor;
}

void parallelColumns(Eigen::Index count, unsigned threads,
                     const std::function<void(Eigen::Index)>& column) {
  threads = std::max(1u, threads);
  std::vector<std::thread> pool;
  std::vector<std::exception_ptr> errors(threads);
  for (unsigned w = 1; w < threads; ++w)
    pool.emplace_back([&, w] {
      const ScopedThreadLimit one_each(1);  // the columns share the cores
      try {
        for (Eigen::Index j = w; j < count; j += threads) column(j);
      } catch (...) {
        errors[w] = std::current_exception();
      }
    });
  try {
    const ScopedThreadLimit one_each(threads > 1 ? 1 : 0);
    for (Eigen::Index j = 0; j < count; j += threads) column(j);
  } catch (...) {
    errors[0] = std::current_exception();
  }
  for (auto& t : pool) t.join();
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
}

Floquet floquet(const Eigen::MatrixXd& monodromy, bool autonomous) {
  Eigen::EigenSolver<Eigen::MatrixXd> eig(monodromy, false);
  std::vector<std::complex<double>> multipliers;
  for (Eigen::Index i = 0; i < eig.eigenvalues().size(); ++i)
    multipliers.push_back(eig.eigenvalues()[i]);
  return classify(std::move(multipliers), autonomous);
}

Floquet classify(std::vector<std::complex<double>> multipliers, bool autonomous) {
  Floquet f;
  f.multipliers = std::move(multipliers);
  std::sort(f.multipliers.begin(), f.multipliers.end(),
            [](auto a, auto b) { return std::abs(a) > std::abs(b); });
  double nearest = 1e300;
  for (std::size_t i = 0; autonomous && i < f.multipliers.size(); ++i)
    if (std::abs(f.multipliers[i] - 1.0) < nearest)
      nearest = std::abs(f.multipliers[i] - 1.0), f.trivial = static_cast<int>(i);
  f.trivial_error = autonomous ? nearest : 0.0;
  for (std::size_t i = 0; i < f.multipliers.size(); ++i)
    if (static_cast<int>(i) != f.trivial)
      f.largest = std::max(f.largest, std::abs(f.multipliers[i]));
  f.stable = f.largest < 1.0;
  return f;
}

bool undecidedStability(const std::vector<std::complex<double>>& multipliers, int trivial,
                        double trivial_error) {
  const double band = std::max(1e-6, 10.0 * trivial_error);
  for (std::size_t i = 0; i < multipliers.size(); ++i)
    if (static_cast<int>(i) != trivial && std::abs(std::abs(multipliers[i]) - 1.0) <= band)
      return true;
  return false;
}

std::string messageNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

double refinedMinimum(const std::vector<double>& x) {
  const auto it = std::min_element(x.begin(), x.end());
  const auto i = static_cast<std::size_t>(it - x.begin());
  if (i == 0 || i + 1 >= x.size()) return *it;
  const double a = x[i - 1], b = x[i], c = x[i + 1], d = a - 2 * b + c;
  if (d <= 0.0) return b;
  return b - (a - c) * (a - c) / (8.0 * d);
}

double refinedMaximum(const std::vector<double>& x) {
  std::vector<double> negated(x.size());
  std::transform(x.begin(), x.end(), negated.begin(), [](double v) { return -v; });
  return -refinedMinimum(negated);
}

SampledPeriod samplePeriod(const Flow& flow, const OrbitCoordinates& coords,
                           const Eigen::VectorXd& y, double T, int body, int axis, bool forced) {
  const auto b = static_cast<std::size_t>(body);
  SampledPeriod p;
  p.t.push_back(0.0);
  p.x.push_back(coords.fromVector(y).bodies[b].position[axis]);
  flow(y, T, [&](double t, const State& s) {
    p.t.push_back(t);
    p.x.push_back(s.bodies[b].position[axis]);
  });
  p.x_max = forced ? refinedMaximum(p.x) : p.x.front();
  p.x_min = refinedMinimum(p.x);
  return p;
}

Eigen::MatrixXd closingJacobian(const Eigen::MatrixXd& monodromy,
                                const Eigen::VectorXd* period_column, Eigen::Index phase) {
  const Eigen::Index n = monodromy.rows(), rows = period_column ? n + 1 : n;
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(rows, rows);
  J.topLeftCorner(n, n) = monodromy - Eigen::MatrixXd::Identity(n, n);
  if (period_column) {
    J.topRightCorner(n, 1) = *period_column;
    J(n, phase) = 1.0;
  }
  return J;
}

}  // namespace tribo::study::shooting
