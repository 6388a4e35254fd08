# The Python module `kiln` (src/python: pybind11 and numpy from Debian 12's pybind11-dev and
# python3-numpy), built for the Python in KILN_PYTHON_EXECUTABLE (default Debian's
# /usr/bin/python3, the one its python3-* packages serve). Built when pybind11 and that Python
# are found, except in sanitizer and fuzzing builds (an instrumented extension cannot be loaded
# into an uninstrumented interpreter). The module goes to <build>/python/kiln (import it with
# PYTHONPATH=<build>/python) and is installed in <prefix>/lib/pythonX.Y/dist-packages/kiln,
# which Debian's Python searches for the prefixes /usr and /usr/local.
option(KILN_PYTHON "Build the Python module kiln" ON)
set(KILN_PYTHON_EXECUTABLE "" CACHE FILEPATH "The Python the module is built for")
set(KILN_PYTHON_FOUND OFF)
if(KILN_PYTHON AND NOT KILN_SANITIZE AND NOT KILN_FUZZ)
    if(NOT KILN_PYTHON_EXECUTABLE AND EXISTS /usr/bin/python3)
        set(KILN_PYTHON_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "" FORCE)
    endif()
    if(KILN_PYTHON_EXECUTABLE)
        set(Python_EXECUTABLE ${KILN_PYTHON_EXECUTABLE})
    endif()
    find_package(Python 3.8 COMPONENTS Interpreter Development.Module)
    if(Python_FOUND)
        set(PYBIND11_FINDPYTHON ON)
        find_package(pybind11 CONFIG QUIET)
    endif()
    if(Python_FOUND AND pybind11_FOUND)
        set(KILN_PYTHON_FOUND ON)
        # Every module's code goes into the extension too. GCC would otherwise assume any
        # global function may be interposed at run time and stop inlining across them.
        set(CMAKE_POSITION_INDEPENDENT_CODE ON)
        target_compile_options(kiln_warnings INTERFACE
            $<$<CXX_COMPILER_ID:GNU>:-fno-semantic-interposition>)
    else()
        message(STATUS "kiln: the Python module is not built (needs pybind11-dev and "
                       "python3-dev for ${KILN_PYTHON_EXECUTABLE})")
    endif()
endif()

# kiln_add_python_module(): the extension kiln._kiln and the package around it
function(kiln_add_python_module)
    if(NOT KILN_PYTHON_FOUND)
        return()
    endif()
    file(GLOB srcs CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/python/*.cpp)
    # Without pybind11's link-time optimisation: it would optimise the bindings alone (kiln's
    # libraries are not compiled for it), and its serial link took 9 s of the build
    set(CMAKE_INTERPROCEDURAL_OPTIMIZATION OFF)
    pybind11_add_module(kiln_python MODULE ${srcs})
    target_include_directories(kiln_python PRIVATE ${PROJECT_SOURCE_DIR}/src)
    target_link_libraries(kiln_python PRIVATE kiln_render)
    add_dependencies(kiln_python kiln_layers)
    set(package_dir ${PROJECT_BINARY_DIR}/python/kiln)
    set_target_properties(kiln_python PROPERTIES OUTPUT_NAME _kiln
                          LIBRARY_OUTPUT_DIRECTORY ${package_dir})
    configure_file(${PROJECT_SOURCE_DIR}/src/python/kiln/__init__.py ${package_dir}/__init__.py
                   COPYONLY)
    set(dest lib/python${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}/dist-packages/kiln)
    install(TARGETS kiln_python LIBRARY DESTINATION ${dest})
    install(FILES ${PROJECT_SOURCE_DIR}/src/python/kiln/__init__.py DESTINATION ${dest})
endfunction()
