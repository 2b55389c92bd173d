// Closed-form contacts of the round primitives with each other, without FCL: a sphere with a
// capsule and a capsule with a capsule, normal from A into B. A capsule is the segment
// c + t u, |t| <= h (u its local z, h its half length), swept by its radius r; h = 0 is a
// sphere.
//
// Every point is the sphere/sphere contact of primitive_contacts.hpp between a point x of A's
// segment (radius r_a) and a point y of B's (radius r_b): d = |y - x|, depth = r_a + r_b - d
// (a contact when > 0), normal n = (y - x) / d, position midway between the two surfaces,
// (x + y) / 2 + (r_a - r_b) n / 2 (the same point, bitwise, with A and B swapped).
//
// Sphere/capsule: x the centre, y = c + clamp(u . (x - c), -h, h) u, one point (feature 0).
// Capsule/capsule: x, y the closest points of the two segments (Ericson, Real-Time Collision
// Detection (2005), 5.1.9): with w = c_a - c_b, b = u_a . u_b, the unconstrained minimiser
// s = (b (u_b . w) - u_a . w) / |u_a x u_b|^2 clamped to [-h_a, h_a], then
// t = clamp(b s + u_b . w) and s = clamp(b t - u_a . w) (s = 0 first for parallel axes).
// No contact when d >= r_a + r_b. Near-parallel axes (|u_a x u_b| < 1e-3, a tilt under
// 1 mrad) whose projections on A's axis overlap over a positive length give a line
// contact: the two ends of the overlap interval on A's segment, each against its closest
// point on B's segment (features 0 and 1, each only when its depth > 0), so a capsule lying
// along another is held at both ends of the overlap like one lying on a box face
// (box_round_contacts.hpp); when neither end touches, the closest points. Otherwise one point
// at the closest points (feature 2).
// Coincident points (d below 1e-12 of r_a + r_b + h_a + h_b): the normal is the capsule's
// local x for sphere/capsule (perpendicular to its segment); for two crossing segments
// u_a x u_b normalised, turned towards B's centre when B's centre is off their common plane
// (it is in the plane when the segments truly cross, so the cross product's own sign decides,
// which flips with the order of the pair); for (near-)parallel coincident segments A's local
// x. The depth is then r_a + r_b. Outputs are finite for any finite pose, h >= 0, r >= 0.
// Limit: a line contact has no point inside the overlap. When near-parallel axes come closest
// inside it (a slight X), the middle is deeper than both ends by up to
// (overlap sin(angle))^2 / (8 d) for axes a distance d apart, and by at most
// overlap sin(angle) / 2 < 5e-4 overlap; the two ends carry the exact depths of their points.
// Swapping A and B flips the normal and keeps single points (to rounding of the closest
// points); a line contact's ends are taken along A's axis, so a swapped pair's ends agree only
// where the two axes are exactly parallel; for coincident parallel segments the fallback
// normal is each first body's own x axis. Does not allocate beyond appending to `out`.
// Not here: capsule/box (box_round_contacts.hpp), cylinders, forces.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "contact/contact_point.hpp"

namespace tribo::contact {

// Sphere A (centre, radius) and capsule B (pose, radius, half length along its z): at most
// one point, normal from A into B. Returns the number of points appended (0 or 1).
int sphereCapsuleContact(const Eigen::Vector3d& centre, double sphere_radius,
                         const Eigen::Isometry3d& capsule_pose, double radius, double half_length,
                         int pair, std::vector<ContactPoint>& out);

// Capsule A and capsule B (pose, radius, half length along its z): normal from A into B.
// Returns the number of points appended (0, 1, or 2 for a line contact).
int capsuleCapsuleContacts(const Eigen::Isometry3d& pose_a, double radius_a, double half_length_a,
                           const Eigen::Isometry3d& pose_b, double radius_b, double half_length_b,
                           int pair, std::vector<ContactPoint>& out);

}  // namespace tribo::contact
