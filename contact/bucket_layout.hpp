// Where the two bucketed broadphases (contact/broadphase.hpp's grid and contact/cell_list.hpp's
// cell list) put an entry of integer cell coordinates: the layout of the buckets (a dense
// block of cells or a spatial hash) and the counting sort of entries into them.
// The hash: Teschner et al., "Optimized spatial hashing for collision detection of deformable
// objects", VMV 2003 (the cell's coordinates times three large primes, xor-ed).
// Not here: which cells a box enters, or how pairs are found in the buckets
// (contact/bucket_pairs.hpp).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "contact/counting_sort.hpp"

namespace tribo::contact {

// 2^30: cell coordinates stay within int32 (and a neighbour's, one further, too).
inline constexpr double kBucketCellLimit = 1073741824.0;

inline std::uint32_t hashedBucket(const std::int32_t cell[3], std::uint32_t mask) {
  const auto h = (static_cast<std::uint32_t>(cell[0]) * 73856093u) ^
                 (static_cast<std::uint32_t>(cell[1]) * 19349663u) ^
                 (static_cast<std::uint32_t>(cell[2]) * 83492791u);
  return (h ^ (h >> 16)) & mask;
}

// Where an entry's cell goes. Dense when the block of cells the entries span is small (at
// most four cells an entry, plus 1024): the bucket is the cell's index in that block, x
// fastest, so neighbouring cells land in neighbouring buckets. Else hashed into a power of two
// of buckets, at least 64 and at least twice the entries.
struct BucketLayout {
  bool dense = true;
  std::int32_t low[3] = {0, 0, 0};    // the block's lowest cell (dense)
  std::uint32_t span[3] = {0, 0, 0};  // the block's cells along x, y, z (dense)
  std::uint32_t mask = 0;             // buckets - 1 (hashed)
  std::size_t buckets = 0;

  // The bucket of `cell`; false when a dense block does not hold it (then no entry is there).
  [[gnu::always_inline]] bool bucketOf(const std::int32_t cell[3], std::uint32_t& bucket) const {
    if (!dense) {
      bucket = hashedBucket(cell, mask);
      return true;
    }
    std::uint32_t at[3];
    for (int i = 0; i < 3; ++i) {
      // Unsigned wrap-around sends a cell below the block past its span as well.
      at[i] = static_cast<std::uint32_t>(cell[i]) - static_cast<std::uint32_t>(low[i]);
      if (at[i] >= span[i]) return false;
    }
    bucket = (at[2] * span[1] + at[1]) * span[0] + at[0];
    return true;
  }
};

// The layout for `entries` (each with a `cell[3]`), as described above.
template <class Entry>
BucketLayout bucketLayoutFor(const std::vector<Entry>& entries) {
  BucketLayout layout;
  std::int32_t high[3] = {0, 0, 0};
  if (!entries.empty())
    for (int i = 0; i < 3; ++i) layout.low[i] = high[i] = entries.front().cell[i];
  for (const Entry& e : entries)
    for (int i = 0; i < 3; ++i) {
      layout.low[i] = std::min(layout.low[i], e.cell[i]);
      high[i] = std::max(high[i], e.cell[i]);
    }
  double block = 1.0;
  for (int i = 0; i < 3; ++i) block *= static_cast<double>(high[i]) - layout.low[i] + 1;
  layout.dense = block <= 4.0 * static_cast<double>(entries.size()) + 1024.0;
  layout.buckets = 64;
  if (layout.dense) {
    layout.buckets = static_cast<std::size_t>(block);
    for (int i = 0; i < 3; ++i)
      layout.span[i] =
          static_cast<std::uint32_t>(static_cast<std::int64_t>(high[i]) - layout.low[i] + 1);
  } else {
    while (layout.buckets < 2 * entries.size()) layout.buckets *= 2;
  }
  layout.mask = static_cast<std::uint32_t>(layout.buckets - 1);
  return layout;
}

// Counting sort of `entries` into the buckets of `layout` (contact/counting_sort.hpp): `sorted`
// = `entries` in bucket order (stable), bucket b's entries then sorted[start[b], start[b + 1]);
// `bucket_of` holds each entry's bucket. Every entry's cell lies in the layout's block (it was
// made from them).
template <class Entry>
void sortIntoBuckets(const BucketLayout& layout, const std::vector<Entry>& entries,
                     std::vector<std::uint32_t>& bucket_of, std::vector<std::uint32_t>& start,
                     std::vector<Entry>& sorted) {
  bucket_of.resize(entries.size());
  for (std::size_t e = 0; e < entries.size(); ++e) {
    std::uint32_t b = 0;
    layout.bucketOf(entries[e].cell, b);
    bucket_of[e] = b;
  }
  countingSort(
      entries, layout.buckets, [&bucket_of](std::size_t e) { return bucket_of[e]; }, start, sorted);
}

}  // namespace tribo::contact
