#include "study/run_progress.hpp"

#include <unistd.h>

namespace tribo::study {

std::string clockText(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  char buf[32];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  return buf;
}

RunProgress::RunProgress(std::FILE* out, double duration)
    : out_(out), duration_(duration), start_(std::chrono::steady_clock::now()), last_line_(start_) {
  terminal_ = out_ && ::isatty(::fileno(out_));
}

void RunProgress::update(double simulated) {
  if (!out_) return;
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (elapsed < kDelay) return;
  if (!terminal_ && std::chrono::duration<double>(now - last_line_).count() < kDelay) return;
  last_line_ = now;
  const double rate = simulated / elapsed;
  const std::string left = rate > 0 ? clockText((duration_ - simulated) / rate) : "?";
  std::fprintf(out_, "%srun  %.6g of %.6g simulated s (%.0f%%)  %.4g s/s  %s elapsed  %s left%s",
               terminal_ ? "\r" : "", simulated, duration_, 100 * simulated / duration_, rate,
               clockText(elapsed).c_str(), left.c_str(), terminal_ ? "\033[K" : "\n");
  std::fflush(out_);
  drawn_ = true;
}

void RunProgress::finish() {
  if (out_ && terminal_ && drawn_) std::fputs("\r\033[K", out_);
  drawn_ = false;
}

}  // namespace tribo::study
