#include "contact/broadphase.hpp"

#include <algorithm>
#include <cmath>

#include "contact/bucket_pairs.hpp"

namespace tribo::contact {

namespace {

// The grid's origin is shifted by this fraction of a cell (the golden section's), so that a
// plane at a round coordinate, the floor z = 0 above all, is not a cell boundary that every
// box resting on it straddles (twice the entries and the tests).
constexpr double kCellShift = 0.381966;

// Cell coordinates of x, or false when they leave +-2^30 or x is not finite.
bool cellOf(const Eigen::Vector3d& x, double inv_cell, std::int32_t out[3]) {
  for (int i = 0; i < 3; ++i) {
    const double c = std::floor(x[i] * inv_cell + kCellShift);
    if (!(std::abs(c) < kBucketCellLimit)) return false;
    out[i] = static_cast<std::int32_t>(c);
  }
  return true;
}

double largestExtent(const Aabb& b) { return (b.hi - b.lo).maxCoeff(); }

}  // namespace

void GridBroadphase::chooseCell(std::span<const Aabb> boxes, std::span<const int> members) {
  std::vector<double> extents;
  extents.reserve(members.size());
  for (const int g : members) {
    const double e = largestExtent(boxes[static_cast<std::size_t>(g)]);
    if (e > 0.0 && std::isfinite(e)) extents.push_back(e);
  }
  if (extents.empty()) {
    cell_ = 1.0;
    return;
  }
  const auto middle = extents.begin() + static_cast<std::ptrdiff_t>(extents.size() / 2);
  std::nth_element(extents.begin(), middle, extents.end());
  cell_ = cell_scale_ * *middle;
}

void GridBroadphase::pairsInBuckets(std::size_t first, std::size_t last,
                                    std::span<const Aabb> boxes, std::span<const int> members,
                                    std::vector<std::pair<int, int>>& out) const {
  for (std::size_t b = first; b < last; ++b) {
    const std::uint32_t end = bucket_start_[b + 1];
    for (std::uint32_t i = bucket_start_[b]; i < end; ++i) {
      const Entry& ei = sorted_[i];
      const int g = members[static_cast<std::size_t>(ei.member)];
      const Aabb& bg = boxes[static_cast<std::size_t>(g)];
      for (std::uint32_t j = i + 1; j < end; ++j) {
        const Entry& ej = sorted_[j];
        if (ei.cell[0] != ej.cell[0] || ei.cell[1] != ej.cell[1] || ei.cell[2] != ej.cell[2])
          continue;  // another cell in the same bucket
        // Report from the cell of the overlap's lower corner only: floor is monotone, so its
        // cell is the larger of the two boxes' lowest cells, axis by axis (integers only).
        if (std::max(ei.first[0], ej.first[0]) != ei.cell[0] ||
            std::max(ei.first[1], ej.first[1]) != ei.cell[1] ||
            std::max(ei.first[2], ej.first[2]) != ei.cell[2])
          continue;
        const int h = members[static_cast<std::size_t>(ej.member)];
        if (!overlaps(bg, boxes[static_cast<std::size_t>(h)])) continue;
        out.emplace_back(std::min(g, h), std::max(g, h));
      }
    }
  }
}

void GridBroadphase::overlappingPairs(std::span<const Aabb> boxes, std::span<const int> members,
                                      std::vector<std::pair<int, int>>& pairs) {
  pairs.clear();
  if (members.empty()) return;
  if (cell_ == 0.0) chooseCell(boxes, members);
  const double inv_cell = 1.0 / cell_;

  // Each box's cell range; the cells (and so the buckets) are rebuilt only when one changed
  // since the last call or the members are others: a resting scene keeps its buckets and
  // only repeats the box tests.
  bool same =
      std::equal(members.begin(), members.end(), last_members_.begin(), last_members_.end());
  ranges_.resize(members.size());
  for (std::size_t k = 0; k < members.size(); ++k) {
    const Aabb& b = boxes[static_cast<std::size_t>(members[k])];
    CellRange r;
    bool aside = !cellOf(b.lo, inv_cell, r.lo) || !cellOf(b.hi, inv_cell, r.hi);
    if (!aside) {
      const double cells = (static_cast<double>(r.hi[0]) - r.lo[0] + 1) *
                           (static_cast<double>(r.hi[1]) - r.lo[1] + 1) *
                           (static_cast<double>(r.hi[2]) - r.lo[2] + 1);
      aside = !(cells >= 1.0 && cells <= kMaxCellsPerBox);
    }
    if (aside) r = CellRange{{1, 1, 1}, {0, 0, 0}};  // empty: no cell
    same = same && r == ranges_[k];
    ranges_[k] = r;
  }
  if (!same) last_members_.assign(members.begin(), members.end());
  if (!same) rebuild();
  pairsFromBuckets(boxes, members, pairs);
}

void GridBroadphase::rebuild() {
  // Entries: every cell each box covers; boxes too big or out of range aside.
  entries_.clear();
  aside_.clear();
  for (std::size_t k = 0; k < ranges_.size(); ++k) {
    const CellRange& r = ranges_[k];
    if (r.lo[0] > r.hi[0]) {
      aside_.push_back(static_cast<int>(k));
      continue;
    }
    for (std::int32_t x = r.lo[0]; x <= r.hi[0]; ++x)
      for (std::int32_t y = r.lo[1]; y <= r.hi[1]; ++y)
        for (std::int32_t z = r.lo[2]; z <= r.hi[2]; ++z)
          entries_.push_back(
              {{x, y, z}, static_cast<std::int32_t>(k), {r.lo[0], r.lo[1], r.lo[2]}});
  }

  // Counting sort into buckets, dense or hashed (contact/bucket_layout.hpp).
  layout_ = bucketLayoutFor(entries_);
  sortIntoBuckets(layout_, entries_, bucket_of_, bucket_start_, sorted_);
}

void GridBroadphase::pairsFromBuckets(std::span<const Aabb> boxes, std::span<const int> members,
                                      std::vector<std::pair<int, int>>& pairs) {
  // Pairs within buckets, split across threads by contiguous bucket ranges; then the boxes
  // kept aside against every other member.
  pairsByBucketRanges(
      layout_.buckets, entries_.size(), threads_, lanes_, pairs,
      [&](std::size_t first, std::size_t last, std::vector<std::pair<int, int>>& out) {
        pairsInBuckets(first, last, boxes, members, out);
      });
  pairAside(aside_, boxes, members, pairs);
}

}  // namespace tribo::contact
