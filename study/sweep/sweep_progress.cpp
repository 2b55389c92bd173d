#include "study/sweep/sweep_progress.hpp"

#include <unistd.h>

#include <string>

#include "study/run_progress.hpp"

namespace tribo::study {

SweepProgress::SweepProgress(std::FILE* out, std::size_t total, std::size_t already_done)
    : out_(out),
      total_(total),
      done_(already_done),
      done_at_start_(already_done),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {
  terminal_ = out_ && ::isatty(::fileno(out_));
  render(true);
}

void SweepProgress::pointDone(bool failed) {
  std::lock_guard lock(mutex_);
  ++done_;
  if (failed) ++failed_;
  render(false);
}

void SweepProgress::finish() {
  std::lock_guard lock(mutex_);
  if (finished_) return;
  render(true);
  if (out_ && terminal_) std::fputc('\n', out_);
  finished_ = true;
}

void SweepProgress::render(bool force) {
  if (!out_ || finished_) return;
  const auto now = std::chrono::steady_clock::now();
  const int tenth = total_ ? static_cast<int>(10 * done_ / total_) : 10;
  if (!force) {
    if (terminal_ && now - last_draw_ < std::chrono::milliseconds(100) && done_ < total_) return;
    if (!terminal_ && tenth == last_tenth_) return;
  }
  last_draw_ = now;
  last_tenth_ = tenth;
  constexpr int kWidth = 20;
  const double share = total_ ? static_cast<double>(done_) / total_ : 1.0;
  const int filled = static_cast<int>(share * kWidth);
  const std::string bar = std::string(filled, '#') + std::string(kWidth - filled, '-');
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const std::size_t ran = done_ - done_at_start_;
  char rate[64] = "";
  char left[64] = "";
  if (ran > 0 && elapsed > 0) {
    const double r = ran / elapsed;
    std::snprintf(rate, sizeof rate, "  %.3g points/s", r);
    std::snprintf(left, sizeof left, "  %s left", clockText((total_ - done_) / r).c_str());
  }
  char failed[48] = "";
  if (failed_) std::snprintf(failed, sizeof failed, "  %zu failed", failed_);
  std::fprintf(out_, "%ssweep [%s] %4zu/%zu %3d%%%s%s  %s elapsed%s%s", terminal_ ? "\r" : "",
               bar.c_str(), done_, total_, static_cast<int>(100 * share), rate, left,
               clockText(elapsed).c_str(), failed, terminal_ ? "\033[K" : "\n");
  std::fflush(out_);
}

}  // namespace tribo::study
