// A loop over the indices [0, n) split across OpenMP threads in contiguous chunks (static
// schedule), for the per-item stages of a force evaluation (core/dynamics.cpp) and the
// narrowphase (contact/collision_detector.cpp). Each index must write only its own outputs
// and read only shared inputs: then the result is the same bit for bit for any number of
// threads. With one thread it is a plain loop: no OpenMP call, no thread team started.
// Include only from a .cpp compiled with OpenMP (the libraries link OpenMP::OpenMP_CXX).
// Not here: reductions (the callers sum per-item results serially, in index order, so the
// additions happen in the order of the one-thread code).
#pragma once

#include <omp.h>

#include <algorithm>
#include <cstddef>

#include "contact/split_count.hpp"

namespace tribo::contact {

// The threads worth starting for `n` items when each thread should have at least
// `per_thread` of them: between 1 and `threads`.
inline int threadsFor(std::size_t n, int threads, std::size_t per_thread) {
  if (threads <= 1 || per_thread == 0) return 1;
  const std::size_t useful = n / per_thread;
  return static_cast<int>(std::clamp<std::size_t>(useful, 1, static_cast<std::size_t>(threads)));
}

// f(i) for every i in [0, n), on `threads` threads (1: the calling thread alone).
template <class F>
void parallelFor(std::size_t n, int threads, F&& f) {
  if (threads <= 1) {
    for (std::size_t i = 0; i < n; ++i) f(i);
    return;
  }
  const auto count = static_cast<long>(n);
#pragma omp parallel num_threads(threads)
  {
    if (omp_get_thread_num() == 0 && omp_get_num_threads() > 1) countSplitLoop();
#pragma omp for schedule(static)
    for (long i = 0; i < count; ++i) f(static_cast<std::size_t>(i));
  }
}

}  // namespace tribo::contact
