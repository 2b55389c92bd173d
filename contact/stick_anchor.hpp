// Per-contact state of stateful friction laws, and contact identity from step to step.
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
// Contact identity (which anchor a new contact point continues), in this order:
//   1. pair + feature: points whose narrowphase names a feature (box corner k, sphere
//      point, rim point k counted from the deepest) keep key = (pair, feature);
//   2. nearest previous point: a point without a feature (FCL's narrowphase) continues the
//      previous step's anchor of the same pair nearest to it, if within `match_radius` of
//      where that anchor was set; two points claiming one anchor: the first in contact order
//      keeps it, the other starts a new one;
//   3. otherwise the contact is new: stuck, zero elongation, a fresh key of its pair.
// Dynamic friction laws use the same records and identity rules for their per-contact
// internal state (State::friction_states), with the state's place in State::friction_values
// instead of material points.
// Anchors are kept sorted by key; keys are (pair << 32) | slot, slot = feature for 1 and
// 2^31 + n for 2 and 3. Not here: the law's decisions (friction/), the step loop (core/).
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <span>
#include <vector>

#include "contact/contact_point.hpp"
#include "friction/friction_law.hpp"

namespace tribo::contact {

struct StickAnchor {
  std::uint64_t key = 0;                               // (pair << 32) | slot
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // world contact point when set [m]
  Eigen::Vector3d anchor_a = Eigen::Vector3d::Zero();  // material point, geometry A frame [m]
  Eigen::Vector3d anchor_b = Eigen::Vector3d::Zero();  // material point, geometry B frame [m]
  double time = 0.0;                                   // when set [s]
  bool sliding = false;
  // Dynamic friction laws (friction/dynamic_law.hpp) only: where the contact's internal
  // state starts in State::friction_values and how many numbers it has (-1, 0: none), and
  // the contact normal its tangent vectors are expressed against (world, unit).
  int state = -1;
  int state_size = 0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();

  bool operator==(const StickAnchor&) const = default;
};

// Where the two geometries of a contact are: world poses and surface velocities (world).
struct AnchorFrames {
  const Eigen::Isometry3d* pose_a;
  const Eigen::Isometry3d* pose_b;
  Eigen::Vector3d surface_a = Eigen::Vector3d::Zero();
  Eigen::Vector3d surface_b = Eigen::Vector3d::Zero();
};

constexpr std::uint64_t kFreshSlot = std::uint64_t{1} << 31;

inline std::uint64_t contactKey(int pair, std::uint64_t slot) {
  return (static_cast<std::uint64_t>(pair) << 32) | slot;
}
inline int keyPair(std::uint64_t key) { return static_cast<int>(key >> 32); }

// The anchor this contact point continues (rules 1 and 2 above), or nullptr. `anchors` is
// sorted by key.
const StickAnchor* findAnchor(std::span<const StickAnchor> anchors, const ContactPoint& cp,
                              double match_radius);

// The law's view of the contact: anchored or not, its mode and the current elongation.
friction::StickView stickView(const StickAnchor* anchor, const ContactPoint& cp,
                              const AnchorFrames& frames, double time);

// A new anchor at contact point cp holding elongation u (projected on the tangent plane).
StickAnchor anchorAt(std::uint64_t key, const ContactPoint& cp, const AnchorFrames& frames,
                     double time, const friction::StickUpdate& update);

// Builds the next step's anchor list: begin() with the current list, claim() hands out each
// contact's key by the rules above (in contact order), add() takes the new anchor, finish()
// sorts them by key and, if they differ, swaps them into the list. The book and the state
// trade buffers instead of giving them away, so once both have grown to the working size a
// step does not allocate.
class AnchorBook {
 public:
  void begin(std::span<const StickAnchor> previous);
  // Key for a contact point given the anchor it matched (nullptr: none).
  std::uint64_t claim(const ContactPoint& cp, const StickAnchor* matched);
  void add(const StickAnchor& anchor) { next_.push_back(anchor); }
  // Sorts the new anchors by key; when they differ from `anchors` (the list given to
  // begin()), swaps them in and returns true.
  bool finish(std::vector<StickAnchor>& anchors);

 private:
  std::vector<std::uint64_t> claimed_;  // keys handed out this step
  std::vector<StickAnchor> next_;
  std::span<const StickAnchor> previous_;
};

}  // namespace tribo::contact
