// The collision detector's pair rule that lists every pair of n geometries, by id g * n + h
// (g < h): for tests that compare the broadphase's pairs with all of them.
#pragma once

#include <algorithm>
#include <utility>

#include "contact/collision_detector.hpp"

namespace tribo::test {

class EveryPair : public contact::PairRule {
 public:
  explicit EveryPair(int n) : n_(n) {}
  int pairId(int g, int h) const override { return std::min(g, h) * n_ + std::max(g, h); }
  std::pair<int, int> geometries(int id) const override { return {id / n_, id % n_}; }

 private:
  int n_;
};

}  // namespace tribo::test
