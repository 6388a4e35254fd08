#include "media/vdb_file.h"

#include "core/base/memory_budget.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Interpolation.h>

#include <mutex>
#include <optional>

#include "core/parser/diagnostics.h"

namespace kiln {

namespace {

openvdb::FloatGrid::Ptr ReadFloatGrid(openvdb::io::File& file, const std::string& name,
                                      const std::string& filename, const FileLoc& loc) {
    openvdb::GridBase::Ptr base = file.readGrid(name);
    openvdb::FloatGrid::Ptr grid = openvdb::gridPtrCast<openvdb::FloatGrid>(base);
    if (!grid)
        throw SceneError(loc, filename + ": grid \"" + name + "\" is not a float grid", name);
    if (!grid->transform().isLinear())
        throw SceneError(loc, filename + ": grid \"" + name + "\" has a non-linear transform",
                         name);
    return grid;
}

}  // namespace

VDBVolume ReadVDBVolume(const std::string& filename, const std::string& densityName,
                        const std::string& temperatureName, const FileLoc& loc, size_t maxVoxels,
                        MemoryBudget* budget) {
    static std::once_flag initialized;
    std::call_once(initialized, [] { openvdb::initialize(); });
    if (filename.size() >= 5 && filename.compare(filename.size() - 5, 5, ".nvdb") == 0)
        throw SceneError(loc,
                         filename +
                             ": kiln cannot read NanoVDB files (no Debian 12 package provides "
                             "NanoVDB); convert the volume to OpenVDB (.vdb, e.g. with "
                             "nanovdb_convert) and name that file: \"nanovdb\" and \"vdb\" "
                             "media read .vdb files",
                         filename);
    VDBVolume v;
    try {
        openvdb::io::File file(filename);
        file.open();
        if (!file.hasGrid(densityName))
            throw SceneError(loc, filename + ": no \"" + densityName + "\" grid", densityName);
        openvdb::FloatGrid::Ptr density = ReadFloatGrid(file, densityName, filename, loc);
        openvdb::FloatGrid::Ptr temperature;
        if (!temperatureName.empty() && file.hasGrid(temperatureName))
            temperature = ReadFloatGrid(file, temperatureName, filename, loc);
        file.close();

        openvdb::CoordBBox box = density->evalActiveVoxelBoundingBox();
        if (box.empty())
            throw SceneError(loc, filename + ": grid \"" + densityName + "\" has no active voxels",
                             densityName);
        openvdb::Coord dim = box.dim();
        size_t n = size_t(dim.x()) * size_t(dim.y()) * size_t(dim.z());
        if (n > maxVoxels)
            throw SceneError(loc,
                             filename + ": the density grid spans " + std::to_string(n) +
                                 " voxels; kiln resamples volumes densely and allows at most " +
                                 std::to_string(maxVoxels),
                             densityName);
        if (budget) {
            try {
                budget->Charge(
                    double(n) * sizeof(Float) * (temperature ? 2 : 1),
                    "the dense grids of \"" + filename + "\" (" + std::to_string(n) + " voxels)");
            } catch (const MemoryLimitError& e) {
                throw SceneError(loc, e.what(), filename);
            }
        }
        // Dense copies over the density's active box; temperatures sampled (trilinearly) at
        // the density's voxel centres
        std::vector<Float> d(n), t(temperature ? n : 0);
        auto densityAccess = density->getConstAccessor();
        using Sampler = openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler>;
        std::optional<Sampler> tSampler;
        if (temperature) tSampler.emplace(*temperature);
        size_t i = 0;
        for (int z = box.min().z(); z <= box.max().z(); ++z)
            for (int y = box.min().y(); y <= box.max().y(); ++y)
                for (int x = box.min().x(); x <= box.max().x(); ++x, ++i) {
                    openvdb::Coord ijk(x, y, z);
                    d[i] = std::max(0.f, densityAccess.getValue(ijk));
                    if (tSampler)
                        t[i] = Float(tSampler->wsSample(density->transform().indexToWorld(ijk)));
                }
        v.density = SampledGrid<Float>(std::move(d), dim.x(), dim.y(), dim.z());
        if (temperature)
            v.temperature = SampledGrid<Float>(std::move(t), dim.x(), dim.y(), dim.z());
        v.indexBounds =
            Bounds3f(Point3f(box.min().x() - 0.5f, box.min().y() - 0.5f, box.min().z() - 0.5f),
                     Point3f(box.max().x() + 0.5f, box.max().y() + 0.5f, box.max().z() + 0.5f));
        // OpenVDB multiplies row vectors (world = index * M); kiln column vectors
        openvdb::math::Mat4d m = density->transform().baseMap()->getAffineMap()->getMat4();
        Float c[16];
        for (int r = 0; r < 4; ++r)
            for (int k = 0; k < 4; ++k) c[4 * r + k] = Float(m[k][r]);
        v.mediumFromIndex = Transform(SquareMatrix4(c));
    } catch (const openvdb::Exception& e) {
        throw SceneError(loc, filename + ": " + e.what(), filename);
    }
    return v;
}

}  // namespace kiln
