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

  // Counting sort into buckets, dense or hashed (contact/bucket_layout.hpp).
  layout_ = bucketLayoutFor(entries_);
  sortIntoBuckets(layout_, entries_, bucket_of_, bucket_start_, sorted_);
  pairsByBucketRanges(
      layout_.buckets, entries_.size(), threads_, lanes_, pairs,
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
  if (layout_.dense) {
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
        if (!layout_.bucketOf(n, nb) || bucket_start_[nb] == bucket_start_[nb + 1]) continue;
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
        layout_.bucketOf(n, nb);
        for (std::uint32_t j = bucket_start_[nb]; j < bucket_start_[nb + 1]; ++j)
          if (sameCell(n, sorted_[j].cell)) test(g, bg, sorted_[j]);
      }
    }
  }
}

}  // namespace tribo::contact
