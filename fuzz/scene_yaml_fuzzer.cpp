// libFuzzer harness: scene YAML text (with --set overrides); the input format and the
// contract are those of tribo::fuzz::sceneYaml (fuzz/fuzz_inputs.hpp, docs/fuzzing.md).
// One mutation in three is structure-aware (fuzz/scene_mutator.hpp: expressions, parameter
// chains and cycles, extreme numbers, non-UTF-8 text, dictionary keys); the others are
// libFuzzer's own.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>

#include "fuzz/fuzz_inputs.hpp"
#include "fuzz/scene_mutator.hpp"

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size,
                                               std::size_t max_size, unsigned int seed) {
  std::mt19937 rng(seed);
  if (rng() % 3 != 0) return LLVMFuzzerMutate(data, size, max_size);
  const std::string out =
      tribo::fuzz::mutateScene(std::string(reinterpret_cast<const char*>(data), size), rng);
  if (out.size() > max_size || out.empty()) return LLVMFuzzerMutate(data, size, max_size);
  std::memcpy(data, out.data(), out.size());
  return out.size();
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tribo::fuzz::sceneYaml(data, size);
  return 0;
}
