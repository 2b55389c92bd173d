// How many loops of a force evaluation or of the narrowphase have run on a team of more
// than one thread in this process (contact/parallel_range.hpp, the narrowphase's lanes in
// contact/collision_detector.cpp): a test's evidence that a scene's work was actually
// split, not only allowed to be. Relaxed atomic counting, one increment per loop that
// split. Not here: which loop split or on how many threads, per-run figures (concurrent
// runs in one process add to the same count).
#pragma once

#include <atomic>

namespace tribo::contact {

inline std::atomic<long>& splitLoopCount() {
  static std::atomic<long> count{0};
  return count;
}

inline void countSplitLoop() { splitLoopCount().fetch_add(1, std::memory_order_relaxed); }

}  // namespace tribo::contact
