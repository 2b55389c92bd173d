// Reads a measured friction curve for the `tabulated` law (friction/tabulated_law.hpp) from
// a CSV file: one point a line, slip speed [m/s] then friction coefficient [-], separated by
// a comma (spaces around the numbers allowed); an optional header line whose first field is
// not a number (e.g. "v,mu"); lines starting with '#' and blank lines are skipped.
// Errors name the file, the line and what was expected against what was found.
// Not here: the rules a curve must follow (speeds increasing, coefficients >= 0: the law
// checks them), units other than m/s, more than two columns.
#pragma once

#include <string>
#include <vector>

namespace tribo::io {

struct FrictionCurve {
  std::vector<double> speeds;        // [m/s]
  std::vector<double> coefficients;  // [-]
  std::vector<int> lines;            // the file line of each point, for messages
};

// Throws SceneError ("FILE:LINE: ...") when the file cannot be read or a line is not two
// numbers.
FrictionCurve readFrictionCurve(const std::string& path);
// The same from the text of such a file; `name` stands for the file in messages.
FrictionCurve parseFrictionCurve(const std::string& text, const std::string& name);

}  // namespace tribo::io
