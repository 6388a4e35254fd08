// Absorbing glass: a "dielectric" with "spectrum k" (complex index n + ik) is transparent where
// k is small and opaque, reflective and emissive in its absorption bands, because scene creation
// fills the body with a medium absorbing 4 pi k / lambda (render/scene_media.h) that glows at
// the body's temperature, and the surface reflects with the complex Fresnel equations. Checked
// against a published n, k (the emission of an opaque body is (1 - R) B) and, as every material,
// by the closed cavity (here in LWIR, where the glass is opaque; volume_equilibrium_test.cpp has
// it in the visible).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "../temp_dir.h"
#include "base/statistics.h"
#include "render/scene_media.h"
#include "render_test_util.h"
#include "spectral/planck.h"

namespace kiln {
namespace {

// A soda-lime body at 1000 K, nothing else in the scene, seen head-on through a 9.6 um pyrometer
// (9595-9605 nm): its radiance is (1 - R) of Planck's, R the normal reflectance of Rubin's
// published index at 9.6 um (n 1.209, k 1.232: M. Rubin, Sol. Energy Mater. 12, 275 (1985),
// Table 2, the row kiln's table holds; 10 nm either side changes R by under 3e-4). The glass is
// half a metre deep where k absorbs 1.6e6 per metre: opaque.
TEST(AbsorbingGlass, EmitsOneMinusItsComplexFresnelReflectanceWhereItIsOpaque) {
    const double T = 1000;
    testing::RenderedScene r = testing::RenderText(
        "Film \"thermal\" \"string sensor\" \"pyrometer\" \"float wavelength\" 9600 "
        "\"integer xresolution\" 16 \"integer yresolution\" 16\n"
        "Sampler \"zsobol\" \"integer pixelsamples\" 64\n"
        "LookAt 0 0 -15  0 0 0  0 1 0\n"
        "Camera \"orthographic\" \"float screenwindow\" [-0.2 0.2 -0.2 0.2]\n"
        "WorldBegin\n"
        "Material \"dielectric\" \"spectrum eta\" \"glass-soda-lime-eta\" \"spectrum k\" "
        "\"glass-soda-lime-k\"\n"
        "Shape \"sphere\" \"float radius\" 10 \"float temperature\" 1000\n");
    for (const auto& w : r.warnings) ADD_FAILURE() << w.message;
    ASSERT_TRUE(r.scene->features.volumetric);
    ASSERT_EQ(r.scene->media.size(), 1u);  // the body's medium, made from its k
    const double n = 1.209, k = 1.232;
    const double R = (std::pow(n - 1, 2) + k * k) / (std::pow(n + 1, 2) + k * k);
    const double expected = (1 - R) * planck_band_radiance(9595, 9605, T);
    RunningStats L = testing::ThermalChannelStats(r, "L");
    const double ratio = L.Mean() / expected, se = L.StandardError() / expected;
    std::printf("soda-lime at 9.6 um, 1000 K: L %.5f of (1 - R) B (se %.5f), R %.4f\n", ratio, se,
                R);
    EXPECT_LT(4 * se, 0.005);
    EXPECT_NEAR(ratio, 1, 4 * se + 1e-3);
}

// A closed cavity at 300 K in LWIR holding smooth soda-lime glass and fused silica, both at the
// ambient temperature (their media take it): opaque at 8-14 um, they reflect up to 25 % and 72 %
// at normal incidence and emit the rest, and where their real index is below 1 their surfaces
// emit too (material_albedo.h); the in-band radiance must be Planck's integral all the same.
// (Smooth: rough glass loses the microfacet model's energy without emitting it.)
TEST(AbsorbingGlass, CavityRendersTheBlackbodyInLwir) {
    const double T = 300;
    std::ostringstream s;
    s << "Option \"float ambienttemperature\" " << T << "\n"
      << "Film \"thermal\" \"string sensor\" \"lwir\" \"integer xresolution\" 20 "
         "\"integer yresolution\" 20\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" 256\n"
      << "Integrator \"volpath\" \"integer maxdepth\" 200\n"
      << "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 50\n"
      << "WorldBegin\n"
      << "Material \"diffuse\" \"spectrum reflectance\" [300 0.9 20000 0.3]\n"
      << "Shape \"sphere\" \"float radius\" 6\n"
      << "AttributeBegin Translate -0.6 0 0.5\n"
      << "Material \"dielectric\" \"spectrum eta\" \"glass-soda-lime-eta\" \"spectrum k\" "
         "\"glass-soda-lime-k\"\n"
      << "Shape \"sphere\" \"float radius\" 0.7\nAttributeEnd\n"
      << "AttributeBegin Translate 0.7 0.2 0.3\n"
      << "Material \"dielectric\" \"spectrum eta\" \"glass-fused-silica-eta\" \"spectrum k\" "
         "\"glass-fused-silica-k\"\n"
      << "Shape \"sphere\" \"float radius\" 0.6\nAttributeEnd\n";
    testing::RenderedScene r = testing::RenderText(s.str());
    for (const auto& w : r.warnings) ADD_FAILURE() << w.message;
    ASSERT_EQ(r.scene->media.size(), 2u);
    const double Lb = planck_band_radiance(8000, 14000, T);
    RunningStats L = testing::ThermalChannelStats(r, "L");
    const double ratio = L.Mean() / Lb, se = L.StandardError() / Lb;
    std::printf("LWIR cavity with glass at %.0f K: L %.5f of Planck's (se %.5f)\n", T, ratio, se);
    EXPECT_LT(4 * se, 0.005);
    EXPECT_NEAR(ratio, 1, 4 * se + 1e-3);
}

// Bodies of one material at one temperature share one medium; a body with its own media keeps
// them (its k then shapes only the surface's reflectance)
TEST(AbsorbingGlass, BodiesShareTheirMediumAndOwnMediaStay) {
    testing::RenderedScene r = testing::RenderText(
        "Film \"rgb\" \"integer xresolution\" 4 \"integer yresolution\" 4\n"
        "Sampler \"zsobol\" \"integer pixelsamples\" 1\n"
        "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\"\n"
        "WorldBegin\n"
        "LightSource \"point\" \"point3 from\" [0 3 -3]\n"
        "MakeNamedMedium \"melt\" \"string type\" \"homogeneous\"\n"
        "Material \"dielectric\" \"float eta\" 1.5 \"float k\" 1e-7\n"
        "Shape \"sphere\" \"float radius\" 0.3\n"
        "AttributeBegin Translate 1 0 0 Shape \"sphere\" \"float radius\" 0.3 AttributeEnd\n"
        "AttributeBegin Translate -1 0 0 Shape \"sphere\" \"float radius\" 0.3 "
        "\"float temperature\" 900 AttributeEnd\n"
        "AttributeBegin MediumInterface \"melt\" \"\" Translate 0 1 0\n"
        "Shape \"sphere\" \"float radius\" 0.3 AttributeEnd\n");
    for (const auto& w : r.warnings) ADD_FAILURE() << w.message;
    // "melt", one medium for the two cold spheres, one for the hot one
    EXPECT_EQ(r.scene->media.size(), 3u);
}

// One shape directive making two bodies at different temperatures (a file included twice: the
// same file, line and column), each glowing at its own: opaque soda-lime at 9.6 um (emissivity
// 0.756 head-on), 700 K on the left and 800 K on the right, reads about 627 K and 709 K where
// it faces the camera
TEST(AbsorbingGlass, BodiesOfOneDirectiveKeepTheirTemperatures) {
    test::TempDir dir;
    dir.Write("ball.pbrt", "Shape \"sphere\" \"float radius\" 0.5\n");
    const std::string ball = "Include \"" + (dir.path / "ball.pbrt").string() + "\"\n";
    testing::RenderedScene r = testing::RenderText(
        "Film \"thermal\" \"string sensor\" \"pyrometer\" \"float wavelength\" 9600 "
        "\"integer xresolution\" 16 \"integer yresolution\" 8\n"
        "Sampler \"zsobol\" \"integer pixelsamples\" 4\n"
        "LookAt 0 0 -15  0 0 0  0 1 0\n"
        "Camera \"orthographic\" \"float screenwindow\" [-2 2 -1 1]\n"
        "WorldBegin\n"
        "Material \"dielectric\" \"spectrum eta\" \"glass-soda-lime-eta\" \"spectrum k\" "
        "\"glass-soda-lime-k\"\n"
        "AttributeBegin Translate -1 0 0 Attribute \"shape\" \"float temperature\" 700\n" +
        ball +
        "AttributeEnd\n"
        "AttributeBegin Translate 1 0 0 Attribute \"shape\" \"float temperature\" 800\n" +
        ball + "AttributeEnd\n");
    for (const auto& w : r.warnings) ADD_FAILURE() << w.message;
    Image img = r.scene->job->film->GetImage(nullptr);
    Float left = 0, right = 0;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x) {
            Float T = img.GetChannel({x, y}, img.ChannelIndex("T"));
            Float& side = x < 8 ? left : right;
            side = std::max(side, T);
        }
    EXPECT_NEAR(left, 627, 10);
    EXPECT_NEAR(right, 709, 10);
}

}  // namespace
}  // namespace kiln
