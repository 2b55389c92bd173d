// A bushing: a linear spring-damper between a frame on body A (or the world) and a frame on
// body B, in all six directions, with per-axis gains along and about frame A's axes (as the
// bushings of Adams, Simbody and Drake).
//
// Frames A and B (origins o_A, o_B; rotations R_A, R_B to world) are fixed in their bodies.
// Deflection, in frame A's axes:
//   d   = R_A^T (o_B - o_A)                      translation of B's origin   [m]
//   phi = log(R_A^T R_B)                         rotation vector (SO(3) log,  [rad]
//                                                core/rotation_log.hpp), |phi| <= pi
//   d'  = R_A^T (v_B(o_B) - v_A(o_B))            velocity of o_B relative to A's material
//                                                point at o_B (= d/dt d)   [m/s]
//   w   = R_A^T (w_B - w_A)                      relative angular velocity  [rad/s]
// Potential V = 1/2 d^T K_t d + 1/2 phi^T K_r phi (K_t, K_r diagonal: stiffness,
// rotational_stiffness). Wrench on B, world; A gets the opposite force AT THE SAME POINT o_B
// and the opposite torque:
//   F_B = -R_A (K_t d + C_t d')                  applied at o_B
//   T_B = -R_A (J_r^-1(phi) K_r phi + C_r w)
// The force at o_B on both bodies is the exact gradient of 1/2 d^T K_t d with respect to
// both poses (d depends on R_A too: the moment of -F_B at o_B about o_A is that term), and
// J_r^-1(phi) K_r phi is the exact gradient of 1/2 phi^T K_r phi for the relative rotation
// taken on the left in A's axes (d phi/dt = J_l^-1(phi) w, J_l^-T = J_r^-1; Sola et al.,
// arXiv:1812.01537, eq. 144). So without damping V + kinetic energy is conserved exactly
// by the equations of motion, at any deflection, and since both bodies get equal and
// opposite forces at one point and opposite torques, linear and angular momentum too. For
// equal rotational gains J_r^-1 phi = phi: T_B = -R_A k phi. The damping terms dissipate
// d'^T C_t d' + w^T C_r w >= 0 (C_r acts on w, not on d phi/dt: the same for small phi).
// Not here: large-angle behaviour other than this potential's (unlike Adams' BUSHING, which
// uses small-angle projections, and Drake's LinearBushingRollPitchYaw, which uses roll-pitch-
// yaw angles, so neither agrees with this one beyond small angles with unequal gains); at
// |phi| = pi the log flips (the potential has a ridge there: the torque jumps); coupling
// terms (off-diagonal K, C), preload, nonlinear or frequency-dependent gains.
#pragma once

#include <string>

#include "core/body_kinematics.hpp"

namespace tribo {

struct Bushing {
  std::string name;
  BodyIndex body_a = BodyIndex::world();
  Vec3 position_a = Vec3::Zero();         // frame A's origin in A's body frame (world) [m]
  Quat orientation_a = Quat::Identity();  // frame A to A's body frame, unit
  BodyIndex body_b;
  Vec3 position_b = Vec3::Zero();            // frame B's origin in B's body frame [m]
  Quat orientation_b = Quat::Identity();     // frame B to B's body frame, unit
  Vec3 stiffness = Vec3::Zero();             // K_t along frame A's x, y, z [N/m]
  Vec3 damping = Vec3::Zero();               // C_t [N s/m]
  Vec3 rotational_stiffness = Vec3::Zero();  // K_r about frame A's x, y, z [N m/rad]
  Vec3 rotational_damping = Vec3::Zero();    // C_r [N m s/rad]
};

struct BushingDeflection {
  Vec3 translation = Vec3::Zero();       // d [m], frame A's axes
  Vec3 rotation = Vec3::Zero();          // phi [rad]
  Vec3 translation_rate = Vec3::Zero();  // d' [m/s]
  Vec3 angular_rate = Vec3::Zero();      // w [rad/s]
  Mat3 frame_a = Mat3::Identity();       // R_A, frame A to world
  Vec3 origin_b = Vec3::Zero();          // o_B, world [m]
};

// A force at a point and a torque, on body B (world); body A gets -force at the same point
// and -torque.
struct PairWrench {
  Vec3 force = Vec3::Zero();   // [N]
  Vec3 point = Vec3::Zero();   // world [m]
  Vec3 torque = Vec3::Zero();  // [N m]
};

BushingDeflection bushingDeflection(const Bushing& bushing, const BodyKinematics& a,
                                    const BodyKinematics& b);
PairWrench bushingWrench(const Bushing& bushing, const BushingDeflection& deflection);
// V = 1/2 d^T K_t d + 1/2 phi^T K_r phi [J].
double bushingEnergy(const Bushing& bushing, const BushingDeflection& deflection);

}  // namespace tribo
