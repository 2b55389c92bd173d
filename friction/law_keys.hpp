// The keys makeFrictionLaw (friction/friction_law.hpp) accepts for each law, for generated
// fuzzing dictionaries and tests (io/scene_dictionary.hpp): the factory's own lists, so they
// cannot drift from what it accepts. Not here: what the keys mean (each law's header).
#pragma once

#include <string>
#include <vector>

namespace tribo::friction {

struct LawKeys {
  std::vector<std::string> keys;          // numbers
  std::vector<std::string> options;       // words
  std::vector<std::string> option_words;  // the words those options take
};

// The keys of law `name` (one of knownFrictionLaws(), knownStatefulFrictionLaws(),
// knownDynamicFrictionLaws()). Throws FrictionParameterError for an unknown name.
LawKeys frictionLawKeys(const std::string& name);

}  // namespace tribo::friction
