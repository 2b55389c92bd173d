#include "study/file_commit.hpp"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace tribo::study {

namespace {

void writeTo(const std::filesystem::path& tmp, const std::string& text) {
  std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
  out << text;
  out.flush();
  if (!out) {
    out.close();
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw std::runtime_error("cannot write '" + tmp.string() + "'");
  }
}

std::string hostName() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return "host";
  std::string s(name);
  for (char& c : s)
    if (c == '/' || c == '.') c = '_';
  return s.empty() ? "host" : s;
}

}  // namespace

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
  writeTo(partialPath(file), text);
  commitFile(file);
}

std::filesystem::path uniquePartialPath(const std::filesystem::path& file) {
  static const std::string host = hostName();
  static std::atomic<unsigned long long> counter{0};
  std::string name(".");
  name += file.filename().string();
  for (const std::string& part :
       {host, std::to_string(::getpid()), std::to_string(counter++), std::string("partial")}) {
    name += '.';
    name += part;
  }
  return file.parent_path() / name;
}

void replaceFileWhole(const std::filesystem::path& file, const std::string& text) {
  const std::filesystem::path tmp = uniquePartialPath(file);
  writeTo(tmp, text);
  std::error_code ec;
  std::filesystem::rename(tmp, file, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw std::runtime_error("cannot write '" + file.string() + "': " + ec.message());
  }
}

bool createFileOnce(const std::filesystem::path& file, const std::string& text) {
  const std::filesystem::path tmp = uniquePartialPath(file);
  writeTo(tmp, text);
  const int linked = ::link(tmp.c_str(), file.c_str());
  const int error = errno;
  std::error_code ignored;
  std::filesystem::remove(tmp, ignored);
  if (linked == 0) return true;
  if (error == EEXIST) return false;
  throw std::runtime_error("cannot create '" + file.string() +
                           "': " + std::generic_category().message(error));
}

}  // namespace tribo::study
