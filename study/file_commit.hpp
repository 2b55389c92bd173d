// Result files appear whole or not at all: each is written under a temporary name beside
// its final one and renamed when complete, so a reader (or a sweep resumed after a kill)
// never sees a half-written file under the final name. One process writing a folder uses
// NAME.partial; several processes writing one folder at once (sweep slices, on one machine
// or several sharing the folder) use a temporary name unique to the host, process and call,
// and a file meant to be written once is created by link(2), which fails atomically when
// the name exists (also on NFS), so the first writer wins.
// Not here: what goes into the files (study/result_writer.hpp,
// study/sweep/sweep_results.hpp, study/tradeoff.hpp); removing the temporary files of a
// killed process (they start with '.' and end in .partial).
#pragma once

#include <filesystem>
#include <string>

namespace tribo::study {

// The temporary name a file is written under before commitFile.
std::filesystem::path partialPath(const std::filesystem::path& file);
// Renames partialPath(file) to file; throws std::runtime_error naming the file on failure.
void commitFile(const std::filesystem::path& file);
// Writes `text` to partialPath(file), then commits it; creates the parent folder if missing.
// Throws std::runtime_error naming the path on any failure.
void writeFileWhole(const std::filesystem::path& file, const std::string& text);

// A temporary name beside `file` no other process or call uses:
// .NAME.HOST.PID.N.partial.
std::filesystem::path uniquePartialPath(const std::filesystem::path& file);
// Writes `text` under uniquePartialPath(file) and renames it to `file`, replacing a file of
// that name: safe while other processes write or read the same folder (or the same file).
// The parent folder must exist. Throws std::runtime_error naming the path on any failure.
void replaceFileWhole(const std::filesystem::path& file, const std::string& text);
// Creates `file` holding `text` unless a file of that name exists: written under
// uniquePartialPath(file), then linked to `file` and the temporary removed. Returns true
// when this call created `file`, false when it was there already (its content may differ:
// the caller compares). The parent folder must exist. Throws std::runtime_error naming the
// path on any failure (also a file system without hard links).
bool createFileOnce(const std::filesystem::path& file, const std::string& text);

}  // namespace tribo::study
