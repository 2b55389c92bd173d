#include "study/dir_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace tribo::study {

DirLock::DirLock(const std::filesystem::path& dir, Mode mode) {
  const std::filesystem::path lock = dir / ".lock";
  fd_ = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw std::runtime_error("cannot open '" + lock.string() + "'");
  if (::flock(fd_, (mode == Mode::kShared ? LOCK_SH : LOCK_EX) | LOCK_NB) != 0) {
    ::close(fd_);
    fd_ = -1;
    throw DirLockedError("'" + dir.string() + "' is in use by another tribo run or sweep (" +
                         lock.string() + " is locked)");
  }
}

DirLock::~DirLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the flock
}

}  // namespace tribo::study
