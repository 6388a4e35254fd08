#include "media/nanovdb_writer.h"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <stdexcept>
#include <tuple>

namespace kiln {

using namespace nanovdb_layout;

namespace {

// NanoVDB 32.3.3: major << 21 | minor << 10 | patch
constexpr uint32_t kVersion = 32u << 21 | 3u << 10 | 3u;

using Coord = std::tuple<int32_t, int32_t, int32_t>;

template <typename T>
void Put(std::vector<uint8_t>& b, uint64_t offset, T v) {
    std::memcpy(b.data() + offset, &v, sizeof(T));
}

void SetBit(std::vector<uint8_t>& b, uint64_t mask, uint32_t n) {
    b[mask + n / 8] |= uint8_t(1u << (n % 8));  // little-endian 64-bit words
}

std::array<double, 9> Inverse(const std::array<double, 9>& m) {
    double det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) +
                 m[2] * (m[3] * m[7] - m[4] * m[6]);
    if (!(std::abs(det) > 0)) throw std::runtime_error("singular index-to-world matrix");
    return {(m[4] * m[8] - m[5] * m[7]) / det, (m[2] * m[7] - m[1] * m[8]) / det,
            (m[1] * m[5] - m[2] * m[4]) / det, (m[5] * m[6] - m[3] * m[8]) / det,
            (m[0] * m[8] - m[2] * m[6]) / det, (m[2] * m[3] - m[0] * m[5]) / det,
            (m[3] * m[7] - m[4] * m[6]) / det, (m[1] * m[6] - m[0] * m[7]) / det,
            (m[0] * m[4] - m[1] * m[3]) / det};
}

// Statistics written into nodes: min, max, average, standard deviation of the voxels' values
struct Stats {
    float lo = 0, hi = 0;
    double sum = 0, sum2 = 0;
    uint64_t n = 0;
    void Add(float v) {
        lo = n ? std::min(lo, v) : v, hi = n ? std::max(hi, v) : v;
        sum += v, sum2 += double(v) * v, ++n;
    }
    void Write(std::vector<uint8_t>& b, uint64_t at) const {
        double mean = n ? sum / n : 0;
        Put(b, at, lo), Put(b, at + 4, hi), Put(b, at + 8, float(mean));
        Put(b, at + 12, float(std::sqrt(std::max(0.0, n ? sum2 / n - mean * mean : 0))));
    }
};

}  // namespace

uint64_t NanoVDBNameHash(const std::string& name) {
    uint64_t hash = 0;
    for (unsigned char c : name) {
        uint64_t overflow = hash >> 56;
        hash = hash * 67 + c + overflow;
    }
    return hash;
}

std::vector<uint8_t> NanoVDBGridBytes(const NanoVDBGridDescription& g) {
    if (g.nx <= 0 || g.ny <= 0 || g.nz <= 0 ||
        g.values.size() != size_t(g.nx) * size_t(g.ny) * size_t(g.nz))
        throw std::runtime_error("a NanoVDB grid needs nx * ny * nz > 0 values");
    if (g.name.size() >= kGridNameBytes) throw std::runtime_error("grid name too long");
    const int32_t x0 = g.origin[0], y0 = g.origin[1], z0 = g.origin[2];
    const int32_t x1 = x0 + g.nx - 1, y1 = y0 + g.ny - 1, z1 = z0 + g.nz - 1;
    auto value = [&](int32_t x, int32_t y, int32_t z) {
        return g.values[(size_t(z - z0) * g.ny + size_t(y - y0)) * g.nx + size_t(x - x0)];
    };
    auto inside = [&](int32_t x, int32_t y, int32_t z) {
        return x >= x0 && x <= x1 && y >= y0 && y <= y1 && z >= z0 && z <= z1;
    };
    // The nodes that hold voxels, by origin (sorted: NanoVDB's breadth-first order)
    std::map<Coord, uint32_t> leaves, lowers, uppers;
    for (int32_t z = z0; z <= z1; ++z)
        for (int32_t y = y0; y <= y1; ++y)
            for (int32_t x = x0; x <= x1; ++x) {
                leaves.emplace(Coord(x & ~7, y & ~7, z & ~7), 0);
                lowers.emplace(Coord(x & ~127, y & ~127, z & ~127), 0);
                uppers.emplace(Coord(x & ~4095, y & ~4095, z & ~4095), 0);
            }
    const uint64_t tree = kGridDataBytes, root = tree + kTreeDataBytes;
    const uint64_t nodes = root + kRootDataBytes + kRootTileBytes * uppers.size();
    const uint64_t upperBytes = kUpperBytes * uppers.size(),
                   lowerBytes = kLowerBytes * lowers.size(), leafBytes = kLeafBytes * leaves.size();
    const uint64_t firstUpper = g.uppersLast ? nodes + leafBytes + lowerBytes : nodes;
    const uint64_t firstLower = g.uppersLast ? nodes + leafBytes : nodes + upperBytes;
    const uint64_t firstLeaf = g.uppersLast ? nodes : nodes + upperBytes + lowerBytes;
    const uint64_t size = nodes + upperBytes + lowerBytes + leafBytes;
    uint32_t i = 0;
    for (auto& u : uppers) u.second = i++;
    i = 0;
    for (auto& l : lowers) l.second = i++;
    i = 0;
    for (auto& l : leaves) l.second = i++;
    std::vector<uint8_t> b(size, 0);

    // GridData
    Put(b, 0, kNanoVDBMagic);
    Put(b, 8, ~uint64_t(0));  // no checksum
    Put(b, kGridVersion, kVersion);
    Put(b, kGridFlags, uint32_t(2 | 4 | 32));  // bounding box, min/max, breadth-first
    Put(b, kGridIndex, uint32_t(0));
    Put(b, kGridCount, uint32_t(1));
    Put(b, kGridSize, size);
    std::memcpy(b.data() + kGridName, g.name.data(), g.name.size());
    const std::array<double, 9> inv = Inverse(g.matrix);
    for (int k = 0; k < 9; ++k) {
        Put(b, kMapMatF + 4 * k, float(g.matrix[k]));
        Put(b, kMapInvMatF + 4 * k, float(inv[k]));
        Put(b, kMapMatD + 8 * k, g.matrix[k]);
        Put(b, kMapInvMatD + 8 * k, inv[k]);
    }
    for (int k = 0; k < 3; ++k) {
        Put(b, kMapVecF + 4 * k, float(g.translation[k]));
        Put(b, kMapVecD + 8 * k, g.translation[k]);
    }
    Put(b, kMapTaperF, 1.f);
    Put(b, kMapTaperD, 1.0);
    // World box: the index box [min, max + 1] mapped (as NanoVDB's grid statistics make it)
    auto map = [&](int k, double x, double y, double z) {
        return g.matrix[3 * k] * x + g.matrix[3 * k + 1] * y + g.matrix[3 * k + 2] * z +
               g.translation[k];
    };
    for (int k = 0; k < 3; ++k) {
        double lo = 1e300, hi = -1e300;
        for (int c = 0; c < 8; ++c) {
            double w = map(k, c & 1 ? x1 + 1 : x0, c & 2 ? y1 + 1 : y0, c & 4 ? z1 + 1 : z0);
            lo = std::min(lo, w), hi = std::max(hi, w);
        }
        Put(b, kWorldBBox + 8 * k, lo);
        Put(b, kWorldBBox + 24 + 8 * k, hi);
        Put(b, kVoxelSize + 8 * k, map(k, 1, 1, 1) - map(k, 0, 0, 0));
    }
    Put(b, kGridClass, uint32_t(g.gridClass));
    Put(b, kGridType, uint32_t(NanoVDBGridType::Float));

    // TreeData: offsets of the first leaf, lower, upper node and the root from the tree
    Put(b, tree, firstLeaf - tree);
    Put(b, tree + 8, firstLower - tree);
    Put(b, tree + 16, firstUpper - tree);
    Put(b, tree + 24, root - tree);
    Put(b, tree + 32, uint32_t(leaves.size()));
    Put(b, tree + 36, uint32_t(lowers.size()));
    Put(b, tree + 40, uint32_t(uppers.size()));
    Put(b, tree + 56, uint64_t(g.values.size()));

    // Nodes: value masks, child masks and tables; statistics over each node's voxels
    std::vector<Stats> upperStats(uppers.size()), lowerStats(lowers.size()),
        leafStats(leaves.size());
    Stats all;
    auto boxOf = [&](uint64_t at, const Coord& o, int32_t width) {
        Put(b, at, std::max(x0, std::get<0>(o)));
        Put(b, at + 4, std::max(y0, std::get<1>(o)));
        Put(b, at + 8, std::max(z0, std::get<2>(o)));
        Put(b, at + 12, std::min(x1, std::get<0>(o) + width - 1));
        Put(b, at + 16, std::min(y1, std::get<1>(o) + width - 1));
        Put(b, at + 20, std::min(z1, std::get<2>(o) + width - 1));
    };
    for (const auto& [o, index] : uppers) {
        uint64_t at = firstUpper + kUpperBytes * index;
        boxOf(at, o, 4096);
        for (uint32_t n = 0; n < 32768; ++n) Put(b, at + kUpperTable + 8 * n, g.background);
    }
    for (const auto& [o, index] : lowers) {
        uint64_t at = firstLower + kLowerBytes * index;
        boxOf(at, o, 128);
        for (uint32_t n = 0; n < 4096; ++n) Put(b, at + kLowerTable + 8 * n, g.background);
        const auto& [x, y, z] = o;
        uint64_t upper =
            firstUpper + kUpperBytes * uppers.at(Coord(x & ~4095, y & ~4095, z & ~4095));
        uint32_t n = uint32_t((x & 4095) >> 7) << 10 | uint32_t((y & 4095) >> 7) << 5 |
                     uint32_t((z & 4095) >> 7);
        SetBit(b, upper + kUpperChildMask, n);
        Put(b, upper + kUpperTable + 8 * n, int64_t(at) - int64_t(upper));
    }
    for (const auto& [o, index] : leaves) {
        uint64_t at = firstLeaf + kLeafBytes * index;
        const auto& [x, y, z] = o;
        uint64_t lower = firstLower + kLowerBytes * lowers.at(Coord(x & ~127, y & ~127, z & ~127));
        uint32_t n = uint32_t((x & 127) >> 3) << 8 | uint32_t((y & 127) >> 3) << 4 |
                     uint32_t((z & 127) >> 3);
        SetBit(b, lower + kLowerChildMask, n);
        Put(b, lower + kLowerTable + 8 * n, int64_t(at) - int64_t(lower));
        int32_t bx = std::max(x0, x), by = std::max(y0, y), bz = std::max(z0, z);
        Put(b, at, bx), Put(b, at + 4, by), Put(b, at + 8, bz);
        b[at + 12] = uint8_t(std::min(x1, x + 7) - bx);
        b[at + 13] = uint8_t(std::min(y1, y + 7) - by);
        b[at + 14] = uint8_t(std::min(z1, z + 7) - bz);
        Stats& s = leafStats[index];
        for (uint32_t v = 0; v < 512; ++v) {
            int32_t vx = x + int32_t(v >> 6), vy = y + int32_t((v >> 3) & 7),
                    vz = z + int32_t(v & 7);
            float f = g.background;
            if (inside(vx, vy, vz)) {
                f = value(vx, vy, vz);
                SetBit(b, at + kLeafValueMask, v);
                s.Add(f), all.Add(f);
                lowerStats[lowers.at(Coord(x & ~127, y & ~127, z & ~127))].Add(f);
                upperStats[uppers.at(Coord(x & ~4095, y & ~4095, z & ~4095))].Add(f);
            }
            Put(b, at + kLeafValues + 4 * v, f);
        }
        s.Write(b, at + kLeafStats);
    }
    for (const auto& l : lowers)
        lowerStats[l.second].Write(b, firstLower + kLowerBytes * l.second + kLowerStats);
    for (const auto& u : uppers)
        upperStats[u.second].Write(b, firstUpper + kUpperBytes * u.second + kUpperStats);

    // RootData and its tiles, one per upper node
    Put(b, root, x0), Put(b, root + 4, y0), Put(b, root + 8, z0);
    Put(b, root + 12, x1), Put(b, root + 16, y1), Put(b, root + 20, z1);
    Put(b, root + 24, uint32_t(uppers.size()));
    Put(b, root + 28, g.background);
    all.Write(b, root + 32);
    for (const auto& [o, index] : uppers) {
        uint64_t tile = root + kRootDataBytes + kRootTileBytes * index;
        Put(b, tile, NanoVDBRootKey(std::get<0>(o), std::get<1>(o), std::get<2>(o)));
        Put(b, tile + 8, int64_t(firstUpper + kUpperBytes * index - root));
    }
    return b;
}

void WriteNanoVDBFile(const std::string& filename, const std::vector<NanoVDBGridDescription>& grids,
                      NanoVDBCodec codec) {
    if (codec != NanoVDBCodec::None && codec != NanoVDBCodec::Zip)
        throw std::runtime_error("kiln writes NanoVDB codecs NONE and ZIP");
    std::vector<uint8_t> out(16, 0);
    Put(out, 0, kNanoVDBMagic);
    Put(out, 8, kVersion);
    Put(out, 12, uint16_t(grids.size()));
    Put(out, 14, uint16_t(codec));
    auto append = [&](const void* p, size_t n) {
        out.insert(out.end(), static_cast<const uint8_t*>(p), static_cast<const uint8_t*>(p) + n);
    };
    std::vector<std::vector<uint8_t>> data;
    for (const NanoVDBGridDescription& g : grids) {
        std::vector<uint8_t> b = NanoVDBGridBytes(g);
        // io::MetaData (176 bytes): sizes, name hash, voxel count, type, class, world and
        // index boxes, voxel size (copied from the grid), name size, node and tile counts,
        // codec, version; then the name and its NUL
        std::vector<uint8_t> m(176, 0);
        Put(m, 0, uint64_t(b.size()));
        Put(m, 16, NanoVDBNameHash(g.name));
        Put(m, 24, uint64_t(g.values.size()));
        Put(m, 32, uint32_t(NanoVDBGridType::Float));
        Put(m, 36, uint32_t(g.gridClass));
        std::memcpy(m.data() + 40, b.data() + kWorldBBox, 48);
        std::memcpy(m.data() + 88, b.data() + kGridDataBytes + kTreeDataBytes, 24);
        std::memcpy(m.data() + 112, b.data() + kVoxelSize, 24);
        Put(m, 136, uint32_t(g.name.size() + 1));
        std::memcpy(m.data() + 140, b.data() + kGridDataBytes + 32, 12);  // leaf, lower, upper
        Put(m, 152, uint32_t(1));                                         // the root
        Put(m, 168, uint16_t(codec));
        Put(m, 172, kVersion);
        if (codec == NanoVDBCodec::Zip) {
            uLongf n = compressBound(uLong(b.size()));
            std::vector<uint8_t> z(8 + n);
            if (compress(z.data() + 8, &n, b.data(), uLong(b.size())) != Z_OK)
                throw std::runtime_error("zlib failed to compress a grid");
            z.resize(8 + n);
            uint64_t n64 = n;
            std::memcpy(z.data(), &n64, 8);
            b = std::move(z);
        }
        Put(m, 8, uint64_t(b.size()));  // the bytes in the file
        append(m.data(), m.size());
        append(g.name.c_str(), g.name.size() + 1);
        data.push_back(std::move(b));
    }
    for (const std::vector<uint8_t>& d : data) append(d.data(), d.size());
    std::ofstream f(filename, std::ios::binary | std::ios::trunc);
    if (!f.write(reinterpret_cast<const char*>(out.data()), std::streamsize(out.size())))
        throw std::runtime_error("cannot write " + filename);
}

}  // namespace kiln
