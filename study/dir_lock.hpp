// A lock on an output folder, so two tribo processes never write the same folder at once:
// flock(2) on DIR/.lock, taken without waiting and released when the
// DirLock is destroyed or the process ends (also when it is killed), so a stale lock never
// outlives its holder. The .lock file itself stays (empty). A run or a one-process sweep
// takes it exclusive; the slices of a sweep (tribo sweep --slice), which write a folder
// together, take it shared, so they keep out, and are kept out by, an exclusive holder. Not here:
// what the folder holds (study/result_writer.hpp, study/sweep/sweep_results.hpp); locks across
// machines (flock on NFS is advisory at best).
#pragma once

#include <filesystem>
#include <stdexcept>

namespace tribo::study {

// The folder's lock is held by another process (what() names the folder).
class DirLockedError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class DirLock {
 public:
  enum class Mode { kExclusive, kShared };
  // Locks `dir` (which must exist). Throws DirLockedError when another process holds the
  // lock (exclusive; or at all, for kExclusive), std::runtime_error naming the lock file when
  // it cannot be opened.
  explicit DirLock(const std::filesystem::path& dir, Mode mode = Mode::kExclusive);
  ~DirLock();
  DirLock(const DirLock&) = delete;
  DirLock& operator=(const DirLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace tribo::study
