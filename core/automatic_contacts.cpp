#include "core/automatic_contacts.hpp"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <map>
#include <numeric>

#include "core/model.hpp"

namespace tribo {

std::uint64_t bodyPairKey(BodyIndex a, BodyIndex b) {
  auto x = static_cast<std::uint64_t>(static_cast<std::uint32_t>(a.value));
  auto y = static_cast<std::uint64_t>(static_cast<std::uint32_t>(b.value));
  if (x > y) std::swap(x, y);
  return (x << 32) | y;
}

std::uint64_t surfacePairKey(int a, int b) { return bodyPairKey(BodyIndex{a}, BodyIndex{b}); }

int surfacePairMaterial(const AutomaticContacts& rule, int a, int b) {
  const std::uint64_t key = surfacePairKey(a, b);
  const auto it = std::lower_bound(
      rule.pair_material.begin(), rule.pair_material.end(), key,
      [](const std::pair<std::uint64_t, int>& e, std::uint64_t k) { return e.first < k; });
  return it != rule.pair_material.end() && it->first == key ? it->second : rule.default_material;
}

int automaticPairId(const Model& model, int g, int h) {
  const AutomaticContacts& rule = model.automatic;
  if (g > h) std::swap(g, h);
  const auto i = static_cast<std::size_t>(g), j = static_cast<std::size_t>(h);
  if (g == h || rule.body[i] == rule.body[j]) return -1;
  if (!rule.dynamic[i] && !rule.dynamic[j]) return -1;
  if (rule.plane[i] && rule.plane[j]) return -1;
  if (!(rule.group[i] & rule.mask[j]) || !(rule.group[j] & rule.mask[i])) return -1;
  if (!rule.joined_bodies_collide && !rule.joined.empty() &&
      std::binary_search(rule.joined.begin(), rule.joined.end(),
                         bodyPairKey(rule.body[i], rule.body[j])))
    return -1;
  return g * rule.geometry_count + h;
}

std::pair<int, int> automaticGeometries(const Model& model, int id) {
  const AutomaticContacts& rule = model.automatic;
  const int g = id / rule.geometry_count, h = id % rule.geometry_count;
  const bool swap = !rule.dynamic[g]   ? false
                    : !rule.dynamic[h] ? true
                                       : !rule.plane[g] && rule.plane[h];
  return swap ? std::pair{h, g} : std::pair{g, h};
}

ContactPair automaticPair(const Model& model, int id) {
  const AutomaticContacts& rule = model.automatic;
  const auto [a, b] = automaticGeometries(model, id);
  const int material = surfacePairMaterial(rule, rule.surface[a], rule.surface[b]);
  // The two geometries as one 8-byte word: built field by field, GCC wrote them to the stack
  // as two 4-byte stores and read them back as the return register's 8 bytes, a
  // store-forwarding stall that was most of this function's time (called once a contact
  // point on a sphere pile).
  const std::uint64_t ab = static_cast<std::uint32_t>(a) |
                           (static_cast<std::uint64_t>(static_cast<std::uint32_t>(b)) << 32);
  ContactPair pair;
  static_assert(offsetof(ContactPair, geometry_a) == 0 &&
                offsetof(ContactPair, geometry_b) == sizeof(std::uint32_t));
  std::memcpy(&pair.geometry_a, &ab, sizeof ab);  // the two first ints (the static_assert)
  pair.material = material;
  return pair;
}

namespace {

std::vector<int> allAutomaticIds(const Model& model) {
  std::vector<int> ids;
  const int n = model.automatic.geometry_count;
  for (int g = 0; g < n; ++g)
    for (int h = g + 1; h < n; ++h)
      if (const int id = automaticPairId(model, g, h); id >= 0) ids.push_back(id);
  return ids;
}

}  // namespace

std::vector<ContactPair> allAutomaticPairs(const Model& model) {
  std::vector<ContactPair> pairs;
  for (int id : allAutomaticIds(model)) pairs.push_back(automaticPair(model, id));
  return pairs;
}

std::vector<ContactPair> representativeAutomaticPairs(const Model& model) {
  const AutomaticContacts& rule = model.automatic;
  const int n = rule.geometry_count;
  auto geometry = [&](int g) -> const Geometry& {
    return model.geometries[static_cast<std::size_t>(g)];
  };
  auto mass = [&](int g) { return model.bodies[geometry(g).body.value].mass; };
  // Dynamic geometries by collision filter (group, mask), then by surface, lightest body
  // first. A geometry looks only into the filters it may touch: a robot's links (a surface
  // each, in one filter that leaves itself out) cost one look each, not one per link.
  using Filter = std::pair<std::uint32_t, std::uint32_t>;
  std::map<Filter, std::map<int, std::vector<int>>> by_filter;
  std::vector<int> fixed;
  for (int g = 0; g < n; ++g) {
    if (!rule.dynamic[g]) {
      fixed.push_back(g);
      continue;
    }
    const Geometry& geo = geometry(g);
    by_filter[{geo.collision_group, geo.collision_mask}][rule.surface[g]].push_back(g);
  }
  for (auto& [filter, by_surface] : by_filter)
    for (auto& [surface, list] : by_surface)
      std::stable_sort(list.begin(), list.end(), [&](int x, int y) { return mass(x) < mass(y); });
  constexpr std::size_t kTried = 64;
  std::vector<int> ids;
  for (int g = 0; g < n; ++g) {
    if (!rule.dynamic[g]) continue;
    for (int f : fixed)
      if (const int id = automaticPairId(model, g, f); id >= 0) ids.push_back(id);
    const Geometry& geo = geometry(g);
    for (const auto& [filter, by_surface] : by_filter) {
      if (!(geo.collision_group & filter.second) || !(filter.first & geo.collision_mask)) continue;
      for (const auto& [surface, list] : by_surface)
        for (std::size_t i = 0; i < std::min(list.size(), kTried); ++i)
          if (const int id = automaticPairId(model, g, list[i]); id >= 0) {
            ids.push_back(id);
            break;
          }
    }
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  std::vector<ContactPair> pairs;
  pairs.reserve(ids.size());
  for (int id : ids) pairs.push_back(automaticPair(model, id));
  return pairs;
}

std::vector<ContactPair> contactPairsToCheck(const Model& model) {
  return model.automatic_contacts ? representativeAutomaticPairs(model) : model.contact_pairs;
}

PairSlots::PairSlots(const Model& model) {
  if (!model.automatic_contacts) {
    pairs_ = model.contact_pairs;
    return;
  }
  automatic_ = true;
  ids_ = allAutomaticIds(model);
  pairs_.reserve(ids_.size());
  for (int id : ids_) pairs_.push_back(automaticPair(model, id));
}

int PairSlots::slot(int id) const {
  if (!automatic_) return id;
  return static_cast<int>(std::lower_bound(ids_.begin(), ids_.end(), id) - ids_.begin());
}

}  // namespace tribo
