// Closed-form contact manifold of two boxes, without FCL: the separating axis test over the
// 15 candidate axes (the 3 + 3 face normals, the 9 cross products of an edge of A with an
// edge of B), with the interval radii of Ericson, Real-Time Collision Detection (2005),
// 4.4.1; separation along a unit axis L,
//   s(L) = |t . L| - (sum_i a_i |A_i . L| + sum_j b_j |B_j . L|),  t = centre B - centre A.
// Any s >= 0: no contact. Otherwise the axis of least penetration (largest s) is taken, with
// the usual bias for a stable choice (Gregorius, "The Separating Axis Test between Convex
// Polyhedra", GDC 2013): a face of B replaces a face of A only when s_B > 0.98 s_A, an edge
// pair replaces the face only when s_E > 0.95 s_face (the 1.05 fudge factor of ODE's box/box).
//   Face axis: the reference face is that box's face along the axis; the incident face is the
//   other box's face most opposed to it; the incident quad is clipped to the reference face's
//   four side planes (Sutherland-Hodgman, Ericson 8.3.4; a vertex within 1e-9 of the box size
//   outside a side plane counts as on it, so flush same-size boxes keep one point a corner)
//   and every clipped vertex x below the reference plane is a contact:
//   depth = u . p_ref - u . x, position = x + depth u / 2 (u the reference face's outward
//   normal), normal u (reference on A) or -u (reference on B).
//   Edge axis: one point midway between the closest points of the two edges (Ericson 5.1.9),
//   depth -s, normal along the cross product.
// Feature ids are stable while the same faces touch: an incident corner (its box corner
// index), an incident edge cut by a side plane, or a reference-face corner projected on the
// incident face; +64 when the reference face is on B; an edge pair is 128 + 3 i + j.
// At most 8 points; fewer when `max_points` asks (deepest first, then farthest-point).
// Does not allocate beyond appending to `out`. Not here: rounded shapes (box_round_contacts),
// boxes against meshes (polyhedron_contacts), contact forces.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "contact/contact_point.hpp"

namespace tribo::contact {

// Appends the contacts of box A (pose, half extents ha) and box B, normal from A into B.
// Returns the number of points added (0 when separated or touching).
int boxBoxContacts(const Eigen::Isometry3d& pose_a, const Eigen::Vector3d& ha,
                   const Eigen::Isometry3d& pose_b, const Eigen::Vector3d& hb, int pair,
                   int max_points, std::vector<ContactPoint>& out);

// Closest points cp, cq of the segments p + s d (|s| <= hp) and q + t e (|t| <= hq), d and e
// unit (Ericson 5.1.9, written about the segments' centres).
void closestOnSegments(const Eigen::Vector3d& p, const Eigen::Vector3d& d, double hp,
                       const Eigen::Vector3d& q, const Eigen::Vector3d& e, double hq,
                       Eigen::Vector3d& cp, Eigen::Vector3d& cq);

// Keeps at most `max_points` of out[first..] (<= 0: all): the deepest, then each time the
// point farthest from those kept. In place, no allocation; for at most 16 points.
void thinSmallManifold(std::vector<ContactPoint>& out, std::size_t first, int max_points);

}  // namespace tribo::contact
