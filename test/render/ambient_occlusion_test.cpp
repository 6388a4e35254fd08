// Integrator "ambientocclusion" (pbrt-v4's AOIntegrator) against closed forms: an open floor is
// unoccluded (luminance 1 everywhere); on the inner wall of a sphere of radius R every
// direction meets the wall again after the chord 2 R cos theta, so within "maxdistance" d the
// cosine-weighted share of the hemisphere that is occluded is (d / 2R)^2 (d < 2R), and
// everything is occluded for d > 2R. Both the cosine-weighted and the uniform sampling estimate
// the same quantity. (Against pbrt-v4's own render: regression/pbrt_features, ambientocclusion.)
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "base/statistics.h"
#include "render_test_util.h"

namespace kiln {
namespace {

// The image's mean luminance and its standard error (testing::BlockStats)
RunningStats PixelLuminance(const testing::RenderedScene& r) {
    return testing::BlockStats(r.scene->job->film->PixelBounds(),
                               [&](Point2i p) { return testing::PixelY(*r.scene, p); });
}

std::string AOScene(const std::string& integrator, const std::string& world) {
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 16\n"
      << "Sampler \"independent\" \"integer pixelsamples\" 256\n"
      << "Integrator \"ambientocclusion\" " << integrator << "\n"
      << "LookAt 0 0 0.5  0 0 -1  0 1 0\nCamera \"perspective\" \"float fov\" 30\n"
      << "WorldBegin\nMaterial \"diffuse\"\n"
      << world;
    return s.str();
}

TEST(AmbientOcclusion, AnOpenFloorIsUnoccluded) {
    for (const char* sampling : {"true", "false"}) {
        testing::RenderedScene r = testing::RenderText(
            AOScene(std::string("\"bool cossample\" ") + sampling,
                    "Shape \"bilinearmesh\" \"point3 P\" [-5 -5 -1 5 -5 -1 -5 5 "
                    "-1 5 5 -1]\n"));
        EXPECT_TRUE(r.warnings.empty()) << r.warnings[0].message;  // no "no lights"
        RunningStats s = PixelLuminance(r);
        // (the noise is the wavelengths' alone with cosine sampling)
        EXPECT_NEAR(s.Mean(), 1, 4 * s.StandardError() + 2e-3) << sampling;
    }
}

// White is the film's (its colour space's illuminant), as in pbrt-v4, not that of a colour
// space declared after the Film directive: an unoccluded floor renders R = G = B = 1 in an sRGB
// film although ACES's D60 white is in effect at the Integrator directive
TEST(AmbientOcclusion, WhiteIsTheFilmsWhite) {
    std::string text = AOScene("",
                               "Shape \"bilinearmesh\" \"point3 P\" [-5 -5 -1 5 -5 -1 -5 5 "
                               "-1 5 5 -1]\n");
    text.insert(text.find("Integrator"), "ColorSpace \"aces2065-1\"\n");
    testing::RenderedScene r = testing::RenderText(text);
    RunningStats channel[3];
    for (int c = 0; c < 3; ++c)
        channel[c] = testing::BlockStats(r.scene->job->film->PixelBounds(), [&](Point2i p) {
            return r.scene->job->film->GetPixelRGB(p)[c];
        });
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(channel[c].Mean(), 1, 4 * channel[c].StandardError() + 3e-3) << "channel " << c;
}

TEST(AmbientOcclusion, InsideASphereTheOccludedShareIsTheChordsShare) {
    const double R = 2;
    for (double d : {1.0, 2.5, 5.0})
        for (const char* sampling : {"true", "false"}) {
            std::ostringstream integrator;
            integrator << "\"bool cossample\" " << sampling << " \"float maxdistance\" " << d;
            testing::RenderedScene r = testing::RenderText(
                AOScene(integrator.str(), "Shape \"sphere\" \"float radius\" 2\n"));
            RunningStats s = PixelLuminance(r);
            double expected = d < 2 * R ? 1 - (d / (2 * R)) * (d / (2 * R)) : 0;
            EXPECT_NEAR(s.Mean(), expected, 4 * s.StandardError() + 2e-3)
                << "maxdistance " << d << " cossample " << sampling;
            EXPECT_LT(4 * s.StandardError(), 0.02);
        }
}

}  // namespace
}  // namespace kiln
