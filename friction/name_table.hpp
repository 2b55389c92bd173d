// One small vocabulary: an enum's values and the names scene files and outputs use for them,
// written once, so the name of a value, the value of a name and the "expected one of" list
// of an error message come from the same table and cannot drift apart. Lives in the leaf
// module so every layer may use it. Not here: parsing scene files, matching loosely
// (names match exactly, case included).
#pragma once

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace tribo {

template <class Enum, std::size_t N>
class NameTable {
 public:
  // `what` names the vocabulary in messages ("integrator", "joint type").
  constexpr NameTable(std::string_view what, std::array<std::pair<Enum, std::string_view>, N> rows)
      : what_(what), rows_(rows) {}

  // The name of `value`; "unknown" for a value the table lacks (a cast integer). The view
  // refers to the string literals the table was made from.
  constexpr std::string_view view(Enum value) const {
    for (const auto& [v, n] : rows_)
      if (v == value) return n;
    return "unknown";
  }
  std::string name(Enum value) const { return std::string(view(value)); }
  std::optional<Enum> find(std::string_view name) const {
    for (const auto& [v, n] : rows_)
      if (n == name) return v;
    return std::nullopt;
  }
  // The value named `name`; throws std::invalid_argument "unknown WHAT 'NAME' (expected one
  // of: a, b, c)" otherwise.
  Enum fromName(std::string_view name) const {
    if (const auto v = find(name)) return *v;
    throw std::invalid_argument("unknown " + std::string(what_) + " '" + std::string(name) +
                                "' (expected one of: " + names() + ")");
  }
  // Every name in table order, comma separated: "a, b, c".
  std::string names() const {
    std::string out;
    for (const auto& [v, n] : rows_) out += (out.empty() ? "" : ", ") + std::string(n);
    return out;
  }

 private:
  std::string_view what_;
  std::array<std::pair<Enum, std::string_view>, N> rows_;
};

}  // namespace tribo
