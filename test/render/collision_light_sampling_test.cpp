// Light sampling at tentative collisions (Integrator "bool collisionlightsampling"): on camera
// rays in a medium, volpath samples lights at the k-th tentative collision of a segment with
// probability 1 / k, weighted by the probability of scattering there, instead of at real
// scatterings only. Both estimate the same image; in a thin scattering medium the light it
// scatters towards the camera is found on every path rather than on the few that scatter. The
// closed form with it on, by default, and light sampling weighed against it: the "hot graded
// air" cavity of volume_equilibrium_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "render_test_util.h"

namespace kiln {
namespace {

// A thin, graded, chromatic, mostly scattering haze (optical depth about 0.05 to 0.5 across)
// lit by a distant light, seen against a dim sky.
std::string ThinHaze(const std::string& integrator, int seed) {
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 24 \"integer yresolution\" 24\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" 16 \"integer seed\" " << seed << "\n"
      << "Integrator \"volpath\" \"integer maxdepth\" 5 " << integrator << "\n"
      << "LookAt 0 1 -4  0 1 0  0 1 0\nCamera \"perspective\" \"float fov\" 30\n"
      << "WorldBegin\n"
      << "LightSource \"infinite\" \"rgb L\" [0.05 0.05 0.05]\n"
      << "LightSource \"distant\" \"point3 from\" [1 3 -1] \"point3 to\" [0 0 0] \"rgb L\" [3 3 "
         "3]\n"
      << "MakeNamedMedium \"haze\" \"string type\" \"uniformgrid\" \"integer nx\" 2 "
         "\"integer ny\" 2 \"integer nz\" 2 \"float density\" [0.1 0.6 0.3 1 0.2 0.8 0.5 0.4] "
         "\"point3 p0\" [-1 0 -1] \"point3 p1\" [1 2 1] \"rgb sigma_a\" [0.05 0.05 0.05] "
         "\"rgb sigma_s\" [0.2 0.25 0.3]\n"
      << "AttributeBegin\nMediumInterface \"haze\" \"\"\nMaterial \"interface\"\n"
      << "Shape \"trianglemesh\" \"integer indices\" [0 2 1 0 3 2 4 5 6 4 6 7 0 1 5 0 5 4 3 7 6 "
         "3 6 2 0 4 7 0 7 3 1 2 6 1 6 5] \"point3 P\" [-1 0 -1 1 0 -1 1 2 -1 -1 2 -1 -1 0 1 1 0 1 "
         "1 2 1 -1 2 1]\n"
      << "AttributeEnd\n";
    return s.str();
}

TEST(CollisionLightSampling, OnByDefaultAndSwitchable) {
    testing::RenderedScene on = testing::RenderText(ThinHaze("", 1));
    EXPECT_TRUE(on.scene->features.collisionLightSampling);
    testing::RenderedScene off =
        testing::RenderText(ThinHaze("\"bool collisionlightsampling\" false", 1));
    EXPECT_FALSE(off.scene->features.collisionLightSampling);
    RenderOptions options;
    options.collisionLightSampling = false;
    testing::RenderedScene overridden = testing::RenderText(ThinHaze("", 1), 0, options);
    EXPECT_FALSE(overridden.scene->features.collisionLightSampling);
}

TEST(CollisionLightSampling, SameImageAsScatteringsWithLessNoiseInAThinMedium) {
    auto render = [&](const std::string& integrator, int seed) {
        return testing::RenderTwoSeeds([&](int s) { return ThinHaze(integrator, s); }, seed);
    };
    testing::TwoSeedNoise collisions = render("", 1),
                          scatterings = render("\"bool collisionlightsampling\" false", 3);
    ASSERT_GT(collisions.mean, 0);
    std::printf(
        "at scatterings: image mean %.5f of at collisions', standard errors %.5f and "
        "%.5f\n",
        scatterings.mean / collisions.mean, scatterings.se / collisions.mean,
        collisions.se / collisions.mean);
    EXPECT_NEAR(scatterings.mean, collisions.mean, 5 * std::hypot(collisions.se, scatterings.se));
    double ratio = collisions.variance / scatterings.variance;
    std::printf("per-pixel variance, at collisions / at scatterings: %.4f\n", ratio);
    EXPECT_LT(ratio, 0.6);
}

}  // namespace
}  // namespace kiln
