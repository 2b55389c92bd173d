// The words a scene file may use, gathered from the tables the loader and the factories read
// (io/scene_keys.hpp, friction/law_keys.hpp, the name tables of normal laws, joint
// types, integrators and constraint solvers, io/output_channels.hpp), as a libFuzzer
// dictionary for fuzz/scene_yaml_fuzzer: a key added to any of those tables is in the
// dictionary the day it exists. Printed by the `scene_dictionary` tool (fuzz/, run by
// scripts/fuzz.sh); tests/io/scene_keys_test.cpp checks the committed
// fuzz/dictionaries/scene.dict holds every word.
// Not here: hand-written fragments of the committed dictionary (expression syntax,
// extreme numbers), which no table lists.
#pragma once

#include <string>
#include <vector>

namespace tribo::io {

// Every word, sorted, without repeats.
std::vector<std::string> sceneDictionaryWords();

// A dictionary line for `word`: kw_WORD="WORD".
std::string dictionaryLine(const std::string& word);

}  // namespace tribo::io
