#include "study/csv_text.hpp"

#include <charconv>
#include <cmath>

namespace tribo::study {

char* csvNumberTo(char* first, char* last, double v, int digits) {
  if (!std::isfinite(v)) return first;
  return std::to_chars(first, last, v, std::chars_format::general, digits).ptr;
}

std::string csvNumber(double v, int digits) {
  char buf[40];
  return std::string(buf, csvNumberTo(buf, buf + sizeof buf, v, digits));
}

std::string csvField(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  if (text.find_first_of(",\"") == std::string::npos) return text;
  std::string q = "\"";
  for (const char c : text) {
    if (c == '"') q += '"';
    q += c;
  }
  return q + '"';
}

std::string csvLine(const std::vector<std::string>& fields) {
  std::string line;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i) line += ',';
    line += csvField(fields[i]);
  }
  return line + '\n';
}

}  // namespace tribo::study
