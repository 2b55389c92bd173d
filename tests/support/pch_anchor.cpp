// The target that builds the tests' precompiled header (tests/CMakeLists.txt,
// cmake/TriboPch.cmake). It holds no test: linked with gtest_main it runs none.
