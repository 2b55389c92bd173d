#include "study/file_commit.hpp"

#include <fstream>
#include <stdexcept>

namespace tribo::study {

std::filesystem::path partialPath(const std::filesystem::path& file) {
  return file.string() + ".partial";
}

void commitFile(const std::filesystem::path& file) {
  std::error_code ec;
  std::filesystem::rename(partialPath(file), file, ec);
  if (ec) throw std::runtime_error("cannot write '" + file.string() + "': " + ec.message());
}

void writeFileWhole(const std::filesystem::path& file, const std::string& text) {
  std::error_code ec;
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ec);
  const std::filesystem::path tmp = partialPath(file);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) throw std::runtime_error("cannot write '" + tmp.string() + "'");
  }
  commitFile(file);
}

}  // namespace tribo::study
