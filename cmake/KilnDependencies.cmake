# Third-party libraries kiln builds on; all come from Debian 12 packages (see README.md).
find_package(embree 3 REQUIRED)
find_package(OpenImageIO REQUIRED)
find_package(OpenEXR REQUIRED)
# Debian installs OpenColorIOConfig.cmake directly in /usr/share/cmake, off the default path.
find_package(OpenColorIO REQUIRED HINTS /usr/share/cmake)
find_package(TBB REQUIRED)
find_package(Threads REQUIRED)
find_package(GTest)
find_package(benchmark)
