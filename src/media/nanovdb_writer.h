// kiln's writer of NanoVDB files (.nvdb, the layout of NanoVDB 32.3, which pbrt-v4 bundles):
// float grids given as dense boxes of voxels, written as NanoVDB's tree (root tiles, upper and
// lower internal nodes, leaves, breadth-first as NanoVDB's builder lays them out) in one
// segment, uncompressed or with ZIP (zlib). For tests, fuzzing seeds and the feature scenes'
// volumes; pbrt-v4 reads what it writes (test/regression/pbrt_features/nanovdb.pbrt).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "media/nanovdb_file.h"
#include "media/nanovdb_grid.h"

namespace kiln {

struct NanoVDBGridDescription {
    std::string name;  // at most 255 bytes
    NanoVDBGridClass gridClass = NanoVDBGridClass::FogVolume;
    // The voxels: nx * ny * nz values, x fastest, values[0] at index `origin`; all active
    std::array<int32_t, 3> origin{};
    int nx = 0, ny = 0, nz = 0;
    std::vector<float> values;
    float background = 0;
    // index-to-world: world = matrix index + translation, matrix row-major (invertible)
    std::array<double, 9> matrix{1, 0, 0, 0, 1, 0, 0, 0, 1};
    std::array<double, 3> translation{};
    // Lay out leaves, lower nodes, then upper nodes (NanoVDB's builder: the reverse). Readers
    // follow the offsets, so both read alike; a file whose last upper node holds voxels near
    // its origin ends in that node's zero table entries (the fuzzing seeds drop them).
    bool uppersLast = false;
};

// The grid's bytes as NanoVDB lays them out in memory (what an uncompressed file holds)
std::vector<uint8_t> NanoVDBGridBytes(const NanoVDBGridDescription& grid);

// Writes the grids to filename in one segment; std::runtime_error if that fails
void WriteNanoVDBFile(const std::string& filename, const std::vector<NanoVDBGridDescription>& grids,
                      NanoVDBCodec codec = NanoVDBCodec::None);

// NanoVDB's hash of a grid name (io::stringHash), which files store beside the name
uint64_t NanoVDBNameHash(const std::string& name);

}  // namespace kiln
