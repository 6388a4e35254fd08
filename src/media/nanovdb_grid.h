// One NanoVDB float grid as NanoVDB lays it out in memory (and in an uncompressed .nvdb file):
// GridData (672 bytes), TreeData (64), the root node with its tiles, upper internal nodes
// (32^3 children), lower internal nodes (16^3) and leaves (8^3 voxels), each node found by a
// byte offset from its parent. The layouts are those of NanoVDB 32.3 (NanoVDB.h of OpenVDB
// commit 414bed84, the version pbrt-v4 bundles); kiln reads them from the bytes, checking every
// offset and count against the grid's size, so a damaged grid is an error, never a read out of
// bounds. Errors are std::runtime_error("reason").
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace kiln {

// NanoVDB's GridType and GridClass values that kiln names
enum class NanoVDBGridType : uint32_t { Unknown = 0, Float = 1 };
enum class NanoVDBGridClass : uint32_t { Unknown = 0, LevelSet = 1, FogVolume = 2 };

// "NanoVDB0" read as a little-endian 64-bit integer: the magic number of files and grids
inline constexpr uint64_t kNanoVDBMagic = 0x304244566f6e614eull;

// Byte sizes and offsets of NanoVDB 32.3's structures (shared with the writer)
namespace nanovdb_layout {
inline constexpr uint64_t kGridDataBytes = 672, kTreeDataBytes = 64, kRootDataBytes = 64,
                          kRootTileBytes = 32;
inline constexpr uint64_t kUpperBytes = 270400, kLowerBytes = 33856, kLeafBytes = 2144;
// GridData fields
inline constexpr uint64_t kGridVersion = 16, kGridFlags = 20, kGridIndex = 24, kGridCount = 28,
                          kGridSize = 32, kGridName = 40, kGridNameBytes = 256, kMapMatF = 296,
                          kMapInvMatF = 332, kMapVecF = 368, kMapTaperF = 380, kMapMatD = 384,
                          kMapInvMatD = 456, kMapVecD = 528, kMapTaperD = 552, kWorldBBox = 560,
                          kVoxelSize = 608, kGridClass = 632, kGridType = 636;
// Internal nodes: masks, statistics and the table of 8-byte entries (a float value or the
// byte offset of a child from the node)
inline constexpr uint64_t kUpperValueMask = 32, kUpperChildMask = 4128, kUpperStats = 8224,
                          kUpperTable = 8256;
inline constexpr uint64_t kLowerValueMask = 32, kLowerChildMask = 544, kLowerStats = 1056,
                          kLowerTable = 1088;
inline constexpr uint64_t kLeafValueMask = 16, kLeafStats = 80, kLeafValues = 96;
}  // namespace nanovdb_layout

// The root table's key of the upper node holding voxel (x, y, z)
uint64_t NanoVDBRootKey(int32_t x, int32_t y, int32_t z);

// NanoVDBFloatGrid Definition
class NanoVDBFloatGrid {
  public:
    // bytes: the whole grid (its GridData's grid size). Checks the magic number, the version
    // (major 32), the type (float) and the root node's place; nodes below are checked as
    // lookups reach them.
    explicit NanoVDBFloatGrid(std::vector<uint8_t> bytes);

    const std::string& Name() const { return name; }
    NanoVDBGridClass Class() const { return gridClass; }
    // The index-to-world map: world = M index + t, M row-major
    const std::array<double, 9>& Matrix() const { return matrix; }
    const std::array<double, 3>& Translation() const { return translation; }
    // The inverse map: index = Minv (world - t)
    const std::array<double, 9>& InverseMatrix() const { return inverse; }
    // The world-space box the grid states (GridData's world bounding box: min x, y, z, max)
    const std::array<double, 6>& WorldBox() const { return worldBox; }
    // The box of the active voxels in index space, inclusive (the root node's): min, max
    const std::array<int32_t, 6>& IndexBox() const { return indexBox; }
    float Background() const { return background; }

    // The value NanoVDB's getValue returns at voxel (x, y, z): a leaf's value (active or
    // not), an internal node's or the root's tile value, else the background.
    float Value(int32_t x, int32_t y, int32_t z) const;

  private:
    template <typename T>
    T Read(uint64_t offset) const;
    // The offset of a node of nodeBytes at a signed byte offset from the node at `from`
    uint64_t Child(uint64_t from, int64_t offset, uint64_t nodeBytes) const;
    bool Bit(uint64_t maskOffset, uint32_t n) const;

    std::vector<uint8_t> bytes;
    std::string name;
    NanoVDBGridClass gridClass = NanoVDBGridClass::Unknown;
    std::array<double, 9> matrix{}, inverse{};
    std::array<double, 3> translation{};
    std::array<double, 6> worldBox{};
    std::array<int32_t, 6> indexBox{};
    float background = 0;
    uint64_t root = 0;
    // The root's tiles by key (the first tile of each key, as NanoVDB's linear search finds)
    std::vector<std::pair<uint64_t, uint32_t>> tilesByKey;
};

}  // namespace kiln
