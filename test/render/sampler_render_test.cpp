// The halton, sobol and pmj02bn samplers render the same image mean as zsobol within noise.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "render_test_util.h"

namespace kiln {
namespace {

std::string SamplerScene(const std::string& sampler) {
    return R"(
Film "rgb" "integer xresolution" 32 "integer yresolution" 32
Sampler ")" +
           sampler +
           R"(" "integer pixelsamples" 16
Integrator "path" "integer maxdepth" 4
LookAt 0 1 -5  0 0.3 0  0 1 0
Camera "perspective" "float fov" 40
WorldBegin
LightSource "infinite" "rgb L" [0.3 0.3 0.35]
AttributeBegin
  AreaLightSource "diffuse" "blackbody L" 4000 "float scale" 6
  Translate 1 2.5 -1
  Shape "sphere" "float radius" 0.4
AttributeEnd
Material "diffuse" "rgb reflectance" [0.7 0.6 0.5]
Shape "sphere" "float radius" 0.8
Material "conductor" "float roughness" 0.2
Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]
  "point3 P" [-10 -0.8 -10  10 -0.8 -10  10 -0.8 10  -10 -0.8 10]
)";
}

std::vector<double> PixelLuminances(const std::string& sampler) {
    testing::RenderedScene r = testing::RenderText(SamplerScene(sampler), 2);
    EXPECT_TRUE(r.warnings.empty()) << sampler;
    std::vector<double> Y;
    Bounds2i b = r.scene->job->film->PixelBounds();
    for (int y = b.pMin.y; y < b.pMax.y; ++y)
        for (int x = b.pMin.x; x < b.pMax.x; ++x) Y.push_back(testing::PixelY(*r.scene, {x, y}));
    return Y;
}

// Per-pixel differences from zsobol: their mean must be within 4 standard errors of zero
// (the standard error from the differences' spread over the 1024 pixels).
TEST(SamplerRender, SameMeanAsZSobol) {
    std::vector<double> ref = PixelLuminances("zsobol");
    double refMean = 0;
    for (double v : ref) refMean += v / double(ref.size());
    ASSERT_GT(refMean, 0);
    for (std::string sampler : {"halton", "sobol", "pmj02bn"}) {
        std::vector<double> Y = PixelLuminances(sampler);
        ASSERT_EQ(Y.size(), ref.size());
        double mean = 0, sq = 0;
        for (size_t i = 0; i < Y.size(); ++i) mean += (Y[i] - ref[i]) / double(Y.size());
        for (size_t i = 0; i < Y.size(); ++i) sq += Sqr(Y[i] - ref[i] - mean);
        double se = std::sqrt(sq / double(Y.size() - 1) / double(Y.size()));
        EXPECT_LT(std::abs(mean), 4 * se)
            << sampler << ": mean difference " << mean << " standard error " << se
            << " (image mean " << refMean << ")";
    }
}

}  // namespace
}  // namespace kiln
