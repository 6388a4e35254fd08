# kiln's layers, checked on every build (CMakeLists.txt runs this script before any module
# compiles; docs/architecture.md explains them). Run by hand:
#   cmake -DSRC=src -P cmake/CheckLayers.cmake [-DSTAMP=file]
#
# Every folder under src/ has a rank. A file may include files of its own folder and of folders
# of lower rank, never of a higher rank or of another folder of the same rank: no include runs
# upward, and the folders cannot form a cycle. A folder missing from the table is an error, so
# a new folder is placed in the layers when it is made.
#
# The thermal module's host interface (docs/thermal-module.md) is stricter: the files listed in
# THERMAL_HOST_INDEPENDENT include only base/, spectral/ and each other, so that a host renderer
# can take them without kiln's materials, textures or geometry.

set(LAYERS
    # folder            rank
    base                0
    spectral            10
    spectral/gen        11   # the RGB-to-spectrum table generator (a build tool)
    core/parser         20
    core/image          21
    core/geometry       21
    core/image/oiio_plugin 22  # OpenImageIO, loaded on first use
    core/film           22
    core/camera         23
    textures            30
    materials/bxdfs     30
    materials           31
    thermal             40
    lights              50
    media               50
    media/vdb_plugin    51   # OpenVDB, loaded on first use
    render              60
    app                 70
    python              80   # the Python module (pybind11)
)
set(THERMAL_HOST_INDEPENDENT
    thermal/emission_model.h thermal/emission_model.cpp
    thermal/surface_emission.h
    thermal/volume_emission.h thermal/volume_emission.cpp
    thermal/cooling.h thermal/cooling.cpp
)

if(NOT SRC)
    message(FATAL_ERROR "CheckLayers.cmake: -DSRC=<kiln's src folder> is required")
endif()
get_filename_component(SRC "${SRC}" ABSOLUTE)

# folder -> rank
set(folders "")
list(LENGTH LAYERS n)
math(EXPR last "${n} - 1")
foreach(i RANGE 0 ${last} 2)
    math(EXPR j "${i} + 1")
    list(GET LAYERS ${i} folder)
    list(GET LAYERS ${j} rank)
    set(rank_${folder} ${rank})
    list(APPEND folders ${folder})
endforeach()

file(GLOB_RECURSE files RELATIVE "${SRC}" "${SRC}/*.h" "${SRC}/*.cpp")
set(errors "")
foreach(file IN LISTS files)
    get_filename_component(from "${file}" DIRECTORY)
    if(NOT DEFINED rank_${from})
        string(APPEND errors "  src/${file}: folder src/${from} has no layer in cmake/CheckLayers.cmake\n")
        continue()
    endif()
    list(FIND THERMAL_HOST_INDEPENDENT "${file}" hostIndependent)
    file(STRINGS "${SRC}/${file}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
    foreach(line IN LISTS includes)
        string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]*)\".*$" "\\1" inc "${line}")
        get_filename_component(to "${inc}" DIRECTORY)
        set(target "${inc}")
        if(to STREQUAL "")  # a file of the same folder
            set(to "${from}")
            set(target "${from}/${inc}")
        endif()
        if(NOT hostIndependent EQUAL -1)
            list(FIND THERMAL_HOST_INDEPENDENT "${target}" allowed)
            if(NOT to STREQUAL "base" AND NOT to STREQUAL "spectral" AND allowed EQUAL -1)
                string(APPEND errors "  src/${file}: includes \"${inc}\": the thermal module's host interface includes only base/, spectral/ and itself\n")
            endif()
        endif()
        if(to STREQUAL from)
            continue()
        endif()
        if(NOT DEFINED rank_${to})
            string(APPEND errors "  src/${file}: includes \"${inc}\" from src/${to}, which has no layer\n")
        elseif(NOT rank_${to} LESS rank_${from})
            string(APPEND errors "  src/${file}: includes \"${inc}\": src/${to} (rank ${rank_${to}}) is not below src/${from} (rank ${rank_${from}})\n")
        endif()
    endforeach()
endforeach()

if(errors)
    message(FATAL_ERROR "kiln: includes that break the layers (cmake/CheckLayers.cmake):\n${errors}")
endif()
if(STAMP)
    file(TOUCH "${STAMP}")
endif()
