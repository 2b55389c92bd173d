// The scenes of bench/peers in a form any engine can build: rigid bodies with boxes, spheres
// and half-spaces at their initial poses, read from a loaded Tribo Model so that Bullet and
// MuJoCo start from exactly what Tribo starts from; the belt as its few numbers; the box grids
// as scene text; and what one engine's run measured. Penalty laws are not carried over: each
// engine keeps its own contact model and its own friction (Coulomb with the scene's mu).
// Not for joints, springs or meshes beyond the belt (the peers' scenes have none).
#pragma once

#include <Eigen/Geometry>
#include <chrono>
#include <ctime>
#include <string>
#include <vector>

#include "core/model.hpp"

namespace tribo::peers {

struct PeerShape {
  enum class Kind { kBox, kSphere, kHalfSpace };
  Kind kind = Kind::kBox;
  Eigen::Vector3d half_extents = Eigen::Vector3d::Zero();  // box [m]
  double radius = 0.0;                                     // sphere [m]
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // body frame (half-space: z = 0 plane,
                                                           // solid below, in this frame)
};

struct PeerBody {
  std::string name;
  bool dynamic = true;  // false: fixed in the world (a ground, a container)
  double mass = 0.0;    // [kg]
  Eigen::Vector3d inertia = Eigen::Vector3d::Zero();  // principal, about the centre [kg m^2]
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  std::vector<PeerShape> shapes;
};

struct PeerScene {
  std::vector<PeerBody> bodies;
  Eigen::Vector3d gravity{0, 0, -9.81};
  double mu = 0.5;    // Coulomb friction coefficient of every pair
  double dt = 1e-3;   // [s]
  long steps = 2000;  // steps of one measured run
};

// Every body of `model` (dynamic ones with one geometry at their centre and a diagonal
// inertia; kinematic ones standing still). Throws std::invalid_argument for anything else.
PeerScene peerSceneFrom(const Model& model, double mu, long steps);

// Horizontal drift: the largest xy displacement of a dynamic body from its start [m].
double horizontalDrift(const PeerScene& scene, const std::vector<Eigen::Vector3d>& positions);

// The belt (scenes/belt.yaml): a box of mass m pressed on a belt moving at v_b along x, tied by
// a spring k; 1 DOF along x (and z for contact), no rotation. With Coulomb friction mu it slides
// all the time (slip speed v_b - xdot > 0) and x(t) = x_eq (1 - cos(w t)), x_eq = mu m g / k,
// w = sqrt(k / m): the reference the engines are measured against.
struct BeltSpec {
  double mass = 10.0;                            // [kg]
  double spring = 300.0;                         // [N/m]
  double belt_speed = 1.5;                       // [m/s]
  double mu = 0.3;                               // Coulomb
  Eigen::Vector3d half_extents{0.1, 0.1, 0.05};  // box [m]
  double dt = 1e-3;                              // [s]
  long steps = 2000;
  double g = 9.81;  // [m/s^2]
  double exactX(double t) const;
};

// One engine's measured run.
struct PeerRun {
  double seconds = 0.0;      // wall time of the steps only (building the world excluded)
  double cpu_seconds = 0.0;  // the process's CPU time over the same steps
  long steps = 0;
  double penetration = 0.0;  // deepest contact after the last step [m]
  double drift = 0.0;        // largest horizontal displacement [m] (grids), 0 otherwise
  double points = 0.0;       // contact points after the last step
  double max_speed = 0.0;    // fastest dynamic body after the last step [m/s] (at rest: ~0)
  double belt_error = 0.0;   // belt: |x(T) - exactX(T)| [m]
  std::string error;         // non-empty: the run failed or was not made (and why)
};

// Wall and process CPU time from construction to stop(), into a PeerRun.
class StepTimer {
 public:
  StepTimer() : wall_(std::chrono::steady_clock::now()), cpu_(std::clock()) {}
  void stop(PeerRun& run) const {
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_).count();
    run.cpu_seconds = static_cast<double>(std::clock() - cpu_) / CLOCKS_PER_SEC;
  }

 private:
  std::chrono::steady_clock::time_point wall_;
  std::clock_t cpu_;
};

}  // namespace tribo::peers
