// A guard on the time one FCL query may take. libccd 2.1's MPR, which FCL 0.7 uses for
// convex/convex and mesh/shape pairs, refines its portal until it converges and has no
// iteration limit (FCL's `max_iterations` reaches only libccd's GJK), so a degenerate pair
// can loop for ever inside a call that cannot be interrupted. The load-time limits
// (contact::kMaxLength, the convex mesh checks of contact/mesh_shape.hpp) keep every known
// case out; this is the net beneath them: a thread that wakes a few times per limit and,
// when one query has run longer than the limit, calls the overrun handler with the pair's
// geometries (-1, -1 for the broadphase) and the time it has run.
// The handler must not return: the query still holds its thread, so the process has to end
// (core/dynamics.cpp names the geometries and bodies, then exits with status 7). A handler
// that returns is called again at the next wake. begin() and end() are two clock reads and
// a few atomic stores: no lock, no allocation.
// Not here: what a query does (contact/collision_detector.cpp), iteration budgets inside
// FCL or libccd (neither offers one for MPR).
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>

namespace tribo::contact {

class QueryWatchdog {
 public:
  using OverrunHandler = std::function<void(int geometry_a, int geometry_b, double seconds)>;

  // Watches `lanes` lanes (one per narrowphase thread) against `limit_seconds` (finite,
  // > 0; else std::invalid_argument).
  QueryWatchdog(double limit_seconds, OverrunHandler on_overrun, int lanes);
  ~QueryWatchdog();  // stops and joins the thread
  QueryWatchdog(const QueryWatchdog&) = delete;
  QueryWatchdog& operator=(const QueryWatchdog&) = delete;

  // More lanes (never fewer); call only while no query is in flight.
  void reserveLanes(int lanes);
  // A query on `lane` between geometries a and b starts / ends.
  void begin(int lane, int a, int b) noexcept;
  void end(int lane) noexcept;

  double limitSeconds() const { return limit_; }

 private:
  struct Slot {
    std::atomic<std::int64_t> since_ns{0};  // steady clock at begin(); 0: no query
    std::atomic<int> a{-1}, b{-1};
  };
  void watch();

  double limit_;
  OverrunHandler on_overrun_;
  std::mutex mutex_;  // guards slots_ against reserveLanes, and the stop flag
  std::condition_variable wake_;
  bool stop_ = false;
  std::unique_ptr<Slot[]> slots_;
  int lane_count_ = 0;
  std::thread thread_;
};

}  // namespace tribo::contact
