// Absorption as a weight in volpath (Integrator "bool weightabsorption"): a path that passes a
// tentative collision carries sigma_n / (sigma_n + sigma_a) instead of being ended there with
// probability sigma_a / sigma_maj, and in a uniform medium only scattering is sampled, the path
// carrying exp(-sigma_a t). Both estimate the same image; behind a thin absorbing medium the
// weighted one has less noise. The closed forms (Beer-Lambert through a slab, the equilibrium
// cavities with absorbing, chromatic and graded melts and hot graded air, where light sampling
// is weighed against the weighted tracking) are checked with it on, by default, in
// volume_test.cpp and volume_equilibrium_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "render_test_util.h"

namespace kiln {
namespace {

// A bright sky seen past a hot, thin, chromatic smoke (optical depth about 0.1 to 1.2 across,
// scattering a fifth of what it absorbs), graded (a grid) or uniform, standing on a dark floor.
std::string ThinSmoke(const std::string& integrator, int seed, bool graded = true) {
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 24 \"integer yresolution\" 24\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" 16 \"integer seed\" " << seed << "\n"
      << "Integrator \"volpath\" \"integer maxdepth\" 5 " << integrator << "\n"
      << "LookAt 0 1 -4  0 1 0  0 1 0\nCamera \"perspective\" \"float fov\" 30\n"
      << "WorldBegin\n"
      << "LightSource \"infinite\" \"rgb L\" [1 1 1]\n"
      << "Material \"diffuse\" \"rgb reflectance\" [0.1 0.1 0.1]\n"
      << "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point3 P\" "
         "[-5 0 -5 5 0 -5 5 0 5 -5 0 5]\n"
      << (graded ? "MakeNamedMedium \"smoke\" \"string type\" \"uniformgrid\" \"integer nx\" 2 "
                   "\"integer ny\" 2 \"integer nz\" 2 \"float density\" [0.1 0.6 0.3 1 0.2 0.8 "
                   "0.5 0.4] \"point3 p0\" [-1 0 -1] \"point3 p1\" [1 2 1] "
                 : "MakeNamedMedium \"smoke\" \"string type\" \"homogeneous\" \"float scale\" 0.5 ")
      << "\"rgb sigma_a\" [0.3 0.6 0.9] \"rgb sigma_s\" [0.1 0.1 0.1] \"float temperature\" 1300\n"
      << "AttributeBegin\nMediumInterface \"smoke\" \"\"\nMaterial \"interface\"\n"
      << "Shape \"trianglemesh\" \"integer indices\" [0 2 1 0 3 2 4 5 6 4 6 7 0 1 5 0 5 4 3 7 6 "
         "3 6 2 0 4 7 0 7 3 1 2 6 1 6 5] \"point3 P\" [-1 0 -1 1 0 -1 1 2 -1 -1 2 -1 -1 0 1 1 0 1 "
         "1 2 1 -1 2 1]\n"
      << "AttributeEnd\n";
    return s.str();
}

TEST(AbsorptionWeights, OnByDefaultAndSwitchable) {
    testing::RenderedScene on = testing::RenderText(ThinSmoke("", 1));
    EXPECT_TRUE(on.scene->integrator.weightAbsorption);
    EXPECT_TRUE(on.scene->features.weightAbsorption);
    testing::RenderedScene off =
        testing::RenderText(ThinSmoke("\"bool weightabsorption\" false", 1));
    EXPECT_FALSE(off.scene->integrator.weightAbsorption);
    EXPECT_FALSE(off.scene->features.weightAbsorption);
    // The command line's --weight-absorption overrides the scene
    RenderOptions options;
    options.weightAbsorption = false;
    testing::RenderedScene overridden = testing::RenderText(ThinSmoke("", 1), 0, options);
    EXPECT_FALSE(overridden.scene->features.weightAbsorption);
}

TEST(AbsorptionWeights, SameImageAsEndingPathsWithLessNoiseBehindAThinMedium) {
    for (bool graded : {true, false}) {
        auto render = [&](const std::string& integrator, int seed) {
            return testing::RenderTwoSeeds([&](int s) { return ThinSmoke(integrator, s, graded); },
                                           seed);
        };
        testing::TwoSeedNoise weighted = render("", 1),
                              ended = render("\"bool weightabsorption\" false", 3);
        ASSERT_GT(weighted.mean, 0);
        std::printf(
            "%s: ending paths: image mean %.5f of weighting's, standard errors %.5f and "
            "%.5f\n",
            graded ? "grid" : "homogeneous", ended.mean / weighted.mean, ended.se / weighted.mean,
            weighted.se / weighted.mean);
        EXPECT_NEAR(ended.mean, weighted.mean, 5 * std::hypot(weighted.se, ended.se));
        double ratio = weighted.variance / ended.variance;
        std::printf("per-pixel variance, weighted / ended: %.4f\n", ratio);
        EXPECT_LT(ratio, 0.6);
    }
}

}  // namespace
}  // namespace kiln
