// White-furnace tests: a diffuse sphere inside a uniform environment of luminance 1.
//
// A convex object sees only the environment, so with albedo a every point reflects exactly
// a * 1 (Lambert: L = a/pi * pi * 1); the image must average to a within Monte Carlo noise.
#include <gtest/gtest.h>

#include <cmath>

#include "base/statistics.h"
#include "render_test_util.h"

namespace kiln {
namespace {

std::string FurnaceScene(Float albedo, const std::string& sampler) {
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 24 \"integer yresolution\" 24\n"
      << "Sampler \"" << sampler << "\" \"integer pixelsamples\" 16\n"
      << "PixelFilter \"box\"\n"
      << "Integrator \"path\" \"integer maxdepth\" 20\n"
      << "LookAt 0 0 -10  0 0 0  0 1 0\n"
      << "Camera \"orthographic\" \"float screenwindow\" [-1 1 -1 1]\n"
      << "WorldBegin\n"
      << "LightSource \"infinite\" \"rgb L\" [1 1 1]\n"
      << "Material \"diffuse\" \"rgb reflectance\" [" << albedo << " " << albedo << " " << albedo
      << "]\n"
      << "Shape \"sphere\" \"float radius\" 4\n";
    return s.str();
}

// Mean pixel luminance and its standard error (testing::BlockStats: neighbouring pixels
// share samples).
RunningStats PixelLuminance(const Scene& scene) {
    return testing::BlockStats(scene.job->film->PixelBounds(),
                               [&](Point2i p) { return testing::PixelY(scene, p); });
}

class FurnaceTest : public ::testing::TestWithParam<Float> {};

TEST_P(FurnaceTest, DiffuseSphereReflectsItsAlbedo) {
    Float a = GetParam();
    for (const char* sampler : {"independent", "zsobol"}) {
        testing::RenderedScene r = testing::RenderText(FurnaceScene(a, sampler));
        RunningStats s = PixelLuminance(*r.scene);
        double standardError = std::sqrt(s.Variance() / s.Count());
        // Five standard errors plus float round-off in the colour conversions.
        EXPECT_NEAR(s.Mean(), a, 5 * standardError + 2e-3) << sampler;
        EXPECT_EQ(r.scene->job->film->NonFiniteSampleCount(), 0);
    }
}

INSTANTIATE_TEST_SUITE_P(Albedos, FurnaceTest, ::testing::Values(1.0f, 0.8f, 0.5f, 0.1f));

}  // namespace
}  // namespace kiln
