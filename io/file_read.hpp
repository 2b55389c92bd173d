// Bounded reads of the files a user hands Tribo (scenes, URDF, meshes, friction curves, run
// and sweep folders for `tribo view`): a file is checked with stat before it is opened, so a
// FIFO, a device (/dev/zero), a directory or a file over its kind's size limit is refused
// with an error naming the file, what it is or its size, and the limit; then at most the
// limit is read, whatever the file does meanwhile. Not here: parsing, and what the callers'
// typed errors are (each caller turns FileReadError into its own).
#pragma once

#include <cstdint>
#include <filesystem>
#include <istream>
#include <stdexcept>
#include <string>

namespace tribo::io {

// Size limits per kind of file [bytes], each hundreds of times the largest real file of its
// kind measured: scene YAML 56 kB (scenes/box_grid20*.yaml, 400 bodies), URDF 37 kB
// (hyq_no_sensors.urdf of ../shared/urdf), mesh 433 kB (hyq's trunk.dae; 2 million triangles
// of binary STL would be 100 MB), friction curves a few kB. Each is read whole into memory,
// so the limit also bounds what a hostile file can allocate. `tribo view` streams a
// trajectory: its lines, not its size, are bounded (kMaxCsvLineBytes).
inline constexpr std::uintmax_t kMiB = 1024 * 1024;
inline constexpr std::uintmax_t kMaxSceneBytes = 16 * kMiB;
inline constexpr std::uintmax_t kMaxUrdfBytes = 64 * kMiB;
inline constexpr std::uintmax_t kMaxMeshBytes = 256 * kMiB;
inline constexpr std::uintmax_t kMaxTableBytes = 64 * kMiB;  // friction curves, sweep results
inline constexpr std::uintmax_t kMaxJsonBytes = 64 * kMiB;   // summary.json, sweep.json
// A sweep's results.csv, read whole to resume or view it (10 million points of 100 bytes).
inline constexpr std::uintmax_t kMaxSweepResultsBytes = 1024 * kMiB;
// The longest line of a CSV file `tribo view` streams (a trajectory of 100,000 bodies has
// lines of 15 MB).
inline constexpr std::size_t kMaxCsvLineBytes = 64 * kMiB;

// "WHAT 'PATH': ..." for a file that is not a regular file, cannot be read, or is larger
// than its limit; "cannot open WHAT 'PATH' (why)" for one that is not there.
class FileReadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws FileReadError unless `path` (symbolic links followed) is a regular file of at most
// `limit` bytes; returns its size. `what` names the kind in the message ("scene file").
std::uintmax_t checkReadableFile(const std::filesystem::path& path, const std::string& what,
                                 std::uintmax_t limit);

// The whole file after checkReadableFile; throws FileReadError when it cannot be read or has
// grown past `limit` meanwhile.
std::string readFileBounded(const std::filesystem::path& path, const std::string& what,
                            std::uintmax_t limit);

// std::getline that reads at most `max` characters of a line: false at the end of the
// stream, throws FileReadError naming `path` on a longer line.
bool getLineBounded(std::istream& in, std::string& line, std::size_t max,
                    const std::filesystem::path& path);

}  // namespace tribo::io
