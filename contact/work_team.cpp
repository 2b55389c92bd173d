#include "contact/work_team.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>

#include "contact/split_count.hpp"

#if defined(__SSE__) || defined(_M_X64)
#include <xmmintrin.h>
#else
#include <cfenv>
#endif

namespace tribo::contact {

namespace {

// The most chunks a loop may be cut into to be shared (the claim word's 16-bit fields); a loop
// of more runs on its caller.
constexpr std::size_t kMaxChunks = 0xffff;

// The floating-point control a loop's chunks run under: the caller's, on every thread. On x86
// the SSE control register (MXCSR): its rounding mode and its flush-to-zero and
// denormals-are-zero bits, which a step sets (core/flush_denormals.hpp) and which change
// results (a subnormal input reads as zero); elsewhere the rounding mode. A helper that ran
// under its own default would compute its chunks differently from the caller whenever a
// subnormal number or another rounding mode is in play, and on subnormals about 100 times
// slower. The status flags are not carried (nothing reads a helper's).
struct FpControl {
#if defined(__SSE__) || defined(_M_X64)
  static constexpr unsigned kStatusFlags = 0x3f;
  unsigned csr = 0;
  static FpControl current() { return {_mm_getcsr() & ~kStatusFlags}; }
  void apply() const { _mm_setcsr(csr); }
#else
  int rounding = FE_TONEAREST;
  static FpControl current() { return {std::fegetround()}; }
  void apply() const { std::fesetround(rounding); }
#endif
};

// A busy-wait hint to the core (the other hyperthread gets the pipeline).
inline void relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

class WorkTeam {
 public:
  // Never destroyed: helpers are detached and sleep until the process ends (a forked child
  // has none, and its loops simply run on the caller).
  static WorkTeam& instance() {
    static WorkTeam* team = new WorkTeam;
    return *team;
  }

  void run(std::size_t chunks, int threads, ChunkWork work) {
    if (busy_.exchange(true, std::memory_order_acquire)) {  // another loop is running
      for (std::size_t c = 0; c < chunks; ++c) work(c);
      return;
    }
    countSplitLoop();
    startHelpers(threads - 1);
    std::uint64_t generation = 0;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      work_ = work;
      chunks_ = chunks;
      control_ = FpControl::current();
      wanted_ = threads - 1;
      joined_ = 0;
      done_.store(0, std::memory_order_relaxed);
      generation = generation_.load(std::memory_order_relaxed) + 1;
      claim_.store((generation << 32) | chunks, std::memory_order_relaxed);  // front 0
      generation_.store(generation, std::memory_order_release);
    }
    wake_.notify_all();
    take(generation, work, chunks, false);
    // Wait for the chunks helpers claimed; a helper that claimed nothing is not waited for.
    for (int spin = 0; done_.load(std::memory_order_acquire) < chunks; ++spin) {
      if (spin < 4096) {
        relax();
        continue;
      }
      std::unique_lock<std::mutex> lock(mutex_);
      finished_.wait(lock, [&] { return done_.load(std::memory_order_acquire) == chunks; });
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      work_ = {};  // a helper waking from now on finds nothing to join
    }
    busy_.store(false, std::memory_order_release);
  }

 private:
  void startHelpers(int count) {
    for (; helpers_ < count; ++helpers_) std::thread([this] { serve(); }).detach();
  }

  // Claims chunks of loop `generation` until none is left: the caller from the front, helpers
  // from the back, so that with steady speeds each thread gets about the same contiguous
  // share from loop to loop (the data its last loop touched is still in its cache).
  void take(std::uint64_t generation, ChunkWork work, std::size_t chunks, bool helper) {
    bool ran = false;
    for (;;) {
      std::uint64_t word = claim_.load(std::memory_order_relaxed);
      std::size_t chunk = 0;
      for (;;) {
        if ((word >> 32) != (generation & 0xffffffffu)) return;  // a later loop
        const std::uint64_t front = (word >> 16) & 0xffffu, back = word & 0xffffu;
        if (front >= back) return;  // all claimed
        std::uint64_t next = 0;
        if (helper) {
          chunk = static_cast<std::size_t>(back - 1);
          next = word - 1;
        } else {
          chunk = static_cast<std::size_t>(front);
          next = word + (std::uint64_t{1} << 16);
        }
        if (claim_.compare_exchange_weak(word, next, std::memory_order_acq_rel)) break;
      }
      work(chunk);
      if (helper && !ran) countHelpedLoop();
      ran = true;
      if (done_.fetch_add(1, std::memory_order_acq_rel) + 1 == chunks && helper) {
        { std::lock_guard<std::mutex> lock(mutex_); }  // the caller is waiting or will see it
        finished_.notify_one();
      }
    }
  }

  void serve() {
    std::uint64_t seen = generation_.load(std::memory_order_acquire);
    for (;;) {
      // The next loop usually comes within microseconds: spin a little before sleeping.
      const auto until = std::chrono::steady_clock::now() + std::chrono::microseconds(50);
      while (generation_.load(std::memory_order_acquire) == seen &&
             std::chrono::steady_clock::now() < until)
        for (int i = 0; i < 64; ++i) relax();
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return generation_.load(std::memory_order_relaxed) != seen; });
      seen = generation_.load(std::memory_order_relaxed);
      if (work_.call == nullptr || joined_ >= wanted_) continue;  // over, or enough helpers
      ++joined_;
      const ChunkWork work = work_;
      const std::size_t chunks = chunks_;
      const FpControl control = control_;
      lock.unlock();
      control.apply();  // the caller's rounding and subnormal handling (a helper runs nothing else)
      take(seen, work, chunks, true);
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_;      // helpers: a new loop
  std::condition_variable finished_;  // the caller: the last chunk is done
  std::atomic<std::uint64_t> generation_{0};
  // The loop's generation (low 32 bits) << 32 | first unclaimed chunk << 16 | end of the
  // unclaimed chunks.
  std::atomic<std::uint64_t> claim_{0};
  std::atomic<std::size_t> done_{0};
  std::atomic<bool> busy_{false};
  ChunkWork work_;          // guarded by mutex_
  std::size_t chunks_ = 0;  // guarded by mutex_
  FpControl control_;       // the caller's, guarded by mutex_
  int wanted_ = 0;          // helpers this loop asked for, guarded by mutex_
  int joined_ = 0;          // helpers that joined it, guarded by mutex_
  int helpers_ = 0;         // started; touched only by the caller holding busy_
};

}  // namespace

void runChunks(std::size_t chunks, int threads, ChunkWork work) {
  if (threads <= 1 || chunks <= 1 || chunks > kMaxChunks) {
    for (std::size_t c = 0; c < chunks; ++c) work(c);
    return;
  }
  WorkTeam::instance().run(chunks, threads, work);
}

}  // namespace tribo::contact
