#include "io/friction_curve.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/file_read.hpp"
#include "io/scene_parameters.hpp"

namespace tribo::io {

namespace {

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

}  // namespace

FrictionCurve parseFrictionCurve(const std::string& text, const std::string& name) {
  FrictionCurve curve;
  std::istringstream in(text);
  int line_number = 0;
  bool first_content = true;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    const std::string t = trimmed(line);
    if (t.empty() || t.front() == '#') continue;
    const auto comma = t.find(',');
    const std::string a = trimmed(t.substr(0, comma));
    const std::string b = comma == std::string::npos ? "" : trimmed(t.substr(comma + 1));
    const auto v = parseNumber(a);
    if (first_content && !v) {  // a header line
      first_content = false;
      continue;
    }
    first_content = false;
    const auto mu = parseNumber(b);
    if (!v || !mu || b.find(',') != std::string::npos)
      throw SceneError({name, line_number, 0}, "",
                       "expected two numbers 'speed, coefficient', found '" + t + "'");
    curve.speeds.push_back(*v);
    curve.coefficients.push_back(*mu);
    curve.lines.push_back(line_number);
  }
  if (curve.speeds.empty())
    throw SceneError({name, line_number, 0}, "",
                     "expected lines of 'speed, coefficient', found no point");
  return curve;
}

FrictionCurve readFrictionCurve(const std::string& path) {
  std::string text;
  try {
    text = readFileBounded(path, "friction curve file", kMaxTableBytes);
  } catch (const FileReadError& e) {
    throw SceneError(e.what());
  }
  return parseFrictionCurve(text, path);
}

}  // namespace tribo::io
