#include "media/nanovdb_volume.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "base/memory_budget.h"
#include "base/system_memory.h"
#include "core/parser/diagnostics.h"
#include "media/nanovdb_file.h"

namespace kiln {

namespace {

// The largest index coordinate kiln accepts (lattices stay far from int overflow)
constexpr double kMaxIndex = double(1 << 30);

// A grid's values sampled trilinearly at index point p (NanoVDB's trilinear sampler: values
// at integer coordinates)
double Trilinear(const NanoVDBFloatGrid& g, const std::array<double, 3>& p) {
    for (double c : p)
        if (!(std::abs(c) < kMaxIndex)) return g.Background();
    int32_t i[3];
    double f[3];
    for (int k = 0; k < 3; ++k) {
        double fl = std::floor(p[k]);
        i[k] = int32_t(fl);
        f[k] = p[k] - fl;
    }
    double v = 0;
    for (int c = 0; c < 8; ++c) {
        int dx = c & 1, dy = (c >> 1) & 1, dz = c >> 2;
        double w = (dx ? f[0] : 1 - f[0]) * (dy ? f[1] : 1 - f[1]) * (dz ? f[2] : 1 - f[2]);
        if (w > 0) v += w * g.Value(i[0] + dx, i[1] + dy, i[2] + dz);
    }
    return v;
}

std::array<double, 3> Apply(const std::array<double, 9>& m, const std::array<double, 3>& p) {
    return {m[0] * p[0] + m[1] * p[1] + m[2] * p[2], m[3] * p[0] + m[4] * p[1] + m[5] * p[2],
            m[6] * p[0] + m[7] * p[1] + m[8] * p[2]};
}

// pbrt-v4 reads fog volumes and grids of unknown class ("isn't a FogVolume grid?" otherwise)
void CheckClass(const NanoVDBFloatGrid& g) {
    if (g.Class() != NanoVDBGridClass::FogVolume && g.Class() != NanoVDBGridClass::Unknown)
        throw std::runtime_error(
            "the grid \"" + g.Name() + "\" is not a fog volume (NanoVDB grid class " +
            std::to_string(uint32_t(g.Class())) +
            (g.Class() == NanoVDBGridClass::LevelSet ? ", a level set)" : ")"));
}

}  // namespace

VDBVolume ReadNanoVDBVolume(const std::string& filename, const std::string& densityName,
                            const std::string& temperatureName, const FileLoc& loc,
                            size_t maxVoxels, MemoryBudget* budget) {
    auto fail = [&](const std::string& why) {
        throw SceneError(loc, filename + ": " + why, filename);
    };
    std::optional<NanoVDBFloatGrid> density, temperature;
    try {
        NanoVDBFile file(filename);
        double allowance = budget ? budget->Remaining() : PhysicalMemoryBytes() / 2;
        uint64_t maxBytes = allowance > 0 ? uint64_t(std::min(allowance, 9e18)) : uint64_t(1) << 62;
        density = file.ReadFloatGrid(densityName, maxBytes);
        if (!density) {
            std::string names;
            for (const NanoVDBFile::Entry& e : file.Grids())
                names += (names.empty() ? "\"" : ", \"") + e.name + "\"";
            fail("no \"" + densityName + "\" grid (the file has " +
                 (names.empty() ? std::string("no grids") : names) + ")");
        }
        CheckClass(*density);
        if (!temperatureName.empty()) {
            temperature = file.ReadFloatGrid(temperatureName, maxBytes);
            if (temperature) CheckClass(*temperature);
        }
    } catch (const SceneError&) {
        throw;
    } catch (const std::runtime_error& e) {
        fail(e.what());
    }

    // The medium's box in index space: the stated world box mapped back (exact for maps
    // without rotation; else the index-space box around it), within the active voxels' box
    // and a voxel beyond it, outside which every value is the background
    const std::array<double, 9>& m = density->Matrix();
    double det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) +
                 m[2] * (m[3] * m[7] - m[4] * m[6]);
    if (!(std::abs(det) > 0) || !std::isfinite(det))
        fail("the grid \"" + densityName + "\" has a singular index-to-world map");
    const std::array<int32_t, 6>& box = density->IndexBox();
    if (box[0] > box[3] || box[1] > box[4] || box[2] > box[5])
        fail("the grid \"" + densityName + "\" has no active voxels");
    for (int32_t c : box)
        if (!(std::abs(double(c)) < kMaxIndex))
            fail("the grid \"" + densityName + "\" has voxels beyond 2^30 of the origin");
    const std::array<double, 6>& w = density->WorldBox();
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (int c = 0; c < 8; ++c) {
        std::array<double, 3> p = {w[c & 1 ? 3 : 0] - density->Translation()[0],
                                   w[c & 2 ? 4 : 1] - density->Translation()[1],
                                   w[c & 4 ? 5 : 2] - density->Translation()[2]};
        std::array<double, 3> i = Apply(density->InverseMatrix(), p);
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], i[k]), hi[k] = std::max(hi[k], i[k]);
    }
    int64_t first[3], last[3];
    for (int k = 0; k < 3; ++k) {
        lo[k] = std::max(lo[k], double(box[k]) - 1);
        hi[k] = std::min(hi[k], double(box[k + 3]) + 2);
        if (!(lo[k] < hi[k]))  // also NaN
            fail("the grid \"" + densityName +
                 "\"'s world bounding box does not contain its active voxels");
        first[k] = int64_t(std::floor(lo[k]));
        last[k] = int64_t(std::ceil(hi[k]));
    }
    const int64_t nx = last[0] - first[0] + 1, ny = last[1] - first[1] + 1,
                  nz = last[2] - first[2] + 1;
    double voxels = double(nx) * double(ny) * double(nz);
    size_t n = ChargeDenseVolume(voxels, temperature.has_value(), filename, densityName, loc,
                                 maxVoxels, budget);

    // Temperatures at the density's voxels: its own values if the maps agree
    const bool sameMap = temperature && temperature->Matrix() == density->Matrix() &&
                         temperature->Translation() == density->Translation();
    std::vector<Float> d(n), t(temperature ? n : 0);
    // A damaged node met on the way is an error naming the file
    try {
        size_t at = 0;
        for (int64_t z = first[2]; z <= last[2]; ++z)
            for (int64_t y = first[1]; y <= last[1]; ++y)
                for (int64_t x = first[0]; x <= last[0]; ++x, ++at) {
                    float v = density->Value(int32_t(x), int32_t(y), int32_t(z));
                    if (!std::isfinite(v))
                        fail("the grid \"" + densityName + "\" has a non-finite value at voxel (" +
                             std::to_string(x) + ", " + std::to_string(y) + ", " +
                             std::to_string(z) + ")");
                    d[at] = std::max(0.f, v);  // negative densities as 0, as for .vdb files
                    if (!temperature) continue;
                    double T;
                    if (sameMap) {
                        T = temperature->Value(int32_t(x), int32_t(y), int32_t(z));
                    } else {
                        std::array<double, 3> world =
                            Apply(density->Matrix(), {double(x), double(y), double(z)});
                        for (int k = 0; k < 3; ++k)
                            world[k] += density->Translation()[k] - temperature->Translation()[k];
                        T = Trilinear(*temperature, Apply(temperature->InverseMatrix(), world));
                    }
                    if (!std::isfinite(T))
                        fail("the grid \"" + temperatureName + "\" has non-finite values");
                    t[at] = Float(T);
                }
    } catch (const SceneError&) {
        throw;
    } catch (const std::runtime_error& e) {
        fail(e.what());
    }

    VDBVolume v;
    v.density = SampledGrid<Float>(std::move(d), int(nx), int(ny), int(nz));
    if (temperature) v.temperature = SampledGrid<Float>(std::move(t), int(nx), int(ny), int(nz));
    v.indexBounds = Bounds3f(Point3f(lo[0], lo[1], lo[2]), Point3f(hi[0], hi[1], hi[2]));
    v.sampleBounds = Bounds3f(Point3f(first[0] - 0.5f, first[1] - 0.5f, first[2] - 0.5f),
                              Point3f(last[0] + 0.5f, last[1] + 0.5f, last[2] + 0.5f));
    const std::array<double, 3>& tr = density->Translation();
    Float c[16] = {Float(m[0]), Float(m[1]), Float(m[2]), Float(tr[0]),
                   Float(m[3]), Float(m[4]), Float(m[5]), Float(tr[1]),
                   Float(m[6]), Float(m[7]), Float(m[8]), Float(tr[2]),
                   0,           0,           0,           1};
    v.mediumFromIndex = Transform(SquareMatrix4(c));
    return v;
}

}  // namespace kiln
