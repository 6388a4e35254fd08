// Sparse volumes from OpenVDB files (.vdb, through Debian's libopenvdb in the OpenVDB plugin,
// vdb_reader.h): the float grids a medium reads, resampled onto a dense SampledGrid over the
// density grid's active voxels.
// NanoVDB files (.nvdb, pbrt-v4's "nanovdb" medium) are read by kiln's own reader
// (nanovdb_volume.h), chosen by the file's magic number or its .nvdb name.
#pragma once

#include <string>

#include "base/transform.h"
#include "core/parser/file_loc.h"
#include "media/sampled_grid.h"

namespace kiln {

class MemoryBudget;

struct VDBVolume {
    SampledGrid<Float> density;
    SampledGrid<Float> temperature;  // empty if the file has no such grid
    // The medium's box in index space (voxel values at integer coordinates): for .nvdb files
    // the grid's stated world box, for .vdb files the box their NanoVDB conversion states, the
    // active voxels' [min, max + 1]. The box the dense samples span (half a voxel beyond the
    // outermost). The grid's index-to-world transform: world is the medium's space.
    Bounds3f indexBounds, sampleBounds;
    Transform mediumFromIndex;
};

// Reads densityName (required: SceneError at loc if missing, not a float grid, or the file is
// unreadable) and temperatureName (optional) from filename. Volumes of more than maxVoxels
// dense voxels are refused.
// OpenVDB reads the file in a child process whose address space may grow by at most what
// budget has left (half the machine's memory without one): a damaged file that would make it
// allocate without end, or crash it, is a SceneError naming the file. The dense grids are then
// charged to budget (if given) before they are allocated here.
VDBVolume ReadVDBVolume(const std::string& filename, const std::string& densityName,
                        const std::string& temperatureName, const FileLoc& loc,
                        size_t maxVoxels = size_t(1) << 30, MemoryBudget* budget = nullptr);

// For the readers: refuses a dense volume of more than maxVoxels voxels (SceneError at loc,
// naming densityName) and charges its grids (two with a temperature) to budget, if given (a
// SceneError naming filename beyond it). Returns the voxel count.
size_t ChargeDenseVolume(double voxels, bool withTemperature, const std::string& filename,
                         const std::string& densityName, const FileLoc& loc, size_t maxVoxels,
                         MemoryBudget* budget);

}  // namespace kiln
