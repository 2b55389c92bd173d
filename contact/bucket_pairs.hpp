// Pieces the two bucketed broadphases share (contact/broadphase.hpp's grid and
// contact/cell_list.hpp's cell list) after their entries are in buckets
// (contact/bucket_layout.hpp): the pair search split across threads by contiguous bucket
// ranges, and the boxes kept aside paired with every member.
// Not here: which cells a box enters, or which entries of a bucket range are tested.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "contact/broadphase.hpp"
#include "contact/bucket_layout.hpp"
#include "contact/parallel_range.hpp"

namespace tribo::contact {

// search(first, last, out) for the bucket ranges of `buckets`, on up to `threads` threads when
// `entries` pay for them: contiguous ranges, one lane each, claimed by the threads
// (contact/work_team.hpp), the lanes appended to `pairs` in bucket order whoever ran them.
template <class Search>
void pairsByBucketRanges(std::size_t buckets, std::size_t entries, int threads,
                         std::vector<std::vector<std::pair<int, int>>>& lanes,
                         std::vector<std::pair<int, int>>& pairs, Search&& search) {
  constexpr std::size_t kEntriesPerThread = 2048;
  const int team = threadsFor(entries, threads, kEntriesPerThread);
  if (team <= 1) {
    search(std::size_t{0}, buckets, pairs);
    return;
  }
  const std::size_t chunks = chunksFor(buckets, team);
  if (lanes.size() < chunks) lanes.resize(chunks);
  auto run = [&](std::size_t c) {
    lanes[c].clear();
    search(buckets * c / chunks, buckets * (c + 1) / chunks, lanes[c]);
  };
  runChunks(chunks, team, run);
  for (std::size_t c = 0; c < chunks; ++c)
    pairs.insert(pairs.end(), lanes[c].begin(), lanes[c].end());
}

// The boxes kept aside (`aside`: increasing indices into `members`) against every other
// member, aside with aside once, appended to `pairs` as (min, max).
inline void pairAside(std::span<const int> aside, std::span<const Aabb> boxes,
                      std::span<const int> members, std::vector<std::pair<int, int>>& pairs) {
  for (std::size_t a = 0; a < aside.size(); ++a) {
    const int g = members[static_cast<std::size_t>(aside[a])];
    const Aabb& bg = boxes[static_cast<std::size_t>(g)];
    std::size_t next_aside = 0;  // skip aside members already paired with g
    for (std::size_t k = 0; k < members.size(); ++k) {
      if (next_aside < aside.size() && static_cast<std::size_t>(aside[next_aside]) == k) {
        ++next_aside;
        if (next_aside - 1 <= a) continue;  // itself, or an aside member that took g before
      }
      const int h = members[k];
      if (overlaps(bg, boxes[static_cast<std::size_t>(h)]))
        pairs.emplace_back(std::min(g, h), std::max(g, h));
    }
  }
}

}  // namespace tribo::contact
