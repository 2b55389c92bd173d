// What the contact stage produces for one contact point between geometries A and B.
//
// Geometry (position, normal from A into B, depth > 0 when penetrating, and which feature of
// the pair made the point) comes from collision detection; kinematics (depth rate,
// tangential slip of B relative to A including surface velocities) and forces (normal load,
// friction force, effective coefficient) are filled by contact_force.hpp. Forces act on B;
// A gets the opposite.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace tribo::contact {

struct ContactPoint {
  int pair = -1;     // index into the detector's pair list
  int feature = -1;  // which point of the pair's manifold (e.g. box corner 0-7), stable from
                     // step to step; -1 when the narrowphase gives no identity (FCL)
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // world [m]
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();   // world, unit, from A into B
  double depth = 0.0;                                  // penetration [m], > 0 in contact
};

struct ContactRecord {
  ContactPoint point;
  double depth_rate = 0.0;                         // d(depth)/dt [m/s]
  Eigen::Vector3d slip = Eigen::Vector3d::Zero();  // tangential velocity of B rel. A [m/s]
  double normal_force = 0.0;                       // >= 0 [N]
  Eigen::Vector3d friction_force = Eigen::Vector3d::Zero();  // on B, tangential [N]
  double mu = 0.0;  // effective coefficient |F_t| / F_n at this contact
  // Rolling and spinning resistance on B [N m] (contact/rolling_resistance.hpp); A gets the
  // opposite. Zero without it.
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  Eigen::Vector3d force() const { return normal_force * point.normal + friction_force; }
};

}  // namespace tribo::contact
