#include "study/modes/modes.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

namespace tribo::study {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Mode makeMode(std::complex<double> lambda, const Eigen::VectorXcd& vector,
              const ReducedCoordinates& coords, double growth_tolerance) {
  Mode mode;
  mode.eigenvalue = lambda;
  mode.growth_rate = lambda.real();
  mode.frequency = std::abs(lambda.imag()) / (2 * std::numbers::pi);
  const double size = std::abs(lambda);
  mode.damping_ratio = size > 0 ? -lambda.real() / size : 0.0;
  mode.unstable = lambda.real() > growth_tolerance;
  const Eigen::VectorXcd shape =
      coords.basis().cast<std::complex<double>>() * vector.head(coords.size());
  Eigen::Index big = 0;
  const double largest = shape.cwiseAbs().maxCoeff(&big);
  const std::complex<double> ref = largest > 0 ? shape(big) : 1.0;
  std::vector<int> order;
  for (int i = 0; i < coords.fullSize(); ++i) {
    const std::complex<double> z = shape(i) / ref;
    mode.shape.push_back({coords.fullName(i), largest > 0 ? std::abs(z) : 0.0,
                          std::arg(z) * 180.0 / std::numbers::pi});
    if (mode.shape.back().magnitude >= 0.1) order.push_back(i);
  }
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return mode.shape[a].magnitude > mode.shape[b].magnitude; });
  // The largest few by name (a chain's mode moves dozens of coordinates; the full shape is
  // in mode.shape and modes.json).
  constexpr std::size_t kNamed = 6;
  for (std::size_t k = 0; k < std::min(order.size(), kNamed); ++k)
    mode.dominant += (mode.dominant.empty() ? "" : " ") + mode.shape[order[k]].coordinate;
  if (order.size() > kNamed) mode.dominant += " (+" + std::to_string(order.size() - kNamed) + ")";
  return mode;
}

void sortByGrowth(std::vector<Mode>& modes) {
  std::stable_sort(modes.begin(), modes.end(),
                   [](const Mode& x, const Mode& y) { return x.growth_rate > y.growth_rate; });
}

// Gives `state` its friction records (Dynamics::beforeStep) and sets every internal state to
// its law's steady state at the slip and load there: a step far beyond every decay time at
// frozen slip lands on the steady state.
void settleFrictionStates(Dynamics& dynamics, State& state) {
  if (!dynamics.frictionMemory().dynamic()) return;
  dynamics.evaluate(state);
  dynamics.beforeStep(state);
  dynamics.evaluate(state);
  constexpr double kForever = 1e12;  // [s]
  dynamics.stepFrictionMemory(state, kForever);
}

// Rolling and spinning resistance (contact/rolling_resistance.hpp): every contact point's
// angular spring anchored at `state` (Dynamics::afterStep with no anchors yet: each one just
// anchored, theta = 0, stuck unless the point turns there), so that the linearization, which
// holds the anchors while it perturbs the state, sees a stuck part's stiffness k and damping
// c, and a sliding part's saturated moment.
void anchorAngularSprings(Dynamics& dynamics, State& state) {
  const std::vector<contact::Material>& materials = dynamics.model().materials;
  if (std::none_of(materials.begin(), materials.end(),
                   [](const contact::Material& m) { return m.resistance.active(); }))
    return;
  state.stick_anchors.clear();
  dynamics.evaluate(state);
  dynamics.afterStep(state);
}

}  // namespace

std::vector<Mode> modesOf(const Eigen::MatrixXd& a, const ReducedCoordinates& coords,
                          double growth_tolerance) {
  if (!a.allFinite())
    throw LinearizationFailure(
        "the linearized system is not finite (a force is not differentiable here)");
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(a, true);
  if (solver.info() != Eigen::Success)
    throw LinearizationFailure(std::string("the eigenvalue problem did not converge (")
                                   .append(std::to_string(a.rows()))
                                   .append(" states)"));
  const Eigen::VectorXcd values = solver.eigenvalues();
  const Eigen::MatrixXcd vectors = solver.eigenvectors();
  if (!values.allFinite()) throw LinearizationFailure("the eigenvalues are not finite");
  std::vector<Mode> modes;
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    if (values(i).imag() < 0) continue;  // the conjugate of a pair reported once
    modes.push_back(makeMode(values(i), vectors.col(i), coords, growth_tolerance));
  }
  sortByGrowth(modes);
  return modes;
}

std::vector<Mode> sparseModesOf(const Eigen::MatrixXd& a, const ReducedCoordinates& coords,
                                double growth_tolerance, const SparseEigenOptions& options,
                                SolverReport* report) {
  const SparseEigenpairs pairs = sparseEigenpairs(a, options);
  std::vector<Mode> modes;
  for (Eigen::Index i = 0; i < pairs.values.size(); ++i)
    modes.push_back(makeMode(pairs.values(i), pairs.vectors.col(i), coords, growth_tolerance));
  sortByGrowth(modes);
  if (report) {
    report->method = "sparse";
    report->requested = options.count;
    report->shifts = pairs.shifts;
    report->found = pairs.found;
    report->band_top = pairs.band_top;
    report->strip = pairs.strip;
    report->worst_residual = pairs.worst_residual;
    report->sparse_factorization = pairs.sparse_factorization;
    report->operations = pairs.operations;
  }
  return modes;
}

SolvedModes solveModes(const Eigen::MatrixXd& a, const ReducedCoordinates& coords,
                       const ModesSpec& spec) {
  SolvedModes out;
  const bool sparse = spec.solver == EigenSolverChoice::kSparse ||
                      (spec.solver == EigenSolverChoice::kAuto && a.rows() > kSparseAboveStates);
  if (!sparse) {
    out.modes = modesOf(a, coords, spec.growth_tolerance);
    return out;
  }
  SparseEigenOptions options;
  options.count = spec.sparse_modes;
  try {
    out.modes = sparseModesOf(a, coords, spec.growth_tolerance, options, &out.solver);
  } catch (const ModesError& e) {
    if (spec.solver != EigenSolverChoice::kAuto) throw;
    out.warnings.push_back(std::string("the sparse eigensolver failed (") + e.what() +
                           "); every mode computed by the dense one instead");
    out.solver = SolverReport{};
    out.modes = modesOf(a, coords, spec.growth_tolerance);
    return out;
  }
  const bool all_grow =
      std::all_of(out.modes.begin(), out.modes.end(), [](const Mode& m) { return m.unstable; });
  if (all_grow)
    out.warnings.push_back("all " + std::to_string(out.modes.size()) +
                           " modes the sparse eigensolver returned grow: more may, and the "
                           "leading one may be among them; ask for more (--modes) or use "
                           "--solver dense");
  return out;
}

ModesResult analyzeModes(const io::Scene& scene, const ModesSpec& spec) {
  const Model& model = *scene.model;
  for (const contact::Material& material : model.materials)
    if (material.friction->stateful())
      throw ModesError("friction law '" + std::string(material.friction->name()) +
                       "' keeps contact anchors, which the linearization does not cover: "
                       "use a memoryless law or one with internal state for the stability "
                       "analysis");
  if (model.dynamicBodyCount() == 0)
    throw ModesError("the scene has no dynamic body: there is nothing to linearize");
  ModesResult out;
  Dynamics dynamics(scene.model);
  auto start = std::chrono::steady_clock::now();
  // Dynamic friction: the steady state under the laws' steady-state curves, then every
  // internal state settled to its steady value there and linearized with the motion.
  dynamics.setSteadyFriction(true);
  try {
    out.steady = findSteadyState(dynamics, spec.steady);
  } catch (const std::invalid_argument& e) {
    throw ModesError(e.what());
  }
  dynamics.setSteadyFriction(false);
  settleFrictionStates(dynamics, out.steady.state);
  anchorAngularSprings(dynamics, out.steady.state);
  out.steady_seconds = secondsSince(start);
  start = std::chrono::steady_clock::now();
  const State& x = out.steady.state;
  ReducedCoordinates coords(model, x);
  out.coordinates = coords.size();
  out.steps = chooseSteps(dynamics, x);
  const Linearization lin = linearize(dynamics, coords, x, out.steps, true, spec.check_tolerance);
  SolvedModes solved = solveModes(firstOrderMatrix(lin), coords, spec);
  out.modes = std::move(solved.modes);
  out.solver = solved.solver;
  out.linearize_seconds = secondsSince(start);
  out.worst_disagreement = lin.worst_disagreement;
  out.warnings = lin.warnings;
  out.warnings.insert(out.warnings.end(), solved.warnings.begin(), solved.warnings.end());
  out.evaluations = out.steady.evaluations + lin.evaluations + 1;
  if (spec.linear_model) {
    out.linear = linearModel(dynamics, coords, x, lin);
    out.evaluations += 2 * static_cast<int>(out.linear->inputs.size());
  }
  for (const Mode& m : out.modes) out.unstable_count += m.unstable ? 1 : 0;
  return out;
}

}  // namespace tribo::study
