// PLY reading: ascii and both binary byte orders, normals, uv, extra vertex attributes,
// planar and non-planar quads, and errors for malformed files.
#include "core/geometry/ply_reader.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/parser/diagnostics.h"

namespace kiln {
namespace {

std::string TempPath(const std::string& name) {
    auto dir = std::filesystem::temp_directory_path() / "kiln_geometry_ply_test";
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

const char* kHeader =
    "element vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
    "property float nx\nproperty float ny\nproperty float nz\nproperty float u\n"
    "property float v\nproperty float temperature\n"
    "element face 2\nproperty list uchar int vertex_indices\nproperty int face_indices\n"
    "end_header\n";
// A planar quad (0 1 2 3) and a triangle (1 4 2).
const float kVerts[5][9] = {{0, 0, 0, 0, 0, 1, 0, 0, 1000},
                            {1, 0, 0, 0, 0, 1, 1, 0, 1100},
                            {1, 1, 0, 0, 0, 1, 1, 1, 1200},
                            {0, 1, 0, 0, 0, 1, 0, 1, 1300},
                            {2, 0, 1, 0, 0, 1, 2, 0, 1400}};

void WriteBinary(const std::string& path, bool bigEndian) {
    std::ofstream f(path, std::ios::binary);
    f << "ply\nformat " << (bigEndian ? "binary_big_endian" : "binary_little_endian")
      << " 1.0\ncomment test\n"
      << kHeader;
    bool swap = bigEndian == (std::endian::native == std::endian::little);
    auto put = [&](const void* p, int n) {
        char b[4];
        std::memcpy(b, p, n);
        if (swap) std::reverse(b, b + n);
        f.write(b, n);
    };
    for (auto& v : kVerts)
        for (float x : v) put(&x, 4);
    auto face = [&](std::vector<int> idx, int fi) {
        unsigned char n = (unsigned char)idx.size();
        f.write(reinterpret_cast<char*>(&n), 1);
        for (int i : idx) put(&i, 4);
        put(&fi, 4);
    };
    face({0, 1, 2, 3}, 5);
    face({1, 4, 2}, 6);
}

void WriteAscii(const std::string& path) {
    std::ofstream f(path);
    f << "ply\nformat ascii 1.0\n" << kHeader;
    for (auto& v : kVerts) {
        for (float x : v) f << x << " ";
        f << "\n";
    }
    f << "4 0 1 2 3 5\n3 1 4 2 6\n";
}

void CheckMesh(const TriQuadMesh& m) {
    ASSERT_EQ(m.p.size(), 5u);
    ASSERT_EQ(m.n.size(), 5u);
    ASSERT_EQ(m.uv.size(), 5u);
    EXPECT_EQ(m.p[4], Point3f(2, 0, 1));
    EXPECT_EQ(m.uv[2], Point2f(1, 1));
    // Planar quad -> two triangles, plus the triangle.
    EXPECT_EQ(m.triIndices, (std::vector<int>{0, 1, 2, 0, 2, 3, 1, 4, 2}));
    EXPECT_TRUE(m.quadIndices.empty());
    EXPECT_EQ(m.triFaceIndices, (std::vector<int>{5, 5, 6}));
    ASSERT_EQ(m.vertexAttributes.count("temperature"), 1u);
    EXPECT_EQ(m.vertexAttributes.at("temperature")[3], 1300);
}

TEST(PLY, AsciiAndBinary) {
    std::string a = TempPath("a.ply"), le = TempPath("le.ply"), be = TempPath("be.ply");
    WriteAscii(a);
    WriteBinary(le, false);
    WriteBinary(be, true);
    CheckMesh(TriQuadMesh::ReadPLY(a));
    CheckMesh(TriQuadMesh::ReadPLY(le));
    CheckMesh(TriQuadMesh::ReadPLY(be));
}

TEST(PLY, NonPlanarQuadBecomesBilinearPatch) {
    std::string path = TempPath("q.ply");
    std::ofstream(path) << "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\n"
                           "property double y\nproperty double z\nelement face 1\n"
                           "property list uchar uint vertex_index\nend_header\n"
                           "0 0 0\n1 0 0\n1 1 1\n0 1 0\n4 0 1 2 3\n";
    TriQuadMesh m = TriQuadMesh::ReadPLY(path);
    EXPECT_TRUE(m.triIndices.empty());
    EXPECT_EQ(m.quadIndices, (std::vector<int>{0, 1, 3, 2}));
}

void ExpectError(const std::string& name, const std::string& content, const std::string& what) {
    std::string path = TempPath(name);
    std::ofstream(path) << content;
    try {
        TriQuadMesh::ReadPLY(path);
        ADD_FAILURE() << "no error for " << name;
    } catch (const SceneError& e) {
        std::string msg = e.what();
        EXPECT_NE(msg.find(name), std::string::npos) << msg;
        EXPECT_NE(msg.find(what), std::string::npos) << msg;
    }
}

TEST(PLY, MalformedFilesThrow) {
    ExpectError("nomagic.ply", "plx\n", "magic");
    ExpectError("noend.ply", "ply\nformat ascii 1.0\nelement vertex 1\n", "end_header");
    ExpectError("badnum.ply",
                "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                "property float z\nend_header\n0 zero 0\n",
                "invalid number");
    ExpectError("short.ply",
                "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\n"
                "property float y\nproperty float z\nend_header\nabcd",
                "end of file");
    ExpectError("range.ply",
                "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",
                "out of range");
    // Indices beyond 32 bits are reported as written, not wrapped
    ExpectError("huge-index.ply",
                "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                "property float z\nelement face 1\nproperty list uchar uint vertex_indices\n"
                "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 4294967295\n",
                "vertex index 4294967295 out of range (3 vertices)");
    ExpectError("negative-index.ply",
                "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n",
                "vertex index -1 out of range");
    ExpectError("novertexprops.ply",
                "ply\nformat ascii 1.0\nelement vertex 22222222222\nend_header\n",
                "lacks x, y or z");
    ExpectError("missing.ply", "", "");
    EXPECT_THROW(TriQuadMesh::ReadPLY(TempPath("does_not_exist.ply")), SceneError);
}

TEST(PLY, ElementsWithoutPropertiesHaveNoData) {
    // A huge element without properties (found by fuzzing: it used to loop for hours)
    TriQuadMesh mesh = TriQuadMesh::ParsePLY(
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement blank 22222222222\nelement face 1\n"
        "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
        "blank.ply");
    EXPECT_EQ(mesh.triIndices, (std::vector<int>{0, 1, 2}));
}

}  // namespace
}  // namespace kiln
