// The threads that share a step's loops (contact/work_team.hpp): every chunk runs exactly
// once and its outputs are seen by the caller, for any chunk and thread count; loops asked
// for from inside a chunk or from two threads at once still run every chunk; helpers take
// part; helpers compute under the caller's floating-point control (rounding, and subnormal
// numbers flushed as the caller flushes them); parallelFor covers every index once.
#include "contact/work_team.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cfenv>
#include <cmath>
#include <thread>
#include <vector>

#include "contact/parallel_range.hpp"
#include "contact/split_count.hpp"
#include "core/flush_denormals.hpp"

namespace tribo::contact {
namespace {

// Work for a chunk: about `n` square roots in a dependent chain.
double spin(std::size_t c, int n = 2000) {
  double x = static_cast<double>(c);
  for (int i = 0; i < n; ++i) x = std::sqrt(x + 1.0);
  return x;
}

TEST(WorkTeam, EveryChunkRunsOnceAndItsOutputsReachTheCaller) {
  for (int threads : {2, 3, 4}) {
    for (std::size_t chunks : {2u, 3u, 7u, 64u, 1000u}) {
      for (int loop = 0; loop < 50; ++loop) {
        std::vector<std::atomic<int>> runs(chunks);
        std::vector<double> out(chunks, 0.0);  // plain writes, one slot a chunk
        auto work = [&](std::size_t c) {
          runs[c].fetch_add(1, std::memory_order_relaxed);
          out[c] = static_cast<double>(c) + 0.5;
        };
        runChunks(chunks, threads, work);
        for (std::size_t c = 0; c < chunks; ++c) {
          ASSERT_EQ(runs[c].load(), 1) << threads << " threads, chunk " << c << " of " << chunks;
          ASSERT_EQ(out[c], static_cast<double>(c) + 0.5);
        }
      }
    }
  }
}

TEST(WorkTeam, HelpersTakePart) {
  // Loops of about 2 ms (16 chunks of 0.1 ms or more): long enough for a woken helper to be
  // scheduled even beside another process, so that some of 100 loops get its help.
  const long split_before = splitLoopCount().load();
  const long helped_before = helpedLoopCount().load();
  std::vector<double> out(16);
  for (int loop = 0; loop < 100; ++loop) {
    auto work = [&](std::size_t c) { out[c] = spin(c, 20000); };
    runChunks(out.size(), 2, work);
  }
  EXPECT_EQ(splitLoopCount().load() - split_before, 100);
  EXPECT_GT(helpedLoopCount().load() - helped_before, 0) << "no helper ran a chunk";
  for (std::size_t c = 0; c < out.size(); ++c) EXPECT_EQ(out[c], spin(c, 20000));
}

// What a chunk computes that depends on the floating-point control: a subnormal times one (0
// when subnormal inputs read as zero), and 1/3 (rounded up or to nearest).
struct ControlSensitive {
  double tiny_times_one = -1.0, third = -1.0;
};
ControlSensitive controlSensitive() {
  volatile double tiny = 1e-310, one = 1.0, three = 3.0;  // tiny: below 2.2e-308
  return {tiny * one, one / three};
}

// The caller runs its loops rounding upwards and, on x86, with subnormals flushed (the step's
// own guard, core/flush_denormals.hpp): every chunk, whichever thread ran it, must give the
// caller's results, which differ from the default mode's in both numbers.
TEST(WorkTeam, HelpersComputeUnderTheCallersFloatingPointControl) {
  const ControlSensitive plain = controlSensitive();
  ASSERT_GT(plain.tiny_times_one, 0.0);
  const int rounding = std::fegetround();
  ASSERT_EQ(std::fesetround(FE_UPWARD), 0);
  const long helped_before = helpedLoopCount().load();
  std::vector<double> sink(16);
  {
    const ScopedFlushDenormals flush;
    const ControlSensitive callers = controlSensitive();
    EXPECT_NE(callers.third, plain.third);
#ifdef TRIBO_HAS_MXCSR
    EXPECT_EQ(callers.tiny_times_one, 0.0);
#endif
    std::vector<ControlSensitive> out(16);
    for (int loop = 0; loop < 100; ++loop) {
      auto work = [&](std::size_t c) {
        sink[c] = spin(c, 20000);  // about 0.1 ms: long enough for a helper to join
        out[c] = controlSensitive();
      };
      runChunks(out.size(), 2, work);
      for (std::size_t c = 0; c < out.size(); ++c) {
        ASSERT_EQ(out[c].tiny_times_one, callers.tiny_times_one)
            << "loop " << loop << ", chunk " << c;
        ASSERT_EQ(out[c].third, callers.third) << "loop " << loop << ", chunk " << c;
      }
    }
  }
  std::fesetround(rounding);
  EXPECT_GT(helpedLoopCount().load() - helped_before, 0) << "no helper ran a chunk";
  // Back in the default mode, every thread computes the default results again.
  std::vector<ControlSensitive> after(16);
  for (int loop = 0; loop < 20; ++loop) {
    auto work = [&](std::size_t c) {
      sink[c] = spin(c, 20000);
      after[c] = controlSensitive();
    };
    runChunks(after.size(), 2, work);
    for (const ControlSensitive& r : after) {
      ASSERT_EQ(r.tiny_times_one, plain.tiny_times_one);
      ASSERT_EQ(r.third, plain.third);
    }
  }
}

TEST(WorkTeam, ALoopInsideAChunkRunsOnItsCaller) {
  std::vector<std::atomic<int>> inner(8 * 8);
  auto outer = [&](std::size_t c) {
    auto work = [&](std::size_t k) { inner[c * 8 + k].fetch_add(1); };
    runChunks(8, 2, work);  // the team is busy with the outer loop
  };
  runChunks(8, 2, outer);
  for (const auto& n : inner) EXPECT_EQ(n.load(), 1);
}

TEST(WorkTeam, LoopsFromTwoThreadsAtOnceEachRunEveryChunk) {
  auto caller = [](std::vector<int>& counts) {
    for (int loop = 0; loop < 200; ++loop) {
      std::vector<std::atomic<int>> runs(32);
      auto work = [&](std::size_t c) {
        spin(c);
        runs[c].fetch_add(1);
      };
      runChunks(runs.size(), 2, work);
      for (const auto& r : runs) counts.push_back(r.load());
    }
  };
  std::vector<int> a, b;
  std::thread other([&] { caller(b); });
  caller(a);
  other.join();
  for (int n : a) ASSERT_EQ(n, 1);
  for (int n : b) ASSERT_EQ(n, 1);
}

TEST(WorkTeam, ParallelForCoversEveryIndexOnce) {
  for (std::size_t n : {0u, 1u, 2u, 5u, 255u, 256u, 10007u}) {
    for (int threads : {1, 2, 3}) {
      std::vector<int> hits(n, 0);
      parallelFor(n, threads, [&](std::size_t i) { ++hits[i]; });  // one writer an index
      for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(hits[i], 1) << n << " items, index " << i;
    }
  }
}

}  // namespace
}  // namespace tribo::contact
