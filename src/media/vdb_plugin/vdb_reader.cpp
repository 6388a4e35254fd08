// The OpenVDB plugin (libkiln_openvdb.so): reads a density grid and an optional temperature
// grid from a .vdb file (see ../vdb_reader.h). Loaded by ReadVDBVolume on first use.
#include <openvdb/openvdb.h>
#include <openvdb/tools/Interpolation.h>

#include <algorithm>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>

#include "media/vdb_reader.h"

namespace kiln {

namespace {

openvdb::FloatGrid::Ptr ReadFloatGrid(openvdb::io::File& file, const std::string& name) {
    openvdb::FloatGrid::Ptr grid = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid(name));
    if (!grid) throw std::runtime_error("grid \"" + name + "\" is not a float grid");
    if (!grid->transform().isLinear())
        throw std::runtime_error("grid \"" + name + "\" has a non-linear transform");
    return grid;
}

class OpenVDBFileReader final : public VDBFileReader {
  public:
    OpenVDBFileReader(const std::string& filename, const std::string& densityName,
                      const std::string& temperatureName) {
        openvdb::io::File file(filename);
        file.open();
        if (!file.hasGrid(densityName)) throw std::runtime_error("no \"" + densityName + "\" grid");
        density = ReadFloatGrid(file, densityName);
        if (!temperatureName.empty() && file.hasGrid(temperatureName))
            temperature = ReadFloatGrid(file, temperatureName);
        file.close();
        box = density->evalActiveVoxelBoundingBox();
        if (box.empty())
            throw std::runtime_error("grid \"" + densityName + "\" has no active voxels");
    }

    std::array<int, 6> ActiveBox() const override {
        return {box.min().x(), box.min().y(), box.min().z(),
                box.max().x(), box.max().y(), box.max().z()};
    }

    bool HasTemperature() const override { return bool(temperature); }

    std::array<double, 16> IndexToWorld() const override {
        // OpenVDB multiplies row vectors (world = index * M); kiln column vectors
        openvdb::math::Mat4d m = density->transform().baseMap()->getAffineMap()->getMat4();
        std::array<double, 16> c;
        for (int r = 0; r < 4; ++r)
            for (int k = 0; k < 4; ++k) c[4 * r + k] = m[k][r];
        return c;
    }

    void ReadDense(float* d, float* t) const override {
        auto densityAccess = density->getConstAccessor();
        using Sampler = openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler>;
        std::optional<Sampler> tSampler;
        if (temperature && t) tSampler.emplace(*temperature);
        size_t i = 0;
        for (int z = box.min().z(); z <= box.max().z(); ++z)
            for (int y = box.min().y(); y <= box.max().y(); ++y)
                for (int x = box.min().x(); x <= box.max().x(); ++x, ++i) {
                    openvdb::Coord ijk(x, y, z);
                    d[i] = std::max(0.f, densityAccess.getValue(ijk));
                    if (tSampler)
                        t[i] = float(tSampler->wsSample(density->transform().indexToWorld(ijk)));
                }
    }

  private:
    openvdb::FloatGrid::Ptr density, temperature;
    openvdb::CoordBBox box;
};

}  // namespace

}  // namespace kiln

extern "C" kiln::VDBFileReader* KilnOpenVDBFile(const char* filename, const char* densityGrid,
                                                const char* temperatureGrid) {
    static std::once_flag initialized;
    std::call_once(initialized, [] { openvdb::initialize(); });
    try {
        return new kiln::OpenVDBFileReader(filename, densityGrid, temperatureGrid);
    } catch (const openvdb::Exception& e) {
        throw std::runtime_error(e.what());
    }
}
