// The kiln command on a full disk (issue 23): run under a file-size limit (`ulimit -f`, with
// SIGXFSZ ignored, so that writes past it fail as on a full disk), a render to EXR, HDR or
// JPEG, with or without checkpoints, exits 1 with "kiln: error:" naming the output, leaves
// the existing output as it was and no temporary beside it. The same command without the limit
// writes the image.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "app_test_util.h"

namespace kiln {
namespace {

namespace fs = std::filesystem;
using testing::ShellQuote;

TEST(FullDisk, RenderOutputsAreErrorsAndTheOldFileStays) {
    fs::path dir = fs::path(::testing::TempDir()) / ("kiln_full_disk_" + std::to_string(getpid()));
    fs::create_directories(dir);
    const std::string kiln = std::string(KILN_BINARY_DIR) + "/kiln";
    const fs::path scene = dir / "scene.pbrt";
    std::ofstream(scene) << R"(LookAt 0 0 5  0 0 0  0 1 0
Camera "perspective" "float fov" 40
Film "rgb" "integer xresolution" 64 "integer yresolution" 64
Sampler "independent" "integer pixelsamples" 2
WorldBegin
LightSource "infinite" "rgb L" [1 1 1]
Material "conductor" "float roughness" 0.2 "float temperature" 1500
Shape "sphere"
)";
    const fs::path log = dir / "stderr.txt";
    const std::string old = "the previous render";
    for (const char* output : {"out.exr", "out.hdr", "out.jpg"})
        for (bool checkpoint : {false, true}) {
            const fs::path out = dir / output;
            std::ofstream(out) << old;
            std::string render = kiln + " --quiet " + ShellQuote(scene.string()) + " -o " +
                                 ShellQuote(out.string()) + (checkpoint ? " --checkpoint 1" : "");
            // ulimit -f counts 1024-byte blocks
            std::string limited = "bash -c " +
                                  ShellQuote("trap '' XFSZ; ulimit -f 4; exec " + render) + " 2> " +
                                  ShellQuote(log.string());
            int status = std::system(limited.c_str());
            std::string what = std::string(output) + (checkpoint ? " --checkpoint" : "");
            ASSERT_TRUE(WIFEXITED(status)) << what;
            EXPECT_EQ(WEXITSTATUS(status), 1) << what;
            std::string err = testing::ReadAll(log.string());
            EXPECT_NE(err.find("kiln: error: " + out.string()), std::string::npos) << what << err;
            EXPECT_EQ(testing::ReadAll(out.string()), old) << what;
            for (const auto& e : fs::directory_iterator(dir)) {
                std::string name = e.path().filename().string();
                EXPECT_TRUE(name == "scene.pbrt" || name == "stderr.txt" || name == output ||
                            name == std::string(output) + ".checkpoint")
                    << what << ": left " << name;
            }
            ASSERT_EQ(std::system((render + " 2> " + ShellQuote(log.string())).c_str()), 0) << what;
            EXPECT_NE(testing::ReadAll(out.string()), old) << what;
            fs::remove(out);
            fs::remove(out.string() + ".checkpoint");
        }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace kiln
