// Studies from Python (sweeps are python/bind_sweep.cpp's): tribo.modes analyses a scene's
// linear stability as `tribo modes` does (study/modes/modes.hpp) and returns the steady
// state's figures and the modes as a dict.
// tribo.tradeoff measures the speed-accuracy ladder as `tribo tradeoff` does
// (study/tradeoff.hpp) and returns its rows. tribo.orbit finds the periodic orbit as
// `tribo orbit` does (study/orbit/periodic_orbit.hpp) and returns orbit.json's document with
// the sampled period as arrays; tribo.orbit_branch continues it in a parameter as
// `tribo orbit --continue` does (study/orbit/orbit_branch.hpp) and returns branch.json's
// document with its columns and each point's orbit as arrays. The GIL is released while they
// run. Not here: plotting.
#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <filesystem>

#include "python/bindings.hpp"
#include "python/python_law.hpp"
#include "python/scene_handle.hpp"
#include "study/modes/modes.hpp"
#include "study/modes/modes_report.hpp"
#include "study/orbit/orbit_branch.hpp"
#include "study/orbit/periodic_orbit.hpp"
#include "study/tradeoff.hpp"

namespace tribo::python {
namespace {

// modes.json's document as a dict (study/modes/modes_report.hpp spells its fields).
py::array_t<double> matrixArray(const Eigen::MatrixXd& m) {
  py::array_t<double> a({static_cast<py::ssize_t>(m.rows()), static_cast<py::ssize_t>(m.cols())});
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      a.mutable_at(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(j)) = m(i, j);
  return a;
}

py::object runModes(const SceneHandle& scene, bool settle, double settle_time, bool matrices) {
  study::ModesSpec spec;
  spec.steady.settle = settle;
  spec.steady.settle_time = settle_time;
  spec.linear_model = matrices;
  study::ModesResult r;
  try {
    py::gil_scoped_release release;
    r = study::analyzeModes(scene.scene, spec);
  } catch (const std::exception&) {
    raisePythonLawErrors(scene.user_laws);  // a Python law's error is the cause: say it
    throw;
  }
  raisePythonLawErrors(scene.user_laws);
  py::object out = jsonToPython(study::modesJsonText(scene.scene, r));
  if (r.linear) {
    py::dict lm;
    lm["A"] = matrixArray(r.linear->a);
    lm["B"] = matrixArray(r.linear->b);
    lm["K"] = matrixArray(r.linear->k);
    lm["C"] = matrixArray(r.linear->c);
    lm["states"] = r.linear->states;
    lm["inputs"] = r.linear->inputs;
    out["linear_model"] = lm;
  }
  return out;
}

py::list runTradeoff(const py::object& scene, const py::object& set,
                     const std::vector<std::string>& integrators, double window, int repeat) {
  study::TradeoffSpec spec;
  if (py::isinstance<SceneHandle>(scene)) {
    const auto& h = scene.cast<const SceneHandle&>();
    if (h.source != SceneHandle::Source::kFile || !h.user_laws.empty())
      throw py::value_error("tradeoff: give a scene file (the study loads it once per setting)");
    spec.scene_path = h.origin;
    spec.overrides = h.overrides;
  } else {
    spec.scene_path = py::module_::import("os").attr("fspath")(scene).cast<std::string>();
  }
  for (const std::string& o : overridesFrom(set)) spec.overrides.push_back(o);
  if (!integrators.empty()) {
    spec.integrators.clear();
    for (const std::string& name : integrators) {
      try {
        spec.integrators.push_back(integratorFromName(name));
      } catch (const std::invalid_argument& e) {
        throw py::value_error(e.what());
      }
    }
  }
  spec.window = window;
  spec.repeat = repeat;
  study::TradeoffResult result;
  {
    py::gil_scoped_release release;
    result = study::measureTradeoff(spec);
  }
  // tradeoff.csv's columns (study::tradeoffFields), numbers at full precision, NaN for none.
  const std::string scene_name = std::filesystem::path(spec.scene_path).stem().string();
  py::list rows;
  for (const study::TradeoffRow& r : result.rows) {
    py::dict d;
    for (const study::TradeoffField& f : study::tradeoffFields(scene_name, r)) {
      using K = study::TradeoffField::Kind;
      if (f.kind == K::kNumber)
        d[f.name] = f.number;
      else if (f.kind == K::kCount)
        d[f.name] = f.count;
      else
        d[f.name] = f.text;
    }
    rows.append(d);
  }
  return rows;
}

py::object runOrbit(const SceneHandle& scene, double settle, double tolerance, double period,
                    int periods, const std::string& solver, bool newton_only, bool step_check) {
  study::OrbitSpec spec;
  spec.return_map = !newton_only;
  if (solver == "dense")
    spec.solver = study::OrbitSolver::kDense;
  else if (solver == "krylov")
    spec.solver = study::OrbitSolver::kKrylov;
  else if (solver != "auto")
    throw py::value_error("orbit: solver must be 'auto', 'dense' or 'krylov', not '" + solver +
                          "'");
  spec.settle = settle;
  spec.tolerance = tolerance;
  spec.period = period;
  spec.periods = periods;
  if (!(settle >= 0.0) || !(tolerance > 0.0) || !(period >= 0.0) || !std::isfinite(period) ||
      periods < 1)
    throw py::value_error(
        "orbit: settle must be >= 0, tolerance > 0, period >= 0 (finite) and periods >= 1");
  if (!scene.user_laws.empty())
    throw py::value_error(
        "orbit: a scene with laws written in Python cannot be shot for an orbit (the flows "
        "run on several threads)");
  study::OrbitResult r;
  {
    py::gil_scoped_release release;
    r = study::findPeriodicOrbit(scene.scene, spec);
    if (step_check)  // as `tribo orbit` checks it (study/orbit/step_check.hpp)
      r.step_check = study::checkOrbitAgainstStep(
          *scene.scene.model, r, spec,
          [&](const io::RunSettings& finer) { return scene.withSettings(finer); });
  }
  py::object out = jsonToPython(study::orbitJsonText(scene.scene, spec, r));
  out["t"] = py::array_t<double>(static_cast<py::ssize_t>(r.t.size()), r.t.data());
  out["x"] = py::array_t<double>(static_cast<py::ssize_t>(r.x.size()), r.x.data());
  return out;
}

py::array_t<double> arrayOf(const std::vector<double>& v) {
  return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
}

// branch.csv's columns of `points` as NumPy arrays.
py::dict branchColumns(const std::vector<study::BranchPoint>& points) {
  std::vector<double> p, period, amplitude, largest, stick, slip, steady;
  py::array_t<bool> stable(static_cast<py::ssize_t>(points.size()));
  py::array_t<bool> undecided(static_cast<py::ssize_t>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const study::BranchPoint& pt = points[i];
    p.push_back(pt.parameter);
    period.push_back(pt.period);
    amplitude.push_back(pt.amplitude_pp);
    largest.push_back(pt.largest);
    stick.push_back(pt.stick_fraction);
    slip.push_back(pt.min_slip);
    steady.push_back(pt.steady_growth);
    stable.mutable_at(static_cast<py::ssize_t>(i)) = pt.stable;
    undecided.mutable_at(static_cast<py::ssize_t>(i)) = pt.undecided;
  }
  py::dict columns;
  columns["parameter"] = arrayOf(p);
  columns["period"] = arrayOf(period);
  columns["amplitude_pp"] = arrayOf(amplitude);
  columns["largest_multiplier"] = arrayOf(largest);
  columns["stable"] = stable;
  columns["undecided"] = undecided;
  columns["stick_fraction"] = arrayOf(stick);
  columns["min_slip"] = arrayOf(slip);
  columns["steady_growth_rate"] = arrayOf(steady);
  return columns;
}

py::object runOrbitBranch(const SceneHandle& scene, const std::string& parameter, double start,
                          double end, int max_points, double step, double settle, double tolerance,
                          bool from_hopf, double hopf_amplitude, const std::string& arclength,
                          double forcing_period, int periods, const std::string& switch_at,
                          double switch_amplitude, bool newton_only) {
  if (!(max_points >= 2) || !(step >= 0.0) || !(settle >= 0.0) || !(tolerance > 0.0) ||
      !(hopf_amplitude >= 0.0) || !std::isfinite(hopf_amplitude))
    throw py::value_error(
        "orbit_branch: max_points must be >= 2, step >= 0, settle >= 0, tolerance > 0 and "
        "hopf_amplitude >= 0");
  if (!scene.user_laws.empty())
    throw py::value_error(
        "orbit_branch: a scene with laws written in Python cannot be shot for an orbit (the "
        "flows run on several threads)");
  if (scene.source == SceneHandle::Source::kUrdf)
    throw py::value_error("orbit_branch: a URDF robot has no parameters to continue in");
  study::BranchSpec spec;
  spec.parameter = parameter;
  spec.from = start;
  spec.to = end;
  spec.max_points = max_points;
  spec.step = step;
  spec.orbit.settle = settle;
  spec.orbit.tolerance = tolerance;
  spec.from_hopf = from_hopf;
  if (!(forcing_period >= 0.0) || !std::isfinite(forcing_period) || periods < 1)
    throw py::value_error("orbit_branch: period must be >= 0 and periods >= 1");
  spec.orbit.period = forcing_period;
  spec.orbit.periods = periods;
  if (arclength == "scaled")
    spec.norm = study::ArclengthNorm::kScaled;
  else if (arclength != "si")
    throw py::value_error("orbit_branch: arclength must be 'si' or 'scaled', got '" + arclength +
                          "'");
  spec.hopf_amplitude = hopf_amplitude;
  if (switch_at == "period_doubling")
    spec.switch_at = study::BranchSwitch::kPeriodDoubling;
  else if (switch_at == "branch_point")
    spec.switch_at = study::BranchSwitch::kBranchPoint;
  else if (switch_at != "none")
    throw py::value_error(
        "orbit_branch: switch must be 'none', 'period_doubling' or 'branch_point', got '" +
        switch_at + "'");
  if (!(switch_amplitude >= 0.0) || !std::isfinite(switch_amplitude))
    throw py::value_error("orbit_branch: switch_amplitude must be >= 0");
  spec.switch_amplitude = switch_amplitude;
  spec.orbit.return_map = !newton_only;
  study::BranchResult r;
  {
    py::gil_scoped_release release;
    r = scene.source == SceneHandle::Source::kFile
            ? study::continueOrbit(scene.origin, scene.overrides, spec)
            : study::continueOrbitFromText(scene.origin, scene.scene.path, scene.overrides, spec);
  }
  py::object out = jsonToPython(study::branchJsonText(scene.scene.path, spec, r));
  out["columns"] = branchColumns(r.points);
  if (r.switched.found) out["primary_columns"] = branchColumns(r.primary);
  py::list orbits;
  for (const study::BranchPoint& pt : r.points) {
    py::dict orbit;
    orbit["t"] = arrayOf(pt.t);
    orbit["x"] = arrayOf(pt.x);
    orbits.append(orbit);
  }
  out["orbits"] = orbits;
  return out;
}

}  // namespace

void bindStudies(py::module_& m) {
  m.def("modes", &runModes, py::arg("scene"), py::arg("settle") = false,
        py::arg("settle_time") = 0.0, py::arg("matrices") = false,
        "modes(scene, settle=False) -> dict: the linear stability of the scene's steady "
        "sliding, as `tribo modes` computes it: modes.json's document (modes sorted by "
        "decreasing growth rate, 'unstable_count' the unstable ones; a figure that is not "
        "finite is None). matrices=True adds 'linear_model': the arrays A, B, K, C of y' = A y + "
        "B w with the names of their 'states' and 'inputs' (the loads' components and the "
        "actuators' targets). Raises NoSteadyState, ModesError.");
  m.def("orbit", &runOrbit, py::arg("scene"), py::arg("settle") = 0.0, py::arg("tolerance") = 1e-9,
        py::arg("period") = 0.0, py::arg("periods") = 1, py::arg("solver") = "auto",
        py::arg("newton_only") = false, py::arg("step_check") = true,
        "orbit(scene, settle=0, tolerance=1e-9, period=0, periods=1, solver='auto', "
        "newton_only=False, step_check=True) -> dict: the periodic "
        "orbit as `tribo orbit` finds it (orbit.json's document: period, amplitude_pp, stable, "
        "multipliers, newton (with picard_iterations, flows_to_converge, periods_to_converge), "
        "forced, start...) with 't' and 'x', the observed coordinate over "
        "one period as arrays. newton_only=True skips the return-map iterations before "
        "Newton's (--newton-only); step_check=False skips 'step_check', the orbit found again "
        "at half the time step (adaptive integrators: tolerances over 100) and the change in "
        "period and amplitude (--no-step-check). A scene whose inputs vary in time has a forced "
        "orbit: period "
        "is the forcing's (0: read from its sines), periods the orbit's length in forcing "
        "periods. solver: 'dense', 'krylov' (GMRES and Arnoldi on flows; the 8 leading "
        "multipliers) or 'auto' (krylov from 40 unknowns). Raises OrbitError (no oscillation, no "
        "forcing period, no convergence).");
  m.def("orbit_branch", &runOrbitBranch, py::arg("scene"), py::arg("parameter"), py::arg("start"),
        py::arg("end"), py::arg("max_points") = 20, py::arg("step") = 0.0, py::arg("settle") = 0.0,
        py::arg("tolerance") = 1e-9, py::arg("from_hopf") = false, py::arg("hopf_amplitude") = 0.0,
        py::arg("arclength") = "si", py::arg("period") = 0.0, py::arg("periods") = 1,
        py::arg("switch") = "none", py::arg("switch_amplitude") = 0.0,
        py::arg("newton_only") = false,
        "orbit_branch(scene, parameter, start, end, max_points=20, step=0, settle=0, "
        "tolerance=1e-9, from_hopf=False, hopf_amplitude=0, arclength='si', period=0, periods=1, "
        "switch='none', switch_amplitude=0, newton_only=False) "
        "-> dict: the orbit "
        "at parameter = start continued towards end as `tribo orbit --continue` does; "
        "from_hopf=True starts instead at the Hopf point of steady sliding between start and "
        "end, with a first orbit of hopf_amplitude (0: 1e-3) ('hopf': where); arclength "
        "'scaled' measures the step with each unknown over its scale (--arclength scaled); a "
        "scene whose inputs vary in time gives a branch of forced orbits (period, periods as "
        "for orbit()); newton_only=True takes every step with the arclength corrector (no "
        "return-map steps on stick-slip stretches: --newton-only); "
        "switch='period_doubling' or 'branch_point' follows the branch to its first "
        "such bifurcation, locates it and returns the branch that leaves it there (--switch: "
        "'switch' says where, 'primary_columns' the first branch's columns) "
        "(branch.json's document: status, stop_reason, events, "
        "'branch' per point), with 'columns' (parameter, period, amplitude_pp, "
        "largest_multiplier, stable, undecided, stick_fraction, min_slip, steady_growth_rate as "
        "arrays) and 'orbits' (each "
        "point's 't' and 'x' over one period). Raises OrbitError (no orbit at start, no Hopf "
        "point in the range), "
        "SceneError (unknown or non-numeric parameter).");
  m.def("tradeoff", &runTradeoff, py::arg("scene"), py::arg("set") = py::none(),
        py::arg("integrators") = std::vector<std::string>{}, py::arg("window") = 10.0,
        py::arg("repeat") = 1,
        "tradeoff(scene_file, set={...}, integrators=[...], window=10, repeat=1) -> list of "
        "dicts, one per setting (tradeoff.csv's columns and rows at full precision, NaN for "
        "an empty field; the first is the reference at half its step), as `tribo tradeoff` "
        "measures them: amplitude and trajectory errors "
        "against a converged reference, and the processor time.");
}

}  // namespace tribo::python
