// kiln convert and kiln info (app/image_tools.h): an EXR render converted to PNG is the PNG the
// render writes itself, with the same view and exposure (fixed or automatic); linear outputs are
// the EXR scaled by 2^EV; info lists the Stokes layers and kiln's metadata; bad outputs fail
// before the input is read.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

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

class ImageTools : public testing::KilnCommandTest {
  protected:
    ImageTools() : KilnCommandTest("image_tools") {}
    void SetUp() override {
        KilnCommandTest::SetUp();
        WriteScene(
            "Film \"rgb\" \"integer xresolution\" 20 \"integer yresolution\" 14"
            " \"bool savefp16\" false \"string view\" \"Glow\"\n"
            "Sampler \"independent\" \"integer pixelsamples\" 4\n"
            "LookAt 0 0 -4 0 0 0 0 1 0 Camera \"perspective\"\nWorldBegin\n"
            "LightSource \"infinite\" \"rgb L\" [0.05 0.05 0.05]\n"
            "Material \"conductor\" \"float roughness\" 0.1 \"float temperature\" 1300\n"
            "Shape \"sphere\"\n");
        scene = (dir / "scene.pbrt").string();
    }
    std::vector<float> Pixels(const std::string& name) {
        return testing::Pixels((dir / name).string());
    }

    std::string scene;
};

TEST_F(ImageTools, ConvertGivesWhatTheRenderWritesItself) {
    ASSERT_EQ(Run(Q(scene) + " --quiet -o r.exr -o r.png"), 0) << log;
    ASSERT_EQ(Run(Q(scene) + " --quiet --exposure 1.5 -o e.png"), 0) << log;
    ASSERT_EQ(Run(Q(scene) + " --quiet --exposure auto -o a.png"), 0) << log;
    // The film's view (Glow) travels in the EXR
    ASSERT_EQ(Run("convert r.exr -o c.png"), 0) << log;
    EXPECT_EQ(Pixels("c.png"), Pixels("r.png"));
    ASSERT_EQ(Run("convert r.exr -o ce.png --exposure 1.5"), 0) << log;
    EXPECT_EQ(Pixels("ce.png"), Pixels("e.png"));
    ASSERT_EQ(Run("convert r.exr -o ca.png --exposure auto"), 0) << log;
    EXPECT_EQ(Pixels("ca.png"), Pixels("a.png"));
    // Another view changes the picture
    ASSERT_EQ(Run("convert r.exr -o s.png --view Standard"), 0) << log;
    EXPECT_NE(Pixels("s.png"), Pixels("r.png"));
    // Linear outputs: the EXR's R, G, B times 2^EV
    ASSERT_EQ(Run("convert r.exr -o l.pfm --exposure -1"), 0) << log;
    Image exr = Image::Read((dir / "r.exr").string()), pfm = Image::Read((dir / "l.pfm").string());
    ASSERT_EQ(pfm.Resolution(), exr.Resolution());
    for (int y = 0; y < exr.Resolution().y; ++y)
        for (int x = 0; x < exr.Resolution().x; ++x)
            for (int c = 0; c < 3; ++c)
                ASSERT_EQ(pfm.GetChannel({x, y}, c), exr.GetChannel({x, y}, c) * 0.5f);
}

TEST_F(ImageTools, SeveralInputsAreJoinedSideBySide) {
    ASSERT_EQ(Run(Q(scene) + " --quiet -o k.exr"), 0) << log;
    ASSERT_EQ(Run(Q(scene) + " --quiet --emission additive -o a.exr"), 0) << log;
    ASSERT_EQ(Run("convert k.exr a.exr -o ka.pfm"), 0) << log;
    Image k = Image::Read((dir / "k.exr").string()), a = Image::Read((dir / "a.exr").string());
    Image ka = Image::Read((dir / "ka.pfm").string());
    ASSERT_EQ(ka.Resolution(), Point2i(2 * k.Resolution().x, k.Resolution().y));
    int w = k.Resolution().x;
    for (int y = 0; y < k.Resolution().y; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) {
                ASSERT_EQ(ka.GetChannel({x, y}, c), k.GetChannel({x, y}, c));
                ASSERT_EQ(ka.GetChannel({w + x, y}, c), a.GetChannel({x, y}, c));
            }
    // Additive emission from a hot metal is brighter than Kirchhoff's (the left half)
    double left = 0, right = 0;
    for (int y = 0; y < k.Resolution().y; ++y)
        for (int x = 0; x < w; ++x)
            left += ka.GetChannel({x, y}, 0), right += ka.GetChannel({w + x, y}, 0);
    EXPECT_GT(right, left);
    // Images of different heights cannot stand side by side
    std::string wide = testing::ReadAll(scene);
    wide.replace(wide.find("\"integer yresolution\" 14"), 24, "\"integer yresolution\" 10");
    std::ofstream((dir / "short.pbrt").string()) << wide;
    ASSERT_EQ(Run("short.pbrt --quiet -o s.exr"), 0) << log;
    EXPECT_EQ(Run("convert k.exr s.exr -o x.png"), 1);
    EXPECT_NE(log.find("same height"), std::string::npos) << log;
}

TEST_F(ImageTools, InfoListsLayersAndMetadata) {
    ASSERT_EQ(Run(Q(scene) + " --quiet --stokes --seed 7 -o p.exr"), 0) << log;
    ASSERT_EQ(Run("info p.exr"), 0) << log;
    for (const char* expect : {"resolution    20 x 14", "channels      15", "S1          R, G, B",
                               "spp           4", "seed          7", "view          Glow"})
        EXPECT_NE(log.find(expect), std::string::npos) << expect << "\n" << log;
    EXPECT_EQ(Run("info missing.exr"), 1);
    EXPECT_NE(log.find("missing.exr"), std::string::npos) << log;
    EXPECT_EQ(Run("info"), 2);
}

TEST_F(ImageTools, BadOutputsAndInputsAreErrors) {
    ASSERT_EQ(Run(Q(scene) + " --quiet -o r.exr"), 0) << log;
    // The log is checked before the (missing) input is read
    EXPECT_EQ(Run("convert missing.exr -o no/such/x.png"), 2);
    EXPECT_NE(log.find("no/such/x.png"), std::string::npos) << log;
    EXPECT_EQ(log.find("missing.exr"), std::string::npos) << log;
    EXPECT_EQ(Run("convert r.exr -o x.png --view Filmc"), 2);
    EXPECT_NE(log.find("the views are"), std::string::npos) << log;
    EXPECT_EQ(Run("convert r.exr -o x.png --exposure bright"), 2);
    EXPECT_EQ(Run("convert missing.exr -o x.png"), 1);
    EXPECT_NE(log.find("missing.exr"), std::string::npos) << log;
    EXPECT_FALSE(fs::exists(dir / "x.png"));
    // An image given where a scene is expected points to kiln convert
    EXPECT_EQ(Run("r.exr -o x.png"), 2);
    EXPECT_NE(log.find("kiln convert r.exr"), std::string::npos) << log;
}

}  // namespace
}  // namespace kiln
