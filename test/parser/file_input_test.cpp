// Scene files as they come: gzip-compressed scenes and includes (by content, whatever their
// names), files that are not regular files (devices that never end, FIFOs, directories),
// include chains deeper than the limit, and binary or huge tokens in error messages.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>

#include "../temp_dir.h"
#include "base/file_reading.h"
#include "core/parser/parser.h"
#include "recording_target.h"

namespace kiln {
namespace {

namespace fs = std::filesystem;

using test::TempDir;

void WriteGzip(const fs::path& file, const std::string& text) {
    gzFile f = gzopen(file.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    ASSERT_EQ(gzwrite(f, text.data(), unsigned(text.size())), int(text.size()));
    gzclose(f);
}

std::string ErrorOfFile(const fs::path& file) {
    RecordingTarget target;
    Diagnostics diag(nullptr);
    try {
        ParseFile(target, file.string(), diag);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "no error";
}

TEST(FileInput, GzipScenesAndIncludesAreReadByContent) {
    TempDir dir;
    // The include has no .gz in its name; the scene has the usual .pbrt.gz
    WriteGzip(dir.path / "part.pbrt", "Translate 1 2 3\n");
    WriteGzip(dir.path / "scene.pbrt.gz", "Include \"part.pbrt\"\nScale 2 2 2\n");
    RecordingTarget target;
    Diagnostics diag(nullptr);
    ParseFile(target, (dir.path / "scene.pbrt.gz").string(), diag);
    EXPECT_EQ(target.Text(), "Translate 1 2 3\nScale 2 2 2\n");

    // Corrupt gzip data is an error naming the file, not binary echoed as directives
    std::ofstream(dir.path / "broken.pbrt", std::ios::binary) << "\x1f\x8b\x08\x00garbage";
    std::string error = ErrorOfFile(dir.path / "broken.pbrt");
    EXPECT_NE(error.find("gzip"), std::string::npos) << error;
}

TEST(FileInput, GunzipHonoursItsOutputBound) {
    std::string big(1 << 20, 'a'), out, error;
    // 1 MB that compresses to about 1 kB: the bound applies to what it decompresses to
    TempDir dir;
    WriteGzip(dir.path / "big.gz", big);
    ASSERT_TRUE(ReadFileBytes((dir.path / "big.gz").string(), &out, &error)) << error;
    EXPECT_EQ(out, big);
    EXPECT_LT(fs::file_size(dir.path / "big.gz"), 100000u);
    EXPECT_FALSE(ReadFileBytes((dir.path / "big.gz").string(), &out, &error, 100000));
    EXPECT_NE(error.find("decompresses to more than"), std::string::npos) << error;
}

TEST(FileInput, FilesThatAreNotRegularAreRefused) {
    TempDir dir;
    fs::create_directories(dir.path / "adir");
    ASSERT_EQ(mkfifo((dir.path / "fifo").c_str(), 0600), 0);
    for (auto [name, reason] : {std::pair{std::string("/dev/zero"), "special file"},
                                {(dir.path / "adir").string(), "is a directory"},
                                {(dir.path / "fifo").string(), "is a FIFO"}}) {
        std::ofstream(dir.path / "scene.pbrt") << "\n  Include \"" << name << "\"\n";
        std::string error = ErrorOfFile(dir.path / "scene.pbrt");
        EXPECT_NE(error.find("scene.pbrt:2:11: error: cannot open"), std::string::npos) << error;
        EXPECT_NE(error.find(reason), std::string::npos) << error;
        // ... and as the scene file itself
        EXPECT_NE(ErrorOfFile(name).find(reason), std::string::npos) << name;
    }
}

TEST(FileInput, IncludeNestingIsLimited) {
    TempDir dir;
    auto chain = [&](int n) {
        for (int i = 0; i < n; ++i)
            std::ofstream(dir.path / ("f" + std::to_string(i) + ".pbrt"))
                << (i + 1 < n ? "Include \"f" + std::to_string(i + 1) + ".pbrt\"\n"
                              : std::string("Translate 1 1 1\n"));
    };
    chain(100);
    EXPECT_EQ(ErrorOfFile(dir.path / "f0.pbrt"), "no error");
    chain(10000);  // deep enough to overflow the stack if nesting were unbounded
    std::string error = ErrorOfFile(dir.path / "f0.pbrt");
    EXPECT_NE(error.find("f127.pbrt:1:9: error: Include/Import nested more than 128"),
              std::string::npos)
        << error;
}

TEST(FileInput, BinaryAndHugeTokensAreShownShortAndEscaped) {
    std::string token = "Bog\x01\xff" + std::string(10 << 20, 'x');
    RecordingTarget target;
    Diagnostics diag(nullptr);
    std::string error;
    try {
        ParseString(target, token, diag, "bin.pbrt");
    } catch (const SceneError& e) {
        error = e.what();
    }
    EXPECT_LT(error.size(), 300u) << error.substr(0, 300);
    EXPECT_NE(error.find("Bog\\x01\\xffxxx"), std::string::npos) << error;
    EXPECT_NE(error.find("(10485765 bytes)"), std::string::npos) << error;
    for (char c : error) EXPECT_TRUE(c >= 0x20 && c < 0x7f);
}

}  // namespace
}  // namespace kiln
