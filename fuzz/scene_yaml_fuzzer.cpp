// libFuzzer harness: scene YAML text (with --set overrides); the input format and the
// contract are those of tribo::fuzz::sceneYaml (fuzz/fuzz_inputs.hpp, docs/fuzzing.md).
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_inputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tribo::fuzz::sceneYaml(data, size);
  return 0;
}
