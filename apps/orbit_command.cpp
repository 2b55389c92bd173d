#include "apps/orbit_command.hpp"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "apps/common_options.hpp"
#include "apps/modes_command.hpp"
#include "io/scene_parameters.hpp"
#include "study/csv_text.hpp"
#include "study/file_commit.hpp"
#include "study/orbit/periodic_orbit.hpp"

namespace tribo::app {
namespace {

struct Arguments {
  std::string scene_path, out_dir;
  std::vector<std::string> overrides;
  study::OrbitSpec spec;
};

double positive(const std::string& option, const std::string& text) {
  const auto v = io::parseNumber(text);
  if (!v || !(*v > 0.0) || !std::isfinite(*v))
    throw std::invalid_argument(option + ": expected a number > 0, found '" + text + "'");
  return *v;
}

int runOrbit(Arguments& a) {
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
  std::printf("orbit            %s, %s\n", scene.path.c_str(), r.stable ? "stable" : "unstable");
  std::printf("period           %.10g s (%.6g Hz); the settled run gave %.6g s\n", r.period,
              1.0 / r.period, r.guess_period);
  std::printf("amplitude        %.10g peak to peak in %s (%.10g to %.10g)\n", r.amplitude_pp,
              r.observed.c_str(), r.x_min, r.x_max);
  std::printf("newton           %d iterations, residual %.3g\n", r.iterations, r.residual);
  std::printf("multipliers      %zu; trivial one %.12g%+.3gi (|mu - 1| = %.3g)\n",
              r.multipliers.size(), r.multipliers[static_cast<std::size_t>(r.trivial)].real(),
              r.multipliers[static_cast<std::size_t>(r.trivial)].imag(), r.trivial_error);
  for (std::size_t i = 0, shown = 0; i < r.multipliers.size() && shown < 4; ++i) {
    if (static_cast<int>(i) == r.trivial) continue;
    std::printf("                 |mu| = %.6g (%.6g%+.6gi)\n", std::abs(r.multipliers[i]),
                r.multipliers[i].real(), r.multipliers[i].imag());
    ++shown;
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
                   "the run whose last two maxima give the first guess (default: the\n"
                   "scene's duration)",
                   [a](const std::string& v) { a->spec.settle = positive("--settle", v); });
  addCheckedOption(*orbit, "--tolerance", "X",
                   "Newton's tolerance on |phi_T(y0) - y0| / (1 + |y0|) (1e-9)",
                   [a](const std::string& v) { a->spec.tolerance = positive("--tolerance", v); });
  orbit->footer(
      "Shoots for the orbit on the scene's own integrator and step: unknowns the state on\n"
      "the orbit where the summary's coordinate peaks, and the period; Newton with the\n"
      "Jacobian by finite differences of the flow (columns on the cores). The multipliers\n"
      "are the monodromy matrix's eigenvalues; one is 1 (reported with its error).\n"
      "Autonomous scenes with rk4 or semi_implicit_euler (docs/orbits.md).\n"
      "exit status: 0 stable orbit, 1 usage, 2 bad scene, 4 output error, 8 unstable orbit,\n"
      "11 no orbit found");
  return {orbit, [a] { return runOrbit(*a); }};
}

}  // namespace tribo::app
