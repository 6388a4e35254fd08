// `kiln diff`: metrics worked by hand, size/channel mismatches, exit codes, difference image.
#include "app/image_diff.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

namespace kiln {
namespace {

namespace fs = std::filesystem;

Image MakeRGB(Point2i res, const std::vector<float>& values) {
    Image img(PixelFormat::Float, res, {"R", "G", "B"});
    size_t i = 0;
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x)
            for (int c = 0; c < 3; ++c) img.SetChannel({x, y}, c, values[i++]);
    return img;
}

fs::path OutDir() {
    fs::path dir = fs::path(KILN_BINARY_DIR) / "test-output" / "image_diff";
    fs::create_directories(dir);
    return dir;
}

TEST(ImageDiffTest, IdenticalImagesHaveZeroError) {
    Image a = MakeRGB({2, 1}, {0.1f, 0.2f, 0.3f, 4, 5, 6});
    ImageDiffMetrics m = CompareImages(a, a);
    EXPECT_EQ(m.mae, 0);
    EXPECT_EQ(m.rmse, 0);
    EXPECT_EQ(m.relmse, 0);
    EXPECT_EQ(m.flipLike, 0);
    EXPECT_TRUE(std::isinf(m.psnr));
    EXPECT_EQ(m.nonFinitePixels, 0);
}

// The relmse is pbrt-v4's MRSE: (v - r)^2 / (r + 0.01)^2 averaged over pixels and channels.
//   pixel 0  v (1.5, 0.25, 0)   r (1, 0.25, 0.5)
//   pixel 1  v (3, 1, 0.125)    r (2, 0, 0.125)
// relmse = (0.25/1.01^2 + 1/2.01^2 + 1/0.01^2 + 0.25/0.51^2) / 6 = 1666.90896023656,
// mae = (0.5 + 0 + 0.5 + 1 + 1 + 0) / 6 = 0.5, rmse = sqrt(2.5 / 6).
TEST(ImageDiffTest, MetricsMatchHandComputedValues) {
    Image v = MakeRGB({2, 1}, {1.5f, 0.25f, 0, 3, 1, 0.125f});
    Image r = MakeRGB({2, 1}, {1, 0.25f, 0.5f, 2, 0, 0.125f});
    ImageDiffMetrics m = CompareImages(v, r);
    EXPECT_NEAR(m.relmse, 1666.90896023656, 1666.9 * 1e-5);
    EXPECT_NEAR(m.mae, 0.5, 1e-6);
    EXPECT_NEAR(m.rmse, std::sqrt(2.5 / 6), 1e-6);
    EXPECT_NEAR(m.psnr, 20 * std::log10(1 / std::sqrt(2.5 / 6)), 1e-4);
    EXPECT_NEAR(m.maxError, 1.0, 1e-6);
    EXPECT_EQ(m.maxErrorPixel.x, 1);
}

TEST(ImageDiffTest, FlipLikeIsCielabDeltaEAfterDisplayClamp) {
    // White vs black: L* 100 vs 0, a* = b* = 0 for the D65 white.
    Image white = MakeRGB({1, 1}, {1, 1, 1}), black = MakeRGB({1, 1}, {0, 0, 0});
    EXPECT_NEAR(CompareImages(white, black).flipLike, 100, 0.05);
    // Above the display's range nothing is visible.
    Image bright = MakeRGB({1, 1}, {2, 3, 4});
    EXPECT_NEAR(CompareImages(bright, white).flipLike, 0, 1e-9);
    EXPECT_GT(CompareImages(bright, white).rmse, 1);
    // Mid grey 0.18 has L* = 116 * 0.18^(1/3) - 16 = 49.5.
    Image grey = MakeRGB({1, 1}, {0.18f, 0.18f, 0.18f});
    EXPECT_NEAR(CompareImages(grey, black).flipLike, 116 * std::cbrt(0.18) - 16, 0.05);
    // A pure hue change with equal luminance is still seen.
    Image red = MakeRGB({1, 1}, {0.5f, 0, 0}),
          green = MakeRGB({1, 1}, {0, 0.5f * 0.2126f / 0.7152f, 0});
    EXPECT_GT(CompareImages(red, green).flipLike, 50);
}

TEST(ImageDiffTest, MismatchedImagesThrow) {
    Image a = MakeRGB({2, 1}, {0, 0, 0, 0, 0, 0}), b = MakeRGB({1, 2}, {0, 0, 0, 0, 0, 0});
    EXPECT_THROW(CompareImages(a, b), std::invalid_argument);
    Image grey(PixelFormat::Float, {2, 1}, {"Y", "A", "Z"});
    EXPECT_THROW(CompareImages(a, grey), std::invalid_argument);
}

TEST(ImageDiffTest, NonFinitePixelsAreCountedAndShownGreen) {
    Image a = MakeRGB({2, 1}, {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f});
    Image b = a, nan = a;
    // SetChannel stores NaN as 0 (pbrt-v4), so an infinity marks the bad pixel.
    nan.SetChannel({1, 0}, 0, std::numeric_limits<float>::infinity());
    Image diff;
    ImageDiffMetrics m = CompareImages(nan, b, &diff);
    EXPECT_EQ(m.nonFinitePixels, 1);
    EXPECT_TRUE(std::isfinite(m.rmse));
    EXPECT_EQ(diff.GetChannel({1, 0}, 1), 1.f);
    EXPECT_EQ(diff.GetChannel({1, 0}, 0), 0.f);
    EXPECT_LT(diff.GetChannel({0, 0}, 1), 0.05f);  // inferno(0) is near black
}

int RunDiff(std::vector<std::string> args, std::string* out = nullptr) {
    ::testing::internal::CaptureStdout();
    int status = RunImageDiff(args);
    std::string s = ::testing::internal::GetCapturedStdout();
    if (out) *out = s;
    return status;
}

TEST(ImageDiffTest, CommandLineExitCodesAndOutput) {
    fs::path dir = OutDir();
    std::string fa = (dir / "a.exr").string(), fb = (dir / "b.exr").string();
    std::string fsmall = (dir / "small.exr").string();
    std::vector<float> va(4 * 4 * 3, 0.5f), vb = va;
    vb[0] = 0.6f;  // one value differs by 0.1
    MakeRGB({4, 4}, va).Write(fa);
    MakeRGB({4, 4}, vb).Write(fb);
    MakeRGB({2, 2}, std::vector<float>(12, 0.5f)).Write(fsmall);

    std::string out;
    EXPECT_EQ(RunDiff({fa, fa}, &out), 0);
    EXPECT_NE(out.find("relmse 0\n"), std::string::npos) << out;
    for (const char* name : {"rmse ", "mae ", "psnr ", "flip-like ", "maxerror ", "nonfinite 0"})
        EXPECT_NE(out.find(name), std::string::npos) << name << "\n" << out;

    // relmse = 0.1^2 / (0.6 + 0.01)^2 / 48 = 5.6e-4 (B is the reference); mae = 0.1 / 48.
    EXPECT_EQ(RunDiff({fa, fb, "--threshold", "1e-3"}), 0);
    EXPECT_EQ(RunDiff({fa, fb, "--threshold", "5e-4"}), 1);
    EXPECT_EQ(RunDiff({fa, fb, "--metric", "mae", "--threshold", "2.5e-3"}), 0);
    EXPECT_EQ(RunDiff({fa, fb, "--metric", "mae", "--threshold", "1.5e-3"}), 1);
    // psnr = 20 log10(1 / sqrt(0.01 / 48)) = 36.8 dB: fails when *below* the threshold.
    EXPECT_EQ(RunDiff({fa, fb, "--metric", "psnr", "--threshold", "30"}), 0);
    EXPECT_EQ(RunDiff({fa, fb, "--metric", "psnr", "--threshold", "40"}), 1);

    // Usage errors and mismatched images: 2.
    EXPECT_EQ(RunDiff({fa}), 2);
    EXPECT_EQ(RunDiff({fa, fb, "--metric", "ssim"}), 2);
    EXPECT_EQ(RunDiff({fa, fb, "--threshold", "x"}), 2);
    EXPECT_EQ(RunDiff({fa, fb, "--bogus"}), 2);
    EXPECT_EQ(RunDiff({fa, (dir / "missing.exr").string()}), 2);
    ::testing::internal::CaptureStderr();
    EXPECT_EQ(RunDiff({fa, fsmall}), 2);
    std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find(fa), std::string::npos) << err;
    EXPECT_NE(err.find(fsmall), std::string::npos) << err;
    EXPECT_NE(err.find("4x4, 3 channels"), std::string::npos) << err;
    EXPECT_NE(err.find("2x2, 3 channels"), std::string::npos) << err;
}

TEST(ImageDiffTest, WritesFalseColourDifferenceImage) {
    fs::path dir = OutDir();
    std::string fa = (dir / "da.exr").string(), fb = (dir / "db.exr").string();
    std::vector<float> va(8 * 2 * 3, 0.5f), vb = va;
    for (int c = 0; c < 3; ++c) vb[3 * 7 + c] = 1.0f;  // pixel (7, 0): 100 % error
    MakeRGB({8, 2}, va).Write(fa);
    MakeRGB({8, 2}, vb).Write(fb);
    for (const char* ext : {"png", "exr"}) {
        std::string diff = (dir / (std::string("diff.") + ext)).string();
        fs::remove(diff);
        EXPECT_EQ(RunDiff({fa, fb, "--out", diff}), 0);
        Image d = Image::Read(diff);
        ASSERT_EQ(d.Resolution(), Point2i(8, 2));
        ASSERT_GE(d.NChannels(), 3);
        // Identical pixels are near black; the 50 % error pixel is bright (inferno, ~0.9).
        EXPECT_LT(d.GetChannel({0, 0}, 0), 0.01f);
        EXPECT_GT(d.GetChannel({7, 0}, 0), 0.5f);
    }
}

}  // namespace
}  // namespace kiln
