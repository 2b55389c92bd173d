// The broadphase: which geometries' world boxes (axis-aligned, AABBs) overlap, so that the
// narrowphase looks only at pairs that may touch (contact/collision_detector.hpp).
//
// A uniform grid, hashed: each box is entered in every cell of edge `c` it covers, cell
// (i, j, k) = floor(x / c + 0.382) per axis (shifted so that the floor z = 0 is no cell
// boundary), in a bucket chosen by a spatial hash of the cell
// (Teschner et al., "Optimized spatial hashing for collision detection of deformable
// objects", VMV 2003). Two boxes of the same cell that overlap are a pair, reported only from
// the cell holding the lower corner of their overlap (max of the two lower corners), which
// both cover: every pair once, with no set of pairs seen. The entries are sorted into their
// buckets by a counting sort, so a call costs O(boxes + entries + pairs). Incremental across
// calls: the buckets are rebuilt only when some box's range of cells changed (a resting
// scene's boxes keep theirs, and a call is then the box tests alone).
// A box covering more than kMaxCellsPerBox cells (a long beam or a big ground box), or one
// whose cell coordinates leave +-2^30 or are not finite, is kept aside and tested against
// every other box. Boxes are closed: touching faces overlap; a NaN coordinate never
// separates two boxes along its axis (a pair too many, never one missed).
//
// The cell edge is fixed at the first call: kCellScale times the median of the boxes'
// largest extents (1 m when every box is a point). Chosen by measurement against FCL's
// dynamic AABB tree and other scales (bench/contact/broadphase_bench.cpp,
// docs/performance.md). Pair tests split across threads by contiguous bucket ranges, each
// thread's pairs joined in bucket order: the output is the same list in the same order for
// any thread count. Does not allocate once its buffers have grown to their working size.
// Not here: the boxes themselves (contact/collision_detector.cpp derives them from the
// shapes), half-spaces (unbounded, never entered), which pairs may collide.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "contact/bucket_layout.hpp"

namespace tribo::contact {

struct Aabb {
  Eigen::Vector3d lo = Eigen::Vector3d::Zero();
  Eigen::Vector3d hi = Eigen::Vector3d::Zero();
};

// Closed boxes overlap (written so that a NaN coordinate never separates them).
inline bool overlaps(const Aabb& a, const Aabb& b) {
  return !(a.hi.x() < b.lo.x() || b.hi.x() < a.lo.x() || a.hi.y() < b.lo.y() ||
           b.hi.y() < a.lo.y() || a.hi.z() < b.lo.z() || b.hi.z() < a.lo.z());
}

class GridBroadphase {
 public:
  static constexpr int kMaxCellsPerBox = 64;
  static constexpr double kCellScale = 2.0;

  // `cell_scale`: the cell edge over the median box's largest extent (a bench varies it).
  explicit GridBroadphase(double cell_scale = kCellScale) : cell_scale_(cell_scale) {}

  // Threads for the pair tests (contact/parallel_range.hpp; 1 by default).
  void setThreads(int threads) { threads_ = threads < 1 ? 1 : threads; }

  // Pairs (g, h), g < h, of `members` (indices into `boxes`) whose boxes overlap; `pairs` is
  // cleared first. Deterministic order (see above), not sorted.
  void overlappingPairs(std::span<const Aabb> boxes, std::span<const int> members,
                        std::vector<std::pair<int, int>>& pairs);

  // The cell edge [m]: 0 before the first call with a member.
  double cellSize() const { return cell_; }

 private:
  struct Entry {
    std::int32_t cell[3];
    std::int32_t member;    // index into `members`
    std::int32_t first[3];  // the box's lowest cell
  };
  struct CellRange {
    std::int32_t lo[3], hi[3];  // lo > hi: kept aside
    bool operator==(const CellRange& o) const {
      return lo[0] == o.lo[0] && lo[1] == o.lo[1] && lo[2] == o.lo[2] && hi[0] == o.hi[0] &&
             hi[1] == o.hi[1] && hi[2] == o.hi[2];
    }
  };
  void rebuild();
  void pairsFromBuckets(std::span<const Aabb> boxes, std::span<const int> members,
                        std::vector<std::pair<int, int>>& pairs);
  void chooseCell(std::span<const Aabb> boxes, std::span<const int> members);
  void pairsInBuckets(std::size_t first, std::size_t last, std::span<const Aabb> boxes,
                      std::span<const int> members, std::vector<std::pair<int, int>>& out) const;

  double cell_scale_;
  double cell_ = 0.0;
  int threads_ = 1;
  std::vector<CellRange> ranges_;  // by member, as of the last call
  std::vector<int> last_members_;
  BucketLayout layout_;
  std::vector<Entry> entries_, sorted_;
  std::vector<std::uint32_t> bucket_of_;     // by entry
  std::vector<std::uint32_t> bucket_start_;  // bucket b's entries: sorted_[start[b], start[b+1])
  std::vector<int> aside_;                   // indices into `members`
  std::vector<std::vector<std::pair<int, int>>> lanes_;
};

}  // namespace tribo::contact
