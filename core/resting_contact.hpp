// The geometry of a contact pair at rest, for the a-priori step limit (core/stability.hpp):
// the face a box rests on and its patch's corners, which bodies can turn about an axis or
// slide across a contact plane without breaking a joint, and the rocking and yaw stiffness
// of a resting face per unit stiffness of its points, and how much a round shape's rolling
// lightens the slip at its contact point. Internal to core/stability.cpp.
// Not here: the limits themselves (core/stability.cpp), rocking and yaw of rounded shapes and
// meshes, rolling of cones and meshes.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <vector>

#include "core/constraint_rows.hpp"
#include "core/model.hpp"
#include "core/state.hpp"

namespace tribo::stability_detail {

// Rocking of a box resting on a face (see stability.hpp). The pair's geometry at the initial
// pose: a box on a half-space rests on the face whose outward normal is most nearly against
// the plane's; two boxes touch by the faces most nearly along the separating axis of least
// overlap (the face axis of either box along which they are farthest apart, a stack's
// vertical, as for every pair the boxes are taken to touch there), and the contact patch is
// the smaller of the two faces with its corners moved into the other face (for faces with
// parallel edges, their overlap: exact for a stack, staggered or not; for a face turned
// against the other about the normal, only an approximation of the overlap). Faces that do
// not overlap along that axis (boxes side by side diagonally, far apart) have no patch.
// Other shapes have no rocking mode here.
struct RestingFace {
  int box = -1;                   // geometry whose face it is
  Vec3 normal;                    // contact normal (world); its sign does not matter
  Vec3 centre;                    // of the face (world)
  std::array<Vec3, 2> edges;      // the face's box axes (world)
  std::array<double, 2> half;     // and its half extents along them
  std::array<Vec3, 4> corners;    // the patch's corners, the contact points (world)
  std::array<Vec3, 2> axes;       // rocking axes: the face's edges, normal to `normal`
  std::array<int, 2> axis_index;  // which box axis each is (0 x, 1 y, 2 z)
};

// The face pair `pair` rests on at the initial pose (see RestingFace); none for other shapes
// or faces that do not overlap.
std::optional<RestingFace> restingFace(const Model& model, const ContactPair& pair);

// Which dynamic bodies can turn about an axis through their centre of mass, everything else
// held still, without breaking a joint equation at the initial pose: every row touching the
// body is unchanged to first order by that rotation. A free body can about any axis; one on
// planar_translation, prismatic or fixed about none; one on a revolute joint through its
// centre of mass about that joint's axis only. Likewise whether a body can slide across a
// contact's plane (free, planar about its normal), for friction across the slip.
class TurnCheck {
 public:
  explicit TurnCheck(const Model& model) : rows_(model.bodies.size()) {
    const std::vector<ConstraintRow> rows = constraintRows(model);
    if (rows.empty()) return;
    State state;
    std::vector<Mat3> rotation;
    for (const Body& body : model.bodies) {
      state.bodies.push_back(
          {body.position, body.orientation, body.velocity, body.angular_velocity});
      rotation.push_back(body.orientation.normalized().toRotationMatrix());
    }
    std::vector<RowValue> values(rows.size());
    evaluateRows(rows, rowGroups(rows), MotionView(state, rotation), 0.0, values);
    for (std::size_t r = 0; r < rows.size(); ++r)
      for (int k = 0; k < rows[r].body_count; ++k)
        if (rows[r].body[k] >= 0) rows_[rows[r].body[k]].push_back(values[r].j[k]);
  }

  bool canTurn(const Model& model, BodyIndex b, const Vec3& axis) const {
    return canMove(model, b, Vec3::Zero(), axis);
  }
  // Whether it can slide along every direction normal to `normal` (a free or planar body on
  // the plane), without turning.
  bool canSlideAcross(const Model& model, BodyIndex b, const Vec3& normal) const {
    const Vec3 u = normal.unitOrthogonal(), w = normal.cross(u).normalized();
    return canMove(model, b, u, Vec3::Zero()) && canMove(model, b, w, Vec3::Zero());
  }

 private:
  // Whether translating along `linear` and turning about `angular` (through the centre of
  // mass) leaves every joint row of body b unchanged to first order.
  bool canMove(const Model& model, BodyIndex b, const Vec3& linear, const Vec3& angular) const {
    if (b.isWorld() || model.bodies[b.value].kind != BodyKind::kDynamic) return false;
    for (const Row6& j : rows_[b.value]) {
      const Vec3 jl = j.head<3>().transpose(), ja = j.tail<3>().transpose();
      if (std::abs(jl.dot(linear) + ja.dot(angular)) > 1e-9 * (jl.norm() + ja.norm())) return false;
    }
    return true;
  }

  std::vector<std::vector<Row6>> rows_;  // per body: its blocks of the joint rows
};

// Rocking about `axis` (unit, in the patch) of the bodies on either side that can turn:
// the largest eigenvalue of the corners' rotational stiffness sum_i g_i g_i^T per unit point
// stiffness (g_i: the normal displacement of corner i per unit turn of each body about the
// axis through its centre of mass) against the bodies' inertias about those axes. Zero when
// neither can turn. The contact's normal stiffness and damping per point then give
// k/m = k_point * it and c/m = c_point * it (the corners' dampers act on the same lever arms,
// so the rotational damping is proportional to the stiffness).
double rockingPerPointStiffness(const Model& model, const TurnCheck& turns, BodyIndex a,
                                BodyIndex b, const RestingFace& face, const Vec3& axis);

// Yaw about the contact normal of the bodies on either side that can turn about it, per unit
// tangential stiffness (or damping) of each point: the largest eigenvalue of
// sum_i g_i g_i^T against the inertias about the normal through each centre of mass, g_i the
// points' tangential displacement per unit turn of each body, n x (p_i - x_cm). A box on a
// square face: 3 times the translation's 4 / m (sum r_i^2 = (a^2 + b^2) against
// I_n = m (a^2 + b^2) / 12). Zero when neither can turn.
double yawPerPointStiffness(const Model& model, const TurnCheck& turns, BodyIndex a, BodyIndex b,
                            const RestingFace& face);

// A round shape's contact: rolling, and the yaw of one lying on its side.
//
// Rolling: friction's force at a contact point of a body that touches at one point (a sphere;
// a capsule or cylinder on an end or rim) or along a line (a capsule or cylinder lying on its
// side, which turns about its axis only) also turns that body, which nothing else holds, so
// the slip there meets the inverse mass
//   w(t) = sum over the pair's bodies of 1/m + (r x t)^T I^-1 (r x t)
// (r from the body's centre of mass to the contact point, t the slip direction in the
// contact plane, I the world inertia about the centre of mass; the bodies' impulse response
// at a point, e.g. Mirtich & Canny 1995, "Impulse-based simulation of rigid bodies"), not just
// the sum of 1/m. `slip_factor` is the largest w over t times the reduced mass: the factor by
// which friction's stiffness and damping per unit mass exceed the translation's (a solid
// sphere on a plane: 1 + m r^2 / (2/5 m r^2) = 3.5; a solid cylinder on its side, rolling: 3);
// 1 when neither geometry is round or can turn there.
//
// Yaw: a shape lying on its side touches at its line's two ends (a cylinder's rims, a
// capsule's segment ends), whose friction turns it about the normal: `yaw` is
// sum_i |n x (p_i - x_cm)|^2 / I_n per unit tangential stiffness of each of the `points` = 2
// (as yawPerPointStiffness for a face's corners); 0 for a point contact (its lever is along
// the normal).
//
// `normal` is the contact normal (world, either sign): the half-space's, or gravity's
// direction. The contact point is each round geometry's support point towards the other
// geometry's centre along the normal; a lying shape's at its middle. Only a body with one
// geometry rolls (`geometry_count`: geometries per body): one touching with several (a foot's
// corner spheres) is taken to be held like a face. Not here: cones, meshes, boxes on an edge
// or corner, a body rolling on several round geometries (an axle's two wheels).
struct RoundContact {
  double slip_factor = 1.0;
  double yaw = 0.0;
  int points = 1;
};
RoundContact roundContact(const Model& model, const TurnCheck& turns, const ContactPair& pair,
                          const Vec3& normal, const std::vector<int>& geometry_count);

}  // namespace tribo::stability_detail
