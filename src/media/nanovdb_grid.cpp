#include "media/nanovdb_grid.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace kiln {

using namespace nanovdb_layout;

uint64_t NanoVDBRootKey(int32_t x, int32_t y, int32_t z) {
    // 21 bits per axis of the coordinate's upper node (4096 voxels wide), x highest
    return uint64_t(uint32_t(z) >> 12) | (uint64_t(uint32_t(y) >> 12) << 21) |
           (uint64_t(uint32_t(x) >> 12) << 42);
}

template <typename T>
T NanoVDBFloatGrid::Read(uint64_t offset) const {
    if (offset > bytes.size() || bytes.size() - offset < sizeof(T))
        throw std::runtime_error("the grid \"" + name + "\" is damaged: a node lies beyond its " +
                                 std::to_string(bytes.size()) + " bytes");
    T v;
    std::memcpy(&v, bytes.data() + offset, sizeof(T));
    return v;
}

uint64_t NanoVDBFloatGrid::Child(uint64_t from, int64_t offset, uint64_t nodeBytes) const {
    // from <= size (a buffer in memory, far below 2^63): the sum is checked before it is made
    const int64_t size = int64_t(bytes.size());
    if (offset < -int64_t(from) || offset > size - int64_t(from) || int64_t(nodeBytes) > size ||
        int64_t(from) + offset > size - int64_t(nodeBytes))
        throw std::runtime_error("the grid \"" + name +
                                 "\" is damaged: a child node's offset points outside its " +
                                 std::to_string(bytes.size()) + " bytes");
    return uint64_t(int64_t(from) + offset);
}

bool NanoVDBFloatGrid::Bit(uint64_t maskOffset, uint32_t n) const {
    return (Read<uint64_t>(maskOffset + 8 * (n >> 6)) >> (n & 63)) & 1;
}

NanoVDBFloatGrid::NanoVDBFloatGrid(std::vector<uint8_t> data) : bytes(std::move(data)) {
    if (bytes.size() < kGridDataBytes + kTreeDataBytes + kRootDataBytes)
        throw std::runtime_error("a grid of " + std::to_string(bytes.size()) +
                                 " bytes is too small for NanoVDB's grid header");
    // "NanoVDB0"; later NanoVDB versions mark grids "NanoVDB1"
    uint64_t magic = Read<uint64_t>(0);
    if (magic != kNanoVDBMagic && magic != kNanoVDBMagic + (uint64_t(1) << 56))
        throw std::runtime_error("a grid lacks NanoVDB's magic number (the file is damaged)");
    const char* nameBytes = reinterpret_cast<const char*>(bytes.data() + kGridName);
    name.assign(nameBytes, strnlen(nameBytes, kGridNameBytes));
    uint32_t version = Read<uint32_t>(kGridVersion);
    if ((version >> 21) != 32)
        throw std::runtime_error(
            "the grid \"" + name + "\" is of NanoVDB version " + std::to_string(version >> 21) +
            "." + std::to_string((version >> 10) & 2047) + "; kiln reads version 32 (pbrt-v4's)");
    uint32_t type = Read<uint32_t>(kGridType);
    if (type != uint32_t(NanoVDBGridType::Float))
        throw std::runtime_error("the grid \"" + name + "\" is not a float grid (NanoVDB type " +
                                 std::to_string(type) + ")");
    if (Read<uint64_t>(kGridSize) != bytes.size())
        throw std::runtime_error("the grid \"" + name + "\" states a size of " +
                                 std::to_string(Read<uint64_t>(kGridSize)) + " bytes, not its " +
                                 std::to_string(bytes.size()) + " (the file is damaged)");
    gridClass = NanoVDBGridClass(Read<uint32_t>(kGridClass));
    for (int i = 0; i < 9; ++i) {
        matrix[i] = Read<double>(kMapMatD + 8 * i);
        inverse[i] = Read<double>(kMapInvMatD + 8 * i);
    }
    for (int i = 0; i < 3; ++i) translation[i] = Read<double>(kMapVecD + 8 * i);
    for (int i = 0; i < 6; ++i) worldBox[i] = Read<double>(kWorldBBox + 8 * i);
    auto finite = [](const auto& values) {
        return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
    };
    if (!finite(matrix) || !finite(inverse) || !finite(translation))
        throw std::runtime_error("the grid \"" + name + "\" has a non-finite index-to-world map");

    // TreeData: the root's offset from the tree is its fourth node offset
    root = Child(kGridDataBytes, int64_t(Read<uint64_t>(kGridDataBytes + 24)), kRootDataBytes);
    for (int i = 0; i < 6; ++i) indexBox[i] = Read<int32_t>(root + 4 * i);
    uint32_t tableSize = Read<uint32_t>(root + 24);
    if (tableSize > (bytes.size() - root - kRootDataBytes) / kRootTileBytes)
        throw std::runtime_error("the grid \"" + name + "\" is damaged: its root states " +
                                 std::to_string(tableSize) + " tiles, beyond its bytes");
    background = Read<float>(root + 28);
    tilesByKey.reserve(tableSize);
    for (uint32_t i = 0; i < tableSize; ++i)
        tilesByKey.emplace_back(Read<uint64_t>(root + kRootDataBytes + kRootTileBytes * i), i);
    // Sorted by key, then index: the first of equal keys is the tile a linear search finds
    std::sort(tilesByKey.begin(), tilesByKey.end());
    tilesByKey.erase(std::unique(tilesByKey.begin(), tilesByKey.end(),
                                 [](const auto& a, const auto& b) { return a.first == b.first; }),
                     tilesByKey.end());
}

float NanoVDBFloatGrid::Value(int32_t x, int32_t y, int32_t z) const {
    uint64_t key = NanoVDBRootKey(x, y, z);
    auto it =
        std::lower_bound(tilesByKey.begin(), tilesByKey.end(), std::make_pair(key, uint32_t(0)));
    if (it == tilesByKey.end() || it->first != key) return background;
    uint64_t tile = root + kRootDataBytes + kRootTileBytes * it->second;
    int64_t child = Read<int64_t>(tile + 8);
    if (child == 0) return Read<float>(tile + 20);
    // Upper node: 32^3 entries of 128^3 voxels, x slowest
    uint64_t upper = Child(root, child, kUpperBytes);
    uint32_t n = (uint32_t((x & 4095) >> 7) << 10) | (uint32_t((y & 4095) >> 7) << 5) |
                 uint32_t((z & 4095) >> 7);
    if (!Bit(upper + kUpperChildMask, n)) return Read<float>(upper + kUpperTable + 8 * n);
    // Lower node: 16^3 entries of 8^3 voxels
    uint64_t lower = Child(upper, Read<int64_t>(upper + kUpperTable + 8 * n), kLowerBytes);
    n = (uint32_t((x & 127) >> 3) << 8) | (uint32_t((y & 127) >> 3) << 4) |
        uint32_t((z & 127) >> 3);
    if (!Bit(lower + kLowerChildMask, n)) return Read<float>(lower + kLowerTable + 8 * n);
    // Leaf: 8^3 values
    uint64_t leaf = Child(lower, Read<int64_t>(lower + kLowerTable + 8 * n), kLeafBytes);
    n = (uint32_t(x & 7) << 6) | (uint32_t(y & 7) << 3) | uint32_t(z & 7);
    return Read<float>(leaf + kLeafValues + 4 * n);
}

}  // namespace kiln
