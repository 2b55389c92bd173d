#include "contact/contact_identity.hpp"

namespace tribo::contact {

std::uint64_t KeyClaims::claim(const ContactPoint& cp, const std::uint64_t* matched,
                               std::uint64_t next_slot) {
  if (cp.feature >= 0) return contactKey(cp.pair, static_cast<std::uint64_t>(cp.feature));
  if (matched != nullptr &&
      std::find(claimed_.begin(), claimed_.end(), *matched) == claimed_.end()) {
    claimed_.push_back(*matched);
    return *matched;
  }
  // A fresh slot above every slot of this pair, old or handed out this step.
  std::uint64_t slot = next_slot;
  for (std::uint64_t k : claimed_)
    if (keyPair(k) == cp.pair && keySlot(k) >= slot) slot = keySlot(k) + 1;
  const std::uint64_t key = contactKey(cp.pair, slot);
  claimed_.push_back(key);
  return key;
}

}  // namespace tribo::contact
