// kiln diff error and falsecolor (app/image_error.h), pbrt-v4 imgtool's uses: the error
// estimate over several renders is the mean of what kiln diff measures for each, the error
// image is the per-pixel mean, and it falls with the sample count as Monte Carlo error should;
// falsecolor maps values through the colour map, or signs to green and red.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "app_test_util.h"
#include "core/image/image.h"

namespace kiln {
namespace {

namespace fs = std::filesystem;

class ImageError : public testing::KilnCommandTest {
  protected:
    ImageError() : KilnCommandTest("image_error") {}
    void SetUp() override {
        KilnCommandTest::SetUp();
        WriteScene(
            "Film \"rgb\" \"integer xresolution\" 24 \"integer yresolution\" 16\n"
            "Sampler \"independent\"\nLookAt 0 0 -4 0 0 0 0 1 0 Camera \"perspective\"\n"
            "WorldBegin\nLightSource \"infinite\" \"rgb L\" [0.5 0.5 0.5]\n"
            "Material \"diffuse\" \"float temperature\" 1300\nShape \"sphere\"\n");
    }
    double Value(const std::string& metric) {
        std::istringstream in(log);
        for (std::string line; std::getline(in, line);)
            if (line.rfind(metric, 0) == 0) return std::stod(line.substr(line.rfind(' ') + 1));
        ADD_FAILURE() << metric << " not in: " << log;
        return -1;
    }
};

TEST_F(ImageError, TheEstimateIsTheMeanOfEachImagesErrorAndFallsWithSamples) {
    ASSERT_EQ(Run("scene.pbrt --quiet --spp 512 --seed 100 -o ref.exr"), 0) << log;
    double sum = 0;
    for (int seed = 0; seed < 3; ++seed) {
        std::string out = "low-" + std::to_string(seed) + ".exr";
        ASSERT_EQ(Run("scene.pbrt --quiet --spp 2 --seed " + std::to_string(seed) + " -o " + out),
                  0);
        ASSERT_EQ(Run("diff " + out + " ref.exr --metric rmse"), 0) << log;
        double rmse = Value("rmse");
        sum += rmse * rmse;
        ASSERT_EQ(Run("scene.pbrt --quiet --spp 32 --seed " + std::to_string(seed) + " -o high-" +
                      std::to_string(seed) + ".exr"),
                  0);
    }
    ASSERT_EQ(Run("diff error --reference ref.exr --metric MSE --errorfile err.exr low-"), 0)
        << log;
    EXPECT_EQ(Value("images"), 3);
    double low = Value("mse estimate");
    EXPECT_NEAR(low, sum / 3, 1e-5 * low);
    // The error image's mean is the estimate
    Image err = Image::Read((dir / "err.exr").string());
    double mean = 0;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 24; ++x) mean += err.GetChannel({x, y}, 0) / (24.0 * 16);
    EXPECT_NEAR(mean, low, 1e-4 * low);
    // 16 times the samples: about a sixteenth of the error (well below a quarter)
    ASSERT_EQ(Run("diff error --reference ref.exr high-"), 0) << log;
    EXPECT_LT(Value("mse estimate"), low / 4);
    // Renders of different sample counts (low-* at 2 spp, high-* at 32), no match: errors
    fs::copy_file(dir / "high-0.exr", dir / "low-9.exr");
    EXPECT_EQ(Run("diff error --reference ref.exr low-"), 1);
    EXPECT_NE(log.find("spp"), std::string::npos) << log;
    EXPECT_EQ(Run("diff error --reference ref.exr nothing-"), 1);
    EXPECT_EQ(Run("diff error low-"), 2);
}

TEST_F(ImageError, FalseColourMapsMagnitudesAndSigns) {
    Image ramp(PixelFormat::Float, {4, 1}, {"Y"});
    for (int x = 0; x < 4; ++x) ramp.SetChannel({x, 0}, 0, Float(x - 1));  // -1 0 1 2
    ramp.Write((dir / "ramp.exr").string());
    ASSERT_EQ(Run("diff falsecolor ramp.exr -o ramp.png"), 0) << log;
    Image png = Image::Read((dir / "ramp.png").string());
    auto luminance = [&](const Image& im, int x) {
        return im.GetChannel({x, 0}, 0) + im.GetChannel({x, 0}, 1) + im.GetChannel({x, 0}, 2);
    };
    EXPECT_LT(luminance(png, 1), luminance(png, 2));  // 0 darker than 1
    EXPECT_LT(luminance(png, 2), luminance(png, 3));  // 1 darker than 2 (the maximum)
    ASSERT_EQ(Run("diff falsecolor ramp.exr -o pm.exr --plusminus --maxvalue 2"), 0) << log;
    Image pm = Image::Read((dir / "pm.exr").string());
    EXPECT_GT(pm.GetChannel({0, 0}, 0), 0);  // -1: red
    EXPECT_EQ(pm.GetChannel({0, 0}, 1), 0);
    EXPECT_EQ(pm.GetChannel({3, 0}, 0), 0);  // 2: green
    EXPECT_GT(pm.GetChannel({3, 0}, 1), pm.GetChannel({2, 0}, 1));
    EXPECT_EQ(Run("diff falsecolor ramp.exr"), 2);
}

}  // namespace
}  // namespace kiln
