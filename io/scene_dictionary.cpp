#include "io/scene_dictionary.hpp"

#include <algorithm>
#include <functional>
#include <stdexcept>

#include "contact/normal_law.hpp"
#include "core/constraint_options.hpp"
#include "core/joint.hpp"
#include "core/model.hpp"
#include "friction/friction_law.hpp"
#include "friction/law_keys.hpp"
#include "io/output_channels.hpp"
#include "io/scene_keys.hpp"

namespace tribo::io {
namespace {

// The names a NameTable-backed parser accepts, read from its own error message for a name it
// does not know ("unknown WHAT '' (expected one of: a, b, c)", friction/name_table.hpp): the
// table itself is private to its module, and this keeps the list in one place.
std::vector<std::string> acceptedNames(const std::function<void(const std::string&)>& parse) {
  std::string message;
  try {
    parse("");
  } catch (const std::invalid_argument& e) {
    message = e.what();
  }
  const std::string marker = "expected one of: ";
  const auto begin = message.find(marker);
  const auto end = message.rfind(')');
  if (begin == std::string::npos || end == std::string::npos || end < begin)
    throw std::logic_error("scene dictionary: no list of names in '" + message + "'");
  const std::string list = message.substr(begin + marker.size(), end - begin - marker.size());
  std::vector<std::string> out;
  for (std::size_t at = 0; at <= list.size();) {
    const auto comma = list.find(", ", at);
    out.push_back(list.substr(at, comma == std::string::npos ? std::string::npos : comma - at));
    if (comma == std::string::npos) break;
    at = comma + 2;
  }
  return out;
}

}  // namespace

std::vector<std::string> sceneDictionaryWords() {
  std::vector<std::string> words;
  const auto add = [&](const std::vector<std::string>& list) {
    words.insert(words.end(), list.begin(), list.end());
  };
  for (const auto& section : scene_keys::sections()) add(*section.words);
  for (const auto* laws : {&friction::knownFrictionLaws(), &friction::knownStatefulFrictionLaws(),
                           &friction::knownDynamicFrictionLaws()})
    for (const std::string& law : *laws) {
      words.push_back(law);
      const friction::LawKeys keys = friction::frictionLawKeys(law);
      add(keys.keys);
      add(keys.options);
      add(keys.option_words);
    }
  add(acceptedNames([](const std::string& n) { (void)contact::normalLawFromName(n); }));
  add(acceptedNames([](const std::string& n) { (void)jointTypeFromName(n); }));
  add(acceptedNames([](const std::string& n) { (void)integratorFromName(n); }));
  add(acceptedNames([](const std::string& n) { (void)constraintSolverFromName(n); }));
  add(knownChannelGroups());
  std::sort(words.begin(), words.end());
  words.erase(std::unique(words.begin(), words.end()), words.end());
  return words;
}

std::string dictionaryLine(const std::string& word) { return "kw_" + word + "=\"" + word + "\""; }

}  // namespace tribo::io
