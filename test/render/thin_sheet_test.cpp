// Shadow rays cross thin sheets (thindielectric: BxDFFlags::StraightThrough), attenuated by the
// sheet's transmittance. A point light inside a thin glass shell lights a diffuse floor through
// it: each pixel is exactly T times the pixel without the shell, where T = 2n / (n^2 + 1) is the
// slab's transmittance at normal incidence (the shell is centred on the light, so every light
// ray crosses it normally). Without shadow rays through sheets the floor would be black: no
// path can hit a point light. The path, volumetric and polarised integrators are checked; the
// cavities of equilibrium_test.cpp and volume_equilibrium_test.cpp check that light sampling
// through sheets and BSDF sampling through them count each path once.
#include <gtest/gtest.h>

#include <sstream>

#include "render_test_util.h"

namespace kiln {
namespace {

std::string FloorUnderALamp(bool shell, const char* eta) {
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 12\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" 4\n"
      << "Integrator \"path\" \"integer maxdepth\" 1\n"
      << "LookAt 0 1 -2  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 20\n"
      << "WorldBegin\n"
      << "LightSource \"point\" \"point3 from\" [0 1 0] \"rgb I\" [1 0.8 0.6]\n"
      << "Material \"diffuse\" \"rgb reflectance\" [0.5 0.5 0.5]\n"
      << "Shape \"trianglemesh\" \"point3 P\" [-5 0 -5  5 0 -5  5 0 5  -5 0 5]"
         " \"integer indices\" [0 1 2 0 2 3]\n";
    if (shell)
        s << "AttributeBegin\nMaterial \"thindielectric\" " << eta << "\n"
          << "Translate 0 1 0\nShape \"sphere\" \"float radius\" 0.25\nAttributeEnd\n";
    return s.str();
}

void ExpectFloorScaledBy(double n, RenderOptions overrides, bool polarized) {
    const double T = 2 * n / (n * n + 1);
    std::ostringstream eta;
    eta << "\"float eta\" " << n;
    testing::RenderedScene bare = testing::RenderText(FloorUnderALamp(false, ""), 1, overrides);
    testing::RenderedScene lamp =
        testing::RenderText(FloorUnderALamp(true, eta.str().c_str()), 1, overrides);
    ASSERT_EQ(lamp.scene->features.sheets, 1);
    ASSERT_EQ(lamp.scene->features.polarized, polarized);
    Bounds2i b = lamp.scene->job->film->PixelBounds();
    for (int y = b.pMin.y; y < b.pMax.y; ++y)
        for (int x = b.pMin.x; x < b.pMax.x; ++x) {
            RGB without = bare.scene->job->film->GetPixelRGB({x, y});
            RGB with = lamp.scene->job->film->GetPixelRGB({x, y});
            for (int c = 0; c < 3; ++c) {
                ASSERT_GT(without[c], 0) << x << "," << y;
                EXPECT_NEAR(with[c] / without[c], T, 1e-4 * T) << x << "," << y << " channel " << c;
            }
        }
}

TEST(ThinSheets, APointLightInAGlassShellLightsTheFloorThroughIt) {
    ExpectFloorScaledBy(1.5, {}, false);
    ExpectFloorScaledBy(2.4, {}, false);
}

TEST(ThinSheets, AndSoInTheVolumetricIntegrator) {
    RenderOptions overrides;
    overrides.genericVolumes = true;
    ExpectFloorScaledBy(1.5, overrides, false);
}

TEST(ThinSheets, AndSoInPolarisedTransport) {
    RenderOptions overrides;
    overrides.stokes = true;
    ExpectFloorScaledBy(1.5, overrides, true);
}

// A dispersive sheet cannot be crossed by a shadow ray (it would have to terminate the path's
// secondary wavelengths): it stays an ordinary specular surface and the floor stays dark.
TEST(ThinSheets, ADispersiveSheetBlocksShadowRays) {
    testing::RenderedScene lamp = testing::RenderText(
        FloorUnderALamp(true, "\"spectrum eta\" \"glass-BAF10\""), 1, RenderOptions{});
    EXPECT_EQ(lamp.scene->features.sheets, 0);
    Bounds2i b = lamp.scene->job->film->PixelBounds();
    for (int y = b.pMin.y; y < b.pMax.y; ++y)
        for (int x = b.pMin.x; x < b.pMax.x; ++x)
            EXPECT_EQ(lamp.scene->job->film->GetPixelRGB({x, y}).g, 0) << x << "," << y;
}

}  // namespace
}  // namespace kiln
