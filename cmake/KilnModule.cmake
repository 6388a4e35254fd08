# kiln_add_module(NAME DIR DEPS...): one static library per source folder; every .cpp in DIR
# (not recursing) that is neither a *_test.cpp nor an executable's main.cpp belongs to it.
function(kiln_add_module name dir)
    file(GLOB srcs CONFIGURE_DEPENDS "${dir}/*.cpp")
    list(FILTER srcs EXCLUDE REGEX "(_test|/main)\\.cpp$")
    if(srcs)
        add_library(${name} STATIC ${srcs})
        add_dependencies(${name} kiln_layers)
        target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR}/src)
        target_link_libraries(${name} PUBLIC kiln_options ${ARGN})
    else()
        add_library(${name} INTERFACE)
        target_include_directories(${name} INTERFACE ${PROJECT_SOURCE_DIR}/src)
        target_link_libraries(${name} INTERFACE kiln_options ${ARGN})
    endif()
endfunction()

# kiln_add_tests(NAME DIR DEPS... [STATISTICAL FILTER] [RELEASE_ONLY FILTER]): one GoogleTest
# executable from DIR/*_test.cpp, registered with ctest. KILN_SOURCE_DIR and KILN_SHARED_DIR
# (../shared beside the checkout) are defined. STATISTICAL: a GoogleTest filter
# ("Suite.*:Other/*") of the tests that are Monte Carlo renders taking seconds each; they are
# labelled `statistical`. RELEASE_ONLY: a filter of tests that check something other than
# kiln's code (the documentation's commands), labelled `releaseonly` (as is the Python module's
# test, CMakeLists.txt: the sanitizer build has no Python module). The sanitizer stage
# leaves both out (scripts/sanitize.sh: ctest -LE); the release stage runs only them (and the
# packaging tests), so an executable with either is part of kiln_release_stage.
function(kiln_add_tests name dir)
    cmake_parse_arguments(PARSE_ARGV 2 arg "" "STATISTICAL;RELEASE_ONLY" "")
    file(GLOB srcs CONFIGURE_DEPENDS "${dir}/*_test.cpp")
    if(NOT srcs)
        return()
    endif()
    add_executable(${name} ${srcs})
    target_link_libraries(${name} PRIVATE ${arg_UNPARSED_ARGUMENTS} GTest::gtest GTest::gtest_main)
    # Compiled without the sanitizers' instrumentation, linked to their runtimes
    # (KilnCompilerOptions.cmake)
    set_target_properties(${name} PROPERTIES KILN_TEST_DRIVER ON)
    # gtest.h takes about a second to parse, in each of some 140 test files and in both CI builds
    # (release and sanitizer): parsed once per test executable instead
    target_precompile_headers(${name} PRIVATE <gtest/gtest.h>)
    target_compile_definitions(${name} PRIVATE
        KILN_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
        KILN_SHARED_DIR="${PROJECT_SOURCE_DIR}/../shared"
        KILN_BINARY_DIR="${PROJECT_BINARY_DIR}")
    set(others "")
    foreach(label statistical releaseonly)
        string(TOUPPER ${label} key)
        string(REPLACE "RELEASEONLY" "RELEASE_ONLY" key ${key})
        if(arg_${key})
            gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 TEST_FILTER "${arg_${key}}"
                                 PROPERTIES TIMEOUT 600 LABELS ${label})
            string(APPEND others "${others_separator}${arg_${key}}")
            set(others_separator ":")
        endif()
    endforeach()
    if(others)
        add_dependencies(kiln_release_stage ${name})
        gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 TEST_FILTER "-${others}"
                             PROPERTIES TIMEOUT 600)
    else()
        gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 600)
    endif()
endfunction()

# kiln_module_definitions(NAME DEFS...): private compile definitions of a module (public while
# the module has no sources yet and is an INTERFACE library).
function(kiln_module_definitions name)
    get_target_property(type ${name} TYPE)
    if(type STREQUAL "INTERFACE_LIBRARY")
        target_compile_definitions(${name} INTERFACE ${ARGN})
    else()
        target_compile_definitions(${name} PRIVATE ${ARGN})
    endif()
endfunction()
