#include "contact/cell_list.hpp"

#include <algorithm>
#include <cmath>

#include "contact/bucket_pairs.hpp"

namespace tribo::contact {

namespace {

// The cell edge over the largest extent: above 1 so that two overlapping boxes' lower corners
// stay in neighbouring cells through the rounding of lo / L (relative 2^-53 of a coordinate
// at most 2^30 cells: 1.2e-7 of a cell, against the 1e-6 kept free).
constexpr double kEdgeOverExtent = 1.0 + 1e-6;
// The 13 neighbour offsets ahead of a cell: first non-zero component +1.
constexpr std::int32_t kAhead[13][3] = {{1, -1, -1}, {1, -1, 0}, {1, -1, 1}, {1, 0, -1}, {1, 0, 0},
                                        {1, 0, 1},   {1, 1, -1}, {1, 1, 0},  {1, 1, 1},  {0, 1, -1},
                                        {0, 1, 0},   {0, 1, 1},  {0, 0, 1}};

bool finiteBox(const Aabb& b) { return b.lo.allFinite() && b.hi.allFinite(); }

bool sameCell(const std::int32_t a[3], const std::int32_t b[3]) {
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

}  // namespace

// Inlined into the pair search, which asks it for 13 neighbours a cell.
[[gnu::always_inline]] inline bool CellList::bucketOfCell(const std::int32_t cell[3],
                                                          std::uint32_t& bucket) const {
  if (!dense_) {
    bucket = hashedBucket(cell, mask_);
    return true;
  }
  std::uint32_t at[3];
  for (int i = 0; i < 3; ++i) {
    // Unsigned wrap-around sends a cell below the block past its span as well.
    at[i] = static_cast<std::uint32_t>(cell[i]) - static_cast<std::uint32_t>(low_[i]);
    if (at[i] >= span_[i]) return false;
  }
  bucket = (at[2] * span_[1] + at[1]) * span_[0] + at[0];
  return true;
}

void CellList::overlappingPairs(std::span<const Aabb> boxes, std::span<const int> members,
                                std::vector<std::pair<int, int>>& pairs) {
  pairs.clear();
  entries_.clear();
  aside_.clear();
  if (members.empty()) return;
  double largest = 0.0;
  for (const int g : members) {
    const Aabb& b = boxes[static_cast<std::size_t>(g)];
    if (finiteBox(b)) largest = std::max(largest, (b.hi - b.lo).maxCoeff());
  }
  cell_ = largest > 0.0 && std::isfinite(largest) ? kEdgeOverExtent * largest : 1.0;
  const double inv_cell = 1.0 / cell_;
  for (std::size_t k = 0; k < members.size(); ++k) {
    const Aabb& b = boxes[static_cast<std::size_t>(members[k])];
    Entry e{{0, 0, 0}, static_cast<std::int32_t>(k)};
    bool aside = !finiteBox(b);
    for (int i = 0; i < 3 && !aside; ++i) {
      const double c = std::floor(b.lo[i] * inv_cell);
      aside = !(std::abs(c) < kBucketCellLimit);
      if (!aside) e.cell[i] = static_cast<std::int32_t>(c);
    }
    if (aside)
      aside_.push_back(static_cast<int>(k));
    else
      entries_.push_back(e);
  }

  // Counting sort into buckets, dense or hashed (see the header).
  std::int32_t high[3] = {0, 0, 0};
  for (int i = 0; i < 3; ++i) low_[i] = 0;
  if (!entries_.empty())
    for (int i = 0; i < 3; ++i) low_[i] = high[i] = entries_.front().cell[i];
  for (const Entry& e : entries_)
    for (int i = 0; i < 3; ++i) {
      low_[i] = std::min(low_[i], e.cell[i]);
      high[i] = std::max(high[i], e.cell[i]);
    }
  double block = 1.0;
  for (int i = 0; i < 3; ++i) block *= static_cast<double>(high[i]) - low_[i] + 1;
  dense_ = block <= 4.0 * static_cast<double>(entries_.size()) + 1024.0;
  std::size_t buckets = 64;
  if (dense_) {
    buckets = static_cast<std::size_t>(block);
    for (int i = 0; i < 3; ++i)
      span_[i] = static_cast<std::uint32_t>(static_cast<std::int64_t>(high[i]) - low_[i] + 1);
  } else {
    while (buckets < 2 * entries_.size()) buckets *= 2;
  }
  mask_ = static_cast<std::uint32_t>(buckets - 1);
  buckets_ = buckets;
  bucket_start_.assign(buckets + 1, 0);
  bucket_of_.resize(entries_.size());
  for (std::size_t e = 0; e < entries_.size(); ++e) {
    std::uint32_t b = 0;
    bucketOfCell(entries_[e].cell, b);  // inside the block: it is the entries' own
    bucket_of_[e] = b;
    ++bucket_start_[b + 1];
  }
  sortIntoBuckets(entries_, bucket_of_, bucket_start_, sorted_);
  pairsByBucketRanges(
      buckets, entries_.size(), threads_, lanes_, pairs,
      [&](std::size_t first, std::size_t last, std::vector<std::pair<int, int>>& out) {
        pairsInBuckets(first, last, boxes, members, out);
      });
  pairAside(aside_, boxes, members, pairs);
}

void CellList::pairsInBuckets(std::size_t first, std::size_t last, std::span<const Aabb> boxes,
                              std::span<const int> members,
                              std::vector<std::pair<int, int>>& out) const {
  auto test = [&](int g, const Aabb& bg, const Entry& other) {
    const int h = members[static_cast<std::size_t>(other.member)];
    if (overlaps(bg, boxes[static_cast<std::size_t>(h)]))
      out.emplace_back(std::min(g, h), std::max(g, h));
  };
  if (dense_) {
    // A bucket is one cell: its neighbours' ranges found once for all its entries.
    std::uint32_t from[13], to[13];
    for (std::size_t b = first; b < last; ++b) {
      const std::uint32_t begin = bucket_start_[b], end = bucket_start_[b + 1];
      if (begin == end) continue;
      const std::int32_t* cell = sorted_[begin].cell;
      int ahead = 0;
      for (const auto& d : kAhead) {
        const std::int32_t n[3] = {cell[0] + d[0], cell[1] + d[1], cell[2] + d[2]};
        std::uint32_t nb = 0;
        if (!bucketOfCell(n, nb) || bucket_start_[nb] == bucket_start_[nb + 1]) continue;
        from[ahead] = bucket_start_[nb];
        to[ahead++] = bucket_start_[nb + 1];
      }
      for (std::uint32_t i = begin; i < end; ++i) {
        const int g = members[static_cast<std::size_t>(sorted_[i].member)];
        const Aabb& bg = boxes[static_cast<std::size_t>(g)];
        for (std::uint32_t j = i + 1; j < end; ++j) test(g, bg, sorted_[j]);
        for (int k = 0; k < ahead; ++k)
          for (std::uint32_t j = from[k]; j < to[k]; ++j) test(g, bg, sorted_[j]);
      }
    }
    return;
  }
  // Hashed: a bucket may hold several cells, and a neighbour's bucket others; each entry
  // looks for its own cell's entries among them.
  for (std::size_t b = first; b < last; ++b) {
    const std::uint32_t end = bucket_start_[b + 1];
    for (std::uint32_t i = bucket_start_[b]; i < end; ++i) {
      const Entry& ei = sorted_[i];
      const int g = members[static_cast<std::size_t>(ei.member)];
      const Aabb& bg = boxes[static_cast<std::size_t>(g)];
      for (std::uint32_t j = i + 1; j < end; ++j)
        if (sameCell(ei.cell, sorted_[j].cell)) test(g, bg, sorted_[j]);
      for (const auto& d : kAhead) {
        const std::int32_t n[3] = {ei.cell[0] + d[0], ei.cell[1] + d[1], ei.cell[2] + d[2]};
        std::uint32_t nb = 0;
        bucketOfCell(n, nb);
        for (std::uint32_t j = bucket_start_[nb]; j < bucket_start_[nb + 1]; ++j)
          if (sameCell(n, sorted_[j].cell)) test(g, bg, sorted_[j]);
      }
    }
  }
}

}  // namespace tribo::contact
