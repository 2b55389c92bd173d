#include "apps/modes_command.hpp"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/common_options.hpp"
#include "io/scene_parameters.hpp"
#include "study/modes/modes_report.hpp"
#include "study/modes/stability_boundary.hpp"

namespace tribo::app {
namespace {

constexpr std::size_t kRowsShown = 12;

struct Arguments {
  std::string scene_path, out_dir;
  std::vector<std::string> overrides;
  study::ModesSpec spec;
  std::optional<study::BoundarySpec> boundary;
};

double number(const std::string& option, const std::string& text) {
  const auto v = io::parseNumber(text);
  if (!v) throw std::invalid_argument(option + ": expected a number, found '" + text + "'");
  return *v;
}

study::BoundarySpec parseBoundary(const std::string& text) {
  const auto eq = text.find('='), colon = text.find(':', eq == std::string::npos ? 0 : eq);
  if (eq == std::string::npos || colon == std::string::npos || eq == 0)
    throw std::invalid_argument("--boundary: expected NAME=LO:HI, found '" + text + "'");
  study::BoundarySpec b;
  b.parameter = text.substr(0, eq);
  b.lo = number("--boundary", text.substr(eq + 1, colon - eq - 1));
  b.hi = number("--boundary", text.substr(colon + 1));
  if (!(b.lo < b.hi)) throw std::invalid_argument("--boundary: expected LO < HI in '" + text + "'");
  return b;
}

study::EigenSolverChoice solverChoice(const std::string& text) {
  if (text == "auto") return study::EigenSolverChoice::kAuto;
  if (text == "dense") return study::EigenSolverChoice::kDense;
  if (text == "sparse") return study::EigenSolverChoice::kSparse;
  throw std::invalid_argument("--solver: expected auto, dense or sparse, found '" + text + "'");
}

int modeCount(const std::string& text) {
  const auto v = io::parseNumber(text);
  if (!v || *v < 1 || *v > 100000 || *v != std::floor(*v))
    throw std::invalid_argument("--modes: expected a whole number of modes >= 1, found '" + text +
                                "'");
  return static_cast<int>(*v);
}

void printTable(const io::Scene& scene, const study::ModesResult& r) {
  const Model& model = *scene.model;
  std::printf("scene            %s\n", scene.path.c_str());
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    if (model.bodies[b].kind != BodyKind::kDynamic) continue;
    const Vec3& p = r.steady.state.bodies[b].position;
    std::printf("steady state     %s at (%.6g, %.6g, %.6g) m\n", model.bodies[b].name.c_str(),
                p.x(), p.y(), p.z());
  }
  std::printf("newton           %d iterations, largest acceleration %.2g%s\n", r.steady.iterations,
              r.steady.residual, r.steady.settled_for > 0 ? " (after a settling run)" : "");
  std::printf(
      "coordinates      %d independent, %d states; steps %.2g (position), %.2g "
      "(velocity), check %.2g\n",
      r.coordinates, 2 * r.coordinates, r.steps.position, r.steps.velocity, r.worst_disagreement);
  if (r.solver.method == "sparse")
    std::printf(
        "eigensolver      sparse: %zu modes of largest growth rate of %d found (%d shifts "
        "covering 0..%.3g 1/s, |Re| < %.3g 1/s; worst residual %.2g)\n",
        r.modes.size(), r.solver.found, r.solver.shifts, r.solver.band_top, r.solver.strip,
        r.solver.worst_residual);
  else
    std::printf("eigensolver      dense: every mode\n");
  std::printf("\n%-5s %-15s %-15s %-14s %-9s %s\n", "mode", "frequency [Hz]", "growth [1/s]",
              "damping ratio", "unstable", "moves");
  for (std::size_t i = 0; i < r.modes.size() && i < kRowsShown; ++i) {
    const study::Mode& m = r.modes[i];
    std::printf("%-5zu %-15.7g %-15.7g %-14.5g %-9s %s\n", i + 1, m.frequency, m.growth_rate,
                m.damping_ratio, m.unstable ? "YES" : "no", m.dominant.c_str());
  }
  if (r.modes.size() > kRowsShown)
    std::printf("... %zu more modes in modes.csv\n", r.modes.size() - kRowsShown);
  const study::Mode& lead = r.leading();
  if (r.unstable_count > 0)
    std::printf(
        "\nverdict          UNSTABLE: %d mode%s grow%s; leading %.6g Hz, growth rate %.6g "
        "1/s (%s)\n",
        r.unstable_count, r.unstable_count > 1 ? "s" : "", r.unstable_count > 1 ? "" : "s",
        lead.frequency, lead.growth_rate, lead.dominant.c_str());
  else
    std::printf("\nverdict          stable: largest growth rate %.6g 1/s\n", lead.growth_rate);
  std::printf(
      "time             steady state %.3g ms, linearization + eigenvalues %.3g ms "
      "(%d evaluations)\n",
      1e3 * r.steady_seconds, 1e3 * r.linearize_seconds, r.evaluations);
}

int runModes(Arguments& a) {
  io::Scene scene;
  study::ModesResult result;
  try {
    scene = io::loadScene(a.scene_path, a.overrides);
    result = study::analyzeModes(scene, a.spec);
  } catch (const study::NoSteadyState& e) {
    std::fprintf(stderr, "tribo modes: no steady state: %s\n", e.what());
    return kExitNoSteadyState;
  } catch (const study::LinearizationFailure& e) {
    std::fprintf(stderr, "tribo modes: %s\n", e.what());
    return kExitEigenFailure;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tribo modes: %s\n", e.what());
    return 2;
  }
  for (const auto& n : scene.notes) std::fprintf(stderr, "tribo modes: note: %s\n", n.c_str());
  for (const auto& w : result.warnings)
    std::fprintf(stderr, "tribo modes: warning: %s\n", w.c_str());
  const std::filesystem::path out(a.out_dir);
  try {
    study::writeModesJson(out / "modes.json", scene, result);
    study::writeModesCsv(out / "modes.csv", result);
    if (result.linear) study::writeLinearModel(out, *result.linear);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tribo modes: %s\n", e.what());
    return 4;
  }
  printTable(scene, result);
  if (a.boundary) {
    study::BoundarySpec& b = *a.boundary;
    b.scene_path = a.scene_path;
    b.overrides = a.overrides;
    b.modes = a.spec;
    study::BoundaryResult br;
    try {
      br = study::findBoundary(b);
    } catch (const study::NoSteadyState& e) {
      std::fprintf(stderr, "tribo modes: --boundary: no steady state: %s\n", e.what());
      return kExitNoSteadyState;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "tribo modes: --boundary: %s\n", e.what());
      return 2;
    }
    try {
      study::writeBoundaryJson(out / "boundary.json", b, br);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "tribo modes: %s\n", e.what());
      return 4;
    }
    std::printf(
        "boundary         %s = %.10g (unstable %s; bracket [%.10g, %.10g], %d analyses; "
        "%.6g Hz at onset)\n",
        b.parameter.c_str(), br.critical, br.unstable_above ? "above" : "below", br.lo, br.hi,
        br.analyses, br.frequency_unstable);
  }
  std::printf("results          %s\n", out.string().c_str());
  return result.unstable_count > 0 ? kExitUnstable : 0;
}

}  // namespace

Command addModesCommand(CLI::App& tribo) {
  auto a = std::make_shared<Arguments>();
  CLI::App* modes =
      tribo.add_subcommand("modes", "linear stability of steady sliding: will it squeal?");
  addPathArgument(*modes, "SCENE", a->scene_path, "the YAML scene");
  addOutOption(*modes, a->out_dir, "output folder: DIR/modes.json and DIR/modes.csv")->required();
  addSetOption(*modes, a->overrides);
  modes->add_flag("--settle", a->spec.steady.settle,
                  "a damped settling run before the steady-state search");
  modes->add_flag("--matrices", a->spec.linear_model,
                  "also the linear model y' = A y + B w with the loads' and actuators' inputs:\n"
                  "DIR/A.mtx, B.mtx, K.mtx, C.mtx, N.mtx (Matrix Market) and\n"
                  "DIR/linear_model.json naming rows and columns");
  addCheckedOption(*modes, "--boundary", "NAME=LO:HI",
                   "bisect NAME over [LO, HI] for where the largest growth rate crosses zero;\n"
                   "writes DIR/boundary.json",
                   [a](const std::string& v) { a->boundary = parseBoundary(v); });
  addCheckedOption(
      *modes, "--growth-tolerance", "X",
      "growth rate above which a mode counts as unstable (1e-6 1/s)",
      [a](const std::string& v) { a->spec.growth_tolerance = number("--growth-tolerance", v); });
  addCheckedOption(
      *modes, "--steady-tolerance", "X",
      "largest acceleration accepted at the steady state (1e-8 m/s^2); stiff\n"
      "springs anchored far away round above the default",
      [a](const std::string& v) { a->spec.steady.tolerance = number("--steady-tolerance", v); });
  addCheckedOption(*modes, "--solver", "auto|dense|sparse",
                   "dense: every mode; sparse: the N modes of largest growth rate near the\n"
                   "imaginary axis; auto (default): dense up to 200 states, sparse above",
                   [a](const std::string& v) { a->spec.solver = solverChoice(v); });
  addCheckedOption(*modes, "--modes", "N",
                   "modes the sparse solver returns, a complex pair once (12)",
                   [a](const std::string& v) { a->spec.sparse_modes = modeCount(v); });
  modes->footer(
      "Finds the steady state (dynamic bodies at rest, belts moving), linearizes about it and\n"
      "prints each mode's frequency, growth rate, damping ratio and what moves.\n"
      "The dense solver (Eigen) is cubic in the states. The sparse one (Spectra) runs\n"
      "shift-and-invert Arnoldi at shifts i w scanning the frequency band, checks residuals,\n"
      "and does not search modes far left of the axis; auto falls back to dense with a warning\n"
      "if it fails.\n"
      "exit status: 0 stable, 1 usage, 2 bad scene, 4 output error, 8 unstable,\n"
      "9 no steady state, 10 linearization or eigenproblem failed");
  return {modes, [a] { return runModes(*a); }};
}

}  // namespace tribo::app
