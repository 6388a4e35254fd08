// NanoVDB volumes (.nvdb, pbrt-v4's "nanovdb" medium) as kiln's dense grids, the way pbrt-v4's
// NanoVDBMedium sees them: the density grid's values at integer index coordinates (every
// voxel NanoVDB's getValue answers: leaves, tiles, background) interpolated trilinearly, inside
// the box the grid states as its world bounding box (NanoVDB writes the active voxels' index
// box [min, max + 1] mapped to world space); the temperature grid sampled trilinearly at the
// density grid's voxels (exactly its values when both grids share a map).
#pragma once

#include <string>

#include "core/parser/file_loc.h"
#include "media/vdb_file.h"

namespace kiln {

class MemoryBudget;

// As ReadVDBVolume, for NanoVDB files: densityName (required) and temperatureName (optional,
// "" for none) from filename; errors (a missing, compressed with BLOSC, non-float or non-fog
// grid, a damaged or truncated file) are SceneErrors at loc naming the file. The density box
// must be within 2^30 voxels of the origin; the dense grids (at most maxVoxels) are charged to
// budget before they are allocated, and the grids' bytes must fit in what it has left (half
// the machine's memory without one).
VDBVolume ReadNanoVDBVolume(const std::string& filename, const std::string& densityName,
                            const std::string& temperatureName, const FileLoc& loc,
                            size_t maxVoxels = size_t(1) << 30, MemoryBudget* budget = nullptr);

}  // namespace kiln
