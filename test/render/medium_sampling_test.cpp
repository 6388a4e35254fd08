// volpath's two ways of sampling media beyond pbrt-v4's, each against pbrt-v4's way: the same
// image, less noise where it is meant to help, and its switch.
//
// Absorption as a weight (Integrator "bool weightabsorption"): a path that passes a tentative
// collision carries sigma_n / (sigma_n + sigma_a) instead of being ended there with
// probability sigma_a / sigma_maj, and in a uniform medium only scattering is sampled, the path
// carrying exp(-sigma_a t). Behind a thin absorbing medium that removes the noise of paths
// ended or not.
//
// Light sampling at tentative collisions (Integrator "bool collisionlightsampling"): on camera
// rays, lights are sampled at the k-th tentative collision of a segment with probability 1 / k,
// weighted by the probability of scattering there, instead of at real scatterings only. In a
// thin scattering medium the light it scatters towards the camera is found on every path.
//
// The closed forms with both on, by default: Beer-Lambert through a slab (volume_test.cpp), the
// equilibrium cavities with absorbing, chromatic and graded melts and hot graded air, where
// light sampling is weighed against both (volume_equilibrium_test.cpp).
#include <gtest/gtest.h>

#include <sstream>

#include "render_test_util.h"

namespace kiln {
namespace {

// A 2 x 2 x 2 box standing on the ground at the origin, filled with `medium` (the directive
// defining it, named "box").
std::string MediumBox(const std::string& medium) {
    return medium +
           "AttributeBegin\nMediumInterface \"box\" \"\"\nMaterial \"interface\"\n"
           "Shape \"trianglemesh\" \"integer indices\" [0 2 1 0 3 2 4 5 6 4 6 7 0 1 5 0 5 4 3 7 6 "
           "3 6 2 0 4 7 0 7 3 1 2 6 1 6 5] \"point3 P\" [-1 0 -1 1 0 -1 1 2 -1 -1 2 -1 -1 0 1 1 0 "
           "1 1 2 1 -1 2 1]\nAttributeEnd\n";
}

// The box seen from the side, 24 x 24 pixels at 16 spp, lit by lights.
std::string BoxScene(const std::string& integrator, int seed, const std::string& lights,
                     const std::string& medium) {
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 24 \"integer yresolution\" 24\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" 16 \"integer seed\" " << seed << "\n"
      << "Integrator \"volpath\" \"integer maxdepth\" 5 " << integrator << "\n"
      << "LookAt 0 1 -4  0 1 0  0 1 0\nCamera \"perspective\" \"float fov\" 30\n"
      << "WorldBegin\n"
      << lights << MediumBox(medium);
    return s.str();
}

// A bright sky seen past a hot, thin, chromatic smoke (optical depth about 0.1 to 1.2 across,
// scattering a fifth of what it absorbs), graded (a grid) or uniform, on a dark floor.
std::string ThinSmoke(const std::string& integrator, int seed, bool graded = true) {
    return BoxScene(
        integrator, seed,
        "LightSource \"infinite\" \"rgb L\" [1 1 1]\n"
        "Material \"diffuse\" \"rgb reflectance\" [0.1 0.1 0.1]\n"
        "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point3 P\" "
        "[-5 0 -5 5 0 -5 5 0 5 -5 0 5]\n",
        std::string(graded ? "MakeNamedMedium \"box\" \"string type\" \"uniformgrid\" \"integer "
                             "nx\" 2 \"integer ny\" 2 \"integer nz\" 2 \"float density\" [0.1 0.6 "
                             "0.3 1 0.2 0.8 0.5 0.4] \"point3 p0\" [-1 0 -1] \"point3 p1\" [1 2 1] "
                           : "MakeNamedMedium \"box\" \"string type\" \"homogeneous\" \"float "
                             "scale\" 0.5 ") +
            "\"rgb sigma_a\" [0.3 0.6 0.9] \"rgb sigma_s\" [0.1 0.1 0.1] \"float temperature\" "
            "1300\n");
}

// A thin, graded, chromatic, mostly scattering haze (optical depth about 0.05 to 0.5 across)
// lit by a distant light, seen against a dim sky.
std::string ThinHaze(const std::string& integrator, int seed) {
    return BoxScene(integrator, seed,
                    "LightSource \"infinite\" \"rgb L\" [0.05 0.05 0.05]\n"
                    "LightSource \"distant\" \"point3 from\" [1 3 -1] \"point3 to\" [0 0 0] "
                    "\"rgb L\" [3 3 3]\n",
                    "MakeNamedMedium \"box\" \"string type\" \"uniformgrid\" \"integer nx\" 2 "
                    "\"integer ny\" 2 \"integer nz\" 2 \"float density\" [0.1 0.6 0.3 1 0.2 0.8 "
                    "0.5 0.4] \"point3 p0\" [-1 0 -1] \"point3 p1\" [1 2 1] \"rgb sigma_a\" [0.05 "
                    "0.05 0.05] \"rgb sigma_s\" [0.2 0.25 0.3]\n");
}

TEST(AbsorptionWeights, OnByDefaultAndSwitchable) {
    testing::ExpectSwitch([](const std::string& i, int seed) { return ThinSmoke(i, seed); },
                          "\"bool weightabsorption\" false", &SceneFeatures::weightAbsorption,
                          &RenderOptions::weightAbsorption);
}

TEST(AbsorptionWeights, SameImageAsEndingPathsWithLessNoiseBehindAThinMedium) {
    for (bool graded : {true, false})
        testing::ExpectSameImageWithLessNoise(
            graded ? "grid" : "homogeneous",
            [&](const std::string& integrator, int seed) {
                return ThinSmoke(integrator, seed, graded);
            },
            "\"bool weightabsorption\" false", 0.6);
}

TEST(CollisionLightSampling, OnByDefaultAndSwitchable) {
    testing::ExpectSwitch(ThinHaze, "\"bool collisionlightsampling\" false",
                          &SceneFeatures::collisionLightSampling,
                          &RenderOptions::collisionLightSampling);
}

TEST(CollisionLightSampling, SameImageAsScatteringsWithLessNoiseInAThinMedium) {
    testing::ExpectSameImageWithLessNoise("haze", ThinHaze, "\"bool collisionlightsampling\" false",
                                          0.6);
}

}  // namespace
}  // namespace kiln
