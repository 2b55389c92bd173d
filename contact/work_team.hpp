// The threads that share a step's loops: the caller and helper threads claim chunks of a loop
// one at a time from a shared counter, and the caller returns when every chunk is done. A
// helper that has not woken up by then (descheduled by another process on a shared machine)
// is not waited for: the caller takes its share, so two threads are never much slower than
// one. Only a chunk a helper has already claimed is waited for. Which thread ran a chunk
// never changes what the chunk computes, so callers that give each chunk its own outputs get
// the same bits for any number of threads. The caller claims from the front, helpers from the
// back, so that each thread keeps about the same share from loop to loop (its cache). A
// helper runs the chunks under the caller's floating-point control (rounding, and on x86 the
// flush-to-zero and denormals-are-zero bits a step sets: core/flush_denormals.hpp), so a
// chunk computes the same bits on any thread.
// Helpers are started on first use (as many as the largest team asked for, less one), spin
// about 50 us for the next loop, then sleep on a condition variable. One loop at a time: a
// loop asked for while another runs (another simulator's thread, or a loop inside a chunk)
// runs on its caller alone.
// Not here: how a loop is cut into chunks (contact/parallel_range.hpp), how many threads a
// stage asks for (core/stage_threads.hpp).
#pragma once

#include <cstddef>

namespace tribo::contact {

// A chunk's work: call(object, chunk). No allocation, no ownership.
struct ChunkWork {
  void* object = nullptr;
  void (*call)(void*, std::size_t) = nullptr;
  void operator()(std::size_t chunk) const { call(object, chunk); }
};

// Runs work(c) for every c in [0, chunks) on the caller and up to `threads` - 1 helpers
// (on the caller alone past 65 535 chunks: cut loops into a few chunks a thread).
void runChunks(std::size_t chunks, int threads, ChunkWork work);

// The same for any callable f(std::size_t chunk).
template <class F>
void runChunks(std::size_t chunks, int threads, F& f) {
  runChunks(chunks, threads,
            ChunkWork{&f, [](void* o, std::size_t c) { (*static_cast<F*>(o))(c); }});
}

}  // namespace tribo::contact
