// Closed-form contact manifolds for primitive pairs, cheaper than the general narrowphase and
// with the points the physics needs (a body resting on a face gets several).
//
// Shape on a half-space (plane n . x = n . x0, solid below): every point of the shape's
// candidate set below the plane is a contact, placed midway between the point and the plane,
// depth = n . x0 - n . p, normal = n (from the half-space into the shape):
//   box: its 8 corners (feature = corner index)
//   sphere: the point c - r n (exact);  capsule: the same for both end spheres
//   cylinder: 8 points on each rim circle, the first at the rim's deepest point (exact
//     depth for any tilt; for a disc resting flat, 8 equal points); feature = 8 rim + k
//   cone: the apex and 8 base-rim points chosen the same way
//   convex or triangle mesh: its vertices below the plane (feature = vertex index), thinned
//     to `max_points` by farthest-point sampling when there are more
// Sphere/sphere and sphere/box: the exact single point (closest points of the surfaces).
// Not here: general convex pairs (FCL), forces. Rim sampling makes a tilted disc's contact
// patch polygonal (8 sides); the penalty force grows with the number of points touching.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "contact/contact_point.hpp"
#include "contact/shape.hpp"

namespace tribo::contact {

// Points of `shape` (at `shape_pose`) below the plane z = 0 of `plane_pose`, normal +z of the
// plane. Appends to `out`; returns the number added.
int halfSpaceContacts(const Shape& shape, const Eigen::Isometry3d& shape_pose,
                      const Eigen::Isometry3d& plane_pose, int pair, int max_points,
                      std::vector<ContactPoint>& out);

// The box-only case, kept as its own entry for the hot belt path.
int boxHalfSpaceContacts(const Eigen::Isometry3d& box_pose, const Eigen::Vector3d& half_extents,
                         const Eigen::Isometry3d& plane_pose, int pair,
                         std::vector<ContactPoint>& out);

// Sphere A (centre ca, radius ra) and sphere B: at most one point, normal from A into B.
int sphereSphereContact(const Eigen::Vector3d& ca, double ra, const Eigen::Vector3d& cb, double rb,
                        int pair, std::vector<ContactPoint>& out);

// Box A and sphere B: at most one point, normal from the box into the sphere. A centre
// inside the box is pushed out through the nearest face.
int boxSphereContact(const Eigen::Isometry3d& box_pose, const Eigen::Vector3d& half_extents,
                     const Eigen::Vector3d& centre, double radius, int pair,
                     std::vector<ContactPoint>& out);

// Farthest-point thinning of out[first..] down to max_points (<= 0: no limit): the deepest
// point first, then each time the point farthest from those kept.
void thinContacts(std::vector<ContactPoint>& out, std::size_t first, int max_points);

}  // namespace tribo::contact
