// pbrt-v4's rendering options on the kiln command: --mse-reference-image with
// --mse-reference-out writes "spp, MSE" after every sample per pixel (the last line is the
// final image's MSE, as kiln diff measures it), and --write-partial-images renders the same
// final image as a render without it; --stats prints time per phase, camera paths and memory;
// --log-level error silences scene warnings.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "app_test_util.h"

namespace kiln {
namespace {

class PbrtV4Options : public testing::KilnCommandTest {
  protected:
    PbrtV4Options() : KilnCommandTest("pbrt_options") {}
    void SetUp() override {
        KilnCommandTest::SetUp();
        WriteScene(
            "Film \"rgb\" \"integer xresolution\" 32 \"integer yresolution\" 24 \"bool savefp16\" "
            "false\n"
            "Sampler \"independent\"\nLookAt 0 0 -4 0 0 0 0 1 0 Camera \"perspective\"\n"
            "WorldBegin\nLightSource \"infinite\" \"rgb L\" [0.3 0.3 0.3]\n"
            "Material \"diffuse\" \"float temperature\" 1500\nShape \"sphere\"\n");
    }
};

TEST_F(PbrtV4Options, MSEAgainstAReferenceAfterEverySample) {
    ASSERT_EQ(Run("scene.pbrt --quiet --spp 256 --seed 9 -o ref.exr"), 0) << log;
    ASSERT_EQ(Run("scene.pbrt --quiet --spp 8 -o img.exr --mse-reference-image ref.exr "
                  "--mse-reference-out mse.txt"),
              0)
        << log;
    std::istringstream lines(testing::ReadAll((dir / "mse.txt").string()));
    std::vector<double> mse;
    int spp;
    double value;
    char comma;
    while (lines >> spp >> comma >> value) {
        EXPECT_EQ(spp, int(mse.size()) + 1);
        EXPECT_EQ(comma, ',');
        mse.push_back(value);
    }
    ASSERT_EQ(mse.size(), 8u);
    // 8 samples have about an eighth of one sample's variance (plus the reference's, 1/256)
    EXPECT_LT(mse.back(), mse.front() / 3);
    // The last line is the written image's MSE (kiln diff's rmse, squared)
    ASSERT_EQ(Run("diff img.exr ref.exr --metric rmse"), 0) << log;
    double rmse = -1;
    for (std::istringstream out(log); out;) {
        std::string name;
        out >> name;
        if (name == "rmse") out >> rmse;
    }
    EXPECT_NEAR(mse.back(), rmse * rmse, 1e-4 * rmse * rmse + 1e-30);
    // Both or neither; a reference that does not cover the image stops before rendering
    EXPECT_EQ(Run("scene.pbrt --quiet -o x.exr --mse-reference-image ref.exr"), 2);
    ASSERT_EQ(Run("scene.pbrt --quiet --spp 1 --pixelbounds 0,8,0,8 -o small.exr"), 0) << log;
    EXPECT_EQ(Run("scene.pbrt --quiet -o x.exr --mse-reference-image small.exr "
                  "--mse-reference-out m.txt"),
              1);
    EXPECT_NE(log.find("do not cover"), std::string::npos) << log;
}

TEST_F(PbrtV4Options, PartialImagesDoNotChangeTheFinalImage) {
    ASSERT_EQ(Run("scene.pbrt --quiet --spp 6 -o plain.exr"), 0) << log;
    ASSERT_EQ(Run("scene.pbrt --quiet --spp 6 -o partial.exr --write-partial-images"), 0) << log;
    EXPECT_EQ(testing::Pixels((dir / "plain.exr").string()),
              testing::Pixels((dir / "partial.exr").string()));
    ASSERT_EQ(Run("info partial.exr"), 0);
    EXPECT_EQ(log.find("partial"), log.find("partial.exr")) << log;  // no kiln:partial
}

TEST_F(PbrtV4Options, StatsAndLogLevels) {
    ASSERT_EQ(Run("scene.pbrt --quiet --spp 3 -o s.exr --stats"), 0) << log;
    for (const char* expect : {"Statistics:", "Parsing and scene creation", "Rendering",
                               "Peak resident set size", "Lights (thermal)"})
        EXPECT_NE(log.find(expect), std::string::npos) << expect << "\n" << log;
    // 34 x 26 pixels x 3 samples: 32 x 24 and the pixels around them whose samples reach
    // them (RGBFilm::SpreadMargin, one pixel for pbrt-v4's default Gaussian)
    std::string paths = "Camera paths";
    size_t at = log.find(paths);
    ASSERT_NE(at, std::string::npos);
    EXPECT_EQ(std::stol(log.substr(log.find_first_not_of(' ', at + paths.size()))), 34 * 26 * 3);
    // A scene warning (a known parameter in the wrong place) shows, unless the level is error
    std::ofstream(dir / "warn.pbrt", std::ios::app)
        << testing::ReadAll((dir / "scene.pbrt").string()) << "Shape \"sphere\" \"float fov\" 3\n";
    ASSERT_EQ(Run("warn.pbrt --quiet --spp 1 -o w.exr"), 0) << log;
    EXPECT_NE(log.find("unused parameter 'float fov'"), std::string::npos) << log;
    ASSERT_EQ(Run("warn.pbrt --quiet --spp 1 -o w.exr --log-level=error"), 0) << log;
    EXPECT_EQ(log, "");
    EXPECT_EQ(Run("scene.pbrt --log-level loud"), 2);
}

}  // namespace
}  // namespace kiln
