// kiln --memory-limit (RenderOptions::memoryLimitBytes): a film, mesh, PLY file, curve or image
// that would pass the limit is an error at its directive naming the object and its estimate,
// raised before the memory is taken; scenes within the limit render as before.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "render_test_util.h"

namespace kiln {
namespace {

// The error creating `scene` under `limit` bytes, or "" if it was created.
std::string ErrorUnderLimit(const std::string& scene, double limit) {
    Diagnostics diag(nullptr);
    RenderOptions o;
    o.memoryLimitBytes = limit;
    try {
        testing::BuildScene(scene, diag, o);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

const std::string kSmallFilm =
    "Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 16\n"
    "Camera \"perspective\"\nWorldBegin\nLightSource \"distant\"\n";

TEST(MemoryLimit, FilmsOverTheLimitAreLocatedErrors) {
    std::string big =
        "Film \"rgb\" \"integer xresolution\" 4000 \"integer yresolution\" 3000\n"
        "Camera \"perspective\"\nWorldBegin\n";
    std::string e = ErrorUnderLimit(big, 100e6);
    EXPECT_NE(e.find("<test>:1:"), std::string::npos) << e;
    EXPECT_NE(e.find("a film of 4000 x 3000 pixels needs"), std::string::npos) << e;
    EXPECT_NE(e.find("memory limit of 100 MB"), std::string::npos) << e;
    EXPECT_EQ(ErrorUnderLimit(big, 4e9), "");
}

TEST(MemoryLimit, MeshesAndCurvesAreChargedBeforeTheyAreMade) {
    // Loop subdivision to level 8: 8 * 4^8 = 524288 triangles, about 100 MB
    std::string loop = kSmallFilm +
                       "Shape \"loopsubdiv\" \"integer levels\" 8 \"point3 P\" [1 0 0 -1 0 0 0 1 "
                       "0 0 -1 0 0 0 1 0 0 -1] \"integer indices\" [0 2 4 2 1 4 1 3 4 3 0 4 2 0 "
                       "5 1 2 5 3 1 5 0 3 5]\n";
    std::string e = ErrorUnderLimit(loop, 50e6);
    EXPECT_NE(e.find("loopsubdiv of 524288 triangles"), std::string::npos) << e;
    EXPECT_NE(e.find("(at 'levels')"), std::string::npos) << e;
    EXPECT_EQ(ErrorUnderLimit(loop, 1e9), "");
    // A PLY header claiming 10^8 faces: refused from the header, before the data (which this
    // file does not even have)
    std::string ply = ::testing::TempDir() + "/kiln_claims_much.ply";
    std::ofstream(ply) << "ply\nformat binary_little_endian 1.0\nelement vertex 50000000\n"
                          "property float x\nproperty float y\nproperty float z\nelement face "
                          "100000000\nproperty list uchar int vertex_indices\nend_header\n";
    e = ErrorUnderLimit(kSmallFilm + "Shape \"plymesh\" \"string filename\" \"" + ply + "\"\n",
                        1e9);
    EXPECT_NE(e.find("50000000 vertices, 100000000 faces) needs"), std::string::npos) << e;
    EXPECT_NE(e.find("<test>:5:"), std::string::npos) << e;
    // A curve of 4000 segments (about 800 kB)
    std::string curve = kSmallFilm + "Shape \"curve\" \"string basis\" \"bspline\" \"point3 P\" [";
    for (int i = 0; i < 4003; ++i) curve += std::to_string(i) + " 0 0 ";
    curve += "]\n";
    e = ErrorUnderLimit(curve, 400e3);
    EXPECT_NE(e.find("a curve of 4000 segments needs"), std::string::npos) << e;
    EXPECT_EQ(ErrorUnderLimit(curve, 10e6), "");
}

TEST(MemoryLimit, PlyTrianglesAreChargedOnceAndQuadsTwice) {
    // 20000 separate triangles (4 MB at MemoryBudget::kBytesPerTriangle, 1.9 MB of vertices):
    // created under 7.5 MB, which two triangles per face (a quad allowance) would exceed; the
    // same faces as 20000 quads are 40000 triangles and are refused
    auto write = [](const std::string& path, int corners) {
        std::ofstream f(path, std::ios::binary);
        const int n = 20000;
        f << "ply\nformat binary_little_endian 1.0\nelement vertex " << n * corners
          << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << n
          << "\nproperty list uchar int vertex_indices\nend_header\n";
        for (int i = 0; i < n; ++i)
            for (int c = 0; c < corners; ++c) {
                float v[3] = {float(i % 100) + (c == 1 || c == 2), float(i / 100) + (c >= 2), 0};
                f.write(reinterpret_cast<const char*>(v), sizeof v);
            }
        for (int i = 0; i < n; ++i) {
            unsigned char k = (unsigned char)corners;
            f.write(reinterpret_cast<const char*>(&k), 1);
            for (int c = 0; c < corners; ++c) {
                int index = i * corners + c;
                f.write(reinterpret_cast<const char*>(&index), sizeof index);
            }
        }
    };
    std::string tris = ::testing::TempDir() + "/kiln_tris.ply",
                quads = ::testing::TempDir() + "/kiln_quads.ply";
    write(tris, 3);
    write(quads, 4);
    auto scene = [](const std::string& ply) {
        return kSmallFilm + "Shape \"plymesh\" \"string filename\" \"" + ply + "\"\n";
    };
    EXPECT_EQ(ErrorUnderLimit(scene(tris), 7.5e6), "");
    std::string e = ErrorUnderLimit(scene(quads), 7.5e6);
    EXPECT_NE(e.find("(40000 triangles) needs"), std::string::npos) << e;
    EXPECT_EQ(ErrorUnderLimit(scene(quads), 12e6), "");
}

TEST(MemoryLimit, ImagesAreChargedFromTheirHeader) {
    // A PPM header (read by OpenImageIO) claiming 30000 x 30000 RGB pixels (2.7 GB at 8 bits)
    // over 12 bytes of data
    std::string ppm = ::testing::TempDir() + "/kiln_claims_much.ppm";
    std::ofstream(ppm, std::ios::binary) << "P6\n30000 30000\n255\n" << std::string(12, '\0');
    auto texture = [](const std::string& file) {
        return kSmallFilm + "Texture \"t\" \"spectrum\" \"imagemap\" \"string filename\" \"" +
               file + "\"\n";
    };
    std::string e = ErrorUnderLimit(texture(ppm), 2e9);
    EXPECT_NE(e.find("30000 x 30000 pixels, 3 channels) needs"), std::string::npos) << e;
    EXPECT_NE(e.find("--memory-limit"), std::string::npos) << e;
    // kiln's own PFM reader refuses such a header before it allocates anything
    std::string pfm = ::testing::TempDir() + "/kiln_claims_much.pfm";
    std::ofstream(pfm, std::ios::binary) << "PF\n30000 30000\n-1.0\n" << std::string(12, '\0');
    e = ErrorUnderLimit(texture(pfm), 2e9);
    EXPECT_NE(e.find("does not hold 30000 x 30000 x 3 floats"), std::string::npos) << e;
}

// Issue 23: 10^6 spheres took 1.76 GB under a 200 MB limit. The parsed directives are charged
// as the builder makes them (an error at the directive that passes the limit) and again when
// the scene is created from them, and each quadric before it is made.
TEST(MemoryLimit, ManyShapesAreChargedAtTheirDirective) {
    std::string spheres = kSmallFilm;
    for (int i = 0; i < 20000; ++i)
        spheres += "AttributeBegin Translate " + std::to_string(i % 100) + " " +
                   std::to_string(i / 100) +
                   " 0 Shape \"sphere\" \"float radius\" 0.1 "
                   "AttributeEnd\n";
    // Creation: the description (about 21 MB) fits 25 MB, 20000 spheres of 700 bytes do not
    std::string e = ErrorUnderLimit(spheres, 25e6);
    EXPECT_NE(e.find("a sphere needs 700 bytes"), std::string::npos) << e;
    EXPECT_NE(e.find("(at 'sphere')"), std::string::npos) << e;
    EXPECT_EQ(e.rfind("<test>:", 0), 0u) << e;
    EXPECT_EQ(ErrorUnderLimit(spheres, 200e6), "");
    // Parsing: the builder stops at the directive that passes its limit
    Diagnostics diag(nullptr);
    SceneBuilder builder(diag);
    builder.SetMemoryLimit(5e6);
    try {
        ParseString(builder, spheres, diag, "<test>");
        ADD_FAILURE() << "no error";
    } catch (const SceneError& error) {
        std::string what = error.what();
        EXPECT_NE(what.find("the scene's directives so far take about"), std::string::npos) << what;
        EXPECT_NE(what.find("more than --memory-limit"), std::string::npos) << what;
        EXPECT_GT(error.Loc().line, 1000);
        EXPECT_LT(error.Loc().line, 20000);
    }
}

// A gzip-compressed scene that inflates past the limit (50 MB of comments in 50 kB) is refused
// as it inflates, naming the file, never read whole
TEST(MemoryLimit, CompressedScenesAreBoundedAsTheyInflate) {
    std::string file = ::testing::TempDir() + "/kiln_inflates.pbrt";
    gzFile gz = gzopen(file.c_str(), "wb9");
    ASSERT_TRUE(gz);
    std::string line = "# " + std::string(1000, 'x') + "\n";
    for (int i = 0; i < 50000; ++i) gzwrite(gz, line.data(), unsigned(line.size()));
    gzclose(gz);
    Diagnostics diag(nullptr);
    SceneBuilder builder(diag);
    try {
        ParseFile(builder, file, diag, 10000000);
        ADD_FAILURE() << "no error";
    } catch (const SceneError& error) {
        std::string what = error.what();
        EXPECT_EQ(what.rfind(file + ":", 0), 0u) << what;
        EXPECT_NE(what.find("decompresses to more than 10 MB"), std::string::npos) << what;
    }
    std::remove(file.c_str());
}

}  // namespace
}  // namespace kiln
