#include "study/series_spill.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace tribo::study {

SpilledColumn::SpilledColumn(const std::filesystem::path& dir)
    : dir_(dir.empty() ? std::filesystem::temp_directory_path() : dir) {
  std::string name = (dir_ / ".spill-XXXXXX").string();
  fd_ = ::mkostemp(name.data(), O_CLOEXEC);
  if (fd_ < 0)
    throw std::runtime_error("cannot create a scratch file in '" + dir_.string() +
                             "': " + std::strerror(errno));
  ::unlink(name.c_str());
  pending_.reserve(kPage);
  page_of_slot_.fill(std::numeric_limits<std::size_t>::max());
}

SpilledColumn::~SpilledColumn() {
  if (fd_ >= 0) ::close(fd_);
}

void SpilledColumn::flush() {
  const auto* bytes = reinterpret_cast<const char*>(pending_.data());
  std::size_t left = pending_.size() * sizeof(double);
  off_t at = static_cast<off_t>(flushed_ * sizeof(double));
  while (left > 0) {
    const ssize_t n = ::pwrite(fd_, bytes, left, at);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      throw std::runtime_error("cannot write a scratch file in '" + dir_.string() +
                               "': " + std::strerror(n < 0 ? errno : ENOSPC));
    bytes += n;
    at += n;
    left -= static_cast<std::size_t>(n);
  }
  flushed_ += pending_.size();
  pending_.clear();
}

void SpilledColumn::append(double v) {
  pending_.push_back(v);
  ++size_;
  if (pending_.size() == kPage) flush();
}

double SpilledColumn::at(std::size_t i) const {
  if (i >= flushed_) return pending_[i - flushed_];
  const std::size_t page = i / kPage;
  const std::size_t slot = page % kSlots;
  std::vector<double>& p = pages_[slot];
  if (page_of_slot_[slot] != page) {
    const std::size_t count = std::min(kPage, flushed_ - page * kPage);
    p.resize(count);
    auto* bytes = reinterpret_cast<char*>(p.data());
    std::size_t left = count * sizeof(double);
    off_t at = static_cast<off_t>(page * kPage * sizeof(double));
    while (left > 0) {
      const ssize_t n = ::pread(fd_, bytes, left, at);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        page_of_slot_[slot] = std::numeric_limits<std::size_t>::max();
        throw std::runtime_error("cannot read back a scratch file in '" + dir_.string() + "'");
      }
      bytes += n;
      at += n;
      left -= static_cast<std::size_t>(n);
    }
    page_of_slot_[slot] = page;
  }
  return p[i - page * kPage];
}

}  // namespace tribo::study
