// Face manifolds between two convex polyhedra (box, convex_mesh), so that a body resting on a
// face gets the corners of the touching patch instead of the single deepest point of
// GJK/EPA (on which a resting cube rocks).
//
// Given the contact normal n (from A into B) and depth d that EPA found, the faces of A and
// B most nearly facing each other along n are candidates; a face's separating-axis overlap
// along its outward normal u,
//   overlap(u) = max over A of u.x - min over B of u.x   (for a face of A; mirrored for B),
// equals d when the contact is face-to-something. The face with the smaller overlap is the
// reference face; when even that exceeds 1.05 d (plus 1e-9 of the shapes' size) the
// contact is edge-to-edge and the caller keeps EPA's point. Otherwise the other body's face
// most opposed to u (the incident face) is clipped to the reference face's side planes
// (Sutherland-Hodgman), and every clipped vertex x below the reference plane is a contact:
//   depth = u . p_ref - u . x,  position = x + depth u / 2 (midway to the plane),
//   normal = u (reference on A) or -u (reference on B),
// thinned to `max_points` by farthest-point sampling from the deepest (Box2D's and ODE's
// dBoxBox clipping, on general polygons: Ericson, Real-Time Collision Detection, 8.3.4).
// Faces are the mesh's coplanar triangles merged into convex polygons when the shape is
// built. Points carry no feature id (contact identity by nearest point, stick_anchor.hpp).
// Not here: round shapes (cylinder, cone, capsule, sphere), triangle meshes, box/box
// (box_box_contacts.hpp), the narrowphase itself (collision_detector.cpp).
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "contact/contact_point.hpp"
#include "contact/shape.hpp"

namespace tribo::contact {

struct Polyhedron {
  struct Face {
    Eigen::Vector3d normal;  // outward, unit, geometry frame
    double offset = 0.0;     // normal . x on the face [m]
    std::vector<int> loop;   // vertex indices, counter-clockwise seen from outside
  };
  std::vector<Eigen::Vector3d> vertices;  // geometry frame [m]
  std::vector<Face> faces;
  double size = 0.0;  // largest distance of a vertex from the centroid [m]

  // max over the vertices of d . x (geometry frame).
  double support(const Eigen::Vector3d& d) const;
};

// True for the shapes a Polyhedron describes: box and convex_mesh.
bool isPolyhedron(const Shape& shape);

// The faces of a box or convex mesh (coplanar triangles merged, within 1e-9 of the size).
// Throws std::invalid_argument for any other shape.
Polyhedron makePolyhedron(const Shape& shape);

// Work buffers of polyhedronContacts, kept between calls so a warm step does not allocate.
struct ClipScratch {
  std::vector<Eigen::Vector3d> polygon, clipped;
};

// Appends the face manifold of A and B (see above) for EPA's normal (unit, from A into B) and
// depth > 0. Returns the number of points added; 0 means the contact is not face-like, or
// nothing was left after clipping (the caller keeps EPA's point).
int polyhedronContacts(const Polyhedron& a, const Eigen::Isometry3d& pose_a, const Polyhedron& b,
                       const Eigen::Isometry3d& pose_b, const Eigen::Vector3d& normal, double depth,
                       int pair, int max_points, ClipScratch& scratch,
                       std::vector<ContactPoint>& out);

}  // namespace tribo::contact
