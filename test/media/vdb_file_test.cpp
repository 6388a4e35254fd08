// OpenVDB volumes: a file written here with libopenvdb reads back as the dense grid of its
// active voxels, in the right place of the medium's space, with its temperature grid.
#include <gtest/gtest.h>

#include <openvdb/openvdb.h>

#include <unistd.h>
#include <cstdio>
#include <filesystem>

#include "../textures/param_helpers.h"
#include "media/medium.h"
#include "media/vdb_file.h"
#include "spectral/planck.h"

namespace kiln {
namespace {

// density(i, j, k) = 20 + i + 10 j + 100 k over i in [2, 5], j in [-1, 1], k in [0, 2] with
// voxels of 0.5 units offset by (1, 2, 3); temperature 1000 + 100 i on a finer grid.
std::string WriteTestVolume() {
    openvdb::initialize();
    auto density = openvdb::FloatGrid::create(0.f);
    density->setName("density");
    density->setTransform(openvdb::math::Transform::createLinearTransform(0.5));
    density->transform().postTranslate(openvdb::Vec3d(1, 2, 3));
    auto acc = density->getAccessor();
    for (int k = 0; k <= 2; ++k)
        for (int j = -1; j <= 1; ++j)
            for (int i = 2; i <= 5; ++i)
                acc.setValue(openvdb::Coord(i, j, k), float(20 + i + 10 * j + 100 * k));
    auto temperature = openvdb::FloatGrid::create(0.f);
    temperature->setName("temperature");
    temperature->setTransform(openvdb::math::Transform::createLinearTransform(0.25));
    temperature->transform().postTranslate(openvdb::Vec3d(1, 2, 3));
    auto tacc = temperature->getAccessor();
    for (int k = -4; k <= 8; ++k)
        for (int j = -6; j <= 6; ++j)
            for (int i = 0; i <= 14; ++i)
                tacc.setValue(openvdb::Coord(i, j, k), float(1000 + 100 * (i * 0.5)));
    std::string path = (std::filesystem::temp_directory_path() /
                        ("kiln-vdb-test-" + std::to_string(getpid()) + ".vdb"))
                           .string();
    openvdb::io::File file(path);
    file.write({density, temperature});
    file.close();
    return path;
}

TEST(VDBFileTest, ReadsTheActiveVoxelsWithTheirTransformAndTemperatures) {
    std::string path = WriteTestVolume();
    VDBVolume v = ReadVDBVolume(path, "density", "temperature", test::TestLoc());
    ASSERT_EQ(v.density.XSize(), 4);
    ASSERT_EQ(v.density.YSize(), 3);
    ASSERT_EQ(v.density.ZSize(), 3);
    EXPECT_FLOAT_EQ(v.density.At(0, 0, 0), 20 + 2 - 10);
    EXPECT_FLOAT_EQ(v.density.At(3, 2, 1), 20 + 5 + 10 + 100);
    ASSERT_FALSE(v.temperature.Empty());
    EXPECT_NEAR(v.temperature.At(1, 0, 0), 1000 + 100 * 3, 1e-2);  // index 3 of the density

    // As a medium: at the world position of density voxel (4, 1, 2) the density is its value
    ObjectArena arena;
    Diagnostics diag(nullptr);
    ParameterDictionary d =
        test::Dict({test::String1("filename", path), test::Rgb("sigma_a", 1, 1, 1),
                    test::Rgb("sigma_s", 0, 0, 0), test::String1("emission", "kirchhoff")});
    TextureParameterDictionary tp(&d, nullptr);
    Medium m = Medium::Create("nanovdb", tp, Translate(Vector3f(-1, 0, 0)), std::nullopt,
                              test::TestLoc(), arena, diag);
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    Point3f p(1 + 0.5f * 4 - 1, 2 + 0.5f * 1, 3 + 0.5f * 2);
    MediumProperties mp = m.SamplePoint(p, lambda);
    EXPECT_NEAR(mp.sigma_a[0], 20 + 4 + 10 + 200, 1e-3);
    SampledSpectrum B = planck_radiance(lambda, 1000 + 100 * 4);
    EXPECT_NEAR(mp.emission[0], mp.sigma_a[0] * B[0], 1e-3 * mp.sigma_a[0] * B[0]);
    EXPECT_TRUE(m.IsThermal());
    // Beyond the volume, nothing
    EXPECT_EQ(m.SamplePoint(Point3f(50, 0, 0), lambda).sigma_a[0], 0);

    EXPECT_THROW(ReadVDBVolume(path, "smoke", "", test::TestLoc()), SceneError);
    EXPECT_THROW(ReadVDBVolume(path, "density", "", test::TestLoc(), 10), SceneError);
    std::remove(path.c_str());
}

}  // namespace
}  // namespace kiln
