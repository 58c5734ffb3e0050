// The owner of the test drivers' precompiled header (proptests/CMakeLists.txt,
// flipflop_test_pch): CMake compiles the header with this target's flags and
// the drivers reuse it. It has no tests; it is built, never run.
int main() { return 0; }
