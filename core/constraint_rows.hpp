// The scalar constraint equations of a model in solve order, and their evaluation at a
// state: Phi, the Jacobian blocks (1x6 per dynamic body, over its world-frame (v, w)),
// J' v, and for rheonomic rows the prescribed rate and acceleration. Order: every joint
// equation (core/joint.hpp) not dropped as redundant, then one row per drive
// (q - f(t) = 0), then one per coupling (q_f - r q_l - offset = 0).
//
// A row's acceleration equation is  J a = -(J' v - f'') - 2 alpha Phi' - beta^2 Phi  with
// Phi' = J v - f'  (Baumgarte 1972, Comput. Methods Appl. Mech. Eng. 1:1-16).
// Joint coordinates: angle q = atan2(z . (x_P x x_C), x_P . x_C) about the parent z axis
// (wrapped to (-pi, pi]), q' = z . (w_C - w_P); slide q = z . (p_C - p_P), the distance
// equation along z. Both are exact on the joint's constraint manifold.
// Not here: the solve (core/constraint_solver.hpp), projection, redundancy detection.
#pragma once

#include <optional>
#include <vector>

#include "core/model.hpp"
#include "core/state.hpp"

namespace tribo {

// Where a body is and how it moves (the world: identity, at rest).
struct BodyMotion {
  const Mat3& rotation;
  const Vec3& origin;
  const Vec3& velocity;
  const Vec3& angular_velocity;
};

// Body motions from a state and its rotation matrices (one per body).
class MotionView {
 public:
  MotionView(const State& state, const std::vector<Mat3>& rotations)
      : state_(state), rotations_(rotations) {}
  BodyMotion operator()(BodyIndex b) const;

 private:
  const State& state_;
  const std::vector<Mat3>& rotations_;
};

// The scalar coordinate of a revolute (angular) or prismatic joint.
struct JointCoordinate {
  bool angular = true;
  BodyIndex parent = BodyIndex::world();
  BodyIndex child;
  Vec3 z_parent = Vec3::UnitZ();  // joint axis, parent frame
  Vec3 x_parent = Vec3::UnitX();  // zero-angle reference, parent frame
  Vec3 x_child = Vec3::UnitX();   // zero-angle reference, child frame
  Vec3 anchor_parent = Vec3::Zero();
  Vec3 anchor_child = Vec3::Zero();
};
JointCoordinate jointCoordinate(const Joint& joint);

struct CoordinateValue {
  double q = 0.0;       // [rad or m]
  double rate = 0.0;    // q' [rad/s or m/s]
  double jdot_v = 0.0;  // J' v
  Row6 j_parent = Row6::Zero();
  Row6 j_child = Row6::Zero();
};
void evaluateCoordinate(const JointCoordinate& c, const BodyMotion& parent, const BodyMotion& child,
                        CoordinateValue& out);

struct ConstraintRow {
  enum class Kind { kDistance, kPerpendicular, kCoordinate, kCoupling };
  static constexpr int kDriveEquation = -1;
  static constexpr int kCouplingEquation = -2;
  static constexpr int kMaxBodies = 4;

  Kind kind = Kind::kDistance;
  int joint = -1;     // the joint it belongs to (a coupling: its follower)
  int equation = 0;   // index in jointEquations(type), or kDriveEquation, kCouplingEquation
  int coupling = -1;  // index in Model::couplings (kCoupling)
  // Primitives (kDistance, kPerpendicular).
  BodyIndex parent = BodyIndex::world();
  BodyIndex child;
  Vec3 u_parent = Vec3::Zero();       // parent axis i, parent frame
  Vec3 w_child = Vec3::Zero();        // child axis j, child frame (perpendicular)
  Vec3 anchor_parent = Vec3::Zero();  // parent frame
  Vec3 anchor_child = Vec3::Zero();   // child frame
  // kCoordinate (a drive) and kCoupling (the follower; the leader below).
  JointCoordinate coordinate;
  const JointDrive* drive = nullptr;  // the model's, which outlives its rows
  JointCoordinate leader;
  double multiplier = 1.0;
  double offset = 0.0;
  // The dynamic bodies the row touches (Jacobian block k belongs to body[k]).
  int body_count = 0;
  int body[kMaxBodies] = {-1, -1, -1, -1};
};

// The rows of a model in solve order; with include_dropped, also the joint equations the
// builder dropped as redundant (for the builder's own check).
std::vector<ConstraintRow> constraintRows(const Model& model, bool include_dropped = false);

// A row evaluated at a state and time.
struct RowValue {
  double phi = 0.0;      // Phi (drives: q - f(t); angles wrapped to (-pi, pi])
  double phi_dot = 0.0;  // J v - f'(t)
  double bias = 0.0;     // J' v - f''(t)
  Row6 j[ConstraintRow::kMaxBodies];
};

// Consecutive rows evaluated together: the equations of one joint share its frames, so the
// world-frame anchors, separation and their rates are computed once per joint.
struct RowGroup {
  int begin = 0;
  int end = 0;
};
std::vector<RowGroup> rowGroups(const std::vector<ConstraintRow>& rows);
// First row of each group, then the row count (the form MultiplierMatrix::init takes).
std::vector<int> groupBegins(const std::vector<RowGroup>& groups, int rows);

// Evaluates rows[g.begin, g.end) into out[g.begin, g.end).
void evaluateRowGroup(const std::vector<ConstraintRow>& rows, const RowGroup& g,
                      const MotionView& motion, double time, RowValue* out);
void evaluateRows(const std::vector<ConstraintRow>& rows, const std::vector<RowGroup>& groups,
                  const MotionView& motion, double time, std::vector<RowValue>& out);

// An angle wrapped to (-pi, pi].
double wrapAngle(double a);

}  // namespace tribo
