// Every output is checked before the scene is parsed: a missing folder, a format kiln cannot
// write, an unknown view, a folder given as the output. Each is one line naming the user's path
// (exit status 2), and nothing is written, not even the outputs that could have been. A usage
// error is one line and "see kiln --help". The scene's own Film "filename" is checked before
// rendering.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "app_test_util.h"
#include "core/image/image.h"

namespace kiln {
namespace {

namespace fs = std::filesystem;
using testing::Q;

class OutputCheckCLI : public testing::KilnCommandTest {
  protected:
    OutputCheckCLI() : KilnCommandTest("outputs") {}
    void SetUp() override {
        KilnCommandTest::SetUp();
        WriteScene(
            "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 6\n"
            "Sampler \"independent\" \"integer pixelsamples\" 1\n"
            "Camera \"perspective\"\nWorldBegin\n"
            "Material \"diffuse\" \"float temperature\" 1200\n"
            "Translate 0 0 4 Shape \"sphere\"\n");
        scene = (dir / "scene.pbrt").string();
    }
    void TearDown() override {
        std::error_code ec;
        fs::permissions(dir / "readonly", fs::perms::owner_all, fs::perm_options::add, ec);
        KilnCommandTest::TearDown();
    }
    // Runs kiln with `args` and --quiet; returns the exit status, its messages in `log`
    int Run(const std::string& args) { return KilnCommandTest::Run(args + " --quiet"); }
    static int Lines(const std::string& text) {
        int n = 0;
        for (char c : text) n += c == '\n';
        return n;
    }

    std::string scene;
};

TEST_F(OutputCheckCLI, BadOutputsFailBeforeParsingAndWriteNothing) {
    fs::create_directories(dir / "readonly");
    fs::permissions(dir / "readonly", fs::perms::owner_read | fs::perms::owner_exec);
    bool root = geteuid() == 0;  // root may write anywhere
    struct Case {
        std::string output, extra, expect;
    };
    for (const Case& c :
         {Case{"missing/x.png", "", "folder \"missing\" does not exist"},
          Case{"x.xyz", "", "cannot write .xyz"}, Case{"noextension", "", "no file extension"},
          Case{"x.png", "--view Filmc", "the views are Standard, Filmic"},
          Case{"x.exr", "--view Filmc", "unknown display view"}, Case{".", "", "no file extension"},
          Case{"readonly/x.exr", "", "cannot create files in"}}) {
        if (root && c.output.rfind("readonly", 0) == 0) continue;
        // A scene file that does not exist: the output is refused before it is read
        EXPECT_EQ(Run("missing.pbrt -o good.exr -o " + Q(c.output) + " " + c.extra), 2) << c.output;
        EXPECT_NE(log.find(c.expect), std::string::npos) << c.output << ": " << log;
        EXPECT_EQ(log.find("missing.pbrt"), std::string::npos) << log;
        EXPECT_EQ(Lines(log), 1) << log;
        EXPECT_EQ(Run(Q(scene) + " -o good.exr -o " + Q(c.output) + " " + c.extra), 2);
        EXPECT_FALSE(fs::exists(dir / "good.exr")) << c.output;
    }
    // Every temporary name stays hidden: no error names a file the user did not give
    EXPECT_EQ(log.find(".kiln"), std::string::npos) << log;
}

TEST_F(OutputCheckCLI, GoodOutputsRenderAndUsageErrorsAreOneLine) {
    EXPECT_EQ(Run(Q(scene) + " -o a.exr -o a.pfm -o a.png --view Glow"), 0) << log;
    for (const char* f : {"a.exr", "a.pfm", "a.png"}) EXPECT_TRUE(fs::exists(dir / f)) << f;
    // The PFM holds the EXR's R, G, B (which are half floats)
    Image pfm = Image::Read((dir / "a.pfm").string()), exr = Image::Read((dir / "a.exr").string());
    ASSERT_EQ(pfm.Resolution(), exr.Resolution());
    ASSERT_EQ(pfm.NChannels(), 3);
    double largest = 0;
    for (int y = 0; y < pfm.Resolution().y; ++y)
        for (int x = 0; x < pfm.Resolution().x; ++x)
            for (int c = 0; c < 3; ++c) {
                float a = pfm.GetChannel({x, y}, c), b = exr.GetChannel({x, y}, c);
                largest = std::max<double>(largest, a);
                EXPECT_NEAR(a, b, 1e-3 * std::abs(a) + 1e-6) << x << " " << y << " " << c;
            }
    EXPECT_GT(largest, 0);  // something glows
    EXPECT_EQ(Run(Q(scene) + " --spp ten"), 2);
    EXPECT_EQ(log, "kiln: --spp expects an integer >= 1, got 'ten'\nsee kiln --help\n");
}

TEST_F(OutputCheckCLI, TheScenesOwnOutputIsCheckedBeforeRendering) {
    std::ofstream(scene, std::ios::app) << "";
    std::string text = testing::ReadAll(scene);
    text.replace(text.find("Film \"rgb\""), 10,
                 "Film \"rgb\" \"string filename\" \"no/such/x.png\"");
    std::ofstream(scene) << text;
    EXPECT_EQ(Run(Q(scene)), 1);
    EXPECT_NE(log.find("no/such/x.png"), std::string::npos) << log;
    EXPECT_NE(log.find("nothing rendered"), std::string::npos) << log;
}

// A format the film cannot write (a thermal film's PFM) is known once the scene is read: it
// fails before rendering, and no output is written
TEST_F(OutputCheckCLI, OutputsTheFilmCannotWriteFailBeforeRendering) {
    std::string text = testing::ReadAll(scene);
    text.replace(text.find("Film \"rgb\""), 10, "Film \"thermal\" \"string sensor\" \"mwir\"");
    std::ofstream(scene) << text;
    EXPECT_EQ(Run(Q(scene) + " -o t.exr -o t.pfm"), 2);
    EXPECT_NE(log.find("t.pfm: the thermal film writes EXR"), std::string::npos) << log;
    EXPECT_NE(log.find("nothing rendered"), std::string::npos) << log;
    EXPECT_EQ(Lines(log), 1) << log;
    EXPECT_FALSE(fs::exists(dir / "t.exr"));
    EXPECT_EQ(Run(Q(scene) + " -o t.exr -o t.png"), 0) << log;
    EXPECT_TRUE(fs::exists(dir / "t.exr") && fs::exists(dir / "t.png"));
}

}  // namespace
}  // namespace kiln
