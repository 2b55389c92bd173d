// Automatic contacts (a scene that lists no contacts): the rule that says which two
// geometries may touch and with what material, applied on demand to the pairs the
// broadphase reports close. Nothing is stored per geometry pair, so memory and set-up grow
// with the number of geometries, not with its square.
//
// Geometries g < h may touch when they are on different bodies, at least one of them
// dynamic, not both half-spaces, their groups and masks agree ((g.group & h.mask) != 0 and
// (h.group & g.mask) != 0), and, unless joined bodies collide, no joint joins their bodies.
// The pair's id is g * n + h (n geometries; so ids sort as the pairs (g, h) sort, the order
// contact points are produced in), which bounds automatic contacts to 46340 geometries.
// Forces are reported on B: B is the dynamic one when only one is, the half-space is A when
// there is one, else B is h. The material is the surface pair's, else the default.
// Not here: listed contacts (Model::contact_pairs), detection (contact/collision_detector).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "core/body.hpp"
#include "core/contact_pair.hpp"

namespace tribo {

struct Model;

struct AutomaticContacts {
  int geometry_count = 0;
  std::vector<int> surface;           // per geometry: its surface's index
  std::vector<std::uint8_t> dynamic;  // per geometry: on a dynamic body
  std::vector<std::uint8_t> plane;    // per geometry: a half-space
  // Per geometry, its body and collision filter, copied from Model::geometries: the test of
  // every pair the broadphase reports close reads these small arrays, not two Geometry records.
  std::vector<BodyIndex> body;
  std::vector<std::uint32_t> group, mask;
  int surface_count = 0;
  // The surface pairs given a material, sorted by surfacePairKey, and the material of every
  // other pair (-1: none). Sparse: a robot's links are a surface each (io/urdf_model.cpp),
  // and a dense surface x surface table grew with the square of the links (1.6 GB at 20 000).
  std::vector<std::pair<std::uint64_t, int>> pair_material;
  int default_material = -1;
  std::vector<std::uint64_t> joined;  // sorted keys of body pairs joined by a joint
  bool joined_bodies_collide = false;
};

// The key of two bodies in AutomaticContacts::joined (either order).
std::uint64_t bodyPairKey(BodyIndex a, BodyIndex b);
// The key of two surface indices in AutomaticContacts::pair_material (either order).
std::uint64_t surfacePairKey(int a, int b);
// The material of surfaces a and b (either order): theirs, else the default.
int surfacePairMaterial(const AutomaticContacts& rule, int a, int b);

// The most geometries automatic contacts take (pair ids are ints).
inline constexpr int kMaxAutomaticGeometries = 46340;

// The pair id of geometries g and h (either order) when they may touch, else -1.
int automaticPairId(const Model& model, int g, int h);

// The pair (A, B, material) of an id automaticPairId returned.
ContactPair automaticPair(const Model& model, int id);
// Its geometries (A, B) alone, without the material's lookup (the detector's question).
std::pair<int, int> automaticGeometries(const Model& model, int id);

// Every pair that may touch, in id order: for what needs them all (per-pair output columns,
// per-pair integrator events); quadratic in the geometries.
std::vector<ContactPair> allAutomaticPairs(const Model& model);

// The pairs the stable-step estimate bounds (core/stability.hpp): each dynamic geometry with
// every non-dynamic one it may touch, and with the lightest dynamic partner of each surface
// it may touch (the smallest reduced mass, so the stiffest test system of that material; the
// first 64 candidates by mass are tried, per collision filter and surface). Linear in the
// geometries when few surfaces share a filter that touches itself: a URDF robot's links are
// a surface each, in a filter that leaves itself out; the same links with self-collision
// would cost geometries x links.
std::vector<ContactPair> representativeAutomaticPairs(const Model& model);

// Every pair (listed) or the representative ones (automatic): what set-up checks go over.
std::vector<ContactPair> contactPairsToCheck(const Model& model);

// Every pair with a slot 0 .. size-1, for what keeps something per pair (output columns,
// integrator events): the list, or with automatic contacts allAutomaticPairs (quadratic:
// made only when asked for).
class PairSlots {
 public:
  PairSlots() = default;  // none
  explicit PairSlots(const Model& model);
  const std::vector<ContactPair>& pairs() const { return pairs_; }
  std::size_t size() const { return pairs_.size(); }
  int slot(int id) const;  // the slot of a contact point's pair id

 private:
  std::vector<ContactPair> pairs_;
  bool automatic_ = false;
  std::vector<int> ids_;  // automatic contacts: the slots' ids, sorted
};

}  // namespace tribo
