// What ReadVDBVolume (vdb_file.cpp) exchanges with the OpenVDB plugin (libkiln_openvdb.so,
// vdb_plugin/), which is loaded the first time a scene reads a .vdb file: OpenVDB and the
// libraries it links cost about 27 MB at start-up in every process that links them. The
// plugin sees only this header (plain data and virtual calls); errors are
// std::runtime_error("reason").
#pragma once

#include <array>

namespace kiln {

// VDBFileReader Definition
class VDBFileReader {
  public:
    virtual ~VDBFileReader() = default;
    // The density grid's active voxels' box in index space, inclusive: min x, y, z, max x, y, z
    virtual std::array<int, 6> ActiveBox() const = 0;
    virtual bool HasTemperature() const = 0;
    // The density grid's index-to-world matrix, row-major, for column vectors
    virtual std::array<double, 16> IndexToWorld() const = 0;
    // Dense copies over ActiveBox, x fastest: densities (negative values as 0), and, if the
    // file has the temperature grid, temperatures sampled trilinearly at the density's voxel
    // centres
    virtual void ReadDense(float* density, float* temperature) const = 0;
};

// The function the plugin exports: extern "C" VDBFileReader* KilnOpenVDBFile(const char* file,
// const char* densityGrid, const char* temperatureGrid) (temperatureGrid "" for none; a
// missing temperature grid is no error). The caller owns the reader.
inline constexpr const char* kOpenVDBFileSymbol = "KilnOpenVDBFile";

}  // namespace kiln
