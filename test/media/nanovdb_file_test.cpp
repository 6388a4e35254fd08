// NanoVDB volumes: files written by kiln's writer read back as the grids written (values,
// boxes, maps; several grids; ZIP), become the dense grids and medium box pbrt-v4's
// NanoVDBMedium sees, and damaged files are SceneErrors naming the file.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "../textures/param_helpers.h"
#include "base/memory_budget.h"
#include "media/medium.h"
#include "media/nanovdb_file.h"
#include "media/nanovdb_volume.h"
#include "media/nanovdb_writer.h"
#include "media/vdb_file.h"

namespace kiln {
namespace {

std::string TempPath(const std::string& name) {
    return (std::filesystem::temp_directory_path() /
            ("kiln-nvdb-" + std::to_string(getpid()) + "-" + name))
        .string();
}

// A value that differs at every voxel
float DensityAt(int x, int y, int z) { return 1 + 0.01f * (x % 100) + 0.1f * y + 0.5f * z; }

// Voxels (4093..4098, -2..1, 125..129): across two upper nodes (x = 4096), two lower nodes
// (z = 128) and several leaves; voxels of 0.5 units, offset by (1, 2, 3)
NanoVDBGridDescription Density(const std::string& name = "density", int32_t x0 = 4093) {
    NanoVDBGridDescription g;
    g.name = name;
    g.origin = {x0, -2, 125};
    g.nx = 6, g.ny = 4, g.nz = 5;
    for (int z = 0; z < g.nz; ++z)
        for (int y = 0; y < g.ny; ++y)
            for (int x = 0; x < g.nx; ++x) g.values.push_back(DensityAt(x0 + x, y - 2, 125 + z));
    g.matrix = {0.5, 0, 0, 0, 0.5, 0, 0, 0, 0.5};
    g.translation = {1, 2, 3};
    return g;
}

// Temperatures 1000 + 100 world x on voxels of 0.25 units covering Density(.., x0)
NanoVDBGridDescription Temperature(int32_t x0 = 4093) {
    NanoVDBGridDescription g;
    g.name = "temperature";
    g.origin = {2 * x0 - 6, -12, 240};
    g.nx = 30, g.ny = 24, g.nz = 30;
    g.matrix = {0.25, 0, 0, 0, 0.25, 0, 0, 0, 0.25};
    g.translation = {1, 2, 3};
    for (int z = 0; z < g.nz; ++z)
        for (int y = 0; y < g.ny; ++y)
            for (int x = 0; x < g.nx; ++x)
                g.values.push_back(float(1000 + 100 * (1 + 0.25 * (g.origin[0] + x))));
    return g;
}

TEST(NanoVDBFileTest, WrittenGridsReadBackWithTheirValuesBoxesAndMaps) {
    // Uncompressed in NanoVDB's order; ZIP with upper nodes last
    for (NanoVDBCodec codec : {NanoVDBCodec::None, NanoVDBCodec::Zip}) {
        std::string path = TempPath("roundtrip.nvdb");
        NanoVDBGridDescription density = Density(), level = Density("level");
        level.gridClass = NanoVDBGridClass::LevelSet;
        density.uppersLast = codec == NanoVDBCodec::Zip;
        WriteNanoVDBFile(path, {density, Temperature(), level}, codec);
        NanoVDBFile file(path);
        ASSERT_EQ(file.Grids().size(), 3u);
        EXPECT_EQ(file.Grids()[1].name, "temperature");
        std::optional<NanoVDBFloatGrid> g = file.ReadFloatGrid("density", 1 << 30);
        ASSERT_TRUE(g);
        EXPECT_EQ(g->Name(), "density");
        EXPECT_EQ(g->Class(), NanoVDBGridClass::FogVolume);
        EXPECT_EQ(g->IndexBox(), (std::array<int32_t, 6>{4093, -2, 125, 4098, 1, 129}));
        // The world box is the index box [min, max + 1] mapped
        EXPECT_EQ(g->WorldBox(), (std::array<double, 6>{1 + 0.5 * 4093, 2 - 1, 3 + 0.5 * 125,
                                                        1 + 0.5 * 4099, 2 + 1, 3 + 0.5 * 130}));
        EXPECT_EQ(g->Translation(), (std::array<double, 3>{1, 2, 3}));
        EXPECT_EQ(g->InverseMatrix()[4], 2);
        int mismatches = 0;
        for (int z = 123; z <= 131; ++z)
            for (int y = -4; y <= 3; ++y)
                for (int x = 4091; x <= 4100; ++x) {
                    bool in = x >= 4093 && x <= 4098 && y >= -2 && y <= 1 && z >= 125 && z <= 129;
                    mismatches += g->Value(x, y, z) != (in ? DensityAt(x, y, z) : 0.f);
                }
        EXPECT_EQ(mismatches, 0);
        EXPECT_FALSE(file.ReadFloatGrid("smoke", 1 << 30));
        // Later NanoVDB versions may mark files "NanoVDB2"
        {
            std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
            f.seekp(7);
            f.put('2');
        }
        EXPECT_EQ(NanoVDBFile(path).Grids().size(), 3u);
        EXPECT_EQ(file.ReadFloatGrid("level", 1 << 30)->Class(), NanoVDBGridClass::LevelSet);
        // A grid larger than the memory allowed is refused before it is allocated
        EXPECT_THROW(file.ReadFloatGrid("temperature", 1000), std::runtime_error);
        std::remove(path.c_str());
    }
}

// pbrt-v4's NanoVDBMedium: trilinear interpolation of the values at integer index
// coordinates, inside the grid's world box (the index box [min, max + 1])
TEST(NanoVDBFileTest, VolumesAreTheDenseGridsAndBoxPbrtSees) {
    std::string path = TempPath("volume.nvdb");
    WriteNanoVDBFile(path, {Temperature(), Density()});
    VDBVolume v = ReadVDBVolume(path, "density", "temperature", test::TestLoc());
    EXPECT_EQ(v.indexBounds.pMin, Point3f(4093, -2, 125));
    EXPECT_EQ(v.indexBounds.pMax, Point3f(4099, 2, 130));
    // Samples at integer coordinates 4093..4099 (the last layer the background)
    ASSERT_EQ(v.density.XSize(), 7);
    ASSERT_EQ(v.density.YSize(), 5);
    ASSERT_EQ(v.density.ZSize(), 6);
    EXPECT_EQ(v.sampleBounds.pMin, Point3f(4092.5f, -2.5f, 124.5f));
    EXPECT_FLOAT_EQ(v.density.At(2, 1, 3), DensityAt(4095, -1, 128));
    EXPECT_EQ(v.density.At(6, 1, 3), 0);
    // Temperatures of the finer grid at the density's voxels (linear in x: exact)
    ASSERT_FALSE(v.temperature.Empty());
    EXPECT_NEAR(v.temperature.At(3, 2, 1), 1000 + 100 * (1 + 0.5 * 4096), 0.05);
    Point3f world = v.mediumFromIndex(Point3f(4093, -2, 125));
    EXPECT_FLOAT_EQ(world.x, 1 + 0.5f * 4093);
    EXPECT_FLOAT_EQ(world.z, 3 + 0.5f * 125);

    // As a medium, at index (4095.25, -0.5, 128.75): the trilinear value of the lattice
    ObjectArena arena;
    Diagnostics diag(nullptr);
    ParameterDictionary d =
        test::Dict({test::String1("filename", path), test::Rgb("sigma_a", 1, 1, 1),
                    test::Rgb("sigma_s", 0, 0, 0)});
    TextureParameterDictionary tp(&d, nullptr);
    Medium m =
        Medium::Create("nanovdb", tp, Transform(), std::nullopt, test::TestLoc(), arena, diag);
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    auto at = [&](double x, double y, double z) {
        return m.SamplePoint(Point3f(1 + 0.5 * x, 2 + 0.5 * y, 3 + 0.5 * z), lambda).sigma_a[0];
    };
    auto lattice = [&](double x, double y, double z) {
        double v = 0;
        for (int c = 0; c < 8; ++c) {
            int i = int(std::floor(x)) + (c & 1), j = int(std::floor(y)) + (c >> 1 & 1),
                k = int(std::floor(z)) + (c >> 2);
            bool in = i >= 4093 && i <= 4098 && j >= -2 && j <= 1 && k >= 125 && k <= 129;
            double w = (c & 1 ? x - std::floor(x) : 1 - x + std::floor(x)) *
                       (c >> 1 & 1 ? y - std::floor(y) : 1 - y + std::floor(y)) *
                       (c >> 2 ? z - std::floor(z) : 1 - z + std::floor(z));
            v += w * (in ? DensityAt(i, j, k) : 0);
        }
        return v;
    };
    for (auto p : {std::array<double, 3>{4095.25, -0.5, 128.75},
                   {4098.5, 1.5, 129.5},
                   {4093.1, -1.9, 125.2}})
        EXPECT_NEAR(at(p[0], p[1], p[2]), lattice(p[0], p[1], p[2]), 1e-4) << p[0];
    // Within the box beyond the last active voxel (toward the background), and outside it
    EXPECT_GT(at(4098.5, 0, 127), 0);
    EXPECT_EQ(at(4092.9, 0, 127), 0);
    EXPECT_EQ(at(4099.1, 0, 127), 0);
    EXPECT_TRUE(m.IsEmissive());

    // Errors naming the file: a missing grid, a level set, the voxel limit
    WriteNanoVDBFile(path, {[] {
                         NanoVDBGridDescription g = Density();
                         g.gridClass = NanoVDBGridClass::LevelSet;
                         return g;
                     }()});
    for (auto [name, maxVoxels] :
         {std::pair<std::string, size_t>{"smoke", 1 << 20}, {"density", 1 << 20}})
        EXPECT_THROW(ReadVDBVolume(path, name, "", test::TestLoc(), maxVoxels), SceneError);
    WriteNanoVDBFile(path, {Density()});
    EXPECT_THROW(ReadVDBVolume(path, "density", "", test::TestLoc(), 100), SceneError);
    EXPECT_TRUE(ReadVDBVolume(path, "density", "temperature", test::TestLoc()).temperature.Empty());
    std::remove(path.c_str());
}

// Truncations, flipped bytes, garbage counts and sizes and a BLOSC codec are each a
// SceneError naming the file (or, where the damage is harmless, a volume), with no other
// exception, under a 256 MB budget
TEST(NanoVDBFileTest, DamagedFilesAreErrorsNamingTheFile) {
    for (NanoVDBCodec codec : {NanoVDBCodec::None, NanoVDBCodec::Zip}) {
        std::string path = TempPath("good.nvdb"), damaged = TempPath("damaged.nvdb");
        WriteNanoVDBFile(path, {Density("density", 10), Temperature(10)}, codec);
        std::string bytes;
        {
            std::ifstream in(path, std::ios::binary);
            bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        }
        int errors = 0, reads = 0;
        auto attempt = [&](const std::string& contents, const std::string& what) {
            std::ofstream(damaged, std::ios::binary) << contents;
            MemoryBudget budget(256e6);
            try {
                ReadVDBVolume(damaged, "density", "temperature", test::TestLoc(), size_t(1) << 22,
                              &budget);
                ++reads;
            } catch (const SceneError& e) {
                ++errors;
                EXPECT_NE(std::string(e.what()).find(damaged), std::string::npos) << what;
            } catch (const std::exception& e) {
                ADD_FAILURE() << what << ": " << e.what();
            }
        };
        auto patch = [&](size_t at, uint64_t v, size_t n) {
            std::string s = bytes;
            std::memcpy(&s[at], &v, n);
            return s;
        };
        // Header: magic, version, grid count, codec; the first grid's sizes and name length
        for (auto [at, v, n] : {std::tuple<size_t, uint64_t, size_t>{0, 0, 8},
                                {8, 33u << 21, 4},
                                {12, 0xffff, 2},
                                {14, 2, 2},
                                {16, uint64_t(1) << 60, 8},
                                {24, uint64_t(1) << 60, 8},
                                {16 + 136, 0x7ffffff0, 4}})
            attempt(patch(at, v, n), "patched at " + std::to_string(at));
        EXPECT_EQ(errors, 7);
        if (codec == NanoVDBCodec::None) {
            // The root tile's child offset, first met in a lookup, not when the grid is read
            // (found by fuzzing: an exception that was no SceneError): the density's bytes
            // follow the header and both grids' metadata and names
            size_t grid = 16 + 176 + sizeof("density") + 176 + sizeof("temperature");
            attempt(patch(grid + 672 + 64 + 64 + 8, uint64_t(1) << 40, 8), "root tile child");
            EXPECT_EQ(errors, 8);
        }
        for (size_t at = 0; at < bytes.size(); at += bytes.size() / 150) {
            std::string s = bytes;
            s[at] = char(~s[at]);
            attempt(s, "byte " + std::to_string(at) + " flipped");
        }
        for (size_t keep : {size_t(0), size_t(10), size_t(100), bytes.size() / 3, bytes.size() / 2,
                            bytes.size() - 1})
            attempt(bytes.substr(0, keep), "truncated to " + std::to_string(keep));
        std::printf("%d damaged files: %d errors, %d read\n", errors + reads, errors, reads);
        std::remove(damaged.c_str());
        std::remove(path.c_str());
    }
}

}  // namespace
}  // namespace kiln

namespace kiln {
namespace {

// The volume of test/regression/pbrt_features/nanovdb.pbrt: 12^3 voxels of 1/6 unit over
// [-1, 1]^3 (index 0..11; the world box [0, 12] mapped), a density and a temperature (kelvin)
// peaking at the centre, from integer arithmetic (exact on every machine)
std::vector<NanoVDBGridDescription> FeatureVolume() {
    NanoVDBGridDescription d, t;
    d.name = "density", t.name = "temperature";
    for (NanoVDBGridDescription* g : {&d, &t}) {
        g->nx = g->ny = g->nz = 12;
        g->matrix = {1.0 / 6, 0, 0, 0, 1.0 / 6, 0, 0, 0, 1.0 / 6};
        g->translation = {-1, -1, -1};
    }
    for (int k = 0; k < 12; ++k)
        for (int j = 0; j < 12; ++j)
            for (int i = 0; i < 12; ++i) {
                int r2 = (2 * i - 11) * (2 * i - 11) + (2 * j - 9) * (2 * j - 9) +
                         (2 * k - 13) * (2 * k - 13);  // off centre
                d.values.push_back(float(24 + 2880 / (r2 + 40)) / 32);
                t.values.push_back(float(500 + 100 * (1600 / (r2 + 100))));
            }
    return {d, t};
}

// The committed file is what kiln's writer makes of FeatureVolume (KILN_WRITE_NVDB=1 rewrites
// it), and reads back as it
TEST(NanoVDBFileTest, FeatureSceneVolumeIsTheWritersOutput) {
    const std::string committed =
        std::string(KILN_SOURCE_DIR) + "/test/regression/pbrt_features/nanovdb.nvdb";
    std::vector<NanoVDBGridDescription> grids = FeatureVolume();
    if (std::getenv("KILN_WRITE_NVDB")) WriteNanoVDBFile(committed, grids, NanoVDBCodec::Zip);
    NanoVDBFile file(committed);
    ASSERT_EQ(file.Grids().size(), 2u);
    for (const NanoVDBGridDescription& g : grids) {
        EXPECT_EQ(file.Grids()[&g - grids.data()].codec, NanoVDBCodec::Zip);
        std::optional<NanoVDBFloatGrid> read = file.ReadFloatGrid(g.name, 1 << 30);
        ASSERT_TRUE(read);
        EXPECT_EQ(read->Matrix(), g.matrix);
        EXPECT_EQ(read->Translation(), g.translation);
        EXPECT_EQ(read->WorldBox(), (std::array<double, 6>{-1, -1, -1, 1, 1, 1}));
        int mismatches = 0;
        for (int k = 0; k < 12; ++k)
            for (int j = 0; j < 12; ++j)
                for (int i = 0; i < 12; ++i)
                    mismatches += read->Value(i, j, k) != g.values[(k * 12 + j) * 12 + i];
        EXPECT_EQ(mismatches, 0) << g.name;
    }
}

}  // namespace
}  // namespace kiln
