// Checks on a read URDF robot that decide whether it can be simulated meaningfully:
//   errors:   negative or non-finite mass, a collision mesh that cannot be found, a
//             collision shape without positive dimensions (a sphere of radius 0 is a note:
//             a contact point), a collision dimension or an origin coordinate (collision,
//             inertial, joint) over contact::kMaxLength (1e6 m; mesh vertices are checked
//             when the mesh is read, io/mesh_loader.hpp);
//   warnings: zero mass, inertia not positive definite or violating the triangle
//             inequality (I1 + I2 >= I3 for the principal moments), a link without
//             <inertial> that carries collision geometry. (Positive mass with no inertia is
//             not a finding here: io/urdf_model.hpp gives it its geometry's inertia, noted.)
// Appends to robot.issues. Not here: parsing, tree structure (urdfdom rejects bad trees).
#pragma once

#include "io/urdf_robot.hpp"

namespace tribo::io {

void checkUrdfRobot(UrdfRobot& robot);

}  // namespace tribo::io
