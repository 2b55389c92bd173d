// libFuzzer harness: URDF text; the input format and the
// contract are those of tribo::fuzz::urdf (fuzz/fuzz_inputs.hpp, docs/fuzzing.md).
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_inputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tribo::fuzz::urdf(data, size);
  return 0;
}
