// The orbit's accuracy against the integrator's setting (`tribo orbit`, orbit.json
// "step_check"), measured as `tribo tradeoff` measures a run's: the same orbit found again on
// the scene loaded with a finer setting, and the change in its period and amplitude. The finer
// setting (finerSettings): half the time step for a fixed-step integrator (rk4,
// semi_implicit_euler), the relative and absolute tolerances over 100 for an adaptive one
// (dopri5, bdf). The finer orbit starts from the orbit found (its start state and period) and
// is reached by the return map (study/orbit/picard.hpp) and then, where that does not
// converge, by chord Newton steps with the orbit's own Jacobian (the dense solver's,
// OrbitResult::monodromy: it differs from the finer flow's by the integration error, so the
// steps contract at that rate), to a hundredth of the orbit's tolerance (else to the orbit's:
// StepCheck::tolerance). For an integrator of order p that converges at its order, the
// orbit's own error is the change times 2^p / (2^p - 1): about the change for rk4 (16/15),
// twice it for semi-implicit Euler (Richardson; Hairer, Norsett & Wanner, "Solving Ordinary
// Differential Equations I", 2nd ed., Springer 1993, sec. II.4).
// The penalty contacts' and friction laws' kinks can keep a method below its order (the
// belt's amplitude changes 5.5 times less, not 16, from 1 ms to 0.5 ms with RK4), so the
// change is what is reported, not an extrapolated error.
// Not here: loading the finer scene (the caller's loader, with io::RunSettings:
// apps/orbit_command.cpp, python/bind_studies.cpp); a check of a branch's points (one orbit's).
#pragma once

#include <functional>
#include <string>

#include "io/scene_loader.hpp"

namespace tribo::study {

struct OrbitResult;
struct OrbitSpec;

struct StepCheck {
  std::string setting;  // "time_step" or "relative_tolerance": what was refined
  double value = 0;     // the finer setting's value
  bool converged = false;
  std::string why;                      // when not converged: what was tried, the best residual
  double period = 0, amplitude_pp = 0;  // the orbit at the finer setting
  double period_change = 0, amplitude_change = 0;                    // finer less the orbit's
  double relative_period_change = 0, relative_amplitude_change = 0;  // over the orbit's
  int iterations = 0;   // the return map's (its best iterate's), then chord steps
  double residual = 0;  // |F| / (1 + |y0|) at the finer setting
  // The tolerance the finer orbit met: the orbit's over 100 (changes below the orbit's own
  // tolerance show), or the orbit's where the finer flow's noise stops the iterations short.
  double tolerance = 0;
  long flows = 0;  // of one period, at the finer setting
};

// The finer run settings for the scene's model (above), and the setting's name and value.
io::RunSettings finerSettings(const Model& model, std::string& setting, double& value);

// The check on `finer` (the orbit's scene loaded with finerSettings). Never throws for an
// orbit that is not reached (converged false, `why`); throws OrbitError for a scene whose
// state does not match the orbit's coordinates.
StepCheck checkAgainstFinerSetting(const io::Scene& finer, const OrbitResult& orbit,
                                   const OrbitSpec& spec);

// The whole check for the orbit found on a scene of `model`: its finer settings, the scene
// `load` gives with them (the scene file again, or a Python scene handle's origin), and the
// check there. Never throws: a scene that refuses the finer setting, or any other failure,
// is a check not converged whose `why` says so.
StepCheck checkOrbitAgainstStep(const Model& model, const OrbitResult& orbit, const OrbitSpec& spec,
                                const std::function<io::Scene(const io::RunSettings&)>& load);

}  // namespace tribo::study
