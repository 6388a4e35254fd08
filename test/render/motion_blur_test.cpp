// Motion blur in the thermal setting: a closed isothermal cavity stays at B(T) when the hot
// body inside it moves (translating and turning) and the camera moves too, under path and bdpt.
// The moving body glows where rays hit it but is not sampled as a light (one warning), so its
// emission is found by BSDF sampling alone; equilibrium holds all the same. (bdpt has no
// Russian roulette: maxdepth 10 leaves out about 1e-4 of the radiance with these walls.) (Images
// against pbrt-v4: test/regression/pbrt_features motionblur*.pbrt; intersection at a ray's time:
// geometry/accelerator_test.cpp; the interpolation: base/animated_transform_test.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "render_test_util.h"

namespace kiln {
namespace {

std::string MovingCavity(const char* integrator, double T) {
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 24 \"integer yresolution\" 24\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" 64\n"
      << "Integrator \"" << integrator << "\" \"integer maxdepth\" "
      << (std::string(integrator) == "bdpt" ? 10 : 60) << "\n"
      << "TransformTimes 0 1\n"
      << "ActiveTransform StartTime\nLookAt 0 0 -3  0 0 0  0 1 0\n"
      << "ActiveTransform EndTime\nLookAt 0.5 0.2 -3  0 0 0.5  0 1 0\n"
      << "ActiveTransform All\nCamera \"perspective\" \"float fov\" 40\n"
      << "WorldBegin\n"
      << "Attribute \"shape\" \"float temperature\" " << T << "\n"
      << "Material \"diffuse\" \"rgb reflectance\" [0.4 0.3 0.2]\n"
      << "Shape \"sphere\" \"float radius\" 6\n"
      << "Material \"conductor\" \"spectrum eta\" \"metal-Au-eta\" \"spectrum k\" "
         "\"metal-Au-k\" \"float roughness\" 0.3\n"
      << "AttributeBegin\n"
      << "ActiveTransform StartTime\nTranslate -0.8 0 0.3\n"
      << "ActiveTransform EndTime\nTranslate 0.8 0.2 0.3\nRotate 120 0 1 0\n"
      << "ActiveTransform All\nScale 1 0.6 1\n"
      << "Shape \"sphere\" \"float radius\" 1\n"
      << "AttributeEnd\n";
    return s.str();
}

TEST(MotionBlur, MovingHotBodyInACavityRendersTheBlackbody) {
    for (const char* integrator : {"path", "bdpt"}) {
        SCOPED_TRACE(integrator);
        const double T = 1500;
        testing::RenderedScene r = testing::RenderText(MovingCavity(integrator, T));
        ASSERT_EQ(r.warnings.size(), 1u);
        EXPECT_NE(r.warnings[0].message.find("moving"), std::string::npos) << r.warnings[0].message;
        r.warnings.clear();
        testing::ExpectBlackbodyImage(r, T, std::string("moving gold, ") + integrator);
    }
}

}  // namespace
}  // namespace kiln

namespace kiln {
namespace {

// Motions that flatten a shape to nothing, fling it beyond the range rays are traced in, spin
// it 1e20 degrees or mirror it render finite pixels, with no warning, under both integrators.
TEST(MotionBlur, HostileMotionsRenderFinitePixels) {
    for (const char* end : {"Scale 0 0 0", "ConcatTransform [0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0]",
                            "Translate 1e30 0 0", "Rotate 1e20 1 1 0", "Scale -1 1 1"}) {
        for (const char* integrator : {"path", "bdpt"}) {
            SCOPED_TRACE(std::string(end) + ", " + integrator);
            std::ostringstream s;
            s << "TransformTimes 0 1\nLookAt 0 -5 2  0 0 0.5  0 0 1\nCamera \"perspective\"\n"
              << "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
              << "Sampler \"zsobol\" \"integer pixelsamples\" 4\n"
              << "Integrator \"" << integrator << "\"\nWorldBegin\n"
              << "LightSource \"infinite\" \"rgb L\" [1 1 1]\n"
              << "AttributeBegin\nActiveTransform EndTime\n"
              << end << "\nActiveTransform All\n"
              << "Shape \"sphere\"\nShape \"trianglemesh\" \"integer indices\" [0 1 2] "
                 "\"point3 P\" [0 0 0 1 0 0 0 1 0]\n"
              << "ObjectBegin \"o\"\nShape \"disk\"\nObjectEnd\nObjectInstance \"o\"\n"
              << "AttributeEnd\n";
            testing::RenderedScene r = testing::RenderText(s.str());
            EXPECT_TRUE(r.warnings.empty());
            Bounds2i b = r.scene->job->film->PixelBounds();
            for (int y = b.pMin.y; y < b.pMax.y; ++y)
                for (int x = b.pMin.x; x < b.pMax.x; ++x) {
                    RGB rgb = r.scene->job->film->GetPixelRGB({x, y});
                    ASSERT_TRUE(std::isfinite(rgb.r) && std::isfinite(rgb.g) &&
                                std::isfinite(rgb.b));
                }
        }
    }
}

}  // namespace
}  // namespace kiln
