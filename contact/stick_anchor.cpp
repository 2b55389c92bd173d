#include "contact/stick_anchor.hpp"

#include <algorithm>

namespace tribo::contact {

namespace {

Eigen::Vector3d tangential(const Eigen::Vector3d& v, const Eigen::Vector3d& n) {
  return v - n.dot(v) * n;
}

struct KeyLess {
  bool operator()(const StickAnchor& a, std::uint64_t k) const { return a.key < k; }
  bool operator()(std::uint64_t k, const StickAnchor& a) const { return k < a.key; }
};

}  // namespace

const StickAnchor* findAnchor(std::span<const StickAnchor> anchors, const ContactPoint& cp,
                              double match_radius) {
  if (anchors.empty()) return nullptr;
  if (cp.feature >= 0) {
    const std::uint64_t key = contactKey(cp.pair, static_cast<std::uint64_t>(cp.feature));
    const auto it = std::lower_bound(anchors.begin(), anchors.end(), key, KeyLess{});
    return (it != anchors.end() && it->key == key) ? &*it : nullptr;
  }
  const auto first =
      std::lower_bound(anchors.begin(), anchors.end(), contactKey(cp.pair, kFreshSlot), KeyLess{});
  const auto last = std::lower_bound(first, anchors.end(), contactKey(cp.pair + 1, 0), KeyLess{});
  const StickAnchor* best = nullptr;
  double best_d2 = match_radius * match_radius;
  for (auto it = first; it != last; ++it) {
    const double d2 = (it->position - cp.position).squaredNorm();
    if (d2 <= best_d2) best_d2 = d2, best = &*it;
  }
  return best;
}

friction::StickView stickView(const StickAnchor* anchor, const ContactPoint& cp,
                              const AnchorFrames& f, double time) {
  friction::StickView view;
  if (anchor == nullptr) return view;
  const double dt = time - anchor->time;
  const Eigen::Vector3d pa = *f.pose_a * anchor->anchor_a + dt * f.surface_a;
  const Eigen::Vector3d pb = *f.pose_b * anchor->anchor_b + dt * f.surface_b;
  view.anchored = true;
  view.sliding = anchor->sliding;
  view.elongation = tangential(pb - pa, cp.normal);
  return view;
}

StickAnchor anchorAt(std::uint64_t key, const ContactPoint& cp, const AnchorFrames& f, double time,
                     const friction::StickUpdate& update) {
  const Eigen::Vector3d u = tangential(update.elongation, cp.normal);
  StickAnchor a;
  a.key = key;
  a.position = cp.position;
  a.anchor_a = f.pose_a->inverse() * Eigen::Vector3d(cp.position - 0.5 * u);
  a.anchor_b = f.pose_b->inverse() * Eigen::Vector3d(cp.position + 0.5 * u);
  a.time = time;
  a.sliding = update.sliding;
  return a;
}

void AnchorBook::begin(std::span<const StickAnchor> previous) {
  previous_ = previous;
  claimed_.clear();
  next_.clear();
}

std::uint64_t AnchorBook::claim(const ContactPoint& cp, const StickAnchor* matched) {
  if (cp.feature >= 0) return contactKey(cp.pair, static_cast<std::uint64_t>(cp.feature));
  if (matched != nullptr &&
      std::find(claimed_.begin(), claimed_.end(), matched->key) == claimed_.end()) {
    claimed_.push_back(matched->key);
    return matched->key;
  }
  // A fresh slot above every slot of this pair, old or handed out.
  std::uint64_t slot = kFreshSlot;
  for (const StickAnchor& a : previous_)
    if (keyPair(a.key) == cp.pair && (a.key & 0xffffffffu) >= slot)
      slot = (a.key & 0xffffffffu) + 1;
  for (std::uint64_t k : claimed_)
    if (keyPair(k) == cp.pair && (k & 0xffffffffu) >= slot) slot = (k & 0xffffffffu) + 1;
  const std::uint64_t key = contactKey(cp.pair, slot);
  claimed_.push_back(key);
  return key;
}

bool AnchorBook::finish(std::vector<StickAnchor>& anchors) {
  std::sort(next_.begin(), next_.end(),
            [](const StickAnchor& a, const StickAnchor& b) { return a.key < b.key; });
  previous_ = {};
  if (next_ == anchors) return false;
  anchors.swap(next_);
  return true;
}

}  // namespace tribo::contact
