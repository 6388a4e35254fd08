# Compiler warnings and sanitizer options shared by every kiln target.
option(KILN_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(KILN_WERROR "Treat warnings as errors" OFF)

option(KILN_FUZZ "Build the libFuzzer targets in test/fuzz (needs clang)" OFF)

# kiln_warnings: language level, warnings and definitions, for every kiln target including
# build-time generators; kiln_options adds the sanitizers to kiln's own code.
add_library(kiln_warnings INTERFACE)
target_compile_features(kiln_warnings INTERFACE cxx_std_20)
target_compile_options(kiln_warnings INTERFACE
    $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wno-unused-parameter
        -Wno-missing-field-initializers -fno-math-errno>)
if(KILN_WERROR)
    target_compile_options(kiln_warnings INTERFACE -Werror)
endif()
add_library(kiln_options INTERFACE)
target_link_libraries(kiln_options INTERFACE kiln_warnings)
if(KILN_SANITIZE)
    # Any report fails the run (no recovery)
    target_compile_options(kiln_options INTERFACE -fsanitize=address,undefined
        -fno-sanitize-recover=all -fno-omit-frame-pointer
        $<$<CXX_COMPILER_ID:Clang>:-fsanitize-ignorelist=${PROJECT_SOURCE_DIR}/cmake/sanitizer-ignorelist.txt>)
    target_link_options(kiln_options INTERFACE -fsanitize=address,undefined)
endif()
if(KILN_FUZZ)
    if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
        message(FATAL_ERROR "KILN_FUZZ needs clang (libFuzzer): configure with CXX=clang++")
    endif()
    target_compile_options(kiln_options INTERFACE -fsanitize=fuzzer-no-link)
endif()

# Thermal emission (ThermalAreaLight) can be compiled out, only to measure that scenes without
# hot objects do not pay for it (bench/thermal_overhead.sh); the test suite needs it ON.
option(KILN_THERMAL_EMISSION "Build Kirchhoff thermal emission" ON)
if(KILN_THERMAL_EMISSION)
    target_compile_definitions(kiln_warnings INTERFACE KILN_THERMAL_EMISSION=1)
else()
    target_compile_definitions(kiln_warnings INTERFACE KILN_THERMAL_EMISSION=0)
endif()
