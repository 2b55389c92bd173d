// A loop over the indices [0, n) split across threads, for the per-item stages of a force
// evaluation (core/dynamics.cpp) and the integrators' updates: the indices cut into
// contiguous chunks (kChunksPerThread for each thread) that the caller and the helper threads
// claim one at a time (contact/work_team.hpp), so a slow or descheduled thread takes fewer of
// them and is never waited for unless it holds one. Each index must write only its own
// outputs and read only shared inputs: then the result is the same bit for bit for any
// number of threads. With one thread it is a plain loop: no helper is asked.
// Not here: reductions (the callers sum per-item results serially, in index order, so the
// additions happen in the order of the one-thread code).
#pragma once

#include <algorithm>
#include <cstddef>

#include "contact/work_team.hpp"

namespace tribo::contact {

// The threads worth starting for `n` items when each thread should have at least
// `per_thread` of them: between 1 and `threads`.
inline int threadsFor(std::size_t n, int threads, std::size_t per_thread) {
  if (threads <= 1 || per_thread == 0) return 1;
  const std::size_t useful = n / per_thread;
  return static_cast<int>(std::clamp<std::size_t>(useful, 1, static_cast<std::size_t>(threads)));
}

// Chunks a thread is offered of a split loop: more than one, so that a thread that falls
// behind leaves work for the others to take.
inline constexpr std::size_t kChunksPerThread = 4;

// The chunks a split loop of `n` items on `threads` threads is cut into (at most one an item).
inline std::size_t chunksFor(std::size_t n, int threads) {
  return std::min(n, static_cast<std::size_t>(threads) * kChunksPerThread);
}

// f(i) for every i in [0, n), on up to `threads` threads (1: the calling thread alone).
template <class F>
void parallelFor(std::size_t n, int threads, F&& f) {
  if (threads <= 1 || n < 2) {
    for (std::size_t i = 0; i < n; ++i) f(i);
    return;
  }
  const std::size_t chunks = chunksFor(n, threads);
  auto chunk = [&](std::size_t c) {
    for (std::size_t i = n * c / chunks; i < n * (c + 1) / chunks; ++i) f(i);
  };
  runChunks(chunks, threads, chunk);
}

}  // namespace tribo::contact
