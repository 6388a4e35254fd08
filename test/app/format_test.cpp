// pbrt-v4's --format and --toply on kiln's own scenes (copied to a temporary folder, since
// relative file names resolve against the scene's folder): the reformatted scene, and the one
// whose triangle meshes were written out as PLY files, render bit-identically to the original;
// formatting is idempotent; a scene with errors is reported as when rendering.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "app_test_util.h"

namespace kiln {
namespace {

namespace fs = std::filesystem;
using testing::Q;

// Runs kiln in dir with its standard output to `stdoutFile`; *err receives its standard error
int RunKilnIn(const fs::path& dir, const std::string& args, std::string* err = nullptr,
              const std::string& stdoutFile = "out.txt") {
    const std::string kiln = std::string(KILN_BINARY_DIR) + "/kiln";
    std::string command = "cd " + Q(dir.string()) + " && " + Q(kiln) + " " + args + " > " +
                          Q(stdoutFile) + " 2> err.txt";
    int status = std::system(command.c_str());
    if (err) *err = testing::ReadAll((dir / "err.txt").string());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

class Format : public ::testing::TestWithParam<std::string> {};

TEST_P(Format, ReformattedAndPlyScenesRenderTheSame) {
    fs::path scene = fs::path(KILN_SOURCE_DIR) / "scenes" / GetParam();
    fs::path dir = fs::path(::testing::TempDir()) /
                   ("kiln_format_" + std::to_string(getpid()) + "_" + scene.stem().string());
    fs::remove_all(dir);
    fs::copy(scene.parent_path(), dir, fs::copy_options::recursive);
    std::string name = scene.filename().string(), log;
    ASSERT_EQ(RunKilnIn(dir, name + " --format", &log, "formatted.pbrt"), 0) << log;
    ASSERT_EQ(RunKilnIn(dir, name + " --toply", &log, "ply.pbrt"), 0) << log;
    ASSERT_EQ(RunKilnIn(dir, "formatted.pbrt --format", &log, "again.pbrt"), 0) << log;
    EXPECT_NE(testing::ReadAll((dir / "formatted.pbrt").string()).find("WorldBegin"),
              std::string::npos);
    EXPECT_EQ(testing::ReadAll((dir / "formatted.pbrt").string()),
              testing::ReadAll((dir / "again.pbrt").string()));
    // The central half of the image on a side (a quarter of the pixels, for the suite's time)
    for (const char* s : {name.c_str(), "formatted.pbrt", "ply.pbrt"})
        ASSERT_EQ(RunKilnIn(dir,
                            std::string(s) + " --spp 1 --crop 0.25 0.75 0.25 0.75 --quiet -o " + s +
                                ".pfm",
                            &log),
                  0)
            << log;
    std::vector<float> original = testing::Pixels((dir / (name + ".pfm")).string());
    EXPECT_EQ(testing::Pixels((dir / "formatted.pbrt.pfm").string()), original);
    EXPECT_EQ(testing::Pixels((dir / "ply.pbrt.pfm").string()), original);
    bool meshes = testing::ReadAll(scene.string()).find("trianglemesh") != std::string::npos;
    if (meshes) {
        EXPECT_TRUE(fs::exists(dir / "mesh_00001.ply"));
        EXPECT_EQ(testing::ReadAll((dir / "ply.pbrt").string()).find("trianglemesh"),
                  std::string::npos);
    }
    fs::remove_all(dir);
}

// Per-vertex temperatures (the forge), an image texture and a gradient, a Cornell box
INSTANTIATE_TEST_SUITE_P(Scenes, Format,
                         ::testing::Values("showcase/forge.pbrt", "thermal/heat-map.pbrt",
                                           "thermal/heated-bar.pbrt",
                                           "cornell-box/cornell-box.pbrt"));

TEST(FormatErrors, AreReportedAsWhenRendering) {
    fs::path dir = fs::path(::testing::TempDir()) / ("kiln_format_err_" + std::to_string(getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "bad.pbrt") << "WorldBegin\nShape \"sphere\" \"float radius\" [ 1\n";
    std::string log;
    EXPECT_EQ(RunKilnIn(dir, "bad.pbrt --format", &log), 1);
    EXPECT_NE(log.find("bad.pbrt:"), std::string::npos) << log;
    fs::remove_all(dir);
}

}  // namespace
}  // namespace kiln
