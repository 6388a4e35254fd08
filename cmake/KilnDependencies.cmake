# Third-party libraries kiln builds on; all come from Debian 12 packages (see README.md).

# Some Debian 12 CMake package configs name include directories that do not exist (OpenImageIO
# lists /usr/include/opencv4 without OpenCV installed; OpenColorIO's config, installed directly
# in /usr/share/cmake, computes "/include"). CMake refuses such targets, so drop those entries
# and fall back to /usr/include.
function(kiln_drop_missing_includes target)
    foreach(prop INTERFACE_INCLUDE_DIRECTORIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES)
        get_target_property(dirs ${target} ${prop})
        if(NOT dirs)
            continue()
        endif()
        set(kept "")
        foreach(dir IN LISTS dirs)
            if(EXISTS "${dir}" OR dir MATCHES "^\\$<")
                list(APPEND kept "${dir}")
            endif()
        endforeach()
        if(NOT kept AND prop STREQUAL "INTERFACE_INCLUDE_DIRECTORIES")
            set(kept /usr/include)
        endif()
        set_target_properties(${target} PROPERTIES ${prop} "${kept}")
    endforeach()
endfunction()

find_package(embree 3 REQUIRED)
find_package(OpenImageIO REQUIRED)
kiln_drop_missing_includes(OpenImageIO::OpenImageIO)
find_package(OpenEXR REQUIRED)
find_package(PNG REQUIRED)
find_package(JPEG REQUIRED)
# Debian installs OpenColorIOConfig.cmake directly in /usr/share/cmake, off the default path.
find_package(OpenColorIO REQUIRED HINTS /usr/share/cmake)
kiln_drop_missing_includes(OpenColorIO::OpenColorIO)
find_package(TBB REQUIRED)
# OpenVDB (libopenvdb-dev; its headers also need libboost-dev) ships only a find module, which
# demands Boost libraries kiln does not use: kiln links the library directly.
find_library(KILN_OPENVDB_LIBRARY openvdb REQUIRED)
find_path(KILN_OPENVDB_INCLUDE_DIR openvdb/openvdb.h REQUIRED)
add_library(kiln_openvdb INTERFACE)
target_include_directories(kiln_openvdb SYSTEM INTERFACE ${KILN_OPENVDB_INCLUDE_DIR})
target_link_libraries(kiln_openvdb INTERFACE ${KILN_OPENVDB_LIBRARY} TBB::tbb)
find_package(Threads REQUIRED)
find_package(ZLIB REQUIRED)
find_package(GTest)
find_package(benchmark)
