#include "study/sweep/sweep_mpi.hpp"

#include <mpi.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstring>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include "io/scene_parameters.hpp"
#include "study/sweep/sweep_progress.hpp"
#include "study/sweep/sweep_results.hpp"

namespace tribo::study {

namespace fs = std::filesystem;

namespace {

enum Tag : int { kRequest = 1, kAssign = 2, kResult = 3, kDone = 4 };
// What failed on rank 0; kOutput + Reason for a SweepOutputError.
enum Failure : int { kNone = 0, kScene = 1, kSpec = 2, kOther = 3, kOutput = 4 };

constexpr auto kIdle = std::chrono::milliseconds(1);

void broadcastString(std::string& s, int root) {
  unsigned long long n = s.size();
  MPI_Bcast(&n, 1, MPI_UNSIGNED_LONG_LONG, root, MPI_COMM_WORLD);
  s.resize(n);
  if (n) MPI_Bcast(s.data(), static_cast<int>(n), MPI_CHAR, root, MPI_COMM_WORLD);
}

// Rank 0's outcome of a step every rank must agree on; rethrown everywhere on failure.
void agree(int failure, std::string message) {
  MPI_Bcast(&failure, 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (failure == kNone) return;
  broadcastString(message, 0);
  if (failure == kScene) throw io::SceneError(message);
  if (failure == kSpec) throw SweepSpecError(message);
  if (failure == kOther) throw std::runtime_error(message);
  throw SweepOutputError(static_cast<SweepOutputError::Reason>(failure - kOutput), message);
}

int failureOf(const std::exception& e) {
  if (dynamic_cast<const io::SceneError*>(&e)) return kScene;
  if (dynamic_cast<const SweepSpecError*>(&e)) return kSpec;
  if (const auto* o = dynamic_cast<const SweepOutputError*>(&e))
    return kOutput + static_cast<int>(o->reason());
  return kOther;
}

std::string encode(const FinishedPoint& p) {
  std::string b(sizeof(std::uint64_t) + 2, '\0');
  const std::uint64_t index = p.index;
  std::memcpy(b.data(), &index, sizeof index);
  b[sizeof index] = p.failed ? 1 : 0;
  b[sizeof index + 1] = p.unsettled ? 1 : 0;
  return b + p.line;
}

FinishedPoint decode(const std::vector<char>& b) {
  FinishedPoint p;
  std::uint64_t index = 0;
  std::memcpy(&index, b.data(), sizeof index);
  p.index = index;
  p.failed = b[sizeof index] != 0;
  p.unsettled = b[sizeof index + 1] != 0;
  p.line.assign(b.begin() + sizeof index + 2, b.end());
  return p;
}

// Rank 0: serves the queue to its own threads and to the other ranks, writes every row.
SweepReport serve(const MpiSession& mpi, const SweepPlan& plan, const fs::path& out, unsigned jobs,
                  std::FILE* progress_out, SweepResultsFile& results) {
  SweepReport report;
  report.points = plan.grid.size();
  report.resumed = results.doneCount();
  report.dropped = results.droppedLines();
  const std::vector<std::size_t> not_done = results.pendingPoints();
  std::deque<std::size_t> pending(not_done.begin(), not_done.end());
  std::mutex mutex;  // guards pending, report, results' order, progress
  SweepProgress progress(progress_out, report.points, report.resumed);
  std::string write_error;  // the first failure to append; ends the job
  auto record = [&](const FinishedPoint& p) {
    std::lock_guard lock(mutex);
    if (!write_error.empty()) return;
    try {
      results.append(p.index, p.line);
    } catch (const SweepOutputError& e) {
      write_error = e.what();
      pending.clear();
      return;
    }
    ++report.ran;
    report.failed += p.failed;
    report.unsettled += p.unsettled;
    progress.pointDone(p.failed);
  };
  std::atomic<bool> local_finished{false};
  std::thread local([&] {
    runPointsOnThreads(
        plan, out, jobs,
        [&]() -> std::optional<std::size_t> {
          std::lock_guard lock(mutex);
          if (pending.empty()) return std::nullopt;
          const std::size_t i = pending.front();
          pending.pop_front();
          return i;
        },
        record);
    local_finished = true;
  });

  int remote_active = mpi.size() - 1;
  std::vector<char> buffer;
  while (remote_active > 0 || !local_finished) {
    {
      std::lock_guard lock(mutex);
      if (!write_error.empty()) {
        std::fprintf(stderr, "tribo: %s\n", write_error.c_str());
        std::fflush(stderr);
        MPI_Abort(MPI_COMM_WORLD, 4);
      }
    }
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
    if (!flag) {
      std::this_thread::sleep_for(kIdle);
      continue;
    }
    int count = 0;
    MPI_Get_count(&status, MPI_CHAR, &count);
    buffer.resize(static_cast<std::size_t>(count));
    MPI_Recv(buffer.data(), count, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    if (status.MPI_TAG == kRequest) {
      std::uint32_t wanted = 0;
      std::memcpy(&wanted, buffer.data(), sizeof wanted);
      std::vector<std::uint64_t> given;
      {
        std::lock_guard lock(mutex);
        while (given.size() < wanted && !pending.empty()) {
          given.push_back(pending.front());
          pending.pop_front();
        }
      }
      MPI_Send(given.data(), static_cast<int>(given.size()), MPI_UINT64_T, status.MPI_SOURCE,
               kAssign, MPI_COMM_WORLD);
    } else if (status.MPI_TAG == kResult) {
      record(decode(buffer));
    } else if (status.MPI_TAG == kDone) {
      --remote_active;
    }
  }
  local.join();
  report.complete = results.doneCount() == plan.grid.size();
  if (report.complete) results.finish();
  progress.finish();
  return report;
}

// Other ranks: ask rank 0 for points as threads fall idle, send every row back.
SweepReport work(const SweepPlan& plan, const fs::path& out, unsigned jobs) {
  SweepReport report;
  std::mutex mutex;
  std::condition_variable wake;
  std::deque<std::size_t> assigned;
  std::deque<FinishedPoint> outbox;
  unsigned waiting = 0;  // threads waiting for a point
  bool no_more = false;
  std::atomic<bool> threads_finished{false};
  std::thread local([&] {
    runPointsOnThreads(
        plan, out, jobs,
        [&]() -> std::optional<std::size_t> {
          std::unique_lock lock(mutex);
          ++waiting;
          wake.wait(lock, [&] { return !assigned.empty() || no_more; });
          --waiting;
          if (assigned.empty()) return std::nullopt;
          const std::size_t i = assigned.front();
          assigned.pop_front();
          return i;
        },
        [&](const FinishedPoint& p) {
          std::lock_guard lock(mutex);
          outbox.push_back(p);
        });
    threads_finished = true;
  });

  std::deque<std::uint32_t> asks;  // requests not yet answered, oldest first
  std::uint32_t requested = 0;     // points they ask for
  std::vector<std::uint64_t> given;
  for (;;) {
    bool busy = false;
    std::deque<FinishedPoint> sending;
    std::uint32_t ask = 0;
    {
      std::lock_guard lock(mutex);
      sending.swap(outbox);
      if (!no_more && waiting > assigned.size() + requested)
        ask = static_cast<std::uint32_t>(waiting - assigned.size() - requested);
    }
    for (const auto& p : sending) {
      const std::string bytes = encode(p);
      MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_CHAR, 0, kResult, MPI_COMM_WORLD);
      ++report.ran;
      report.failed += p.failed;
      report.unsettled += p.unsettled;
      busy = true;
    }
    if (ask > 0) {
      MPI_Send(&ask, sizeof ask, MPI_CHAR, 0, kRequest, MPI_COMM_WORLD);
      requested += ask;
      asks.push_back(ask);
      busy = true;
    }
    if (!asks.empty()) {
      int flag = 0;
      MPI_Status status;
      MPI_Iprobe(0, kAssign, MPI_COMM_WORLD, &flag, &status);
      if (flag) {
        int count = 0;
        MPI_Get_count(&status, MPI_UINT64_T, &count);
        given.resize(static_cast<std::size_t>(count));
        MPI_Recv(given.data(), count, MPI_UINT64_T, 0, kAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        // Replies come in request order; an empty one means rank 0 has no more points.
        std::lock_guard lock(mutex);
        for (const auto i : given) assigned.push_back(static_cast<std::size_t>(i));
        requested -= asks.front();
        asks.pop_front();
        if (given.empty()) no_more = true;
        wake.notify_all();
        busy = true;
      }
    }
    if (threads_finished && asks.empty()) {
      std::lock_guard lock(mutex);
      if (outbox.empty()) break;
    }
    if (!busy) std::this_thread::sleep_for(kIdle);
  }
  local.join();
  MPI_Send(nullptr, 0, MPI_CHAR, 0, kDone, MPI_COMM_WORLD);
  return report;
}

}  // namespace

MpiSession::MpiSession(int* argc, char*** argv) {
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node);
  MPI_Comm_size(node, &node_size_);
  MPI_Comm_free(&node);
}

MpiSession::~MpiSession() { MPI_Finalize(); }

SweepReport runSweepDistributed(const MpiSession& mpi, const SweepSpec& spec, const fs::path& out,
                                unsigned jobs, std::FILE* progress) {
  const auto start = std::chrono::steady_clock::now();
  if (jobs == 0) jobs = defaultJobs(static_cast<unsigned>(mpi.ranksOnThisNode()));
  // Rank 0 reads the scene; everybody plans from the same text.
  std::string text;
  int failure = kNone;
  std::string message;
  if (mpi.rank() == 0) {
    try {
      text = readSceneText(spec.scene_path);
    } catch (const std::exception& e) {
      failure = failureOf(e);
      message = e.what();
    }
  }
  agree(failure, message);
  broadcastString(text, 0);
  std::optional<SweepPlan> plan;
  std::optional<SweepResultsFile> results;
  if (mpi.rank() == 0) {
    try {
      plan.emplace(planSweep(spec, text));
      results.emplace(out, plan->manifest, plan->grid, plan->setup.analysis);
    } catch (const std::exception& e) {
      failure = failureOf(e);
      message = e.what();
    }
  }
  agree(failure, message);
  if (mpi.rank() != 0) plan.emplace(planSweep(spec, text));

  SweepReport report =
      mpi.rank() == 0 ? serve(mpi, *plan, out, jobs, progress, *results) : work(*plan, out, jobs);
  report.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace tribo::study
