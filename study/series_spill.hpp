// A column of doubles too long to keep in memory, kept in an unlinked file instead: append
// while a run records, read back by index afterwards (a SampleSeries for the oscillation
// analysis, study/oscillation_summary.hpp). The file is created in a chosen folder and
// unlinked at once, so it never shows in the folder and vanishes with the process, however
// that ends. Reads go through a small cache of 64 KiB pages (4 of them), so memory stays
// about 300 KiB whatever the length. Not thread-safe. Not here: what the column holds.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <vector>

#include "study/oscillation_summary.hpp"

namespace tribo::study {

class SpilledColumn : public SampleSeries {
 public:
  // Creates the file in `dir` (the system's temporary folder when empty). Throws
  // std::runtime_error naming the folder when it cannot.
  explicit SpilledColumn(const std::filesystem::path& dir = {});
  ~SpilledColumn() override;
  SpilledColumn(const SpilledColumn&) = delete;
  SpilledColumn& operator=(const SpilledColumn&) = delete;

  // Throws std::runtime_error when the file cannot be written (e.g. the disk is full).
  void append(double v);

  std::size_t size() const override { return size_; }
  // Sample i < size(). Throws std::runtime_error when the file cannot be read.
  double at(std::size_t i) const override;

 private:
  static constexpr std::size_t kPage = 8192;  // doubles per page (64 KiB)
  static constexpr std::size_t kSlots = 4;
  void flush();

  int fd_ = -1;
  std::filesystem::path dir_;
  std::size_t size_ = 0, flushed_ = 0;  // samples in all, samples in the file
  std::vector<double> pending_;         // appended, not yet in the file
  mutable std::array<std::vector<double>, kSlots> pages_;
  mutable std::array<std::size_t, kSlots> page_of_slot_;
};

}  // namespace tribo::study
