// A broadphase for boxes of about one size: linked cells (the cell lists of molecular
// dynamics; Allen & Tildesley, "Computer Simulation of Liquids", 2nd ed. 2017, sec. 5.3).
//
// The cell edge L is the largest extent of the boxes at this call (times 1 + 1e-6, against
// rounding), and each box is entered once, in the cell of its lower corner,
// (i, j, k) = floor(lo / L). Two closed boxes that overlap have lower corners less than one
// extent, so at most L, apart on every axis: their cells differ by -1, 0 or +1 per axis. Each
// cell is tested against itself (each pair once, in entry order) and against the 13 of its 26
// neighbours that lie ahead of it (offsets whose first non-zero component is +1), so each
// pair of neighbouring cells is looked at once and every overlapping pair is reported once.
// A box of a sphere pile or a granular chute meets about 14 L^3 rho others this way, where
// the hashed grid of contact/broadphase.hpp (cells twice the median extent, each box entered
// in every cell it covers, pairs reported from one of them) meets about 46 e^3 rho, e the
// median extent: the cell list is the cheaper while L stays under about 1.5 e, that is for
// boxes of nearly one size. With one huge box it degenerates towards all pairs (the caller
// chooses: contact/collision_detector.cpp's skin list, when its fat boxes are of one size).
// Cells are sorted into buckets by a counting sort: dense (the cell's index in the block the
// cells span) when that block has at most 4 cells a box plus 1024, else hashed (Teschner et al.
// 2003) into at least twice as many buckets as boxes, a neighbour's entries then filtered by
// their cell. A box with a coordinate that is not finite or whose cell leaves +-2^30 is kept
// aside and tested against every member (a NaN never separates two boxes: a pair too many,
// never one missed). The pair search splits across threads by contiguous bucket ranges, each
// range's pairs joined in bucket order: the same list in the same order for any thread count.
// Every call starts again from the boxes (no state kept between calls but buffers, which
// stop allocating once grown).
// Not here: which pairs may collide (the caller filters), half-spaces (unbounded), boxes of
// many sizes (contact/broadphase.hpp's grid).
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "contact/broadphase.hpp"

namespace tribo::contact {

class CellList {
 public:
  // Threads for the pair search (contact/parallel_range.hpp; 1 by default).
  void setThreads(int threads) { threads_ = threads < 1 ? 1 : threads; }
  // Pairs (g, h), g < h, of `members` (indices into `boxes`) whose boxes overlap; `pairs` is
  // cleared first. Deterministic order (see above), not sorted.
  void overlappingPairs(std::span<const Aabb> boxes, std::span<const int> members,
                        std::vector<std::pair<int, int>>& pairs);
  // The cell edge of the last call [m] (0 before a call with a member).
  double cellSize() const { return cell_; }

 private:
  struct Entry {
    std::int32_t cell[3];
    std::int32_t member;  // index into `members`
  };
  // The pairs of the cells whose entries lie in buckets [first, last): each cell with itself
  // and with its 13 neighbours ahead, appended to `out`.
  void pairsInBuckets(std::size_t first, std::size_t last, std::span<const Aabb> boxes,
                      std::span<const int> members, std::vector<std::pair<int, int>>& out) const;

  int threads_ = 1;
  double cell_ = 0.0;
  BucketLayout layout_;
  std::vector<Entry> entries_, sorted_;
  std::vector<std::uint32_t> bucket_of_;     // by entry
  std::vector<std::uint32_t> bucket_start_;  // bucket b's entries: sorted_[start[b], start[b+1])
  std::vector<int> aside_;                   // indices into `members`
  std::vector<std::vector<std::pair<int, int>>> lanes_;
};

}  // namespace tribo::contact
