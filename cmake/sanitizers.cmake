# The clang build that CI runs the test suite and the fuzzers in (scripts/sanitize.sh,
# scripts/fuzz.sh): one configuration for both, so the library is compiled once.
#
# CANDELA_SANITIZE: every target with AddressSanitizer + UndefinedBehaviorSanitizer. UB aborts
#   (no recovery), so a ctest run fails on the first report. -O1 keeps the suite's render tests
#   fast enough while leaving stack traces exact; -g1 (line tables) is all the reports need.
#   _GLIBCXX_ASSERTIONS adds libstdc++'s bounds checks (operator[] between size and capacity,
#   which ASan cannot see); it does not change the ABI, so the system libraries still fit.
# CANDELA_FUZZ: builds the fuzz targets in fuzz/ (which link libFuzzer's main) and instruments
#   the library's readers for them (-fsanitize=fuzzer-no-link: coverage counters and comparison
#   hooks, whose no-op defaults come with ASan's runtime for the tests; fuzz/CMakeLists.txt).
#
# Embree, oneTBB, OpenEXR and GoogleTest are Debian's uninstrumented builds: ASan still sees
# every allocation they make (malloc is intercepted process-wide) but not their out-of-bounds
# accesses, and the fuzzers get no coverage from inside them (docs/RELIABILITY.md).
option(CANDELA_SANITIZE "Build everything with ASan + UBSan (clang; CI's sanitizer build)" OFF)
option(CANDELA_FUZZ "Build the libFuzzer targets in fuzz/ (needs CANDELA_SANITIZE)" OFF)

if(CANDELA_FUZZ AND NOT CANDELA_SANITIZE)
  message(FATAL_ERROR "CANDELA_FUZZ needs CANDELA_SANITIZE=ON: fuzzing without ASan misses most memory errors")
endif()
if(CANDELA_SANITIZE AND NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "CANDELA_SANITIZE needs clang (CXX=clang++): libFuzzer and the flags below are clang's")
endif()

if(CANDELA_SANITIZE)
  set(candela_sanitizers -fsanitize=address,undefined -fno-sanitize-recover=undefined)
  add_compile_options(${candela_sanitizers} -fno-omit-frame-pointer -O1 -g1 -D_GLIBCXX_ASSERTIONS)
  add_link_options(${candela_sanitizers})
endif()
