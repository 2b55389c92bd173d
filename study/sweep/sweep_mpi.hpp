// A sweep spread over the ranks of an MPI job (`mpirun -n N tribo sweep ...`); built only
// with TRIBO_WITH_MPI. Rank 0 reads the scene and sends its text to every rank (so all run
// the same scene, with or without a shared file system), owns the output folder, the
// progress line and the queue of points. Every rank runs points on its own threads; the
// others ask rank 0 for points as their threads fall idle and send each finished row back,
// which rank 0 appends to DIR/results.csv at once. Handing out points on demand balances
// points of very different cost. Only the main thread of a rank calls MPI
// (MPI_THREAD_FUNNELED); it polls with short sleeps, so an idle rank costs no core.
// An interrupted job resumes like a local sweep; ranks may differ in number between runs.
// Not here: the points themselves (study/sweep/sweep_runner.hpp), argument parsing.
#pragma once

#include <cstdio>
#include <filesystem>

#include "study/sweep/sweep_runner.hpp"

namespace tribo::study {

// MPI_Init_thread / MPI_Finalize for the life of the object.
class MpiSession {
 public:
  MpiSession(int* argc, char*** argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  int ranksOnThisNode() const { return node_size_; }

 private:
  int rank_ = 0, size_ = 1, node_size_ = 1;
};

// Runs the sweep over all ranks with `jobs` threads each (0: the node's cores shared among
// its ranks). Rank 0 returns the full report; other ranks return theirs (points run here).
// A failure to plan or to open the folder on rank 0 is thrown on every rank with rank 0's
// message, as SceneError, SweepSpecError or SweepOutputError.
SweepReport runSweepDistributed(const MpiSession& mpi, const SweepSpec& spec,
                                const std::filesystem::path& out, unsigned jobs,
                                std::FILE* progress);

}  // namespace tribo::study
