// Wavelengths drawn by what hot matter radiates (Integrator "wavelengthsampling",
// render/scene_wavelengths.h): chosen at load only for scenes that glow thermally, and a hot
// body seen directly renders the same image as with pbrt-v4's visible density, with less noise.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "render_test_util.h"

namespace kiln {
namespace {

// A hot coloured diffuse sphere filling most of the view; `extra` adds to the world
std::string HotSphere(const std::string& sampling, int seed, const std::string& extra = "") {
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 32 \"integer yresolution\" 32\n"
      << "Sampler \"independent\" \"integer pixelsamples\" 16 \"integer seed\" " << seed << "\n"
      << "Integrator \"path\" \"string wavelengthsampling\" \"" << sampling << "\"\n"
      << "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 30\n"
      << "WorldBegin\n"
      << extra
      << "Material \"diffuse\" \"rgb reflectance\" [0.6 0.3 0.1] \"float temperature\" 1300\n"
      << "Shape \"sphere\" \"float radius\" 1\n";
    return s.str();
}

TEST(WavelengthSampling, ChosenOnlyWhereHotMatterGlows) {
    EXPECT_EQ(testing::RenderText(HotSphere("emission", 1)).scene->features.wavelengthVisibleShare,
              0.5f);
    EXPECT_EQ(testing::RenderText(HotSphere("visible", 1)).scene->features.wavelengthVisibleShare,
              1.f);
    // Other light, whose spectrum is not the glow's: more of the visible density
    EXPECT_EQ(testing::RenderText(
                  HotSphere("emission", 1, "LightSource \"infinite\" \"rgb L\" [0.1 0.1 0.1]\n"))
                  .scene->features.wavelengthVisibleShare,
              0.75f);
    // Nothing hot: the visible density
    std::string cold = HotSphere("emission", 1, "LightSource \"infinite\" \"rgb L\" [1 1 1]\n");
    cold.replace(cold.find("\"float temperature\" 1300"), 24, "");
    EXPECT_EQ(testing::RenderText(cold).scene->features.wavelengthVisibleShare, 1.f);
}

// The hottest temperature a scene may give (1e27 K) leaves the density finite and normalised
TEST(WavelengthSampling, ExtremeTemperaturesKeepAFiniteDensity) {
    std::string text = HotSphere("emission", 1);
    text.replace(text.find("1300"), 4, "1e27");
    testing::RenderedScene r = testing::RenderText(text);
    double integral = 0;
    for (int i = 0; i < WavelengthDistribution::kBins; ++i) {
        Float p = r.scene->wavelengths.PDF(Lambda_min + i + 0.5f);
        ASSERT_TRUE(std::isfinite(p) && p > 0) << Lambda_min + i + 0.5f << " nm";
        integral += p;
    }
    EXPECT_NEAR(integral, 1, 1e-3);
}

TEST(WavelengthSampling, HotBodyRendersTheSameImageWithLessNoise) {
    auto render = [](const std::string& sampling, int seed) {
        return testing::RenderTwoSeeds([&](int s) { return HotSphere(sampling, s); }, seed);
    };
    testing::TwoSeedNoise emission = render("emission", 1), visible = render("visible", 3);
    ASSERT_GT(emission.mean, 0);
    std::printf("visible density: image mean %.5f of emission's, standard errors %.5f, %.5f\n",
                visible.mean / emission.mean, visible.se / emission.mean,
                emission.se / emission.mean);
    EXPECT_NEAR(visible.mean, emission.mean, 5 * std::hypot(emission.se, visible.se));
    double ratio = emission.variance / visible.variance;
    std::printf("per-pixel variance of luminance, emission / visible: %.4f\n", ratio);
    EXPECT_LT(ratio, 0.8);  // measured 0.61 (per-pixel variances from 1024 pixels each)
}

}  // namespace
}  // namespace kiln
