// A number as error and note messages print it: the stream's default form (6 significant
// digits, "1e+09", "nan"), so every module words values the same way. Not for output files:
// the writers choose their own precision.
#pragma once

#include <sstream>
#include <string>

namespace tribo {

inline std::string numberText(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace tribo
