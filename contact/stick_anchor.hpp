// The anchors of stateful friction laws (elastic_stick) and of rolling and spinning
// resistance: one per contact point.
//
// A StickAnchor remembers, for one contact point, the two material points (one on each
// geometry, in the geometry's own frame) that a tangential spring joins, and whether the
// contact was sliding. Its elongation at any later configuration is
//   u = tangential part of (P_B - P_A),   P = pose * anchor + s (t - t_anchor)
// with s a geometry's surface velocity (world; a belt's surface carries its material point
// along while the geometry stays put). The anchors are re-set after every step at the
// current contact point, keeping the elongation the law decided (rebase), so they follow a
// rolling or sliding contact instead of staying behind on the surfaces.
//
// Which anchor a new contact point continues is contact identity (contact/
// contact_identity.hpp): by pair and feature, else the nearest anchor of the pair within
// the match radius, else a new one (stuck, zero elongation). Not here: the law's decisions
// (friction/), when anchors are re-set (core/friction_states.hpp).
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <span>
#include <vector>

#include "contact/contact_identity.hpp"
#include "contact/contact_point.hpp"
#include "contact/rolling_resistance.hpp"
#include "friction/friction_law.hpp"

namespace tribo::contact {

struct StickAnchor {
  std::uint64_t key = 0;                               // (pair << 32) | slot
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // world contact point when set [m]
  Eigen::Vector3d anchor_a = Eigen::Vector3d::Zero();  // material point, geometry A frame [m]
  Eigen::Vector3d anchor_b = Eigen::Vector3d::Zero();  // material point, geometry B frame [m]
  double time = 0.0;                                   // when set [s]
  bool sliding = false;
  AngularAnchor angular;  // rolling and spinning resistance (contact/rolling_resistance.hpp)

  bool operator==(const StickAnchor&) const = default;
};

// Where the two geometries of a contact are: world poses and surface velocities (world).
struct AnchorFrames {
  const Eigen::Isometry3d* pose_a;
  const Eigen::Isometry3d* pose_b;
  Eigen::Vector3d surface_a = Eigen::Vector3d::Zero();
  Eigen::Vector3d surface_b = Eigen::Vector3d::Zero();
};

// The anchor this contact point continues (contact identity), or nullptr. `anchors` is
// sorted by key.
inline const StickAnchor* findAnchor(std::span<const StickAnchor> anchors, const ContactPoint& cp,
                                     double match_radius) {
  return findRecord(anchors, cp, match_radius);
}

// The law's view of the contact: anchored or not, its mode and the current elongation.
friction::StickView stickView(const StickAnchor* anchor, const ContactPoint& cp,
                              const AnchorFrames& frames, double time);

// A new anchor at contact point cp holding elongation u (projected on the tangent plane).
StickAnchor anchorAt(std::uint64_t key, const ContactPoint& cp, const AnchorFrames& frames,
                     double time, const friction::StickUpdate& update);

// Builds the next step's anchor list (contact/contact_identity.hpp).
using AnchorBook = RecordBook<StickAnchor>;

}  // namespace tribo::contact
