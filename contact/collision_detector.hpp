// Collision detection over a fixed set of geometries and candidate pairs: the one place
// FCL is used (behind a pimpl, so no FCL type leaks into Tribo headers).
//
// Each pair (A, B) yields contact points with the normal from A into B. Box/half-space
// pairs use an exact closed form (every penetrating box corner is a point, so a box
// resting on a face gets four) unless `closed_form_box_halfspace` is off; box/box pairs use
// FCL's narrowphase. With `broadphase` on, FCL's dynamic AABB tree culls the pairs first.
// Not here: forces, materials, contact identity between steps.
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "contact/contact_point.hpp"
#include "contact/shape.hpp"

namespace tribo::contact {

struct CollisionOptions {
  bool broadphase = false;                 // cull pairs with FCL's dynamic AABB tree
  bool closed_form_box_halfspace = true;   // exact corners instead of FCL's single point
  int max_points_per_pair = 8;
};

class CollisionDetector {
 public:
  // Throws std::invalid_argument for a pair that cannot collide (half-space/half-space)
  // or an index out of range.
  CollisionDetector(std::vector<Shape> shapes, std::vector<std::pair<int, int>> pairs,
                    CollisionOptions options = {});
  ~CollisionDetector();
  CollisionDetector(CollisionDetector&&) noexcept;
  CollisionDetector& operator=(CollisionDetector&&) noexcept;

  // World poses of all geometries in, contact points out (cleared first). Does not
  // allocate once `out` has grown to its working size.
  void detect(std::span<const Eigen::Isometry3d> poses, std::vector<ContactPoint>& out);

  const std::vector<std::pair<int, int>>& pairs() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Exact box/half-space contact: every box corner below the plane, at the midpoint between
// the corner and the plane, normal = the plane's outward normal (from the half-space into
// the box). Appends to `out`; returns the number of points added.
int boxHalfSpaceContacts(const Eigen::Isometry3d& box_pose, const Eigen::Vector3d& half_extents,
                         const Eigen::Isometry3d& plane_pose, int pair,
                         std::vector<ContactPoint>& out);

}  // namespace tribo::contact
