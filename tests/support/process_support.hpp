// Runs the `tribo` binary as a child process the test can signal while it works: spawn with
// stdout and stderr to files, poll for a file or an output text, send a signal, and wait
// for the exit status, watching the child's peak resident memory on the way (VmHWM of
// /proc/PID/status, polled every 5 ms: rusage's ru_maxrss would not do, since a spawned
// child starts with its parent's high-water mark, here the test's own). Not here:
// expectations; tests/support/cli_support.hpp runs a command to its end through a shell.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace tribo::test {

struct Child {
  pid_t pid = -1;
  std::filesystem::path out, err;  // its stdout and stderr
};

struct Exit {
  int status = -1;       // exit status, -1 when killed by a signal
  int signal = 0;        // the signal that killed it, 0 when it exited
  long max_rss_kib = 0;  // peak resident set [KiB]
};

// Starts `binary args...` with stdout/stderr into files `io_prefix`.out/.err.
inline Child spawnChild(const std::string& binary, const std::vector<std::string>& args,
                        const std::filesystem::path& io_prefix) {
  Child c;
  c.out = io_prefix.string() + ".out";
  c.err = io_prefix.string() + ".err";
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, c.out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&fa, 2, c.err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(binary.c_str()));
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  if (posix_spawn(&c.pid, binary.c_str(), &fa, nullptr, argv.data(), environ) != 0) c.pid = -1;
  posix_spawn_file_actions_destroy(&fa);
  return c;
}

// Polls `ready` every 20 ms for up to `timeout`; true once it holds.
inline bool waitUntil(const std::function<bool()>& ready, std::chrono::duration<double> timeout) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < end) {
    if (ready()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return ready();
}

// The child's high-water resident set [KiB], 0 once it has exited.
inline long residentHighWater(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::strtol(line.c_str() + 6, nullptr, 10);
  return 0;
}

inline Exit waitChild(const Child& c) {
  Exit e;
  int raw = 0;
  for (;;) {
    e.max_rss_kib = std::max(e.max_rss_kib, residentHighWater(c.pid));
    const pid_t done = ::waitpid(c.pid, &raw, WNOHANG);
    if (done == c.pid) break;
    if (done < 0) return e;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (WIFEXITED(raw)) e.status = WEXITSTATUS(raw);
  if (WIFSIGNALED(raw)) e.signal = WTERMSIG(raw);
  return e;
}

}  // namespace tribo::test
