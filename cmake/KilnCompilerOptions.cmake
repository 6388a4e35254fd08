# Compiler warnings and sanitizer options shared by every kiln target.
option(KILN_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(KILN_WERROR "Treat warnings as errors" OFF)

add_library(kiln_options INTERFACE)
target_compile_features(kiln_options INTERFACE cxx_std_20)
target_compile_options(kiln_options INTERFACE
    $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wno-unused-parameter
        -Wno-missing-field-initializers -fno-math-errno>)
if(KILN_WERROR)
    target_compile_options(kiln_options INTERFACE -Werror)
endif()
if(KILN_SANITIZE)
    target_compile_options(kiln_options INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer)
    target_link_options(kiln_options INTERFACE -fsanitize=address,undefined)
endif()

# Thermal emission (ThermalAreaLight) can be compiled out, only to measure that scenes without
# hot objects do not pay for it (bench/thermal_overhead.sh); the test suite needs it ON.
option(KILN_THERMAL_EMISSION "Build Kirchhoff thermal emission" ON)
if(KILN_THERMAL_EMISSION)
    target_compile_definitions(kiln_options INTERFACE KILN_THERMAL_EMISSION=1)
else()
    target_compile_definitions(kiln_options INTERFACE KILN_THERMAL_EMISSION=0)
endif()
