// Brute-force pairs of boxes for the broadphase tests (tests/contact/broadphase_test.cpp,
// cell_list_test.cpp): every pair (g < h) of members whose closed boxes overlap, written out
// per axis (a NaN coordinate separates nothing), sorted; and two small helpers.
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "contact/broadphase.hpp"

namespace tribo::test {

using BoxPairs = std::vector<std::pair<int, int>>;

inline BoxPairs bruteForcePairs(const std::vector<contact::Aabb>& boxes,
                                const std::vector<int>& members) {
  BoxPairs pairs;
  for (std::size_t i = 0; i < members.size(); ++i)
    for (std::size_t j = i + 1; j < members.size(); ++j) {
      const contact::Aabb& a = boxes[static_cast<std::size_t>(members[i])];
      const contact::Aabb& b = boxes[static_cast<std::size_t>(members[j])];
      bool apart = false;
      for (int k = 0; k < 3; ++k) apart = apart || a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k];
      if (!apart)
        pairs.emplace_back(std::min(members[i], members[j]), std::max(members[i], members[j]));
    }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

// The pairs sorted, duplicates kept (so that a pair reported twice shows).
inline BoxPairs sortedPairs(BoxPairs p) {
  std::sort(p.begin(), p.end());
  return p;
}

// 0, 1, ..., n - 1.
inline std::vector<int> allMembers(std::size_t n) {
  std::vector<int> m(n);
  for (std::size_t i = 0; i < n; ++i) m[i] = static_cast<int>(i);
  return m;
}

}  // namespace tribo::test
