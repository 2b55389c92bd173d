#include "io/file_read.hpp"

#include <fstream>
#include <system_error>

namespace tribo::io {

namespace {

std::string kindOf(std::filesystem::file_type type) {
  using T = std::filesystem::file_type;
  switch (type) {
    case T::directory:
      return "a directory";
    case T::fifo:
      return "a FIFO (named pipe)";
    case T::character:
      return "a character device";
    case T::block:
      return "a block device";
    case T::socket:
      return "a socket";
    default:
      return "not a regular file";
  }
}

std::string sizeText(std::uintmax_t bytes) {
  if (bytes < 10 * 1024) return std::to_string(bytes) + " bytes";
  if (bytes < 10 * kMiB)
    return std::to_string(bytes / 1024) + " KiB (" + std::to_string(bytes) + " bytes)";
  return std::to_string(bytes / kMiB) + " MiB (" + std::to_string(bytes) + " bytes)";
}

}  // namespace

std::uintmax_t checkReadableFile(const std::filesystem::path& path, const std::string& what,
                                 std::uintmax_t limit) {
  const std::string who = what + " '" + path.string() + "'";
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (ec || status.type() == std::filesystem::file_type::not_found)
    throw FileReadError("cannot open " + who + " (" +
                        (ec ? ec.message() : std::string("no such file")) + ")");
  if (status.type() != std::filesystem::file_type::regular)
    throw FileReadError(who + ": expected a regular file, found " + kindOf(status.type()));
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) throw FileReadError(who + ": cannot read its size (" + ec.message() + ")");
  if (size > limit)
    throw FileReadError(who + ": " + sizeText(size) + ", larger than the " + sizeText(limit) +
                        " a " + what + " may have");
  return size;
}

std::string readFileBounded(const std::filesystem::path& path, const std::string& what,
                            std::uintmax_t limit) {
  const std::uintmax_t size = checkReadableFile(path, what, limit);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileReadError(what + " '" + path.string() + "': cannot open it");
  std::string text;
  text.reserve(static_cast<std::size_t>(size));
  char buffer[1 << 16];
  while (in) {
    in.read(buffer, sizeof buffer);
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > limit)
      throw FileReadError(what + " '" + path.string() + "': grew past the " + sizeText(limit) +
                          " a " + what + " may have while it was read");
  }
  if (in.bad()) throw FileReadError(what + " '" + path.string() + "': cannot read it");
  return text;
}

bool getLineBounded(std::istream& in, std::string& line, std::size_t max,
                    const std::filesystem::path& path) {
  line.clear();
  std::istream::sentry ok(in, true);
  if (!ok) return false;
  std::streambuf* buf = in.rdbuf();
  for (;;) {
    const int c = buf->sbumpc();
    if (c == std::char_traits<char>::eof()) {
      in.setstate(std::ios::eofbit);
      if (line.empty()) in.setstate(std::ios::failbit);
      return !line.empty();
    }
    if (c == '\n') return true;
    if (line.size() >= max)
      throw FileReadError("'" + path.string() + "': a line longer than " + sizeText(max) +
                          " (expected CSV lines)");
    line.push_back(static_cast<char>(c));
  }
}

}  // namespace tribo::io
