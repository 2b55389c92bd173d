// libFuzzer harness: near-degenerate and far-flung convex hulls made from the input bytes,
// read as binary STL, checked for convexity and, when accepted, collided with a box through
// contact/ (FCL and libccd); the input format and the contract are those of
// tribo::fuzz::hull (fuzz/fuzz_inputs.hpp, docs/fuzzing.md).
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_inputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tribo::fuzz::hull(data, size);
  return 0;
}
