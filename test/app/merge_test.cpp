// Tiles and sample sets (issue 14): a tile (--pixelbounds) is bit-identical to the same pixels
// of a full render at any thread count, and `kiln merge` of tiles is bit-identical to the full
// render, in half and in float; merges that would be wrong are refused with nothing written;
// `kiln merge --samples` weights renders by their samples.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "app/command_line.h"
#include "app/merge.h"
#include "app_test_util.h"
#include "core/film/thermal_sensor.h"

namespace kiln {
namespace {

namespace fs = std::filesystem;

struct Dir {
    fs::path path;
    Dir() {
        path = fs::path(::testing::TempDir()) / ("kiln_merge_" + std::to_string(::getpid()));
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~Dir() { fs::remove_all(path); }
    std::string operator/(const std::string& name) const { return (path / name).string(); }
};

// A small scene with a diffuse floor, a glossy sphere, an area light and an environment.
std::string WriteScene(const Dir& dir, bool savefp16, const std::string& name = "scene.pbrt") {
    std::string file = dir / name;
    std::ofstream(file)
        << "Film \"rgb\" \"integer xresolution\" 24 \"integer yresolution\" 20 "
           "\"bool savefp16\" "
        << (savefp16 ? "true" : "false") << "\n"
        << "Sampler \"zsobol\" \"integer pixelsamples\" 8\n"
           "LookAt 0 1 4  0 0.4 0  0 1 0\nCamera \"perspective\" \"float fov\" 40\n"
           "WorldBegin\nLightSource \"infinite\" \"rgb L\" [0.3 0.3 0.4]\n"
           "AttributeBegin AreaLightSource \"diffuse\" \"rgb L\" [5 5 5]\n"
           "Translate 0 2 0 ReverseOrientation Shape \"disk\" \"float radius\" 0.5\n"
           "AttributeEnd\n"
           "Material \"coateddiffuse\" \"rgb reflectance\" [0.6 0.3 0.2]\n"
           "Shape \"bilinearmesh\" \"point3 P\" [-3 0 -3 3 0 -3 -3 0 3 3 0 3]\n"
           "Material \"conductor\" \"float roughness\" 0.1\n"
           "AttributeBegin Translate 0 0.5 0 Shape \"sphere\" \"float radius\" 0.5 "
           "AttributeEnd\n";
    return file;
}

int Kiln(std::vector<std::string> args) {
    args.insert(args.begin(), "kiln");
    args.push_back("--quiet");
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    return RunKiln(int(argv.size()), argv.data());
}

// Four tiles of 24 x 20 (uneven), each rendered with a different thread count.
std::vector<std::string> RenderTiles(const Dir& dir, const std::string& scene,
                                     const std::string& prefix, int seed = 3) {
    const int bounds[4][4] = {{0, 10, 0, 7}, {10, 24, 0, 7}, {0, 17, 7, 20}, {17, 24, 7, 20}};
    std::vector<std::string> files;
    for (int t = 0; t < 4; ++t) {
        std::string out = dir / (prefix + std::to_string(t) + ".exr");
        std::vector<std::string> args = {scene, "--seed", std::to_string(seed), "--pixelbounds"};
        for (int k = 0; k < 4; ++k) args.push_back(std::to_string(bounds[t][k]));
        args.insert(args.end(), {"--nthreads", std::to_string(1 + t % 2), "-o", out});
        EXPECT_EQ(Kiln(args), 0);
        files.push_back(out);
    }
    return files;
}

TEST(Merge, TilesAreBitIdenticalToTheFullRender) {
    Dir dir;
    for (bool half : {false, true}) {
        SCOPED_TRACE(half ? "savefp16" : "float");
        std::string scene = WriteScene(dir, half);
        std::string full = dir / "full.exr";
        ASSERT_EQ(Kiln({scene, "--seed", "3", "-o", full}), 0);
        std::vector<std::string> tiles = RenderTiles(dir, scene, "tile");
        // A tile records the frame it belongs to, and is float whatever the film asks
        ImageMetadata meta;
        Image tile = Image::Read(tiles[3], &meta);
        ASSERT_TRUE(meta.fullResolution && meta.pixelBounds);
        EXPECT_EQ(*meta.fullResolution, Point2i(24, 20));
        EXPECT_EQ(meta.pixelBounds->pMin, Point2i(17, 7));
        EXPECT_EQ(tile.Format(), PixelFormat::Float);
        // Its pixels are the full render's (exactly, when the full render is float)
        if (!half) {
            Image f = Image::Read(full);
            for (int y = 0; y < 13; ++y)
                for (int x = 0; x < 7; ++x)
                    for (int c = 0; c < 3; ++c)
                        ASSERT_EQ(tile.GetChannel({x, y}, c), f.GetChannel({17 + x, 7 + y}, c));
        }
        std::string merged = dir / "merged.exr";
        std::vector<std::string> args = {"merge"};
        args.insert(args.end(), tiles.begin(), tiles.end());
        args.insert(args.end(), {"-o", merged});
        ASSERT_EQ(Kiln(args), 0);
        // Under a memory limit the parts and the frame are charged as they are read and
        // made: 1 kB is refused, naming what did not fit, and nothing is written
        std::vector<std::string> limited = args;
        limited.back() = dir / "limited.exr";
        limited.insert(limited.end(), {"--memory-limit", "1k"});
        ::testing::internal::CaptureStderr();
        EXPECT_EQ(Kiln(limited), 1);
        std::string err = ::testing::internal::GetCapturedStderr();
        EXPECT_NE(err.find("the memory limit of 1 kB (--memory-limit)"), std::string::npos) << err;
        EXPECT_FALSE(fs::exists(limited.back()));
        std::vector<float> a = testing::Pixels(merged), b = testing::Pixels(full);
        EXPECT_EQ(Image::Read(merged).Format(), Image::Read(full).Format());
        ASSERT_EQ(a.size(), b.size());
        for (size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i], b[i]) << i;
        EXPECT_GT(b[100], 0);
    }
}

TEST(Merge, WrongMergesAreRefusedAndWriteNothing) {
    Dir dir;
    std::string scene = WriteScene(dir, true);
    std::vector<std::string> tiles = RenderTiles(dir, scene, "tile");
    std::string out = dir / "out.exr";
    auto merge = [&](const std::vector<std::string>& parts) {
        std::vector<std::string> args = {"merge"};
        args.insert(args.end(), parts.begin(), parts.end());
        args.insert(args.end(), {"-o", out});
        return Kiln(args);
    };
    // A missing tile, a tile twice, a tile with another seed, a tile of another scene
    EXPECT_EQ(merge({tiles[0], tiles[1], tiles[2]}), 1);
    EXPECT_EQ(merge({tiles[0], tiles[1], tiles[2], tiles[3], tiles[0]}), 1);
    std::vector<std::string> seed4 = RenderTiles(dir, scene, "seed4_", 4);
    EXPECT_EQ(merge({tiles[0], tiles[1], tiles[2], seed4[3]}), 1);
    std::string other = WriteScene(dir, false, "other.pbrt");
    std::vector<std::string> otherTiles = RenderTiles(dir, other, "other");
    EXPECT_EQ(merge({tiles[0], tiles[1], tiles[2], otherTiles[3]}), 1);
    // The last tile rendered with another emission model (same scene, seed and pixels)
    std::string additive = dir / "additive3.exr";
    ASSERT_EQ(Kiln({scene, "--seed", "3", "--pixelbounds", "17", "24", "7", "20", "--emission",
                    "additive", "-o", additive}),
              0);
    EXPECT_EQ(merge({tiles[0], tiles[1], tiles[2], additive}), 1);
    EXPECT_FALSE(fs::exists(out));
    // The library says what is wrong
    std::vector<RenderPart> parts;
    for (const std::string& f : {tiles[0], tiles[1], tiles[2]}) {
        RenderPart p;
        p.file = f;
        p.image = Image::Read(f, &p.metadata);
        parts.push_back(p);
    }
    ImageMetadata meta;
    try {
        MergeTiles(parts, &meta);
        ADD_FAILURE() << "merged with a tile missing";
    } catch (const std::runtime_error& e) {
        // The missing tile: 7 x 13 pixels at (17, 7)
        EXPECT_NE(std::string(e.what()).find("91 of the frame's 480 pixels are in no part (all "
                                             "within [17, 24) x [7, 20))"),
                  std::string::npos)
            << e.what();
    }
    // Usage errors
    EXPECT_EQ(Kiln({"merge", tiles[0]}), 2);
}

TEST(Merge, SamplesAreWeightedBySamplesPerPixel) {
    Dir dir;
    std::string scene = WriteScene(dir, false);
    std::string a = dir / "a.exr", b = dir / "b.exr", out = dir / "ab.exr";
    ASSERT_EQ(Kiln({scene, "--seed", "1", "--spp", "8", "-o", a}), 0);
    ASSERT_EQ(Kiln({scene, "--seed", "2", "--spp", "32", "-o", b}), 0);
    ASSERT_EQ(Kiln({"merge", "--samples", a, b, "-o", out}), 0);
    ImageMetadata meta;
    Image m = Image::Read(out, &meta);
    EXPECT_EQ(meta.samplesPerPixel, 40);
    Image ia = Image::Read(a), ib = Image::Read(b);
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 24; ++x)
            for (int c = 0; c < 3; ++c)
                ASSERT_FLOAT_EQ(
                    m.GetChannel({x, y}, c),
                    float((8.0 * ia.GetChannel({x, y}, c) + 32.0 * ib.GetChannel({x, y}, c)) / 40));
    // The same seed twice is the same samples
    EXPECT_EQ(Kiln({"merge", "--samples", a, a, "-o", dir / "aa.exr"}), 1);
    EXPECT_FALSE(fs::exists(dir / "aa.exr"));
}

// Thermal films: the merged L is the weighted mean, T the temperature the sensor reports for
// it (from the parts' kiln:thermal metadata), not the mean of the parts' temperatures
TEST(Merge, ThermalSamplesReportTheTemperatureOfTheMergedRadiance) {
    Dir dir;
    std::string scene = dir / "thermal.pbrt";
    std::ofstream(scene) << "Film \"thermal\" \"string sensor\" \"mwir\" \"float emissivity\" 0.8 "
                            "\"float reflectedtemperature\" 290 \"integer xresolution\" 12 "
                            "\"integer yresolution\" 10\n"
                            "Sampler \"independent\" \"integer pixelsamples\" 2\n"
                            "LookAt 0 0 -4 0 0 0 0 1 0\nCamera \"perspective\" \"float fov\" 40\n"
                            "WorldBegin\nMaterial \"conductor\" \"float roughness\" 0.3 "
                            "\"float temperature\" 800\nShape \"sphere\" \"float radius\" 1\n";
    std::string a = dir / "a.exr", b = dir / "b.exr", out = dir / "ab.exr";
    ASSERT_EQ(Kiln({scene, "--seed", "1", "-o", a}), 0);
    ASSERT_EQ(Kiln({scene, "--seed", "2", "--spp", "6", "-o", b}), 0);
    ASSERT_EQ(Kiln({"merge", "--samples", a, b, "-o", out}), 0);
    ImageMetadata meta;
    Image m = Image::Read(out, &meta);
    std::optional<ThermalSensor> sensor = ThermalSensor::FromSettings(meta.strings["kiln:thermal"]);
    ASSERT_TRUE(sensor);
    EXPECT_EQ(sensor->Emissivity(), 0.8f);
    Image ia = Image::Read(a), ib = Image::Read(b);
    const int L = m.ChannelIndex("L"), T = m.ChannelIndex("T");
    ASSERT_GE(L, 0);
    ASSERT_GE(T, 0);
    int hot = 0;
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 12; ++x) {
            float la = ia.GetChannel({x, y}, L), lb = ib.GetChannel({x, y}, L);
            float merged = float((2.0 * la + 6.0 * lb) / 8);
            ASSERT_FLOAT_EQ(m.GetChannel({x, y}, L), merged);
            ASSERT_FLOAT_EQ(m.GetChannel({x, y}, T), float(sensor->ApparentTemperature(merged)));
            hot += m.GetChannel({x, y}, T) > 0;
        }
    EXPECT_GT(hot, 10);
}

// Parts that no render of kiln's could have written are refused, with nothing written: a
// non-finite pixel (an infinity here: Image::SetChannel stores NaN as 0, so a test cannot write
// a NaN part; the check is the same), and headers that claim a frame far larger than the parts
// (refused from the rectangles, before a frame of that size is allocated)
TEST(Merge, DamagedAndOverclaimingPartsAreRefused) {
    Dir dir;
    auto part = [&](const std::string& name, Point2i full, Bounds2i bounds, float value) {
        Point2i size(bounds.pMax.x - bounds.pMin.x, bounds.pMax.y - bounds.pMin.y);
        Image im(PixelFormat::Float, size, {"R", "G", "B"});
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x)
                for (int c = 0; c < 3; ++c)
                    im.SetChannel({x, y}, c, x == 1 && y == 0 ? value : 0.5f);
        ImageMetadata md;
        md.samplesPerPixel = 8;
        md.fullResolution = full;
        md.pixelBounds = bounds;
        md.strings["kiln:scene"] = "0123456789abcdef";
        md.strings["kiln:seed"] = "1";
        md.strings["kiln:savefp16"] = "false";
        std::string file = dir / name;
        im.Write(file, md);
        RenderPart p;
        p.file = file;
        p.image = Image::Read(file, &p.metadata);
        return p;
    };
    auto refusal = [&](const std::vector<RenderPart>& parts) {
        ImageMetadata meta;
        try {
            MergeTiles(parts, &meta);
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
        return std::string("merged");
    };
    const Point2i full(4, 2);
    RenderPart left = part("left.exr", full, {{0, 0}, {2, 2}}, 0.5f);
    RenderPart right = part("right.exr", full, {{2, 0}, {4, 2}}, 0.5f);
    EXPECT_EQ(refusal({left, right}), "merged");
    for (float bad :
         {std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()}) {
        RenderPart damaged = part("damaged.exr", full, {{2, 0}, {4, 2}}, bad);
        std::string why = refusal({left, damaged});
        EXPECT_NE(why.find("damaged.exr: pixel 1, 0 R is not finite"), std::string::npos) << why;
    }
    // Four 2 x 2 tiles whose headers claim a 60000 x 60000 frame
    std::vector<RenderPart> claims;
    for (int t = 0; t < 4; ++t)
        claims.push_back(part("claim" + std::to_string(t) + ".exr", Point2i(60000, 60000),
                              {{2 * t, 0}, {2 * t + 2, 2}}, 0.5f));
    std::string why = refusal(claims);
    EXPECT_NE(why.find("3599999984 of the frame's 3600000000 pixels are in no part"),
              std::string::npos)
        << why;
    // A frame of 2^30 - 1 pixels square (OpenEXR's largest display window): the holes are found
    // band by band between the parts' edges, at once (row by row took minutes: fuzz_exr_part)
    std::vector<RenderPart> vast = {
        part("vast.exr", Point2i((1 << 30) - 1, (1 << 30) - 1), {{0, 0}, {2, 2}}, 0.5f)};
    why = refusal(vast);
    EXPECT_NE(why.find("1152921502459363325 of the frame's 1152921502459363329 pixels are in no "
                       "part (all within [0, 1073741823) x [0, 1073741823))"),
              std::string::npos)
        << why;
    // Through the command: nothing written
    std::string out = dir / "out.exr";
    std::vector<std::string> args = {"merge"};
    for (const RenderPart& p : claims) args.push_back(p.file);
    args.insert(args.end(), {"-o", out});
    EXPECT_EQ(Kiln(args), 1);
    EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace kiln
