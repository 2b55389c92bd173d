// Result files appear whole or not at all: each is written under a temporary name beside
// its final one (NAME.partial) and renamed when complete, so a reader (or a sweep resumed
// after a kill) never sees a half-written file under the final name. Not here: what goes
// into the files (study/result_writer.hpp, study/sweep/sweep_results.hpp, study/tradeoff.hpp).
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

}  // namespace tribo::study
