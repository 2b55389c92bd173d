// A stable counting sort over small integer keys: the one pass pattern behind the bucketed
// broadphases (contact/bucket_layout.hpp, entries by bucket), the skin list's rebuild (close
// pairs by first geometry) and the radix passes of the sort of pairs by id (both in
// contact/collision_detector.cpp).
// Not here: what the keys are, or any order within a key beyond the input's.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tribo::contact {

// `sorted` = `entries` ordered by key(e) (e the entry's index, key below `keys`), stable;
// key k's entries then fill sorted[start[k], start[k + 1]). `start` and `sorted` are the
// caller's, kept between calls so that a steady size allocates nothing.
template <class Entry, class Key>
void countingSort(const std::vector<Entry>& entries, std::size_t keys, Key key,
                  std::vector<std::uint32_t>& start, std::vector<Entry>& sorted) {
  start.assign(keys + 1, 0);
  for (std::size_t e = 0; e < entries.size(); ++e) ++start[key(e) + 1];
  for (std::size_t k = 0; k < keys; ++k) start[k + 1] += start[k];
  sorted.resize(entries.size());
  // start is the write cursor of each key while scattering, then restored.
  for (std::size_t e = 0; e < entries.size(); ++e) sorted[start[key(e)]++] = entries[e];
  for (std::size_t k = keys; k > 0; --k) start[k] = start[k - 1];
  start[0] = 0;
}

}  // namespace tribo::contact
