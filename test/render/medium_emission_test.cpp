// Hot media as light sources (Integrator "mediumemission" "sampled"): a small hot, chromatic,
// scattering grid lighting a floor renders the same image whether its emission is sampled
// with MIS, by light sampling alone, by path sampling alone or by tracking alone (pbrt-v4's
// way), and sampling it makes the floor far less noisy than tracking does. The same for a
// hot melt inside a glass ball, sampled through the glass (glass windows) or not, and with the
// emission along the chord behind a window integrated exactly or met at collisions.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "base/statistics.h"
#include "render_test_util.h"

namespace kiln {
namespace {

// A glass ball (eta 1.5) holding a hot absorbing, scattering melt above the floor
std::string GlassBall() {
    return "MakeNamedMedium \"melt\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [2 3 5] "
           "\"rgb sigma_s\" [0.5 0.5 0.5] \"float temperature\" 1500\n"
           "AttributeBegin\nMediumInterface \"melt\" \"\"\nMaterial \"dielectric\" \"float eta\" "
           "1.5\nTranslate 0 0.35 0\nShape \"sphere\" \"float radius\" 0.1\nAttributeEnd\n";
}

std::string SmallFlame(const std::string& strategy, const std::string& emission, int seed,
                       bool glass = false, bool windows = true,
                       const std::string& integrator = "") {
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 16\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" 256 \"integer seed\" " << seed << "\n"
      << "Integrator \"volpath\" \"integer maxdepth\" 4 \"string strategy\" \"" << strategy
      << "\" \"string mediumemission\" \"" << emission << "\" \"bool glasswindows\" "
      << (windows ? "true" : "false") << " " << integrator
      << "\n"
      // The floor in front of the flame, the flame itself out of view
      << "LookAt 0 1.2 -2.5  0 0 -1  0 1 0\nCamera \"perspective\" \"float fov\" 30\n"
      << "WorldBegin\n"
      << "Material \"diffuse\" \"rgb reflectance\" [0.5 0.5 0.5]\n"
      << "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point3 P\" "
         "[-3 0 -3 3 0 -3 3 0 3 -3 0 3]\n";
    if (glass) return s.str() + GlassBall();
    // A 4^3 grid 0.3 across, uneven density (majorant voxels above sigma_t: null
    // collisions), absorbing more in blue, scattering
    s << "MakeNamedMedium \"flame\" \"string type\" \"uniformgrid\" \"integer nx\" 4 "
         "\"integer ny\" 4 \"integer nz\" 4 \"float density\" [";
    for (int i = 0; i < 64; ++i) s << (i % 5 == 0 ? 0.1 : 1.0 + 0.5 * (i % 3)) << " ";
    s << "] \"point3 p0\" [-0.15 0.3 -0.15] \"point3 p1\" [0.15 0.6 0.15] "
         "\"rgb sigma_a\" [0.3 0.6 1.2] \"rgb sigma_s\" [0.6 0.6 0.6] \"float g\" 0.3 "
         "\"float temperature\" 1600\n"
      << "AttributeBegin\nMediumInterface \"flame\" \"\"\nMaterial \"interface\"\n"
      << "Translate 0 0.45 0\nShape \"sphere\" \"float radius\" 0.26\nAttributeEnd\n";
    return s.str();
}

struct LuminanceImage {
    std::vector<double> Y;
    double Mean() const {
        double m = 0;
        for (double y : Y) m += y;
        return m / double(Y.size());
    }
};

LuminanceImage Render(const std::string& strategy, const std::string& emission, int seed,
                      bool glass = false, bool windows = true) {
    testing::RenderedScene r =
        testing::RenderText(SmallFlame(strategy, emission, seed, glass, windows));
    bool sampled = emission == "sampled";
    EXPECT_EQ(r.scene->features.sampledMedia, sampled && !glass ? 1 : 0);
    EXPECT_EQ(r.scene->features.glassWindows > 0, sampled && glass && windows);
    LuminanceImage image;
    Bounds2i b = r.scene->job->film->PixelBounds();
    for (int y = b.pMin.y; y < b.pMax.y; ++y)
        for (int x = b.pMin.x; x < b.pMax.x; ++x)
            image.Y.push_back(testing::PixelY(*r.scene, {x, y}));
    return image;
}

// The mean squared difference of two renders of one kind: twice the per-pixel variance
double NoiseVariance(const LuminanceImage& a, const LuminanceImage& b) {
    double sum = 0;
    for (size_t i = 0; i < a.Y.size(); ++i) sum += (a.Y[i] - b.Y[i]) * (a.Y[i] - b.Y[i]);
    return sum / (2.0 * double(a.Y.size()));
}

// One kind of render at two seeds of its own (independent of the other kinds'): the image
// mean over both and its standard error, and the per-pixel variance of one render
struct Kind {
    double mean, se, variance;
};
Kind RenderKind(const std::string& strategy, const std::string& emission, int seed,
                bool glass = false, bool windows = true) {
    LuminanceImage a = Render(strategy, emission, seed, glass, windows),
                   b = Render(strategy, emission, seed + 1, glass, windows);
    double variance = NoiseVariance(a, b);
    return {(a.Mean() + b.Mean()) / 2, std::sqrt(variance / (2.0 * double(a.Y.size()))), variance};
}

TEST(MediumEmission, SampledAndTrackedEmissionRenderTheSameImage) {
    Kind mis = RenderKind("mis", "sampled", 1), tracked = RenderKind("mis", "tracked", 3);
    Kind light = RenderKind("light", "sampled", 5), bsdf = RenderKind("bsdf", "sampled", 7);
    ASSERT_GT(mis.mean, 0);
    for (const auto& [name, k] : {std::pair{"mis", &mis}, std::pair{"tracked", &tracked},
                                  std::pair{"light", &light}, std::pair{"bsdf", &bsdf}})
        std::printf("%-8s image mean %.5f of mis's, standard error %.5f\n", name,
                    k->mean / mis.mean, k->se / mis.mean);
    for (const Kind* k : {&tracked, &light, &bsdf})
        EXPECT_NEAR(k->mean, mis.mean, 5 * std::hypot(k->se, mis.se));
    // The floor's noise: sampling the small emitter beats finding it by chance
    double ratio = mis.variance / tracked.variance;
    std::printf("per-pixel variance, sampled / tracked: %.4f\n", ratio);
    EXPECT_LT(ratio, 0.25);
}

TEST(MediumEmission, HotMeltInGlassRendersTheSameImageThroughItsWindows) {
    Kind mis = RenderKind("mis", "sampled", 11, true),
         off = RenderKind("mis", "sampled", 13, true, false);
    Kind light = RenderKind("light", "sampled", 15, true),
         bsdf = RenderKind("bsdf", "sampled", 17, true);
    ASSERT_GT(mis.mean, 0);
    for (const auto& [name, k] : {std::pair{"windows", &mis}, std::pair{"off", &off},
                                  std::pair{"light", &light}, std::pair{"bsdf", &bsdf}})
        std::printf("%-8s image mean %.5f of the windows', standard error %.5f\n", name,
                    k->mean / mis.mean, k->se / mis.mean);
    for (const Kind* k : {&off, &light, &bsdf})
        EXPECT_NEAR(k->mean, mis.mean, 5 * std::hypot(k->se, mis.se));
    // The floor lit through the glass: sampling the windows beats chance refractions
    double ratio = mis.variance / off.variance;
    std::printf("per-pixel variance, windows / off: %.4f\n", ratio);
    EXPECT_LT(ratio, 0.5);
}

// A uniform melt's emission along the chord a window opens onto is integrated exactly, by
// window sampling and by the path that refracts there alike (weighted against each other as a
// whole), rather than met at collisions: the same floor, far less noisy
TEST(MediumEmission, WindowChordsIntoUniformMeltsAreIntegratedExactly) {
    testing::ExpectSameImageWithLessNoise(
        "floor lit through the glass",
        [](const std::string& integrator, int seed) {
            return SmallFlame("mis", "sampled", seed, true, true, integrator);
        },
        "\"bool exactmediumemission\" false", 0.5);
}

// Under an environment much brighter than a small glow, window sampling is kept only where
// the glow would add noise comparable to the environment's (GlassWindows::
// WeighAgainstEnvironment): less of it at the floor, and the same image as without windows
TEST(MediumEmission, WindowsAreWeighedAgainstTheEnvironment) {
    const std::string sky = "LightSource \"infinite\" \"rgb L\" [0.02 0.02 0.02]\n";
    auto scene = [&](bool withSky, bool windows, int seed) {
        return SmallFlame("mis", "sampled", seed, true, windows) + (withSky ? sky : "");
    };
    testing::RenderedScene dark = testing::RenderText(scene(false, true, 1));
    testing::RenderedScene lit = testing::RenderText(scene(true, true, 1));
    ASSERT_TRUE(dark.scene->glassWindows && lit.scene->glassWindows);
    EXPECT_FALSE(dark.scene->features.glassWindowsAgainstEnvironment);
    EXPECT_TRUE(lit.scene->features.glassWindowsAgainstEnvironment);
    // The floor half a unit in front of the ball (which subtends about 0.09 sr there)
    Point3f floor(0, 0, -0.5f);
    Float keepDark = dark.scene->glassWindows->PMF(0, floor),
          keepLit = lit.scene->glassWindows->PMF(0, floor);
    std::printf("window kept at the floor with probability %.4f (dark), %.4f (under the sky)\n",
                keepDark, keepLit);
    EXPECT_FLOAT_EQ(keepDark, 1);
    EXPECT_GT(keepLit, 0.02f);
    EXPECT_LT(keepLit, 0.5f);
    // Unbiased: the same image as finding the glow by chance refractions alone
    testing::TwoSeedNoise on =
        testing::RenderTwoSeeds([&](int s) { return scene(true, true, s); }, 21);
    testing::TwoSeedNoise off =
        testing::RenderTwoSeeds([&](int s) { return scene(true, false, s); }, 23);
    std::printf("under the sky: windows off / on image mean %.5f (standard errors %.5f, %.5f)\n",
                off.mean / on.mean, off.se / on.mean, on.se / on.mean);
    EXPECT_NEAR(off.mean, on.mean, 5 * std::hypot(on.se, off.se));
}

}  // namespace
}  // namespace kiln
