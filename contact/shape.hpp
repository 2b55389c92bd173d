// Collision shapes attached to bodies, described in the geometry's own frame.
//
//   box:           centred on the origin, half extents (hx, hy, hz) [m]
//   sphere:        centred on the origin, radius r; r = 0 is a contact point (a point of the
//                  body that touches surfaces, as Gazebo, Drake and PyBullet treat a
//                  zero-radius collision sphere: no volume, no inertia)
//   cylinder:      axis z, centred, radius r, length 2 h (faces at z = -h and z = +h)
//   capsule:       the segment z in [-h, h] swept by a sphere of radius r
//   cone:          axis z, base disc of radius r at z = -h, apex at z = +h (FCL's convention)
//   half-space:    the solid below the plane z = 0 (outward normal +z)
//   convex_mesh:   a closed convex polyhedron (vertices and outward triangles)
//   mesh:          a triangle mesh, not necessarily convex or closed (a surface)
// Meshes are shared, immutable vertex/triangle lists (io/mesh_loader.hpp reads them;
// contact/mesh_shape.hpp checks convex ones). Not here: collision tests
// (contact/collision_detector.hpp), inertia (shape_inertia.hpp).
#pragma once

#include <Eigen/Core>
#include <array>
#include <memory>
#include <string>
#include <vector>

namespace tribo::contact {

// The largest length a scene may hold [m]: every dimension of a shape (a box's edge, a
// radius, a cylinder's or capsule's length), every mesh vertex coordinate (after scale) and
// every coordinate of a position (io/ and the model builder check these at load). 1e6 m
// (1000 km) is far beyond any contact problem, keeps a millimetre contact depth 1e7 times
// above the rounding of a coordinate (1.2e-10 m at 1e6 m), and keeps FCL's broadphase
// finite: its AABB tree multiplies extents (volumes, sizes), which overflow near 1e102 m
// for a cube and crash the tree well before that.
inline constexpr double kMaxLength = 1e6;

// "WHAT: expected at most 1e6 m, found F m" when |found| > kMaxLength, else empty; and
// "WHAT: expected coordinates within +-1e6 m, found (x, y, z) m" when a coordinate of p is.
// Lengths printed with 10 significant digits.
std::string overLengthLimit(const std::string& what, double found);
std::string outsideLengthLimit(const std::string& what, const Eigen::Vector3d& p);
std::string lengthText(double v);

enum class ShapeType {
  kBox,
  kSphere,
  kCylinder,
  kCapsule,
  kCone,
  kHalfSpace,
  kConvexMesh,
  kTriangleMesh
};

// Triangles index `vertices`, counter-clockwise seen from outside for closed meshes.
struct MeshData {
  std::vector<Eigen::Vector3d> vertices;  // geometry frame [m]
  std::vector<std::array<int, 3>> triangles;
  std::string source;  // file it came from (for messages), may be empty
};

struct Shape {
  ShapeType type = ShapeType::kBox;
  Eigen::Vector3d half_extents = Eigen::Vector3d::Constant(0.5);  // box [m]
  double radius = 0.0;                   // sphere, cylinder, capsule, cone [m]
  double half_length = 0.0;              // cylinder, capsule, cone: half the length along z [m]
  std::shared_ptr<const MeshData> mesh;  // convex_mesh, mesh

  static Shape box(const Eigen::Vector3d& half_extents) {
    Shape s;
    s.type = ShapeType::kBox;
    s.half_extents = half_extents;
    return s;
  }
  static Shape halfSpace() {
    Shape s;
    s.type = ShapeType::kHalfSpace;
    s.half_extents.setZero();
    return s;
  }
  static Shape sphere(double radius) { return round(ShapeType::kSphere, radius, 0.0); }
  static Shape cylinder(double radius, double half_length) {
    return round(ShapeType::kCylinder, radius, half_length);
  }
  static Shape capsule(double radius, double half_length) {
    return round(ShapeType::kCapsule, radius, half_length);
  }
  static Shape cone(double radius, double half_length) {
    return round(ShapeType::kCone, radius, half_length);
  }
  static Shape convexMesh(std::shared_ptr<const MeshData> mesh) {
    return meshShape(ShapeType::kConvexMesh, std::move(mesh));
  }
  static Shape triangleMesh(std::shared_ptr<const MeshData> mesh) {
    return meshShape(ShapeType::kTriangleMesh, std::move(mesh));
  }

  // Characteristic size [m]: the smallest half dimension for solids; infinite for a
  // half-space, a triangle mesh (a surface has no thickness to measure against) and a point.
  double size() const;
  // Half the shape's width along the unit direction n (geometry frame) [m]:
  // (h(n) + h(-n)) / 2, the depth at which a contact along n has gone through the middle of
  // the shape (a cylinder on its rim: its radius; on a face: half its length). Infinite for
  // a half-space, a triangle mesh and a point.
  double extent(const Eigen::Vector3d& n) const;
  // A lower bound of extent(n) over every unit direction n [m], so that a contact shallower
  // than it needs no extent(n) at all: a box's smallest half extent; a sphere's and a
  // capsule's radius; a cylinder's smaller of radius and half length (its width along n is
  // at least that times |n_z| + |n_xy| >= 1); a cone's that over sqrt 2 (its base disc and
  // its height bound its width by 2 r |n_xy| and 2 h |n_z|). Zero for a convex mesh (no
  // bound is derived: its extent is always evaluated); infinite where extent is.
  double thinnestHalfWidth() const;
  bool isPoint() const { return type == ShapeType::kSphere && radius == 0.0; }
  // The shape's points farthest along -n would be the first to touch a plane with outward
  // normal n: its support distance h(d) = max over the shape of d . x (geometry frame).
  double support(const Eigen::Vector3d& d) const;
  // Throws std::invalid_argument naming what is wrong (non-positive dimensions, a dimension
  // or a mesh vertex coordinate over kMaxLength, empty mesh), what was expected and found.
  void validate() const;

 private:
  static Shape round(ShapeType type, double radius, double half_length) {
    Shape s;
    s.type = type;
    s.half_extents.setZero();
    s.radius = radius;
    s.half_length = half_length;
    return s;
  }
  static Shape meshShape(ShapeType type, std::shared_ptr<const MeshData> mesh) {
    Shape s;
    s.type = type;
    s.half_extents.setZero();
    s.mesh = std::move(mesh);
    return s;
  }
};

// Scene names: "box", "sphere", "cylinder", "capsule", "cone", "halfspace", "convex_mesh",
// "mesh".
std::string shapeName(ShapeType type);

}  // namespace tribo::contact
