// Closed-form contacts of a box with a capsule or a cylinder, without FCL where the closed
// form is exact; normal from the box into the round shape. Computed in the box's frame.
//
// Capsule (segment S swept by radius r): the closest points of S and the box, as the
// nearest of the two end points clamped to the box and of S against the 12 box edges
// (Ericson, Real-Time Collision Detection (2005), 5.1.3 and 5.1.9); no contact when the
// distance d >= r. When the box point is on a face (outward normal u), S is clipped to the
// face's rectangle and each remaining end x with depth = r - (u . x - h_u) > 0 is a contact at
// x - r u + depth u / 2: a capsule lying on a face gets both ends (features 0/1 for the
// capsule's ends, 2/3 where S was clipped at the face's border), a tilted one its lowest
// end. Closest point on an edge or a corner: one point midway between the surfaces, depth
// r - d (feature 4). S crossing the box (d = 0): the least-penetration axis among the box's 3
// face normals and the 3 products S x box edge (overlap = box radius + capsule radius along
// the axis - centre distance, with the 0.95 face bias of box_box_contacts.hpp); a face gives
// the clipped ends as above, an edge axis one point (feature 5).
//
// Cylinder: exact only when it touches one face of the box and stays over it: the box axis
// of least separation (Ericson 4.4: cylinder extent along box axis j is
// hl |a_j| + r sqrt(1 - a_j^2)) gives the face; when the whole cylinder projects inside that
// face's rectangle and its centre is outside the face's plane, the box is a half-space for it
// and the contact is primitive_contacts.hpp's cylinder on a plane (8 rim points per rim
// below the face, the first at the rim's deepest point: a cylinder standing on its end gets
// the rim, one lying on its side the two ends of the line contact, feature 8 rim + k).
// Every other cylinder pose (over a box edge, crossing it, reaching past the face) returns
// -1: the caller uses FCL's narrowphase (GJK/EPA, one point).
// Does not allocate beyond appending to `out`. Not here: box/box (box_box_contacts.hpp).
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "contact/contact_point.hpp"

namespace tribo::contact {

// Box (pose, half extents h) and capsule (pose, radius, half length along its z). Returns the
// number of points appended.
int boxCapsuleContacts(const Eigen::Isometry3d& box_pose, const Eigen::Vector3d& h,
                       const Eigen::Isometry3d& capsule_pose, double radius, double half_length,
                       int pair, std::vector<ContactPoint>& out);

// Box and cylinder (pose, radius, half length along its z). Returns the number of points
// appended, or -1 (nothing appended) when the pose has no closed form here (see above).
int boxCylinderContacts(const Eigen::Isometry3d& box_pose, const Eigen::Vector3d& h,
                        const Eigen::Isometry3d& cylinder_pose, double radius, double half_length,
                        int pair, std::vector<ContactPoint>& out);

}  // namespace tribo::contact
