// Camera rays split at their first smooth dielectric (Integrator "bool splitdielectrics"): path
// and volpath trace both the reflection and the transmission, each weighted by its Fresnel
// factor, instead of one chosen with probability R / (R + T). Both estimate the same image; a
// glow seen through glass (whose colour the sky's reflection shifts) has less noise. The closed
// forms with it on, by default: the equilibrium cavities holding glass bodies
// (equilibrium_test.cpp, volume_equilibrium_test.cpp).
#include <gtest/gtest.h>

#include <sstream>

#include "render_test_util.h"

namespace kiln {
namespace {

// A glass ball (eta 1.5) holding a hot body, filling the view, under a dim blue sky: a hot
// absorbing melt (volpath) or a hot black core (path).
std::string GlowInGlass(const std::string& integrator, int seed, bool volumetric) {
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 24 \"integer yresolution\" 24\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" 16 \"integer seed\" " << seed << "\n"
      << "Integrator \"" << (volumetric ? "volpath" : "path") << "\" \"integer maxdepth\" 8 "
      << integrator << "\n"
      << "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 35\n"
      << "WorldBegin\n"
      << "LightSource \"infinite\" \"rgb L\" [0.02 0.03 0.06]\n";
    if (volumetric)
        s << "MakeNamedMedium \"melt\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [3 5 9] "
             "\"rgb sigma_s\" [0.3 0.3 0.3] \"float temperature\" 1300\n"
          << "AttributeBegin\nMediumInterface \"melt\" \"\"\n";
    else
        s << "AttributeBegin\nMaterial \"diffuse\" \"rgb reflectance\" [0 0 0] \"float "
             "temperature\" 1300\nShape \"sphere\" \"float radius\" 0.7\nAttributeEnd\n"
          << "AttributeBegin\n";
    s << "Material \"dielectric\" \"float eta\" 1.5\nShape \"sphere\" \"float radius\" 1\n"
      << "AttributeEnd\n";
    return s.str();
}

TEST(DielectricSplitting, OnByDefaultAndSwitchable) {
    testing::ExpectSwitch([](const std::string& i, int seed) { return GlowInGlass(i, seed, true); },
                          "\"bool splitdielectrics\" false", &SceneFeatures::splitDielectrics,
                          &RenderOptions::splitDielectrics);
    // bdpt does not split
    std::string bdpt = GlowInGlass("", 1, false);
    bdpt.replace(bdpt.find("\"path\""), 6, "\"bdpt\"");
    EXPECT_FALSE(testing::RenderText(bdpt).scene->features.splitDielectrics);
}

TEST(DielectricSplitting, SameImageAsChoosingWithLessNoise) {
    for (bool volumetric : {true, false})
        testing::ExpectSameImageWithLessNoise(
            volumetric ? "melt in glass (volpath)" : "hot core in glass (path)",
            [&](const std::string& integrator, int seed) {
                return GlowInGlass(integrator, seed, volumetric);
            },
            "\"bool splitdielectrics\" false", 0.7);
}

}  // namespace
}  // namespace kiln
