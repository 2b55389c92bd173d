#include "apps/orbit_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "apps/common_options.hpp"
#include "apps/modes_command.hpp"
#include "apps/stop_signals.hpp"
#include "io/scene_parameters.hpp"
#include "study/csv_text.hpp"
#include "study/file_commit.hpp"
#include "study/orbit/orbit_branch.hpp"
#include "study/orbit/periodic_orbit.hpp"

namespace tribo::app {
namespace {

struct Arguments {
  std::string scene_path, out_dir;
  std::vector<std::string> overrides;
  study::OrbitSpec spec;
  bool continuation = false;    // --continue given
  bool branch_options = false;  // --max-points, --step, --max-step, --arclength, --from-hopf,
                                // --hopf-amplitude
  bool forced_options = false;  // --period or --periods given
  bool step_check = true;       // the orbit again at a finer setting (not with --continue)
  study::BranchSpec branch;
};

double positive(const std::string& option, const std::string& text) {
  const auto v = io::parseNumber(text);
  if (!v || !(*v > 0.0) || !std::isfinite(*v))
    throw std::invalid_argument(option + ": expected a number > 0, found '" + text + "'");
  return *v;
}

// --continue NAME=FROM:TO into the branch's spec; throws std::invalid_argument saying what was
// expected and what was found.
void parseContinue(const std::string& text, study::BranchSpec& b) {
  const auto eq = text.find('=');
  const auto colon = text.find(':', eq == std::string::npos ? 0 : eq);
  if (eq == std::string::npos || eq == 0 || colon == std::string::npos)
    throw std::invalid_argument("--continue: expected NAME=FROM:TO (e.g. v_b=1:2), found '" + text +
                                "'");
  const std::string from = text.substr(eq + 1, colon - eq - 1), to = text.substr(colon + 1);
  const auto f = io::parseNumber(from), t = io::parseNumber(to);
  if (!f || !std::isfinite(*f))
    throw std::invalid_argument("--continue: expected a number for FROM in NAME=FROM:TO, found '" +
                                from + "'");
  if (!t || !std::isfinite(*t))
    throw std::invalid_argument("--continue: expected a number for TO in NAME=FROM:TO, found '" +
                                to + "'");
  if (*f == *t)
    throw std::invalid_argument("--continue: expected FROM and TO to differ, found both " + from);
  b.parameter = text.substr(0, eq);
  b.from = *f;
  b.to = *t;
}

int wholeAtLeast(const std::string& option, const std::string& text, int least) {
  const auto v = io::parseNumber(text);
  if (!v || *v != std::floor(*v) || *v < least || *v > 1e6)
    throw std::invalid_argument(option + ": expected a whole number from " + std::to_string(least) +
                                " to 1000000, found '" + text + "'");
  return static_cast<int>(*v);
}

// tribo orbit --continue: the branch, point by point on stderr, into branch.csv and
// branch.json (written also when the branch is lost on the way or interrupted).
int runBranch(Arguments& a) {
  study::BranchSpec& b = a.branch;
  b.orbit = a.spec;
  // The first SIGINT or SIGTERM ends the branch after the point in hand, its points kept.
  b.stop = &catchStopSignals();
  try {
    const io::Scene scene = io::loadScene(a.scene_path, a.overrides);
    for (const auto& n : scene.notes) std::fprintf(stderr, "tribo orbit: note: %s\n", n.c_str());
    const auto it = std::find_if(scene.parameters.begin(), scene.parameters.end(),
                                 [&](const auto& kv) { return kv.first == b.parameter; });
    if (it == scene.parameters.end() || !io::parseNumber(it->second)) {
      std::string names;
      for (const auto& [name, value] : scene.parameters)
        if (io::parseNumber(value)) {
          if (!names.empty()) names += ", ";
          names += name;
        }
      std::fprintf(stderr,
                   "tribo orbit: --continue: expected a numeric parameter of %s (%s), found "
                   "'%s'%s\n",
                   scene.path.c_str(), names.c_str(), b.parameter.c_str(),
                   it == scene.parameters.end() ? "" : (" = '" + it->second + "'").c_str());
      return 1;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tribo orbit: %s\n", e.what());
    return 2;
  }
  if (b.switch_amplitude > 0.0 && b.switch_at == study::BranchSwitch::kNone) {
    std::fprintf(stderr, "tribo orbit: --switch-amplitude applies with --switch only\n");
    return 1;
  }
  study::BranchResult r;
  try {
    if (b.from_hopf)
      std::fprintf(stderr,
                   "tribo orbit: the Hopf point of steady sliding between %s = %.6g and %.6g, "
                   "then the branch from it\n",
                   b.parameter.c_str(), b.from, b.to);
    else
      std::fprintf(stderr, "tribo orbit: the orbit at %s = %.6g, then the branch towards %.6g\n",
                   b.parameter.c_str(), b.from, b.to);
    std::size_t seen = 0;
    r = study::continueOrbit(
        a.scene_path, a.overrides, b, [&](const study::BranchPoint& p, std::size_t i) {
          if (i == 0 && seen++ > 0)
            std::fprintf(stderr,
                         "tribo orbit: switched at the located %s; the new branch's points:\n",
                         study::branchSwitchName(b.switch_at).c_str());
          std::fprintf(stderr,
                       "tribo orbit: point %zu  %s = %.8g  period %.8g s  amplitude %.6g  "
                       "|mu|max %.3g  %s  (%d iterations)\n",
                       i, b.parameter.c_str(), p.parameter, p.period, p.amplitude_pp, p.largest,
                       p.stable ? "stable" : "unstable", p.iterations);
        });
  } catch (const study::OrbitError& e) {
    if (b.from_hopf)
      std::fprintf(stderr, "tribo orbit: no branch from a Hopf point: %s\n", e.what());
    else
      std::fprintf(stderr, "tribo orbit: no orbit at %s = %.6g: %s\n", b.parameter.c_str(), b.from,
                   e.what());
    return kExitNoOrbit;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tribo orbit: %s\n", e.what());
    return 2;
  }
  const std::filesystem::path out(a.out_dir);
  try {
    std::filesystem::create_directories(out);
    study::writeFileWhole(out / "branch.csv", study::branchCsvText(r));
    study::writeFileWhole(out / "branch_orbits.csv", study::branchOrbitsCsvText(r));
    study::writeFileWhole(out / "branch.json", study::branchJsonText(a.scene_path, b, r) + "\n");
    if (r.switched.found)
      study::writeFileWhole(out / "primary_branch.csv", study::primaryBranchCsvText(r));
    else
      std::filesystem::remove(out / "primary_branch.csv");  // not from an earlier run
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tribo orbit: %s\n", e.what());
    return 4;
  }
  std::printf("branch           %s in %s: %zu points, %s\n", a.scene_path.c_str(),
              b.parameter.c_str(), r.points.size(), r.stop_reason.c_str());
  for (const study::BranchEvent& e : r.events)
    if (e.before == e.after)
      std::printf("event            %s at %s ~ %.8g (past point %zu, bracketed)\n",
                  study::branchEventName(e.kind).c_str(), b.parameter.c_str(), e.parameter,
                  e.after);
    else
      std::printf("event            %s at %s ~ %.6g (between points %zu and %zu, interpolated)\n",
                  study::branchEventName(e.kind).c_str(), b.parameter.c_str(), e.parameter,
                  e.before, e.after);
  if (b.from_hopf)
    std::printf(
        "start            Hopf point at %s ~ %.8g, period %.8g s there (%d modes analyses)\n",
        b.parameter.c_str(), r.hopf_parameter, 2.0 * std::numbers::pi / r.hopf_omega,
        r.hopf_analyses);
  if (r.switched.found) {
    for (const study::BranchEvent& e : r.primary_events)
      std::printf("primary event    %s at %s ~ %.6g (interpolated)\n",
                  study::branchEventName(e.kind).c_str(), b.parameter.c_str(), e.parameter);
    std::printf(
        "switch           %s located at %s = %.10g (multiplier %.9g%+.2gi, %d orbits at fixed "
        "%s); primary: %zu points in primary_branch.csv\n",
        study::branchSwitchName(b.switch_at).c_str(), b.parameter.c_str(), r.switched.parameter,
        r.switched.multiplier.real(), r.switched.multiplier.imag(), r.switched.evaluations,
        b.parameter.c_str(), r.primary.size());
  }
  std::printf("results          %s (%.3g s)\n", out.string().c_str(), r.seconds);
  if (b.switch_at != study::BranchSwitch::kNone && !r.switched.found && !r.interrupted && !r.lost)
    return kExitNoSwitch;
  return r.interrupted ? kExitInterrupted : r.lost ? kExitBranchLost : 0;
}

int runOrbit(Arguments& a) {
  if (a.continuation) return runBranch(a);
  if (a.branch_options) {
    std::fprintf(stderr,
                 "tribo orbit: --max-points, --step, --max-step, --arclength, --from-hopf, "
                 "--hopf-amplitude, --switch and --switch-amplitude apply with --continue "
                 "only\n");
    return 1;
  }
  io::Scene scene;
  study::OrbitResult r;
  try {
    scene = io::loadScene(a.scene_path, a.overrides);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tribo orbit: %s\n", e.what());
    return 2;
  }
  for (const auto& n : scene.notes) std::fprintf(stderr, "tribo orbit: note: %s\n", n.c_str());
  try {
    r = study::findPeriodicOrbit(scene, a.spec);
  } catch (const study::OrbitError& e) {
    std::fprintf(stderr, "tribo orbit: no orbit: %s\n", e.what());
    return kExitNoOrbit;
  }
  // The orbit against a finer setting of the integrator (study/orbit/step_check.hpp).
  if (a.step_check)
    r.step_check =
        study::checkOrbitAgainstStep(*scene.model, r, a.spec, [&](const io::RunSettings& finer) {
          return io::loadScene(a.scene_path, a.overrides, {}, finer);
        });
  const std::filesystem::path out(a.out_dir);
  try {
    std::filesystem::create_directories(out);
    study::writeFileWhole(out / "orbit.json", study::orbitJsonText(scene, a.spec, r) + "\n");
    std::string csv = "t," + r.observed + "\n";
    for (std::size_t i = 0; i < r.t.size(); ++i)
      csv += study::csvNumber(r.t[i], 17) + "," + study::csvNumber(r.x[i], 17) + "\n";
    study::writeFileWhole(out / "orbit.csv", csv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tribo orbit: %s\n", e.what());
    return 4;
  }
  std::printf("orbit            %s, %s%s\n", scene.path.c_str(),
              r.neutral  ? "neutral (a second multiplier on the unit circle: the orbit is one of "
                           "a family, its stability undecided)"
              : r.stable ? "stable"
                         : "unstable",
              r.forced ? ", forced" : "");
  if (r.forced)
    std::printf("period           %.10g s = %d x the forcing's %.10g s (%s)\n", r.period, r.periods,
                r.forcing_period, r.forcing.c_str());
  else
    std::printf("period           %.10g s (%.6g Hz); the settled run gave %.6g s (after %.4g s)\n",
                r.period, 1.0 / r.period, r.guess_period, r.guess_seconds);
  std::printf("amplitude        %.10g peak to peak in %s (%.10g to %.10g)\n", r.amplitude_pp,
              r.observed.c_str(), r.x_min, r.x_max);
  std::printf(
      "newton           %d iterations after %d return-map iterations, residual %.3g (%s: %ld "
      "flows; converged after %ld, %.3g periods of integration",
      r.iterations, r.picard_iterations, r.residual, r.solver.c_str(), r.flows, r.flows_to_converge,
      r.periods_to_converge);
  if (r.solver == "krylov") std::printf(", %ld Krylov products", r.krylov_products);
  std::printf(")\n");
  const char* which = r.solver == "krylov" ? " leading" : "";
  if (r.forced)
    std::printf("multipliers      %zu%s (no trivial one: the forcing fixes the phase)\n",
                r.multipliers.size(), which);
  else
    std::printf("multipliers      %zu%s; trivial one %.12g%+.3gi (|mu - 1| = %.3g)\n",
                r.multipliers.size(), which,
                r.multipliers[static_cast<std::size_t>(r.trivial)].real(),
                r.multipliers[static_cast<std::size_t>(r.trivial)].imag(), r.trivial_error);
  for (std::size_t i = 0, shown = 0; i < r.multipliers.size() && shown < 4; ++i) {
    if (static_cast<int>(i) == r.trivial) continue;
    std::printf("                 |mu| = %.6g (%.6g%+.6gi)\n", std::abs(r.multipliers[i]),
                r.multipliers[i].real(), r.multipliers[i].imag());
    ++shown;
  }
  if (r.step_check) {
    const study::StepCheck& c = *r.step_check;
    if (c.converged)
      std::printf(
          "step check       at %s %.4g: period %+.3g s (%+.3g of it), amplitude %+.3g "
          "(%+.3g of it)\n",
          c.setting.c_str(), c.value, c.period_change, c.relative_period_change, c.amplitude_change,
          c.relative_amplitude_change);
    else
      std::printf("step check       at %s %.4g: not done: %s\n", c.setting.c_str(), c.value,
                  c.why.c_str());
  }
  std::printf("results          %s (%.3g s)\n", out.string().c_str(), r.seconds);
  return r.stable ? 0 : kExitUnstable;
}

}  // namespace

Command addOrbitCommand(CLI::App& tribo) {
  auto a = std::make_shared<Arguments>();
  CLI::App* orbit = tribo.add_subcommand(
      "orbit", "the periodic orbit (limit cycle): period, amplitude, Floquet multipliers");
  addPathArgument(*orbit, "SCENE", a->scene_path, "the YAML scene");
  addOutOption(*orbit, a->out_dir, "output folder: DIR/orbit.json and DIR/orbit.csv")->required();
  addSetOption(*orbit, a->overrides);
  addCheckedOption(*orbit, "--settle", "SECONDS",
                   "the run whose last two maxima give the first guess, at most this long\n"
                   "(default: the scene's duration); it stops once three cycles repeat\n"
                   "the one before to 1e-6",
                   [a](const std::string& v) { a->spec.settle = positive("--settle", v); });
  addCheckedOption(*orbit, "--tolerance", "X",
                   "Newton's tolerance on |phi_T(y0) - y0| / (1 + |y0|) (1e-9)",
                   [a](const std::string& v) { a->spec.tolerance = positive("--tolerance", v); });
  orbit->add_flag_callback(
      "--no-step-check", [a] { a->step_check = false; },
      "skip the orbit found again at half the time step (an adaptive integrator:\n"
      "its tolerances over 100) that says how much period and amplitude\n"
      "change with the step (orbit.json step_check; one orbit: a branch has none)");
  orbit->add_flag_callback(
      "--newton-only", [a] { a->spec.return_map = false; },
      "skip the return-map iterations that come before Newton's (the orbit is the\n"
      "same; they save most of the flows on a strongly contracting one)");
  addCheckedOption(*orbit, "--period", "SECONDS",
                   "a forced scene: the forcing's period (default: read from its inputs,\n"
                   "which must then be sines or sine drives; any input is checked to\n"
                   "repeat with the period given)",
                   [a](const std::string& v) {
                     a->spec.period = positive("--period", v);
                     a->forced_options = true;
                   });
  addCheckedOption(*orbit, "--periods", "K",
                   "a forced scene: the orbit spans K forcing periods (a subharmonic; 1)",
                   [a](const std::string& v) {
                     a->spec.periods = wholeAtLeast("--periods", v, 1);
                     a->forced_options = true;
                   });
  addCheckedOption(*orbit, "--solver", "KIND",
                   "Newton's linear systems: dense (every multiplier), krylov (GMRES and\n"
                   "Arnoldi on products, one flow each; the 8 leading multipliers) or auto\n"
                   "(krylov from 40 unknowns; default)",
                   [a](const std::string& v) {
                     if (v == "dense")
                       a->spec.solver = study::OrbitSolver::kDense;
                     else if (v == "krylov")
                       a->spec.solver = study::OrbitSolver::kKrylov;
                     else if (v == "auto")
                       a->spec.solver = study::OrbitSolver::kAuto;
                     else
                       throw std::invalid_argument(
                           "--solver: expected dense, krylov or auto, found '" + v + "'");
                   });
  addCheckedOption(*orbit, "--continue", "NAME=FROM:TO",
                   "follow the orbit's branch in parameter NAME from FROM towards TO\n"
                   "(pseudo-arclength): DIR/branch.csv, branch.json, branch_orbits.csv",
                   [a](const std::string& v) {
                     parseContinue(v, a->branch);
                     a->continuation = true;
                   });
  addCheckedOption(*orbit, "--max-points", "N",
                   "with --continue: points at most, the first included (20)",
                   [a](const std::string& v) {
                     a->branch.max_points = wholeAtLeast("--max-points", v, 2);
                     a->branch_options = true;
                   });
  addCheckedOption(*orbit, "--step", "S",
                   "with --continue: the first arclength step, in the norm's units\n"
                   "(default: |TO - FROM| / 10 with --arclength si, 0.1 scaled)",
                   [a](const std::string& v) {
                     a->branch.step = positive("--step", v);
                     a->branch_options = true;
                   });
  addCheckedOption(*orbit, "--max-step", "S",
                   "with --continue: the largest arclength step, in the norm's units\n"
                   "(default: 4 times the first; the step grows by 1.5 after an easy point);\n"
                   "--step S --max-step S spaces the points evenly",
                   [a](const std::string& v) {
                     a->branch.max_step = positive("--max-step", v);
                     a->branch_options = true;
                   });
  addCheckedOption(
      *orbit, "--arclength", "NORM",
      "with --continue: the arclength's norm, si (the unknowns in their SI\n"
      "units; the default) or scaled (each unknown over its scale: the state\n"
      "over its range on the first orbit, the period over the first period,\n"
      "the parameter over |TO - FROM|; the branch then does not depend on\n"
      "the parameter's units and --step defaults to 0.1)",
      [a](const std::string& v) {
        if (v == "si")
          a->branch.norm = study::ArclengthNorm::kSi;
        else if (v == "scaled")
          a->branch.norm = study::ArclengthNorm::kScaled;
        else
          throw std::invalid_argument("--arclength: expected si or scaled, found '" + v + "'");
        a->branch_options = true;
      });
  orbit->add_flag_function(
      "--from-hopf",
      [a](std::int64_t) {
        a->branch.from_hopf = true;
        a->branch_options = true;
      },
      "with --continue: start at the Hopf point of steady sliding between FROM\n"
      "and TO (where `tribo modes` finds its leading oscillatory mode turning\n"
      "unstable) instead of at the orbit a settling run finds at FROM; finds the\n"
      "unstable cycles of a subcritical Hopf point");
  addCheckedOption(*orbit, "--switch", "KIND",
                   "with --continue: follow the branch until its first period_doubling (a\n"
                   "multiplier through -1) or branch_point (a real multiplier through +1 that\n"
                   "is not a fold's), locate it, and follow the branch that leaves it there\n"
                   "(orbits of twice the period, or the same period) either way within FROM:TO;\n"
                   "the first branch goes to DIR/primary_branch.csv",
                   [a](const std::string& v) {
                     if (v == "period_doubling")
                       a->branch.switch_at = study::BranchSwitch::kPeriodDoubling;
                     else if (v == "branch_point")
                       a->branch.switch_at = study::BranchSwitch::kBranchPoint;
                     else
                       throw std::invalid_argument(
                           "--switch: expected period_doubling or branch_point, found '" + v + "'");
                     a->branch_options = true;
                   });
  addCheckedOption(*orbit, "--switch-amplitude", "A",
                   "with --switch: the first orbit of the new branch is A off the located one\n"
                   "[m or rad] along the critical mode, in its largest position entry (1e-3)",
                   [a](const std::string& v) {
                     a->branch.switch_amplitude = positive("--switch-amplitude", v);
                     a->branch_options = true;
                   });
  addCheckedOption(*orbit, "--hopf-amplitude", "A",
                   "with --from-hopf: the first orbit peaks A above steady sliding in the\n"
                   "summary's coordinate [m or rad] (1e-3)",
                   [a](const std::string& v) {
                     a->branch.hopf_amplitude = positive("--hopf-amplitude", v);
                     a->branch_options = true;
                   });
  orbit->footer(
      "Shoots for the orbit on the scene's own integrator and step: unknowns the state on\n"
      "the orbit where the summary's coordinate peaks, and the period; Newton with the\n"
      "Jacobian by finite differences of the flow (columns on the cores). The multipliers\n"
      "are the monodromy matrix's eigenvalues; one is 1 (reported with its error).\n"
      "The orbit is then found again at half the step (dopri5, bdf: tolerances over\n"
      "100) and the change in period and amplitude printed (step check).\n"
      "A scene whose inputs vary in time has forced orbits: their period is the\n"
      "forcing's (or K times it, --periods), the unknowns the state alone, no\n"
      "trivial multiplier. rk4 or semi_implicit_euler (docs/orbits.md).\n"
      "--continue follows the orbit in a parameter (pseudo-arclength continuation) and\n"
      "reports folds, period doublings, tori, stability changes, grazing and Hopf points\n"
      "between its points; a forced scene's branch is its forced orbits (in the forcing\n"
      "frequency: the frequency response, unstable part included).\n"
      "exit status: 0 stable orbit (with --continue: a branch not lost on the way),\n"
      "1 usage, 2 bad scene, 4 output error, 8 unstable orbit, 11 no orbit found,\n"
      "12 the branch was lost (the points found so far are written), 5 interrupted (the\n"
      "first SIGINT or SIGTERM ends the branch after the point in hand; its points are\n"
      "written)");
  return {orbit, [a] { return runOrbit(*a); }};
}

}  // namespace tribo::app
