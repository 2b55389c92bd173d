// Pieces the two bucketed broadphases share (contact/broadphase.hpp's grid and
// contact/cell_list.hpp's cell list): the spatial hash of a cell, the counting sort of entries
// into buckets, the pair search split across threads by contiguous bucket ranges, and the
// boxes kept aside paired with every member.
// The hash: Teschner et al., "Optimized spatial hashing for collision detection of deformable
// objects", VMV 2003 (the cell's coordinates times three large primes, xor-ed).
// Not here: which cells a box enters, or which entries of a bucket range are tested.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "contact/broadphase.hpp"
#include "contact/parallel_range.hpp"

namespace tribo::contact {

// 2^30: cell coordinates stay within int32 (and a neighbour's, one further, too).
inline constexpr double kBucketCellLimit = 1073741824.0;

inline std::uint32_t hashedBucket(const std::int32_t cell[3], std::uint32_t mask) {
  const auto h = (static_cast<std::uint32_t>(cell[0]) * 73856093u) ^
                 (static_cast<std::uint32_t>(cell[1]) * 19349663u) ^
                 (static_cast<std::uint32_t>(cell[2]) * 83492791u);
  return (h ^ (h >> 16)) & mask;
}

// `sorted` = `entries` in bucket order (stable), bucket b's entries then
// sorted[start[b], start[b + 1]); `bucket_of` holds each entry's bucket, `start` has
// buckets + 1 counts on entry (start[b + 1] the size of bucket b, start[0] 0).
template <class Entry>
void sortIntoBuckets(const std::vector<Entry>& entries, const std::vector<std::uint32_t>& bucket_of,
                     std::vector<std::uint32_t>& start, std::vector<Entry>& sorted) {
  const std::size_t buckets = start.size() - 1;
  for (std::size_t b = 0; b < buckets; ++b) start[b + 1] += start[b];
  sorted.resize(entries.size());
  // start is the write cursor of each bucket while scattering, then restored.
  for (std::size_t e = 0; e < entries.size(); ++e) sorted[start[bucket_of[e]]++] = entries[e];
  for (std::size_t b = buckets; b > 0; --b) start[b] = start[b - 1];
  start[0] = 0;
}

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
