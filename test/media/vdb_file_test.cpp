// OpenVDB volumes: a file written here with libopenvdb reads back as the dense grid of its
// active voxels, in the right place of the medium's space, with its temperature grid.
#include <gtest/gtest.h>

#include <openvdb/openvdb.h>

#include <unistd.h>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "../textures/param_helpers.h"
#include "base/memory_budget.h"
#include "media/medium.h"
#include "media/nanovdb_writer.h"
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
    // The active box and one layer of background beyond its far faces
    ASSERT_EQ(v.density.XSize(), 5);
    ASSERT_EQ(v.density.YSize(), 4);
    ASSERT_EQ(v.density.ZSize(), 4);
    EXPECT_FLOAT_EQ(v.density.At(0, 0, 0), 20 + 2 - 10);
    EXPECT_FLOAT_EQ(v.density.At(3, 2, 1), 20 + 5 + 10 + 100);
    EXPECT_FLOAT_EQ(v.density.At(4, 2, 1), 0);
    EXPECT_FLOAT_EQ(v.density.At(3, 3, 1), 0);
    EXPECT_FLOAT_EQ(v.density.At(3, 2, 3), 0);
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

// A .vdb file and the .nvdb file of the same grid (same voxels, same index-to-world map) give the
// same volume: values, box and map (the box NanoVDB's conversion states, [min, max + 1]).
TEST(VDBFileTest, ReadsAsItsNanoVDBConversion) {
    std::string path = WriteTestVolume();
    VDBVolume fromVdb = ReadVDBVolume(path, "density", "", test::TestLoc());
    NanoVDBGridDescription g;
    g.name = "density";
    g.origin = {2, -1, 0};
    g.nx = 4, g.ny = 3, g.nz = 3;
    for (int k = 0; k <= 2; ++k)
        for (int j = -1; j <= 1; ++j)
            for (int i = 2; i <= 5; ++i) g.values.push_back(float(20 + i + 10 * j + 100 * k));
    g.matrix = {0.5, 0, 0, 0, 0.5, 0, 0, 0, 0.5};
    g.translation = {1, 2, 3};
    std::string nvdb = path + ".nvdb";
    WriteNanoVDBFile(nvdb, {g});
    VDBVolume fromNvdb = ReadVDBVolume(nvdb, "density", "", test::TestLoc());
    ASSERT_EQ(fromVdb.density.XSize(), fromNvdb.density.XSize());
    ASSERT_EQ(fromVdb.density.YSize(), fromNvdb.density.YSize());
    ASSERT_EQ(fromVdb.density.ZSize(), fromNvdb.density.ZSize());
    for (int z = 0; z < 4; ++z)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 5; ++x)
                EXPECT_EQ(fromVdb.density.At(x, y, z), fromNvdb.density.At(x, y, z));
    EXPECT_EQ(fromVdb.indexBounds.pMin, fromNvdb.indexBounds.pMin);
    EXPECT_EQ(fromVdb.indexBounds.pMax, fromNvdb.indexBounds.pMax);
    EXPECT_EQ(fromVdb.sampleBounds.pMin, fromNvdb.sampleBounds.pMin);
    EXPECT_EQ(fromVdb.sampleBounds.pMax, fromNvdb.sampleBounds.pMax);
    EXPECT_EQ(fromVdb.mediumFromIndex.Matrix(), fromNvdb.mediumFromIndex.Matrix());
    EXPECT_EQ(fromNvdb.indexBounds.pMin, Point3f(2, -1, 0));
    EXPECT_EQ(fromNvdb.indexBounds.pMax, Point3f(6, 2, 3));
    std::remove(path.c_str());
    std::remove(nvdb.c_str());
}

// Issue 23: damaged .vdb files made OpenVDB allocate gigabytes or grow without end, and end in
// std::bad_alloc with no file or line. Now a garbage name length or grid count, every byte
// flipped in turn and truncations are each a SceneError naming the file (or, where OpenVDB
// does not notice the damage, a volume), under a 256 MB memory limit, with no other exception.
TEST(VDBFileTest, DamagedFilesAreErrorsNamingTheFile) {
    std::string path = WriteTestVolume();
    std::string bytes;
    {
        std::ifstream in(path, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    const std::string damaged = path + ".damaged.vdb";
    int errors = 0, reads = 0;
    auto attempt = [&](const std::string& contents, const std::string& what) {
        std::ofstream(damaged, std::ios::binary) << contents;
        MemoryBudget budget(256e6);
        try {
            ReadVDBVolume(damaged, "density", "temperature", test::TestLoc(), size_t(1) << 30,
                          &budget);
            ++reads;
        } catch (const SceneError& e) {
            ++errors;
            EXPECT_NE(std::string(e.what()).find(damaged), std::string::npos) << what << e.what();
        } catch (const std::exception& e) {
            ADD_FAILURE() << what << ": " << e.what();
        }
    };
    // The descriptor of the first grid: its name's length (4 bytes) before "density"; the
    // grid count (4 bytes) before that
    size_t name = bytes.find("density");
    ASSERT_NE(name, std::string::npos);
    for (size_t at : {name - 4, name - 8}) {
        std::string s = bytes;
        const uint32_t garbage = 0x7ffffff0;
        std::memcpy(&s[at], &garbage, 4);
        attempt(s, "garbage length at " + std::to_string(at));
    }
    EXPECT_EQ(errors, 2);
    for (size_t at = 0; at < bytes.size(); at += bytes.size() / 150) {
        std::string s = bytes;
        s[at] = char(~s[at]);
        attempt(s, "byte " + std::to_string(at) + " flipped");
    }
    for (size_t keep : {bytes.size() / 3, bytes.size() / 2, bytes.size() - 9})
        attempt(bytes.substr(0, keep), "truncated to " + std::to_string(keep));
    std::printf("%d damaged files: %d errors, %d read\n", errors + reads, errors, reads);
    std::remove(damaged.c_str());
    std::remove(path.c_str());
}

}  // namespace
}  // namespace kiln
