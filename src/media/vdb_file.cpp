#include "media/vdb_file.h"

#include <memory>
#include <stdexcept>

#include "base/memory_budget.h"
#include "base/plugin.h"
#include "core/parser/diagnostics.h"
#include "media/vdb_reader.h"

namespace kiln {

VDBVolume ReadVDBVolume(const std::string& filename, const std::string& densityName,
                        const std::string& temperatureName, const FileLoc& loc, size_t maxVoxels,
                        MemoryBudget* budget) {
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
        using Open = VDBFileReader* (*)(const char*, const char*, const char*);
        auto open = reinterpret_cast<Open>(PluginSymbol("libkiln_openvdb.so", kOpenVDBFileSymbol));
        std::unique_ptr<VDBFileReader> file(
            open(filename.c_str(), densityName.c_str(), temperatureName.c_str()));
        const std::array<int, 6> box = file->ActiveBox();
        const int nx = box[3] - box[0] + 1, ny = box[4] - box[1] + 1, nz = box[5] - box[2] + 1;
        size_t n = size_t(nx) * size_t(ny) * size_t(nz);
        if (n > maxVoxels)
            throw SceneError(loc,
                             filename + ": the density grid spans " + std::to_string(n) +
                                 " voxels; kiln resamples volumes densely and allows at most " +
                                 std::to_string(maxVoxels),
                             densityName);
        const bool hasTemperature = file->HasTemperature();
        if (budget) {
            try {
                budget->Charge(
                    double(n) * sizeof(Float) * (hasTemperature ? 2 : 1),
                    "the dense grids of \"" + filename + "\" (" + std::to_string(n) + " voxels)");
            } catch (const MemoryLimitError& e) {
                throw SceneError(loc, e.what(), filename);
            }
        }
        // Dense copies over the density's active box; temperatures sampled (trilinearly) at
        // the density's voxel centres
        std::vector<Float> d(n), t(hasTemperature ? n : 0);
        file->ReadDense(d.data(), hasTemperature ? t.data() : nullptr);
        v.density = SampledGrid<Float>(std::move(d), nx, ny, nz);
        if (hasTemperature) v.temperature = SampledGrid<Float>(std::move(t), nx, ny, nz);
        v.indexBounds = Bounds3f(Point3f(box[0] - 0.5f, box[1] - 0.5f, box[2] - 0.5f),
                                 Point3f(box[3] + 0.5f, box[4] + 0.5f, box[5] + 0.5f));
        const std::array<double, 16> m = file->IndexToWorld();
        Float c[16];
        for (int i = 0; i < 16; ++i) c[i] = Float(m[i]);
        v.mediumFromIndex = Transform(SquareMatrix4(c));
    } catch (const SceneError&) {
        throw;
    } catch (const std::runtime_error& e) {  // the file, a grid or the plugin
        throw SceneError(loc, filename + ": " + e.what(), filename);
    }
    return v;
}

}  // namespace kiln
