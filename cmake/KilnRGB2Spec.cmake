# Build-time RGB-to-spectrum tables (Jakob & Hanika 2019) for kiln_spectral.
#
# kiln_rgb2spec_gen (src/spectral/gen/rgb2spec_gen.cpp) is a host executable; it fits the
# sigmoid-polynomial coefficients for every colour space in KILN_RGB2SPEC_SPACES and writes one
# C++ file per table (its bytes as a string literal, which compiles in about a second) plus
# rgb2spec_tables.cpp, which defines RGBToSpectrumTableData. Colour spaces left out fall back to
# the sRGB table at run time (RGBToSpectrumTable::HasOwnTable says which).
set(KILN_RGB2SPEC_SPACES "srgb;dci-p3;rec2020;aces2065-1" CACHE STRING
    "Colour spaces whose RGB-to-spectrum tables are generated at build time (srgb required)")
if(NOT "srgb" IN_LIST KILN_RGB2SPEC_SPACES)
    message(FATAL_ERROR "KILN_RGB2SPEC_SPACES must contain srgb (the fallback table)")
endif()

add_executable(kiln_rgb2spec_gen
    ${PROJECT_SOURCE_DIR}/src/spectral/gen/rgb2spec_gen.cpp
    ${PROJECT_SOURCE_DIR}/src/spectral/cie_data.cpp
    ${PROJECT_SOURCE_DIR}/src/spectral/named_spectra_pbrt_data.cpp)
target_include_directories(kiln_rgb2spec_gen PRIVATE ${PROJECT_SOURCE_DIR}/src)
# Warnings only: a sanitized build need not fit the tables under the sanitizers
target_link_libraries(kiln_rgb2spec_gen PRIVATE kiln_warnings Threads::Threads)
# Always optimised: the fit takes minutes unoptimised.
target_compile_options(kiln_rgb2spec_gen PRIVATE
    $<$<CXX_COMPILER_ID:GNU,Clang>:-O3>)

set(_kiln_rgb2spec_dir ${PROJECT_BINARY_DIR}/generated/rgb2spec)
set(_kiln_rgb2spec_outputs ${_kiln_rgb2spec_dir}/rgb2spec_tables.cpp)
foreach(space IN LISTS KILN_RGB2SPEC_SPACES)
    string(REPLACE "-" "_" id "${space}")
    list(APPEND _kiln_rgb2spec_outputs ${_kiln_rgb2spec_dir}/rgb2spec_kiln_rgb2spec_${id}.cpp)
endforeach()

add_custom_command(
    OUTPUT ${_kiln_rgb2spec_outputs}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${_kiln_rgb2spec_dir}
    COMMAND kiln_rgb2spec_gen ${_kiln_rgb2spec_dir} ${KILN_RGB2SPEC_SPACES}
    DEPENDS kiln_rgb2spec_gen
    COMMENT "Fitting RGB-to-spectrum tables (${KILN_RGB2SPEC_SPACES})"
    VERBATIM)
target_sources(kiln_spectral PRIVATE ${_kiln_rgb2spec_outputs})
# The string literals are far longer than the standard's minimum; -Woverlength-strings would
# warn under -Wpedantic.
set_source_files_properties(${_kiln_rgb2spec_outputs} PROPERTIES
    COMPILE_OPTIONS "$<$<CXX_COMPILER_ID:GNU,Clang>:-Wno-overlength-strings>")
