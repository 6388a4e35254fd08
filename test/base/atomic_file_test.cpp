// WriteFileAtomically: a complete file or none, never through a planted link, nothing left
// behind on failure.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "../temp_dir.h"
#include "base/atomic_file.h"

namespace fs = std::filesystem;

namespace kiln {
namespace {

std::string Read(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Names in dir other than the given ones (temporaries left behind)
int Others(const fs::path& dir, std::initializer_list<std::string> known) {
    int n = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
        std::string name = e.path().filename().string();
        if (std::find(known.begin(), known.end(), name) == known.end()) ++n;
    }
    return n;
}

using test::TempDir;

TEST(AtomicFile, WritesAndReplacesWholeFiles) {
    TempDir d;
    fs::path f = d.path / "out.txt";
    WriteFileAtomically(f.string(), "first");
    EXPECT_EQ(Read(f), "first");
    WriteFileAtomically(f.string(), std::string(100000, 'x'), true);
    EXPECT_EQ(Read(f), std::string(100000, 'x'));
    EXPECT_TRUE((fs::status(f).permissions() & fs::perms::owner_exec) != fs::perms::none);
    EXPECT_EQ(Others(d.path, {"out.txt"}), 0);
}

TEST(AtomicFile, APlantedLinkIsReplacedNotFollowed) {
    TempDir d;
    fs::path victim = d.path / "victim.txt", f = d.path / "out.txt";
    std::ofstream(victim) << "precious";
    fs::create_symlink(victim, f);
    WriteFileAtomically(f.string(), "new");
    EXPECT_EQ(Read(victim), "precious");
    EXPECT_FALSE(fs::is_symlink(fs::symlink_status(f)));
    EXPECT_EQ(Read(f), "new");
}

TEST(AtomicFile, FailuresNameThePathAndLeaveNothing) {
    TempDir d;
    // No such folder
    fs::path missing = d.path / "no" / "out.txt";
    try {
        WriteFileAtomically(missing.string(), "x");
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(d.path / "no"));
    // The target is a directory: it stays, and no temporary is left beside it
    fs::create_directories(d.path / "dir" / "inside");
    EXPECT_THROW(WriteFileAtomically((d.path / "dir").string(), "x"), std::runtime_error);
    EXPECT_TRUE(fs::is_directory(d.path / "dir" / "inside"));
    EXPECT_EQ(Others(d.path, {"dir"}), 0);
}

TEST(AtomicFile, StaleTemporariesAreRemovedAndNothingElse) {
    TempDir d;
    fs::path f = d.path / "out.bin";
    for (const char* name : {"out.bin.tmp.a1B2c3", "out.bin.tmp.zzzzzz", "out.bin.tmp.short",
                             "out.bin.tmp.toolong1", "other.tmp.a1B2c3", "out.bin"})
        std::ofstream(d.path / name) << "x";
    fs::create_symlink(d.path / "other.tmp.a1B2c3", d.path / "out.bin.tmp.link00");
    RemoveStaleTemporaries(f.string());
    EXPECT_FALSE(fs::exists(d.path / "out.bin.tmp.a1B2c3"));
    EXPECT_FALSE(fs::exists(d.path / "out.bin.tmp.zzzzzz"));
    for (const char* kept : {"out.bin.tmp.short", "out.bin.tmp.toolong1", "other.tmp.a1B2c3",
                             "out.bin", "out.bin.tmp.link00"})
        EXPECT_TRUE(fs::exists(fs::symlink_status(d.path / kept))) << kept;
}

// A name as long as a file system allows (255 bytes) has no room for ".tmp.XXXXXX": its
// temporaries are named from a shortened name, so the write succeeds, and a stale one of that
// name is removed
TEST(AtomicFile, LongestNamesCanBeWrittenAndCleanedUp) {
    TempDir d;
    fs::path f = d.path / (std::string(251, 'n') + ".exr");
    WriteFileAtomically(f.string(), "data");
    std::ifstream in(f);
    std::string read;
    in >> read;
    EXPECT_EQ(read, "data");
    fs::path stale = d.path / (std::string(255 - 11, 'n') + ".tmp.Ab12Cd");
    std::ofstream(stale) << "x";
    RemoveStaleTemporaries(f.string());
    EXPECT_FALSE(fs::exists(stale));
    EXPECT_TRUE(fs::exists(f));
}

}  // namespace
}  // namespace kiln
