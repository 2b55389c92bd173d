#include "contact/query_watchdog.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace tribo::contact {

namespace {

std::int64_t nowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace

QueryWatchdog::QueryWatchdog(double limit_seconds, OverrunHandler on_overrun, int lanes)
    : limit_(limit_seconds), on_overrun_(std::move(on_overrun)) {
  if (!(limit_seconds > 0.0) || !std::isfinite(limit_seconds) || !on_overrun_)
    throw std::invalid_argument(
        "query watchdog: the limit must be finite and > 0 s, and a handler given");
  reserveLanes(std::max(1, lanes));
  thread_ = std::thread([this] { watch(); });
}

QueryWatchdog::~QueryWatchdog() {
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void QueryWatchdog::reserveLanes(int lanes) {
  const std::lock_guard lock(mutex_);
  if (lanes <= lane_count_) return;
  auto grown = std::make_unique<Slot[]>(static_cast<std::size_t>(lanes));
  slots_ = std::move(grown);  // no query is in flight: the old slots are all idle
  lane_count_ = lanes;
}

void QueryWatchdog::begin(int lane, int a, int b) noexcept {
  Slot& s = slots_[static_cast<std::size_t>(lane)];
  s.a.store(a, std::memory_order_relaxed);
  s.b.store(b, std::memory_order_relaxed);
  s.since_ns.store(nowNs(), std::memory_order_release);
}

void QueryWatchdog::end(int lane) noexcept {
  slots_[static_cast<std::size_t>(lane)].since_ns.store(0, std::memory_order_release);
}

void QueryWatchdog::watch() {
  // Four looks per limit, at most one a second: an overrun is seen within 1.25 limits.
  const auto period = std::chrono::duration<double>(std::min(limit_ / 4.0, 1.0));
  const auto limit_ns = static_cast<std::int64_t>(limit_ * 1e9);
  std::unique_lock lock(mutex_);
  while (!wake_.wait_for(lock, period, [this] { return stop_; })) {
    const std::int64_t now = nowNs();
    for (int i = 0; i < lane_count_; ++i) {
      const Slot& s = slots_[static_cast<std::size_t>(i)];
      const std::int64_t since = s.since_ns.load(std::memory_order_acquire);
      if (since == 0 || now - since <= limit_ns) continue;
      const int a = s.a.load(std::memory_order_relaxed);
      const int b = s.b.load(std::memory_order_relaxed);
      on_overrun_(a, b, static_cast<double>(now - since) * 1e-9);
    }
  }
}

}  // namespace tribo::contact
