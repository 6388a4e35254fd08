// Polarised rendering end to end: Malus's law through polariser sheets and the camera's
// polariser, the polarisation of thermal emission against Fresnel's equations (orthogonal to
// that of reflection), and the paper's Fig. 8 (a glowing gold disc behind horizontal and
// vertical filters).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <functional>
#include <sstream>

#include "base/statistics.h"
#include "materials/bxdfs/fresnel.h"
#include "materials/bxdfs/fresnel_mueller.h"
#include "render_test_util.h"
#include "spectral/metal_temperature.h"
#include "spectral/named_spectra.h"
#include "spectral/planck.h"

namespace kiln {
namespace {

// A square facing the camera, its shading frame's x axis along +x everywhere (explicit uv)
constexpr const char* kQuad =
    "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point3 P\" [-3 -3 0  3 -3 0  3 3 0 "
    " "
    "-3 3 0] \"point2 uv\" [0 0 1 0 1 1 0 1]\n";

// Sheet materials: a polariser, a retarder (angles and retardance in degrees).
std::string Polarizer(Float angle) {
    return "\"polarizer\" \"float angle\" " + std::to_string(angle);
}
std::string Retarder(Float angle, Float retardance) {
    return "\"retarder\" \"float angle\" " + std::to_string(angle) + " \"float retardance\" " +
           std::to_string(retardance);
}

// An orthographic view along +z of a uniform light through sheets of the given materials, the
// first nearest the camera (light crosses them in reverse order); the camera's polariser if
// cameraAngle is given. Behind the first sheet, Russian roulette makes the estimate noisy:
// spp samples per pixel.
std::string Sheets(std::vector<std::string> materials, std::optional<Float> cameraAngle = {},
                   int spp = 1) {
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" " << spp << "\n"
      << "Integrator \"path\" \"integer maxdepth\" 8\n"
      << "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"orthographic\"";
    if (cameraAngle) s << " \"float polarizer\" " << *cameraAngle;
    s << "\nWorldBegin\n";
    Float z = -2;
    for (const std::string& m : materials) {
        s << "AttributeBegin Translate 0 0 " << z << " Material " << m << "\n"
          << kQuad << "AttributeEnd\n";
        z += 0.5f;
    }
    s << "AttributeBegin Translate 0 0 2 Material \"diffuse\" \"rgb reflectance\" [0 0 0]\n"
      << "AreaLightSource \"diffuse\" \"rgb L\" [1 1 1] \"bool twosided\" true\n"
      << kQuad << "AttributeEnd\n";
    return s.str();
}

// The image's mean luminance and its standard error (testing::BlockStats)
RunningStats PixelStats(const Scene& scene) {
    return testing::BlockStats(scene.job->film->PixelBounds(),
                               [&](Point2i p) { return testing::PixelY(scene, p); });
}
Float MeanY(const Scene& scene) { return Float(PixelStats(scene).Mean()); }

}  // namespace

TEST(PolarizedRender, MalusLawThroughTwoPolarizerSheets) {
    const Float open = MeanY(*testing::RenderText(Sheets({})).scene);
    ASSERT_GT(open, 0.1f);
    for (Float b : {0.f, 30.f, 45.f, 60.f, 90.f, 135.f}) {
        testing::RenderedScene r =
            testing::RenderText(Sheets({Polarizer(20), Polarizer(20 + b)}, {}, 256));
        EXPECT_TRUE(r.scene->features.polarized);
        Float expected = 0.5f * Sqr(std::cos(Radians(b)));
        RunningStats y = PixelStats(*r.scene);
        EXPECT_NEAR(y.Mean() / open, expected, 4 * y.StandardError() / open + 1e-4) << b;
        EXPECT_LT(4 * y.StandardError() / open, 0.03);  // sees a 3 % error
    }
    // A third sheet at 45 degrees between crossed ones lets light through again
    RunningStats y = PixelStats(
        *testing::RenderText(Sheets({Polarizer(0), Polarizer(45), Polarizer(90)}, {}, 256)).scene);
    EXPECT_NEAR(y.Mean() / open, 0.125f, 4 * y.StandardError() / open + 1e-4);
}

TEST(PolarizedRender, RetarderSheets) {
    const Float open = MeanY(*testing::RenderText(Sheets({})).scene);
    for (Float analyser : {0.f, 45.f, 90.f, 135.f}) {
        // Light polarised at 0 degrees through a quarter-wave plate at 45 degrees: circular,
        // so an analyser at any angle passes half of it
        RunningStats q = PixelStats(
            *testing::RenderText(Sheets({Retarder(45, 90), Polarizer(0)}, analyser, 256)).scene);
        EXPECT_NEAR(q.Mean() / open, 0.25, 4 * q.StandardError() / open + 1e-4) << analyser;
        // Through a half-wave plate at 22.5 degrees: linear at 45 degrees
        RunningStats h = PixelStats(
            *testing::RenderText(Sheets({Retarder(22.5f, 180), Polarizer(0)}, analyser, 256))
                 .scene);
        Float expected = 0.5f * Sqr(std::cos(Radians(analyser - 45)));
        EXPECT_NEAR(h.Mean() / open, expected, 4 * h.StandardError() / open + 1e-4) << analyser;
        EXPECT_LT(4 * h.StandardError() / open, 0.03);
    }
}

TEST(PolarizedRender, CameraPolarizerFollowsMalusLaw) {
    const Float open = MeanY(*testing::RenderText(Sheets({})).scene);
    for (Float b : {0.f, 30.f, 90.f, 120.f}) {
        testing::RenderedScene r = testing::RenderText(Sheets({Polarizer(10)}, 10 + b));
        Float expected = 0.5f * Sqr(std::cos(Radians(b)));
        EXPECT_NEAR(MeanY(*r.scene) / open, expected, 1e-3f) << b;
    }
    // Unpolarised light through the camera's polariser alone: half
    EXPECT_NEAR(MeanY(*testing::RenderText(Sheets({}, 33)).scene) / open, 0.5f, 1e-3f);
}

namespace {

// A hot polished disk (normal +z) of the given material seen at angles theta from its normal:
// its emission against B (1 - (Rs + Rp) / 2, -(Rs - Rp) / 2) about the plane of n and w, and
// against the polarisation of its reflection.
void CheckEmissionPolarisation(const std::string& material,
                               const std::function<std::complex<Float>(Float)>& eta) {
    std::string scene =
        "Film \"rgb\" \"integer xresolution\" 4 \"integer yresolution\" 4 \"bool stokes\" true\n"
        "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
        "Material " +
        material +
        " \"float roughness\" 0 \"float temperature\" 1200\n"
        "Shape \"disk\" \"float radius\" 10\n";
    Diagnostics diag(nullptr);
    std::unique_ptr<Scene> s = testing::BuildScene(scene, diag);
    ASSERT_TRUE(s->features.polarized);
    const Normal3f n(0, 0, 1);
    for (Float degrees : {0.f, 20.f, 45.f, 56.3f, 70.f, 85.f})
        for (Float l : {450.f, 550.f, 650.f}) {
            Float theta = Radians(degrees);
            Vector3f w(std::sin(theta) * 0.6f, std::sin(theta) * 0.8f, std::cos(theta));
            // (render space is world space moved to the camera)
            Point3f from = s->camera->GetCameraTransform().RenderFromWorld()(
                Point3f(0.1f, -0.2f, 0) + 3.f * w);
            std::optional<ShapeIntersection> hit = s->aggregate->Intersect(Ray(from, -w), 10);
            ASSERT_TRUE(hit);
            SampledWavelengths lambda = SampledWavelengths::FromWavelength(l), lb = lambda;
            BSDF bsdf = s->GetBSDF(hit->intr, lb);
            Stokes Le = s->SurfaceLe<Stokes>(hit->intr, bsdf, w, lambda);
            FresnelRsRp R = FrComplexPolarized(std::cos(theta), eta(l));
            Float B = planck_radiance(l, 1200);
            Stokes local = RotateStokesBasis(Le, w, StokesBasis(w), PlaneAxis(Vector3f(n), w));
            EXPECT_NEAR(local[0][0], B * (1 - (R.Rs + R.Rp) / 2), 1e-4f * B);
            EXPECT_NEAR(local[1][0], -B * (R.Rs - R.Rp) / 2, 1e-4f * B);
            EXPECT_NEAR(local[2][0], 0, 1e-5f * B);
            Float dop = DegreeOfPolarization(Le)[0];
            EXPECT_NEAR(dop, (R.Rs - R.Rp) / (2 - R.Rs - R.Rp), 1e-4f) << degrees << " " << l;
            if (degrees < 40) continue;
            EXPECT_GT(dop, 0.005f);
            // Reflection of unpolarised light towards w is polarised at 90 degrees to it
            Stokes reflected =
                bsdf.Sample_f<MuellerMatrix>(w, 0, {0, 0})->f * Stokes(SampledSpectrum(1.f));
            Float difference = std::remainder(
                AngleOfLinearPolarization(Le)[0] - AngleOfLinearPolarization(reflected)[0], Pi);
            EXPECT_NEAR(std::abs(difference), Pi / 2, 1e-3f) << degrees << " " << l;
            EXPECT_GT(DegreeOfPolarization(reflected)[0], 0.005f);
        }
}

}  // namespace

TEST(PolarizedRender, ThermalEmissionIsPolarisedAsFresnelSaysAndOrthogonalToReflection) {
    CheckEmissionPolarisation(
        "\"conductor\" \"spectrum eta\" \"metal-Au-eta\" \"spectrum k\" \"metal-Au-k\"",
        [](Float l) {
            // Gold's constants at the disk's 1200 K (spectral/metal_temperature.h)
            SampledSpectrum eta, k;
            MetalTemperatureTable::Find("Au")->Evaluate(SampledWavelengths::FromWavelength(l), 1200,
                                                        &eta, &k);
            return std::complex<Float>(eta[0], k[0]);
        });
    // An opaque dielectric (black glass: Fresnel reflection of n = 1.5, the rest absorbed):
    // totally polarised reflection at Brewster's angle (56.3 degrees), weakly polarised glow
    CheckEmissionPolarisation(
        "\"conductor\" \"spectrum eta\" [360 1.5 830 1.5] \"spectrum k\" [360 0 830 0]",
        [](Float) { return std::complex<Float>(1.5f, 0); });
}

TEST(PolarizedRender, AdditiveAndDiffuseEmissionAreUnpolarised) {
    for (const char* model : {"additive", "diffuse", "kirchhoff"}) {
        std::string scene = std::string(
                                "Film \"rgb\" \"integer xresolution\" 4 \"integer yresolution\" 4 "
                                "\"bool stokes\" true\n"
                                "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
                                "Material \"conductor\" \"spectrum eta\" \"metal-Au-eta\" "
                                "\"spectrum k\" \"metal-Au-k\" \"float temperature\" 1200 "
                                "\"string emission\" \"") +
                            model + "\"\nShape \"disk\" \"float radius\" 10\n";
        Diagnostics diag(nullptr);
        std::unique_ptr<Scene> s = testing::BuildScene(scene, diag);
        Vector3f w = Normalize(Vector3f(0.5f, 0.3f, 0.4f));
        Point3f from =
            s->camera->GetCameraTransform().RenderFromWorld()(Point3f(0, 0, 0) + 3.f * w);
        std::optional<ShapeIntersection> hit = s->aggregate->Intersect(Ray(from, -w), 10);
        ASSERT_TRUE(hit);
        SampledWavelengths lambda = SampledWavelengths::FromWavelength(600), lb = lambda;
        BSDF bsdf = s->GetBSDF(hit->intr, lb);
        Stokes Le = s->SurfaceLe<Stokes>(hit->intr, bsdf, w, lambda);
        EXPECT_GT(Le[0][0], 0) << model;
        Float dop = DegreeOfPolarization(Le)[0];
        if (std::string(model) == "kirchhoff")
            EXPECT_GT(dop, 0.05f);  // what the others would show if they were polarised
        else
            EXPECT_EQ(dop, 0) << model;
    }
}

TEST(PolarizedRender, GlowingGoldDiscPassesMoreThroughTheVerticalFilter) {
    // Wilkie & Weidlich 2011, Fig. 8: a polished gold disc at 1200 K tilted about the image's
    // horizontal axis, so that the planes of emission towards the camera are vertical and the
    // emission is polarised vertically
    auto scene = [](Float polarizer) {
        std::ostringstream s;
        s << "Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 16\n"
          << "Sampler \"zsobol\" \"integer pixelsamples\" 4\n"
          << "LookAt 0 0 6  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 20 "
          << "\"float polarizer\" " << polarizer << "\nWorldBegin\n"
          << "Rotate 60 1 0 0\n"
          << "Material \"conductor\" \"spectrum eta\" \"metal-Au-eta\" \"spectrum k\" "
             "\"metal-Au-k\" \"float roughness\" 0 \"float temperature\" 1200\n"
          << "Shape \"disk\" \"float radius\" 1\n";
        return s.str();
    };
    Float horizontal = MeanY(*testing::RenderText(scene(0)).scene);
    Float vertical = MeanY(*testing::RenderText(scene(90)).scene);
    ASSERT_GT(horizontal, 0);
    std::printf("horizontal filter %.4g, vertical filter %.4g (ratio %.3f)\n", horizontal, vertical,
                vertical / horizontal);
    EXPECT_GT(vertical, 1.1f * horizontal);
}

}  // namespace kiln
