// The result files of `tribo modes`, each written whole (study/file_commit.hpp):
//   modes.json  scene, parameters, verdict (stable / unstable, unstable_count), the leading
//               mode, the steady state (every dynamic body's position and orientation,
//               Newton's iterations and residual), the finite-difference steps and their
//               check, the eigensolver (method dense or sparse; the sparse one's modes
//               asked for, shifts, eigenvalues found, band_top and strip covered, worst
//               residual, factorization, operations), warnings, timings, and every mode computed:
//               eigenvalue (re, im), frequency [Hz], growth rate [1/s], damping ratio, unstable,
//               dominant coordinates and the shape (coordinate, magnitude, phase [deg]);
//   modes.csv   one row per mode: mode, frequency_hz, growth_rate, damping_ratio,
//               eigen_re, eigen_im, unstable (0/1), dominant, then one magnitude column per
//               full coordinate (e.g. box.x);
//   boundary.json (with --boundary) the parameter, bracket, critical value, growth rates
//               at the ends and the number of analyses.
// Not here: the analysis (study/modes/modes.hpp), printing (apps/modes_command.cpp).
#pragma once

#include <filesystem>
#include <string>

#include "io/scene_loader.hpp"
#include "study/modes/modes.hpp"
#include "study/modes/stability_boundary.hpp"

namespace tribo::study {

// Throw std::runtime_error naming the path when a file cannot be written.
void writeModesJson(const std::filesystem::path& file, const io::Scene& scene,
                    const ModesResult& result);
// The text writeModesJson writes (without its final newline): also the Python module's
// tribo.modes() dict, so the two spell every field once.
std::string modesJsonText(const io::Scene& scene, const ModesResult& result);
void writeModesCsv(const std::filesystem::path& file, const ModesResult& result);
void writeBoundaryJson(const std::filesystem::path& file, const BoundarySpec& spec,
                       const BoundaryResult& result);

}  // namespace tribo::study
