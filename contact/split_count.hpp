// How many loops of a force evaluation or of the detection have been split in this process
// (contact/work_team.hpp): offered to a team of more than one thread (cut into chunks for
// helpers to claim), and helped (a helper thread ran at least one chunk of it). A test's
// evidence that a scene's work was cut for threads (offered: decided by the scene's size
// alone) and that other threads did take part (helped: depends on when the helpers were
// scheduled, so only a count over many loops is meaningful). Relaxed atomic counting. Not
// here: which loop split or on how many threads, per-run figures (concurrent runs in one
// process add to the same counts).
#pragma once

#include <atomic>

namespace tribo::contact {

inline std::atomic<long>& splitLoopCount() {
  static std::atomic<long> count{0};
  return count;
}

inline std::atomic<long>& helpedLoopCount() {
  static std::atomic<long> count{0};
  return count;
}

inline void countSplitLoop() { splitLoopCount().fetch_add(1, std::memory_order_relaxed); }
inline void countHelpedLoop() { helpedLoopCount().fetch_add(1, std::memory_order_relaxed); }

}  // namespace tribo::contact
