// The emission of a uniform medium along a ray segment, integrated exactly (Integrator "bool
// exactmediumemission", Medium::UniformSegmentEmission): the integral matches quadrature of
// T(t) sigma_a Le, is offered only where it is exact, and a hot melt in a glass ball renders
// the same image as with emission met at collisions (pbrt-v4's way), with less noise.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "render_test_util.h"

namespace kiln {
namespace {

// A glass ball (eta 1.5) holding a hot absorbing, scattering, chromatic melt on a floor, seen
// from above, lit by a dim sky. The melt is optically thin (0.25 to 1.25 across), where
// collisions estimate emission worst; in thick media nearly every path collides and both
// estimates are nearly exact.
std::string HotBall(bool exact, int seed, int spp = 64,
                    const std::string& temperature = "\"float temperature\" 1400",
                    const std::string& textures = "") {
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 16\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" " << spp << " \"integer seed\" " << seed
      << "\n"
      << "Integrator \"volpath\" \"integer maxdepth\" 5 \"bool exactmediumemission\" "
      << (exact ? "true" : "false") << "\n"
      << "LookAt 0 1.2 -1.6  0 0.25 0  0 1 0\nCamera \"perspective\" \"float fov\" 25\n"
      << "WorldBegin\n"
      << textures << "LightSource \"infinite\" \"rgb L\" [0.05 0.05 0.05]\n"
      << "Material \"diffuse\" \"rgb reflectance\" [0.5 0.5 0.5]\n"
      << "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point3 P\" "
         "[-3 0 -3 3 0 -3 3 0 3 -3 0 3]\n"
      << "MakeNamedMedium \"melt\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [0.5 1 2] "
         "\"rgb sigma_s\" [0.5 0.5 0.5] "
      << temperature << "\n"
      << "AttributeBegin\nMediumInterface \"melt\" \"\"\nMaterial \"dielectric\" \"float eta\" "
         "1.5\nTranslate 0 0.25 0\nShape \"sphere\" \"float radius\" 0.25\nAttributeEnd\n";
    return s.str();
}

TEST(ExactMediumEmission, SegmentIntegralMatchesQuadrature) {
    testing::RenderedScene r = testing::RenderText(HotBall(true, 1));
    ASSERT_EQ(r.scene->media.size(), 1u);
    const Medium& melt = r.scene->media[0];
    ASSERT_TRUE(melt.IsUniform());
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.37f);
    MediumProperties mp = melt.SamplePoint(Point3f(0, 0.25f, 0), lambda);
    for (Float d : {Float(1e-6), Float(0.01), Float(0.3), Float(2), Float(Infinity)}) {
        std::optional<SampledSpectrum> E = melt.UniformSegmentEmission(d, lambda);
        ASSERT_TRUE(E.has_value());
        for (int i = 0; i < NSpectrumSamples; ++i) {
            // Midpoint rule over [0, min(d, 40 / sigma_t)] (beyond, T < 1e-17)
            double sigma_t = double(mp.sigma_a[i]) + double(mp.sigma_s[i]);
            double end = std::min(double(d), 40 / sigma_t), sum = 0;
            const int n = 100000;
            for (int k = 0; k < n; ++k) sum += std::exp(-sigma_t * (k + 0.5) * end / n);
            double expected = double(mp.emission[i]) * sum * end / n;
            ASSERT_GT(expected, 0);
            EXPECT_NEAR((*E)[i] / expected, 1, 1e-4) << "d " << d << ", lambda " << lambda[i];
        }
    }
    EXPECT_EQ(r.scene->features.exactEmissionMedia, 1);
}

TEST(ExactMediumEmission, OnlyUniformMediaAreIntegratedExactly) {
    // A temperature that varies over the medium: met at collisions
    testing::RenderedScene textured = testing::RenderText(
        HotBall(true, 1, 1, "\"texture temperature\" \"heat\"",
                "Texture \"heat\" \"float\" \"checkerboard\" \"string mapping\" \"planar\" "
                "\"float tex1\" 900 \"float tex2\" 1500\n"));
    ASSERT_EQ(textured.scene->media.size(), 1u);
    EXPECT_FALSE(textured.scene->media[0].IsUniform());
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    EXPECT_FALSE(textured.scene->media[0].UniformSegmentEmission(1, lambda).has_value());
    EXPECT_EQ(textured.scene->features.exactEmissionMedia, 0);
    // Switched off: nothing integrated exactly
    testing::RenderedScene off = testing::RenderText(HotBall(false, 1, 1));
    EXPECT_EQ(off.scene->features.exactEmissionMedia, 0);
    EXPECT_TRUE(off.scene->exactEmissionMedia.empty());
}

TEST(ExactMediumEmission, RendersTheSameImageAsCollisionsWithLessNoise) {
    // A flat emission spectrum, so that the noise left is mostly that of the emission
    // estimate rather than of the wavelengths drawn
    const std::string flat = "\"spectrum Le\" [360 1 830 1]";
    auto render = [&](bool exact, int seed) {
        return testing::RenderTwoSeeds([&](int s) { return HotBall(exact, s, 64, flat); }, seed);
    };
    testing::TwoSeedNoise exact = render(true, 1), collisions = render(false, 3);
    ASSERT_GT(exact.mean, 0);
    std::printf("collisions: image mean %.5f of exact's, standard errors %.5f and %.5f\n",
                collisions.mean / exact.mean, collisions.se / exact.mean, exact.se / exact.mean);
    EXPECT_NEAR(collisions.mean, exact.mean, 5 * std::hypot(exact.se, collisions.se));
    double ratio = exact.variance / collisions.variance;
    std::printf("per-pixel variance, exact / collisions: %.4f\n", ratio);
    EXPECT_LT(ratio, 0.5);
}

}  // namespace
}  // namespace kiln
