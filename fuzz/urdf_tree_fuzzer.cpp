// libFuzzer harness: URDF robots generated from the input's bytes, deep and wide trees with
// hostile numbers; the input format and the contract are those of tribo::fuzz::urdfTree
// (fuzz/urdf_tree_input.hpp, docs/fuzzing.md).
#include <cstddef>
#include <cstdint>

#include "fuzz/urdf_tree_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tribo::fuzz::urdfTree(data, size);
  return 0;
}
