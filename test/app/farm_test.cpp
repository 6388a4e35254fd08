// kiln farm (app/farm.h): tiles cover the film exactly; the submission calls sbatch with the
// array, the user's options and an afterok dependency (checked with a stand-in sbatch that
// records its arguments); and the batch scripts it writes, run as Slurm would run them (each
// array index, then the merge), give frames bit-identical to single-process renders. (A real
// Slurm cluster runs them in slurm_cluster_test.cpp.) The scene and the output live in a folder
// whose name has spaces, quotes and '%'; -o with a control character or a format the merge
// cannot write is refused before anything is written or submitted.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/farm.h"
#include "app_test_util.h"
#include "core/image/image.h"

namespace kiln {
namespace {

namespace fs = std::filesystem;

using testing::Q;
using testing::ShellQuote;

TEST(Farm, TilesCoverTheFilmOnce) {
    for (Point2i res : {Point2i(24, 20), Point2i(1920, 1080), Point2i(3, 700), Point2i(1, 1)})
        for (int n : {1, 2, 3, 4, 6, 7, 12, 64}) {
            std::vector<Bounds2i> tiles = TileGrid(res, n);
            std::vector<int> count(size_t(res.x) * res.y, 0);
            for (const Bounds2i& b : tiles)
                for (int y = b.pMin.y; y < b.pMax.y; ++y)
                    for (int x = b.pMin.x; x < b.pMax.x; ++x) ++count[size_t(y) * res.x + x];
            for (int c : count) ASSERT_EQ(c, 1) << res.x << "x" << res.y << " in " << n;
            if (res.x >= n && res.y >= n) {
                EXPECT_EQ(int(tiles.size()), n);
            }
        }
    // About square: 16:9 in 4 tiles is 2 x 2, in 2 tiles two halves side by side
    std::vector<Bounds2i> two = TileGrid({1920, 1080}, 2);
    EXPECT_EQ(two[0].pMax, Point2i(960, 1080));
}

TEST(Farm, ScriptsRunAsSlurmWouldGiveTheSingleProcessRender) {
    fs::path dir =
        fs::path(::testing::TempDir()) / ("kiln farm 'q' \"dq\" 100% " + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "bin");
    const std::string kiln = std::string(KILN_BINARY_DIR) + "/kiln";
    const std::string scene = (dir / "scene.pbrt").string();
    std::ofstream(scene) << "Film \"rgb\" \"integer xresolution\" 24 \"integer yresolution\" 20\n"
                            "Sampler \"zsobol\" \"integer pixelsamples\" 8\n"
                            "LookAt 0 1 4  0 0.4 0  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
                            "LightSource \"infinite\" \"rgb L\" [0.4 0.4 0.5]\n"
                            "Material \"coateddiffuse\" \"rgb reflectance\" [0.7 0.3 0.2]\n"
                            "Shape \"sphere\" \"float radius\" 0.8\n";
    // A stand-in sbatch: records its arguments, answers job ids 100, 101, ...
    const std::string log = (dir / "sbatch.log").string();
    {
        std::ofstream fake(dir / "bin" / "sbatch");
        fake << "#!/bin/bash\necho \"$@\" >> " << Q(log) << "\n"
             << "n=$(wc -l < " << Q(log) << ")\necho $((99 + n))\n";
    }
    fs::permissions(dir / "bin" / "sbatch", fs::perms::owner_all);
    const std::string env = "PATH=" + Q((dir / "bin").string()) + ":\"$PATH\" ";
    const std::string out = (dir / "out#.exr").string();
    const std::string farm =
        env + Q(kiln) + " farm " + Q(scene) + " --tiles 4 --frames 0-1 --spp 8 -o " + Q(out);
    const std::string stdoutFile = (dir / "stdout.txt").string();
    // Refused before anything is written or submitted: a newline in -o, a format the merge
    // cannot write
    for (std::string bad : {(dir / "a\nb#.exr").string(), (dir / "out#.png").string()}) {
        std::string refused = env + Q(kiln) + " farm " + Q(scene) + " --frames 0-1 -o " + Q(bad);
        EXPECT_NE(std::system((refused + " 2> " + Q(stdoutFile)).c_str()), 0) << bad;
        EXPECT_NE(testing::ReadAll(stdoutFile).find("kiln farm: "), std::string::npos);
    }
    EXPECT_FALSE(fs::exists(log));
    EXPECT_FALSE(fs::exists(dir / "a\nb.exr.farm"));
    EXPECT_FALSE(fs::exists(dir / "out.png.farm"));
    ASSERT_EQ(std::system((farm + " -- --partition=test > " + Q(stdoutFile)).c_str()), 0);
    EXPECT_NE(testing::ReadAll(stdoutFile).find("render job 100 (8 tasks), merge job 101"),
              std::string::npos)
        << testing::ReadAll(stdoutFile);
    std::string calls = testing::ReadAll(log);
    const std::string farmDir = (dir / "out.exr.farm").string();
    // Both jobs run in the farm folder (the scripts' logs/ is there)
    EXPECT_NE(calls.find("--parsable --array=0-7 --chdir=" + farmDir + " --partition=test"),
              std::string::npos)
        << calls;
    EXPECT_NE(calls.find("--dependency=afterok:100 --chdir=" + farmDir + " --partition=test"),
              std::string::npos)
        << calls;
    // No path of the user's in an #SBATCH line
    for (const char* script : {"/render.sbatch", "/merge.sbatch"})
        for (std::istringstream lines(testing::ReadAll(farmDir + script)); !lines.eof();) {
            std::string line;
            std::getline(lines, line);
            if (line.rfind("#SBATCH", 0) == 0) {
                EXPECT_EQ(line.find(dir.string()), std::string::npos) << line;
            }
        }
    // Nothing rendered yet: --status lists the 8 parts
    EXPECT_NE(std::system((farm + " --status > " + Q(stdoutFile)).c_str()), 0);
    EXPECT_NE(testing::ReadAll(stdoutFile).find("8 parts missing"), std::string::npos);
    // What Slurm would run, in the farm folder: every array index, then the merge
    for (int i = 0; i < 8; ++i)
        ASSERT_EQ(std::system(("cd " + Q(farmDir) + " && SLURM_ARRAY_TASK_ID=" + std::to_string(i) +
                               " bash render.sbatch")
                                  .c_str()),
                  0)
            << i;
    ASSERT_EQ(std::system(("cd " + Q(farmDir) + " && bash merge.sbatch").c_str()), 0);
    EXPECT_EQ(std::system((farm + " --status > " + Q(stdoutFile)).c_str()), 0);
    // Each frame as one process renders it
    for (int f = 0; f < 2; ++f) {
        std::string single = (dir / ("single" + std::to_string(f) + ".exr")).string();
        ASSERT_EQ(std::system((Q(kiln) + " " + Q(scene) + " --frames " + std::to_string(f) + "-" +
                               std::to_string(f) + " --spp 8 --quiet -o " + Q(single))
                                  .c_str()),
                  0);
        EXPECT_EQ(testing::Pixels((dir / ("out" + std::to_string(f) + ".exr")).string()),
                  testing::Pixels(single))
            << "frame " << f;
    }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace kiln
