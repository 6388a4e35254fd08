# Compiler warnings and sanitizer options shared by every kiln target.
option(KILN_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(KILN_WERROR "Treat warnings as errors" OFF)

option(KILN_FUZZ "Build the libFuzzer targets in test/fuzz (needs clang)" OFF)

# Unity builds: each target's sources compile in batches of KILN_UNITY_BATCH files, one
# translation unit per batch, so headers are parsed once per batch rather than once per file.
# A clean build of kiln and its tests took 4 min 49 s on 2 cores, against 8 min 34 s file by
# file (docs/guide/accuracy-and-speed.md); a change to one file recompiles its batch. Names at file scope (anonymous namespaces included) must therefore be
# unique within a target. -DKILN_UNITY_BUILD=OFF compiles file by file.
option(KILN_UNITY_BUILD "Compile each target's sources in batches (CMake unity builds)" ON)
set(KILN_UNITY_BATCH 8 CACHE STRING "Sources per unity batch (KILN_UNITY_BUILD)")
if(KILN_UNITY_BUILD)
    set(CMAKE_UNITY_BUILD ON)
    set(CMAKE_UNITY_BUILD_BATCH_SIZE ${KILN_UNITY_BATCH})
endif()

# kiln_warnings: language level, warnings and definitions, for every kiln target including
# build-time generators; kiln_options adds the sanitizers to kiln's own code.
add_library(kiln_warnings INTERFACE)
target_compile_features(kiln_warnings INTERFACE cxx_std_20)
# -fno-math-errno: sqrt and friends set no errno, so they compile to single instructions.
# -fno-trapping-math (Clang's default): kiln never enables floating-point traps or reads the
# exception flags, so GCC may compute both sides of a select between floating-point values and
# vectorise loops with conditions (materials/bxdfs/fresnel.cpp: FrComplex over a path's
# wavelengths). Neither changes a computed value.
target_compile_options(kiln_warnings INTERFACE
    $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wno-unused-parameter
        -Wno-missing-field-initializers -fno-math-errno -fno-trapping-math>)
if(KILN_WERROR)
    target_compile_options(kiln_warnings INTERFACE -Werror)
endif()
add_library(kiln_options INTERFACE)
target_link_libraries(kiln_options INTERFACE kiln_warnings)
# The instrumentation goes into kiln's own code (its libraries, plug-ins and binaries), not into
# the test executables, whose property KILN_TEST_DRIVER is set (kiln_add_tests): the tests drive
# instrumented code and link the sanitizer runtimes, so what kiln's code reads or writes is
# checked, including memory the tests allocated. A test batch compiled about 60 % longer with
# the instrumentation (clang 14, -O3: 20.6 s against 12.9 s).
set(kiln_instrumented "$<NOT:$<BOOL:$<TARGET_PROPERTY:KILN_TEST_DRIVER>>>")
if(KILN_SANITIZE)
    # Any report fails the run (no recovery)
    target_compile_options(kiln_options INTERFACE "$<${kiln_instrumented}:-fsanitize=address,undefined;-fno-sanitize-recover=all;-fno-omit-frame-pointer;$<$<CXX_COMPILER_ID:Clang>:-fsanitize-ignorelist=${PROJECT_SOURCE_DIR}/cmake/sanitizer-ignorelist.txt>>")
    target_link_options(kiln_options INTERFACE -fsanitize=address,undefined)
endif()
# The test executables of a release build at -O1: their own code (set-up, assertions,
# reference sums) is not what they measure, and a batch of test files compiles 40 % faster
# than at -O3 (GCC 12: 7.4 s against 12.4 s); the code under test keeps -O3
target_compile_options(kiln_options INTERFACE
                       "$<$<AND:$<NOT:${kiln_instrumented}>,$<CONFIG:Release>>:-O1>")
if(KILN_FUZZ)
    if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
        message(FATAL_ERROR "KILN_FUZZ needs clang (libFuzzer): configure with CXX=clang++")
    endif()
    # Coverage for libFuzzer's guidance, in the code the fuzzers reach
    target_compile_options(kiln_options INTERFACE "$<${kiln_instrumented}:-fsanitize=fuzzer-no-link>")
endif()

# Thermal emission (ThermalAreaLight) can be compiled out, only to measure that scenes without
# hot objects do not pay for it (bench/thermal_overhead.sh); the test suite needs it ON.
option(KILN_THERMAL_EMISSION "Build Kirchhoff thermal emission" ON)
if(KILN_THERMAL_EMISSION)
    target_compile_definitions(kiln_warnings INTERFACE KILN_THERMAL_EMISSION=1)
else()
    target_compile_definitions(kiln_warnings INTERFACE KILN_THERMAL_EMISSION=0)
endif()
