// libFuzzer harness: the command line's value parsers (numbers, --set, --grid, --list); the input
// format and the contract are those of tribo::fuzz::cliValues (fuzz/fuzz_inputs.hpp,
// docs/fuzzing.md).
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_inputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tribo::fuzz::cliValues(data, size);
  return 0;
}
