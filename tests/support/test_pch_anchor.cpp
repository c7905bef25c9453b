// The one source file of candela_test_pch (tests/CMakeLists.txt): the target exists to build the
// precompiled header that most test executables reuse, and CMake needs a file to compile with it.
