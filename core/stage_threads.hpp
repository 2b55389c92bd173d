// How many threads one per-item stage of a step starts: one per kItemsPerThread items
// (bodies, geometries, contact points), at most the threads the scene may use. Shared by the
// force evaluation (core/dynamics.cpp), the integrators' per-body updates
// (core/integrator.cpp) and the energy account (core/energy.cpp), so every stage of a step
// splits by the same measured rule (docs/performance.md, "Two threads").
// Not here: the parallel loop itself (contact/parallel_range.hpp), the threads a scene may
// use (core/thread_count.hpp).
#pragma once

#include <cstddef>

#include "contact/parallel_range.hpp"

namespace tribo {

// Below this many items per thread, starting and joining the thread costs more than it saves.
inline constexpr std::size_t kItemsPerThread = 256;

// Between 1 and `threads`: the threads worth starting for `items` items.
inline int stageThreads(std::size_t items, int threads) {
  return contact::threadsFor(items, threads, kItemsPerThread);
}

}  // namespace tribo
