// Will a run's output fit? Checked before a run starts, so a duration or output rate whose
// trajectory could never be stored is an error naming the keys, not a crash or a full disk
// hours later. Estimates, from the scene alone:
//   rows    = duration / max(output.interval, time_step) + 2
//   columns = 1 + 8 per body (study/trajectory_recorder.hpp)
//   on disk (a streamed run): rows * (columns * kCsvBytesPerField + kSpillBytesPerRow),
//           against the free space of the output folder (std::filesystem::space)
//   in memory (a run that keeps its rows: sweeps, the tradeoff): rows * columns * 8 bytes,
//           against kMaxKeptBytes
// The CSV figure is an upper bound (every field at its longest); the check errs on the
// side of refusing a run that would have just fitted. Not here: writing (study/result_writer.hpp).
#pragma once

#include <cstddef>
#include <filesystem>
#include <stdexcept>

#include "io/scene_loader.hpp"

namespace tribo::study {

// The longest number a trajectory field takes ("-1.234567891e-308": 10 significant digits)
// and its comma.
inline constexpr double kCsvBytesPerField = 18;
// The summary's three columns spilled beside the output while a streamed run goes.
inline constexpr double kSpillBytesPerRow = 24;
// The most a run may keep in memory: 2 GiB (a sweep runs one such run per core).
inline constexpr double kMaxKeptBytes = 2.0 * (1ull << 30);

// The output would not fit: what() names output.interval and duration, the estimate and
// the limit.
class OutputTooLarge : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct OutputEstimate {
  double rows = 0, columns = 0;
  double csv_bytes = 0;   // trajectory.csv plus the summary's spill
  double kept_bytes = 0;  // the rows kept in memory
};

OutputEstimate estimateOutput(const io::Scene& scene);

// Throws OutputTooLarge when a streamed run's files would not fit the free space of `dir`
// (or of its nearest existing parent when it does not exist yet).
void checkOutputFitsDisk(const io::Scene& scene, const std::filesystem::path& dir);
// Throws OutputTooLarge when a run keeping its rows would hold more than kMaxKeptBytes.
void checkOutputFitsMemory(const io::Scene& scene);

}  // namespace tribo::study
