// libFuzzer harness: mesh file bytes (STL, OBJ, DAE); the input format and the
// contract are those of tribo::fuzz::mesh (fuzz/fuzz_inputs.hpp, docs/fuzzing.md).
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_inputs.hpp"

// assimp 5.2.5 (Debian 12) leaks about 2.5 kB when its ASCII STL reader throws on a malformed
// file (fuzz/regressions/mesh_fuzzer/leak-stl-bad-keyword): a defect of the library, which
// Tribo cannot free; the input still has to end in contact::MeshError. LeakSanitizer reads
// this function's suppressions (a no-op in builds without it).
extern "C" const char* __lsan_default_suppressions() { return "leak:libassimp.so\n"; }

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tribo::fuzz::mesh(data, size);
  return 0;
}
