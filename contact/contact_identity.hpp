// Contact identity: what makes a contact point "the same one" from step to step, for every
// kind of per-contact friction memory (the anchors of stateful laws, contact/stick_anchor.hpp;
// the internal states of dynamic laws, contact/dynamic_friction.hpp).
//
// A record of either kind carries a persistent key and the world point where it was last set.
// A new contact point continues a record by these rules, in this order:
//   1. pair + feature: points whose narrowphase names a feature (box corner k, sphere
//      point, rim point k counted from the deepest) keep key = (pair, feature);
//   2. nearest previous point: a point without a feature (FCL's narrowphase) continues the
//      previous step's record of the same pair nearest to it, if within `match_radius` of
//      where that record was set; two points claiming one record: the first in contact order
//      keeps it, the other starts a new one;
//   3. otherwise the contact is new: a fresh key of its pair.
// Keys are (pair << 32) | slot, slot = feature for 1 and 2^31 + n for 2 and 3; records are
// kept sorted by key. A RecordBook builds the next step's list of one kind of record.
// Not here: what a record holds (its kind's header) and when the lists are rebuilt
// (core/friction_states.hpp).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cstdint>
#include <iterator>
#include <span>
#include <vector>

#include "contact/contact_point.hpp"

namespace tribo::contact {

constexpr std::uint64_t kFreshSlot = std::uint64_t{1} << 31;

inline std::uint64_t contactKey(int pair, std::uint64_t slot) {
  return (static_cast<std::uint64_t>(pair) << 32) | slot;
}
inline int keyPair(std::uint64_t key) { return static_cast<int>(key >> 32); }
inline std::uint64_t keySlot(std::uint64_t key) { return key & 0xffffffffu; }

// The keys a step has handed out, and the rule that hands out the next one (rules 1-3).
class KeyClaims {
 public:
  void clear() { claimed_.clear(); }
  // Key for contact point cp. `matched`: the key of the record it matched (nullptr: none);
  // `next_slot`: the first fresh slot above every slot of cp's pair among the previous
  // records (freshSlotAbove).
  std::uint64_t claim(const ContactPoint& cp, const std::uint64_t* matched,
                      std::uint64_t next_slot);

 private:
  std::vector<std::uint64_t> claimed_;
};

// The record that contact point cp continues (rules 1 and 2), or nullptr. `records` is
// sorted by key; Record has `key` and `position` (world, where it was set).
template <class Record>
const Record* findRecord(std::span<const Record> records, const ContactPoint& cp,
                         double match_radius) {
  if (records.empty()) return nullptr;
  auto below = [](const Record& r, std::uint64_t k) { return r.key < k; };
  if (cp.feature >= 0) {
    const std::uint64_t key = contactKey(cp.pair, static_cast<std::uint64_t>(cp.feature));
    const auto it = std::lower_bound(records.begin(), records.end(), key, below);
    return (it != records.end() && it->key == key) ? &*it : nullptr;
  }
  const auto first =
      std::lower_bound(records.begin(), records.end(), contactKey(cp.pair, kFreshSlot), below);
  const auto last = std::lower_bound(first, records.end(), contactKey(cp.pair + 1, 0), below);
  const Record* best = nullptr;
  double best_d2 = match_radius * match_radius;
  for (auto it = first; it != last; ++it) {
    const double d2 = (it->position - cp.position).squaredNorm();
    if (d2 <= best_d2) best_d2 = d2, best = &*it;
  }
  return best;
}

// The first fresh slot above every slot of `pair` in `records` (sorted by key).
template <class Record>
std::uint64_t freshSlotAbove(std::span<const Record> records, int pair) {
  auto below = [](const Record& r, std::uint64_t k) { return r.key < k; };
  const auto end = std::lower_bound(records.begin(), records.end(), contactKey(pair + 1, 0), below);
  if (end == records.begin()) return kFreshSlot;
  const std::uint64_t key = std::prev(end)->key;
  if (keyPair(key) != pair || keySlot(key) < kFreshSlot) return kFreshSlot;
  return keySlot(key) + 1;
}

// Builds the next step's records of one kind: begin() with the current list, claim() hands
// out each contact's key by the rules above (in contact order), add() takes the new record,
// finish() sorts them by key and, if they differ, swaps them into the list. The book and the
// state trade buffers instead of giving them away, so once both have grown to the working
// size a step does not allocate. Record needs `key` and operator==.
template <class Record>
class RecordBook {
 public:
  void begin(std::span<const Record> previous) {
    previous_ = previous;
    claims_.clear();
    next_.clear();
  }
  // Key for a contact point given the record it matched (nullptr: none).
  std::uint64_t claim(const ContactPoint& cp, const Record* matched) {
    const std::uint64_t next_slot =
        cp.feature >= 0 ? kFreshSlot : freshSlotAbove(previous_, cp.pair);
    return claims_.claim(cp, matched != nullptr ? &matched->key : nullptr, next_slot);
  }
  void add(const Record& record) { next_.push_back(record); }
  // Sorts the new records by key; when they differ from `records` (the list given to
  // begin()), swaps them in and returns true.
  bool finish(std::vector<Record>& records) {
    std::sort(next_.begin(), next_.end(),
              [](const Record& a, const Record& b) { return a.key < b.key; });
    previous_ = {};
    if (next_ == records) return false;
    records.swap(next_);
    return true;
  }

 private:
  KeyClaims claims_;
  std::vector<Record> next_;
  std::span<const Record> previous_;
};

}  // namespace tribo::contact
