// The rows a continuation step solves and how (study/orbit/orbit_branch.hpp, internal to
// study/orbit/): the shooting rows at z = (y0, T, p) with the scene reloaded at p (the orbit
// closing, then the phase or, for a forced orbit, the period the forcing fixes), their
// Jacobian by central differences of the scene's flow, Newton's iteration on them plus one
// linear row (a continuation step's arclength row, a Hopf start's fixed amplitude, a switch's
// fixed offset or a located bifurcation's fixed parameter), the branch's unit tangent, and
// the scaled arclength norm's weights of the state.
// Not here: the continuation loop and the switch (orbit_branch.cpp), the events
// (branch_events.cpp), the files (branch_files.cpp).
#pragma once

#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

#include "io/scene_loader.hpp"
#include "io/scene_parameters.hpp"
#include "study/orbit/forcing.hpp"
#include "study/orbit/orbit_coordinates.hpp"
#include "study/orbit/shooting.hpp"

namespace tribo::study::branch {

// "NAME=VALUE" with every digit of VALUE, for a scene override.
std::string assignment(const std::string& name, double value);

// A forced branch's period: K forcing periods of the scene at p (`given` as forcingPeriod
// takes it: a period the user gave, or 0 to read it from the inputs).
struct ForcedPeriod {
  int periods = 1;
  double given = 0;
};

// The shooting rows and their Jacobian at z = (y0, T, p), the scene reloaded at p and p +- dp:
// the orbit closing, then the phase (autonomous) or the period fixed by the forcing (forced).
class BranchShooter {
 public:
  BranchShooter(const io::SceneDocument& document, std::vector<std::string> overrides,
                std::string parameter, const OrbitCoordinates& coords, Eigen::Index phase,
                Eigen::VectorXd floor, double fd_step, double dp, unsigned threads,
                std::optional<ForcedPeriod> forced)
      : document_(document),
        overrides_(std::move(overrides)),
        parameter_(std::move(parameter)),
        coords_(coords),
        phase_(phase),
        floor_(std::move(floor)),
        fd_step_(fd_step),
        dp_(dp),
        threads_(threads),
        forced_(forced) {}

  // The same rows for orbits `factor` times as long: a forced orbit spans factor K forcing
  // periods (an autonomous one's period is an unknown anyway).
  BranchShooter withPeriods(int factor) const {
    BranchShooter twin = *this;
    if (twin.forced_) twin.forced_->periods *= factor;
    return twin;
  }

  io::Scene sceneAt(double p) const {
    std::vector<std::string> o = overrides_;
    o.push_back(assignment(parameter_, p));
    return document_.load(o);
  }

  const OrbitCoordinates& coordinates() const { return coords_; }
  Eigen::Index phase() const { return phase_; }
  bool forced() const { return forced_.has_value(); }
  // A forced orbit's period at the scene `at`: K forcing periods.
  double forcedPeriod(const io::Scene& at) const {
    return forced_->periods * forcingPeriod(*at.model, forced_->given);
  }
  const Eigen::VectorXd& floor() const { return floor_; }
  double fdStep() const { return fd_step_; }
  unsigned threads() const { return threads_; }

  // The Jacobian's parameter column at z (its first n rows: d phi / d p by central
  // differences, two flows side by side), for a point whose other columns are known.
  Eigen::VectorXd parameterColumn(const Eigen::VectorXd& z) const {
    const Eigen::Index n = coords_.size();
    const Eigen::VectorXd y = z.head(n);
    const double T = z[n], p = z[n + 1];
    const io::Scene up_p = sceneAt(p + dp_), down_p = sceneAt(p - dp_);
    const shooting::Flow flow_up(up_p.model, coords_), flow_down(down_p.model, coords_);
    Eigen::VectorXd up, down;
    shooting::parallelColumns(2, threads_, [&](Eigen::Index j) {
      (j == 0 ? up : down) = (j == 0 ? flow_up : flow_down)(y, T);
    });
    return (up - down) / (2 * dp_);
  }

  // F (n + 1: the orbit closing; the phase, or for a forced orbit T - K P(p)), A = dF/dz
  // ((n + 1) x (n + 2)) and the monodromy matrix. Throws OrbitError (a failed step, no
  // forcing period) or io::SceneError (p outside the scene's range).
  void evaluate(const Eigen::VectorXd& z, Eigen::VectorXd& F, Eigen::MatrixXd& A,
                Eigen::MatrixXd& monodromy) const {
    const Eigen::Index n = coords_.size();
    const Eigen::VectorXd y = z.head(n);
    const double T = z[n], p = z[n + 1];
    const io::Scene at = sceneAt(p), up_p = sceneAt(p + dp_), down_p = sceneAt(p - dp_);
    const shooting::Flow flow(at.model, coords_), flow_up(up_p.model, coords_),
        flow_down(down_p.model, coords_);
    F.resize(n + 1);
    F.head(n) = flow(y, T) - y;
    auto period = [&](const io::Scene& scene) { return forcedPeriod(scene); };
    F[n] = forced_ ? T - period(at) : y[phase_];
    A = Eigen::MatrixXd::Zero(n + 1, n + 2);
    shooting::parallelColumns(n + 2, threads_, [&](Eigen::Index j) {
      // Central differences, as periodic_orbit.cpp takes them.
      if (j < n) {
        const double d = fd_step_ * std::max(std::abs(y[j]), floor_[j]);
        Eigen::VectorXd up = y, down = y;
        up[j] += d;
        down[j] -= d;
        A.col(j).head(n) = (flow(up, T) - flow(down, T)) / (2 * d);
      } else if (j == n) {
        const double d = fd_step_ * T;
        A.col(n).head(n) = (flow(y, T + d) - flow(y, T - d)) / (2 * d);
      } else {
        A.col(n + 1).head(n) = (flow_up(y, T) - flow_down(y, T)) / (2 * dp_);
      }
    });
    monodromy = A.topLeftCorner(n, n);
    A.topLeftCorner(n, n) -= Eigen::MatrixXd::Identity(n, n);
    if (forced_) {
      A(n, n) = 1.0;
      A(n, n + 1) = -(period(up_p) - period(down_p)) / (2 * dp_);
    } else {
      A(n, phase_) = 1.0;
    }
  }

 private:
  const io::SceneDocument& document_;
  std::vector<std::string> overrides_;
  std::string parameter_;
  const OrbitCoordinates& coords_;
  Eigen::Index phase_;
  Eigen::VectorXd floor_;
  double fd_step_, dp_;
  unsigned threads_;
  std::optional<ForcedPeriod> forced_;
};

// The unit tangent of the branch at a point with Jacobian A, in the scaled unknowns z / w:
// A diag(w) t = 0, |t| = 1, oriented along `along` (scaled too).
Eigen::VectorXd unitTangent(const Eigen::MatrixXd& A, const Eigen::VectorXd& along,
                            const Eigen::VectorXd& w);

// What a corrector found: the point z with its rows F, Jacobian A and monodromy matrix, or
// why it failed (`why`; ok false).
struct Correction {
  bool ok = false;
  std::string why;
  Eigen::VectorXd z, F;
  Eigen::MatrixXd A, monodromy;
  int iterations = 0;
  double residual = 0;
};

// Newton from z0 on the closing and phase rows and one linear row, row . z = value: the
// arclength row of a continuation step (row d, value d . z_pred), the amplitude row of a
// Hopf start (row e_obs, value the fixed peak, hopf_start.hpp), a switch's offset along the
// critical mode or a located bifurcation's parameter (branch_switch.hpp). A correction
// farther than `reach` from z0 in the norm of the weights w fails.
Correction newtonWithRow(const BranchShooter& shooter, const Eigen::VectorXd& z0,
                         const Eigen::VectorXd& row, double value, double reach,
                         const Eigen::VectorXd& w, int max_iterations, double tolerance);

// The corrector of a continuation step from the prediction z_pred = z_k + ds w d (d a unit
// direction in the scaled unknowns z / w): the correction normal to d there, no longer than ds.
Correction correct(const BranchShooter& shooter, const Eigen::VectorXd& z_pred,
                   const Eigen::VectorXd& d, double ds, const Eigen::VectorXd& w,
                   int max_iterations, double tolerance);

// The first orbit of a Hopf start: z[index] = value keeps it off the equilibrium.
Correction solveFixedAmplitude(const BranchShooter& shooter, const Eigen::VectorXd& z0,
                               Eigen::Index index, double value, int max_iterations,
                               double tolerance);

// The scaled norm's weight of each state entry: its range along the orbit from y0 over T,
// at least 1e-3 of the largest range of its kind (positions, rotations, velocities, angular
// velocities, friction states: OrbitCoordinates::kind) and 1e-3 of `floor` (the finite differences'
// scale: 10 um, 10 um/s, 10 urad), so that an entry that does not move (a box's turn on a flat
// belt, its rounding 1e-19) weighs nothing.
Eigen::VectorXd stateScales(const shooting::Flow& flow, const OrbitCoordinates& coords,
                            const Eigen::VectorXd& y0, double T, const Eigen::VectorXd& floor);

}  // namespace tribo::study::branch
