// Thermal emission end to end: Kirchhoff equilibrium in a closed isothermal cavity, the
// additive model's excess, equal results for light and BSDF sampling of hot emitters, and the
// colour of glowing metals.
#include <gtest/gtest.h>

#include <cmath>

#include "../lights/light_test_util.h"
#include "base/rng.h"
#include "base/statistics.h"
#include "lights/thermal_area_light.h"
#include "render_test_util.h"
#include "spectral/cie.h"
#include "spectral/metal_temperature.h"
#include "spectral/named_spectra.h"
#include "spectral/planck.h"

#if KILN_THERMAL_EMISSION
namespace kiln {
namespace {

// Luminance Y = int B ybar / int ybar of a blackbody, W m^-2 sr^-1 nm^-1 (the film's
// convention), by the same 1 nm sum the film's colour matching uses.
// Pixel luminance statistics (pixels are independent estimates: the cavity's film gives each
// pixel its own samples)
RunningStats ImageLuminance(const Scene& scene) {
    RunningStats stats;
    Bounds2i b = scene.job->film->PixelBounds();
    for (int y = b.pMin.y; y < b.pMax.y; ++y)
        for (int x = b.pMin.x; x < b.pMax.x; ++x) stats.Add(testing::PixelY(scene, {x, y}));
    return stats;
}

// A closed cavity (the camera inside a diffuse sphere) holding a smooth gold sphere, a rough
// copper sphere, a coated body and a rough platinum disk, everything at temperature T.
std::string Cavity(double T, const std::string& model, int spp) {
    std::ostringstream s;
    // Each pixel its own samples (too few pixels for testing::BlockStats; the test below
    // takes the pixels' spread as the noise of independent estimates)
    s << "Film \"rgb\" \"integer xresolution\" 12 \"integer yresolution\" 12 "
         "\"string reconstruction\" \"importance\"\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" " << spp << "\n"
      << "Integrator \"path\" \"integer maxdepth\" 400\n"
      << "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 70\n"
      << "WorldBegin\n"
      << "Attribute \"shape\" \"float temperature\" " << T << "\n"
      << "Attribute \"material\" \"string emission\" \"" << model << "\"\n"
      << "Material \"diffuse\" \"rgb reflectance\" [0.7 0.6 0.5]\n"
      << "Shape \"sphere\" \"float radius\" 6\n"
      << "Material \"conductor\" \"spectrum eta\" \"metal-Au-eta\" \"spectrum k\" \"metal-Au-k\"\n"
      << "AttributeBegin\n Translate -0.7 0 0\n Shape \"sphere\" \"float radius\" "
         "0.6\nAttributeEnd\n"
      << "Material \"conductor\" \"spectrum eta\" \"metal-Cu-eta\" \"spectrum k\" \"metal-Cu-k\""
         " \"float roughness\" 0.2\n"
      << "AttributeBegin\n Translate 0.7 0 0\n Shape \"sphere\" \"float radius\" "
         "0.6\nAttributeEnd\n"
      << "Material \"coateddiffuse\" \"rgb reflectance\" [0.3 0.3 0.3] \"float roughness\" 0.05\n"
      << "AttributeBegin\n Translate 0 0.9 0.5\n Shape \"sphere\" \"float radius\" "
         "0.4\nAttributeEnd\n"
      << "Material \"conductor\" \"spectrum eta\" \"metal-Pt-eta\" \"spectrum k\" \"metal-Pt-k\""
         " \"float roughness\" 0.4\n"
      << "AttributeBegin\n Translate 0 -1 1\n Rotate -60 1 0 0\n Shape \"disk\" \"float radius\" "
         "1.5\n"
         "AttributeEnd\n";
    return s.str();
}

TEST(ThermalTest, KirchhoffCavityIsInEquilibriumAtEveryPixel) {
    // A glowing temperature and a near-white one (flatter Planck curve, less spectral noise).
    for (double T : {1400.0, 5500.0}) {
        SCOPED_TRACE(T);
        const double expected = testing::BlackbodyLuminance(T);
        testing::RenderedScene r = testing::RenderText(Cavity(T, "kirchhoff", 128));
        EXPECT_TRUE(r.warnings.empty());
        EXPECT_GT(r.scene->thermalEmitterCount, 0);
        // Every pixel has the same expected value B(T), so the spread of the pixels is the
        // per-pixel Monte Carlo noise (much of it from sampling 4 wavelengths of the Planck
        // curve). The image mean must be B(T) within 1% and within its standard error; no
        // pixel, whatever object it sees, may stand out from the noise.
        RunningStats s = ImageLuminance(*r.scene);
        double sigma = std::sqrt(s.Variance()) / expected;
        double standardError = sigma / std::sqrt(double(s.Count()));
        std::printf("cavity at %.0f K: mean %.5f of B(T), pixel sigma %.4f\n", T,
                    s.Mean() / expected, sigma);
        EXPECT_NEAR(s.Mean() / expected, 1.0, std::min(0.01, 4 * standardError + 1e-3));
        EXPECT_LT(sigma, 0.05);
        Bounds2i b = r.scene->job->film->PixelBounds();
        for (int y = b.pMin.y; y < b.pMax.y; ++y)
            for (int x = b.pMin.x; x < b.pMax.x; ++x)
                EXPECT_NEAR(testing::PixelY(*r.scene, {x, y}) / expected, 1.0, 4.5 * sigma)
                    << "pixel " << x << "," << y;
    }
}

TEST(ThermalTest, AdditiveEmissionOverfillsTheCavity) {
    const double T = 1400, expected = testing::BlackbodyLuminance(T);
    testing::RenderedScene r = testing::RenderText(Cavity(T, "additive", 64));
    RunningStats s = ImageLuminance(*r.scene);
    // Emission B plus reflected light: B / (1 - R) on reflective surfaces.
    EXPECT_GT(s.Mean() / expected, 1.2);
}

// A hot rough sphere above a diffuse floor: the floor's light must not depend on whether the
// emitter is found by light sampling, BSDF sampling or both.
std::string HotSphere(const std::string& strategy) {
    return "Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 16\n"
           "Sampler \"zsobol\" \"integer pixelsamples\" 256\n"
           "Integrator \"path\" \"integer maxdepth\" 3 \"string strategy\" \"" +
           strategy +
           "\"\n"
           "LookAt 0 4 -4  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 40\n"
           "WorldBegin\n"
           "Material \"diffuse\" \"rgb reflectance\" [0.5 0.5 0.5]\n"
           "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point3 P\" "
           "[-3 0 -3 3 0 -3 3 0 3 -3 0 3]\n"
           "Material \"conductor\" \"spectrum eta\" \"metal-Ni-eta\" \"spectrum k\" "
           "\"metal-Ni-k\" \"float roughness\" 0.3 \"float temperature\" 1500\n"
           "AttributeBegin\n Translate 0 1.2 0\n Shape \"sphere\" \"float radius\" 0.5\n"
           "AttributeEnd\n";
}

TEST(ThermalTest, LightAndBsdfSamplingOfThermalEmittersAgree) {
    RunningStats mis = ImageLuminance(*testing::RenderText(HotSphere("mis")).scene);
    RunningStats light = ImageLuminance(*testing::RenderText(HotSphere("light")).scene);
    RunningStats bsdf = ImageLuminance(*testing::RenderText(HotSphere("bsdf")).scene);
    ASSERT_GT(mis.Mean(), 0);
    // Image means are averages over 256 pixels x 256 samples; their standard errors come
    // from the spread of the pixel values.
    auto se = [](const RunningStats& s) { return std::sqrt(s.Variance() / s.Count()); };
    EXPECT_NEAR(light.Mean(), mis.Mean(), 5 * std::hypot(se(light), se(mis)) + 2e-3 * mis.Mean());
    EXPECT_NEAR(bsdf.Mean(), mis.Mean(), 5 * std::hypot(se(bsdf), se(mis)) + 2e-3 * mis.Mean());
}

// Glow of one smooth sphere of a material at 1300 K, no other light: mean XYZ of the central
// pixels (seen near normal incidence).
XYZ GlowXYZ(const std::string& material) {
    std::string text =
        "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
        "Sampler \"zsobol\" \"integer pixelsamples\" 16\n"
        "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 4\n"
        "WorldBegin\nMaterial " +
        material + "\nShape \"sphere\" \"float radius\" 1 \"float temperature\" 1300\n";
    testing::RenderedScene r = testing::RenderText(text);
    XYZ sum;
    Bounds2i b = r.scene->job->film->PixelBounds();
    for (int y = b.pMin.y; y < b.pMax.y; ++y)
        for (int x = b.pMin.x; x < b.pMax.x; ++x)
            sum = sum +
                  r.scene->job->film->ColorSpace()->ToXYZ(r.scene->job->film->GetPixelRGB({x, y}));
    return sum / Float(b.Area());
}

// XYZ of B(T) (1 - R_normal(lambda)) for a metal's named eta and k, at T for the metals whose
// constants follow temperature (spectral/metal_temperature.h): the prediction.
XYZ PredictedGlowXYZ(const std::string& metal, double T) {
    const Spectrum* eta = GetNamedSpectrum("metal-" + metal + "-eta");
    const Spectrum* k = GetNamedSpectrum("metal-" + metal + "-k");
    const MetalTemperatureTable* hot = MetalTemperatureTable::Find(metal);
    double X = 0, Y = 0, Z = 0;
    for (int l = 360; l <= 830; ++l) {
        double n = (*eta)(Float(l)), kk = (*k)(Float(l));
        if (hot) {
            SampledSpectrum e, kt;
            hot->Evaluate(SampledWavelengths::FromWavelength(Float(l)), Float(T), &e, &kt);
            n = e[0], kk = kt[0];
        }
        double R = ((n - 1) * (n - 1) + kk * kk) / ((n + 1) * (n + 1) + kk * kk);
        double L = planck_radiance(l, T) * (1 - R);
        X += L * CIE_X(Float(l));
        Y += L * CIE_Y(Float(l));
        Z += L * CIE_Z(Float(l));
    }
    return XYZ(Float(X), Float(Y), Float(Z)) / CIE_Y_integral;
}

std::string Metal(const std::string& m) {
    return "\"conductor\" \"spectrum eta\" \"metal-" + m + "-eta\" \"spectrum k\" \"metal-" + m +
           "-k\"";
}

TEST(ThermalTest, GoldGlowsYellowerThanSilverAndPlatinumAsItsAbsorbancePredicts) {
    Point2f gold = GlowXYZ(Metal("Au")).xy(), silver = GlowXYZ(Metal("Ag")).xy(),
            platinum = GlowXYZ(Metal("Pt")).xy();
    Point2f goldPred = PredictedGlowXYZ("Au", 1300).xy(),
            silverPred = PredictedGlowXYZ("Ag", 1300).xy(),
            platinumPred = PredictedGlowXYZ("Pt", 1300).xy();
    // Rendered chromaticities follow the normal-incidence prediction (the pixels see the
    // sphere within a few degrees of normal incidence).
    for (auto [got, want] :
         {std::pair{gold, goldPred}, {silver, silverPred}, {platinum, platinumPred}}) {
        EXPECT_NEAR(got.x, want.x, 4e-3);
        EXPECT_NEAR(got.y, want.y, 4e-3);
    }
    // Gold's chromaticity is measurably different, in the direction 1 - R predicts.
    for (auto [other, otherPred] : {std::pair{silver, silverPred}, {platinum, platinumPred}}) {
        Vector2f got(gold.x - other.x, gold.y - other.y);
        Vector2f want(goldPred.x - otherPred.x, goldPred.y - otherPred.y);
        EXPECT_GT(std::sqrt(want.x * want.x + want.y * want.y), 0.01);
        Float cosAngle =
            (got.x * want.x + got.y * want.y) /
            std::sqrt((got.x * got.x + got.y * got.y) * (want.x * want.x + want.y * want.y));
        EXPECT_GT(cosAngle, 0.95);
    }
}

TEST(ThermalTest, SilverGlowsFarWeakerThanBlackQuartz) {
    Float silver = GlowXYZ(Metal("Ag")).Y;
    Float quartz = GlowXYZ(
                       "\"coateddiffuse\" \"rgb reflectance\" [0 0 0] \"spectrum eta\" "
                       "\"glass-SiO2\" \"float roughness\" 0")
                       .Y;
    EXPECT_GT(quartz, 10 * silver);
    // Black quartz is nearly a blackbody at normal incidence: 1 - R of fused silica ~ 0.96.
    EXPECT_NEAR(quartz / testing::BlackbodyLuminance(1300), 0.965, 0.01);
}

// Hot emitters resting on a floor (a sphere and a triangle-mesh box touching it): the floor
// right up to the contact lines must be free of fireflies, the near-zero-distance problem of
// light sampling. Two renders with different seeds differ only by noise: with fireflies the
// largest pixel difference would dwarf the typical one.
TEST(ThermalTest, NoFirefliesWhereHotEmittersTouchTheFloor) {
    const std::string scene = R"(
Film "rgb" "integer xresolution" 64 "integer yresolution" 48
Sampler "zsobol" "integer pixelsamples" 64
Integrator "path" "integer maxdepth" 3
LookAt 0 0.35 -1.6  0 0.1 0  0 1 0
Camera "perspective" "float fov" 40
WorldBegin
Material "diffuse" "rgb reflectance" [0.5 0.5 0.5]
Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-3 0 -3 3 0 -3 3 0 3 -3 0 3]
Material "conductor" "spectrum eta" "metal-Ni-eta" "spectrum k" "metal-Ni-k"
    "float roughness" 0.2 "float temperature" 1400
AttributeBegin
  Translate -0.3 0.25 0
  Shape "sphere" "float radius" 0.25
AttributeEnd
AttributeBegin
  Translate 0.25 0 0
  Shape "trianglemesh" "integer indices" [0 1 2 0 2 3  4 5 6 4 6 7]
    "point3 P" [0 0 -0.2  0.3 0 -0.2  0.3 0.3 -0.2  0 0.3 -0.2
                0 0 -0.2  0 0 0.1  0 0.3 0.1  0 0.3 -0.2]
AttributeEnd
)";
    RenderOptions a, b;
    a.seed = 1;
    b.seed = 2;
    testing::RenderedScene ra = testing::RenderText(scene, 0, a);
    testing::RenderedScene rb = testing::RenderText(scene, 0, b);
    // Floor rows just below the contact line (row ~30 of 48, where the emitters end) down
    std::vector<double> diff;
    RunningStats floor;
    for (int y = 31; y < 48; ++y)
        for (int x = 0; x < 64; ++x) {
            double ya = testing::PixelY(*ra.scene, {x, y}), yb = testing::PixelY(*rb.scene, {x, y});
            diff.push_back(std::abs(ya - yb));
            floor.Add(0.5 * (ya + yb));
        }
    double sumSq = 0, maxDiff = 0;
    size_t maxAt = 0;
    for (size_t i = 0; i < diff.size(); ++i) {
        sumSq += diff[i] * diff[i];
        if (diff[i] > maxDiff) maxDiff = diff[i], maxAt = i;
    }
    double rms = std::sqrt(sumSq / diff.size());
    ASSERT_GT(floor.Mean(), 0);
    EXPECT_LT(maxDiff, 8 * rms) << "max " << maxDiff << " at pixel " << maxAt % 64 << ","
                                << 31 + maxAt / 64 << ", rms " << rms;
    EXPECT_LT(rms, 0.2 * floor.Mean());
    EXPECT_EQ(ra.scene->job->film->NonFiniteSampleCount(), 0);
}

// T = 0 K emits exactly nothing (and nothing goes non-finite), whatever the model; a tiny
// temperature far below the Draper point is exact but vanishingly dim.
TEST(ThermalTest, ZeroAndTinyTemperaturesAreExact) {
    for (const char* model : {"kirchhoff", "additive", "diffuse"}) {
        for (double T : {0.0, 1e-3, 300.0}) {
            std::ostringstream text;
            text << "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
                 << "Sampler \"independent\" \"integer pixelsamples\" 4\n"
                 << "LookAt 0 0 -4  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 30\n"
                 << "WorldBegin\nMaterial \"conductor\" \"string emission\" \"" << model
                 << "\"\nShape \"sphere\" \"float temperature\" " << T << "\n";
            testing::RenderedScene r = testing::RenderText(text.str());
            EXPECT_EQ(r.scene->job->film->NonFiniteSampleCount(), 0);
            double maxY = 0;
            for (int y = 0; y < 8; ++y)
                for (int x = 0; x < 8; ++x)
                    maxY = std::max(maxY, double(testing::PixelY(*r.scene, {x, y})));
            // Planck luminance at 300 K is ~1e-33 W m^-2 sr^-1 nm^-1: representable, not visible.
            if (T == 0 || T == 1e-3) {
                EXPECT_EQ(maxY, 0) << model << " " << T;
            }
            EXPECT_LT(maxY, 1e-20) << model << " " << T;
        }
    }
}

// A cool mesh with one hot vertex: the scene's light sampler picks its triangles (each a
// thermal emitter) with the probabilities it reports (chi-square), those probabilities grow
// steeply with temperature, and the hottest triangles get most of the samples.
TEST(ThermalTest, PowerSamplerDrawsHotTrianglesWithTheReportedProbability) {
    // 4 x 4 grid of quads (32 triangles) at 500 K except one vertex at 1500 K.
    std::ostringstream P, T, idx;
    for (int j = 0; j <= 4; ++j)
        for (int i = 0; i <= 4; ++i) {
            P << i << " 2 " << j << " ";
            T << ((i == 3 && j == 1) ? 1500 : 500) << " ";
        }
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            int a = j * 5 + i;
            idx << a << " " << a + 1 << " " << a + 6 << " " << a << " " << a + 6 << " " << a + 5
                << " ";
        }
    std::string text =
        "Film \"rgb\" \"integer xresolution\" 4 \"integer yresolution\" 4\n"
        "Integrator \"path\" \"string lightsampler\" \"power\"\n"
        "WorldBegin\nShape \"trianglemesh\" \"integer indices\" [" +
        idx.str() + "] \"point3 P\" [" + P.str() + "] \"float temperature\" [" + T.str() + "]\n";
    Diagnostics diag(nullptr);
    std::unique_ptr<Scene> scene = testing::BuildScene(text, diag);
    ASSERT_EQ(scene->lights.size(), 32u);
    ASSERT_EQ(scene->thermalEmitterCount, 32);
    std::vector<double> observed(32, 0), expected(32, 0);
    const int n = 200000;
    LightSampleContext ctx;  // the power sampler ignores the receiving point
    RNG rng(7);
    for (int k = 0; k < n; ++k) {
        std::optional<SampledLight> sl = scene->lightSampler->Sample(ctx, rng.UniformFloat());
        ASSERT_TRUE(sl);
        size_t i = size_t(sl->index);
        ASSERT_LT(i, 32u);
        EXPECT_FLOAT_EQ(sl->p, scene->lightSampler->PMF(ctx, sl->index));
        observed[i] += 1;
    }
    double pmfSum = 0, hotPmf = 0, coolPmf = 1;
    for (size_t i = 0; i < 32; ++i) {
        double pmf = scene->lightSampler->PMF(ctx, int(i));
        expected[i] = pmf * n;
        pmfSum += pmf;
        hotPmf = std::max(hotPmf, pmf);
        coolPmf = std::min(coolPmf, pmf);
    }
    EXPECT_NEAR(pmfSum, 1, 1e-5);
    ChiSquareResult chi = ChiSquareTest(observed, expected);
    EXPECT_TRUE(chi.passed) << chi.message;
    // Triangles touching the 1500 K vertex emit orders of magnitude more than the 500 K ones.
    EXPECT_GT(hotPmf / coolPmf, 100);
}

}  // namespace
}  // namespace kiln

namespace kiln {
namespace {

// A hot shape whose temperature varies over it (a gradient from 500 K to 1600 K along x) is
// sampled in proportion to its emitted power, for every shape kind: the points SampleLi draws
// follow, over the shape's parameterisation, the area density that PDF_Li reports (converted
// from solid angle; chi-square), each sample's pdf is PDF_Li's, the closed shapes pass the
// same test over directions from inside, and most samples fall on the hot half, far more than
// its share of the area.
TEST(ThermalTest, EmittersWithVaryingTemperatureAreSampledByPower) {
    const std::string gradient =
        "Texture \"heat\" \"float\" \"gradient\" \"point3 p0\" [-1 0 0] \"point3 p1\" [1 0 0] "
        "\"float t0\" 500 \"float t1\" 1600 \"string space\" \"world\"\n"
        "Material \"diffuse\" \"rgb reflectance\" [0.3 0.3 0.3] \"texture temperature\" \"heat\"\n";
    struct Case {
        const char* name;
        std::string shape;
        bool closed;  // tested from inside, where every point is visible at a steep angle
    };
    const Case shapes[] = {
        {"sphere", "Shape \"sphere\" \"float radius\" 1", true},
        {"disk", "Shape \"disk\" \"float radius\" 1", false},
        {"cylinder", "Shape \"cylinder\" \"float radius\" 1 \"float zmin\" -0.5 \"float zmax\" 0.5",
         true},
        {"bilinear patch",
         "Shape \"bilinearmesh\" \"point3 P\" [-1 -1 0 1 -1 0 -1 1 0 1 1 0] \"integer indices\" "
         "[0 1 2 3]",
         false},
        {"triangles",
         "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point3 P\" "
         "[-1 -1 0 1 -1 0 1 1 0 -1 1 0]",
         false},
    };
    for (const auto& [name, shape, closed] : shapes) {
        SCOPED_TRACE(name);
        Diagnostics diag(nullptr);
        std::unique_ptr<Scene> scene = testing::BuildScene(
            "Film \"rgb\" \"integer xresolution\" 4 \"integer yresolution\" 4\nWorldBegin\n" +
                gradient + shape + "\n",
            diag);
        ASSERT_GE(scene->lights.size(), 1u);
        SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.4f);
        Point3f p = closed ? Point3f(0.2f, 0.1f, 0.05f) : Point3f(0.3f, 0.2f, 3);
        LightSampleContext ctx =
            closed ? LightSampleContext(Interaction(p, {}, {}))
                   : LightSampleContext(p, Normal3f(0, 0, -1), Normal3f(0, 0, -1));
        int hot = 0, all = 0;
        for (const Light& light : scene->lights) {
            const ThermalAreaLight* t = light.GetIf<ThermalAreaLight>();
            ASSERT_TRUE(t);
            EXPECT_TRUE(t->SamplesByPower());
            const Shape& s = t->GetShape();
            // The area density PDF_Li implies at the point of parameter u, per unit u
            auto densityU = [&](Point2f u) -> double {
                std::optional<ShapeSample> ss = s.SampleParametric(u);
                if (!ss) return 0;
                Vector3f d = ss->intr.p - p;
                Vector3f w = Normalize(d);
                return light.PDF_Li(ctx, w, true) * AbsDot(ss->intr.n, w) / LengthSquared(d) /
                       ss->pdf;
            };
            constexpr int nb = 8, sub = 24, n = 200000;
            std::vector<double> observed(nb * nb, 0), expected(nb * nb, 0);
            RNG rng(5);
            int mismatches = 0;
            for (int k = 0; k < n; ++k) {
                std::optional<LightLiSample> ls = light.SampleLi(
                    ctx, Point2f(rng.UniformFloat(), rng.UniformFloat()), lambda, true);
                if (!ls) continue;
                ++all;
                if (ls->pLight.p.x > 0) ++hot;
                Float q = light.PDF_Li(ctx, ls->wi, true);
                if (std::abs(q - ls->pdf) > 2e-3f * ls->pdf) ++mismatches;
                Point2f u = s.InvertParametric(ls->pLight.p);
                observed[size_t(std::min(nb - 1, int(u.y * nb)) * nb +
                                std::min(nb - 1, int(u.x * nb)))] += 1;
            }
            // Piecewise-constant densities jump across cell edges, which rounding may straddle
            EXPECT_LE(mismatches, n / 500);
            for (int j = 0; j < nb * sub; ++j)
                for (int i = 0; i < nb * sub; ++i)
                    expected[size_t((j / sub) * nb + i / sub)] +=
                        densityU(Point2f((i + 0.5f) / (nb * sub), (j + 0.5f) / (nb * sub))) * n /
                        Sqr(nb * sub);
            ChiSquareResult chi = ChiSquareTest(observed, expected, 0.01, 1);
            EXPECT_TRUE(chi.passed) << "parameter space: " << chi.message;
            if (closed) {
                auto sample = [&](Point2f u) -> std::optional<testing::DirectionSample> {
                    std::optional<LightLiSample> ls = light.SampleLi(ctx, u, lambda, true);
                    if (!ls) return std::nullopt;
                    return testing::DirectionSample{ls->wi, ls->pdf};
                };
                auto pdf = [&](Vector3f w) { return light.PDF_Li(ctx, w, true); };
                ChiSquareResult dir = testing::DirectionChiSquare(sample, pdf, Vector3f(0, 0, 1),
                                                                  -1, 200000, 1, 6, 12, 96, 2e-3);
                EXPECT_TRUE(dir.passed) << "directions: " << dir.message;
            }
        }
        // The hot half (x > 0) emits far more than the cool one
        EXPECT_GT(double(hot) / all, 0.9);
    }
}

// A light sample's radiance is the surface's emission there, exactly as a ray hitting that
// point computes it (same BSDF, shading frame, texture footprint, mix choice): for hot
// textured and heat-mapped emitters, a shading-normal mesh and a mix.
TEST(ThermalTest, LightSamplesEmitWhatRayHitsThereEmit) {
    const std::string scene =
        "Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 16\n"
        "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 50\n"
        "WorldBegin\n"
        "Texture \"checks\" \"spectrum\" \"checkerboard\" \"float uscale\" 8 \"float vscale\" 8"
        " \"rgb tex1\" [0.9 0.8 0.7] \"rgb tex2\" [0.1 0.2 0.05]\n"
        "Texture \"heat\" \"float\" \"checkerboard\" \"float uscale\" 5 \"float vscale\" 5"
        " \"float tex1\" 900 \"float tex2\" 1500\n"
        "MakeNamedMaterial \"a\" \"string type\" \"diffuse\" \"texture reflectance\" \"checks\"\n"
        "MakeNamedMaterial \"b\" \"string type\" \"conductor\" \"float roughness\" 0.2\n"
        "Material \"mix\" \"string materials\" [\"a\" \"b\"] \"float amount\" 0.5"
        " \"texture temperature\" \"heat\"\n"
        "Shape \"bilinearmesh\" \"point3 P\" [-1 -1 0 1 -1 0 -1 1 0 1 1 0] "
        "\"integer indices\" [0 1 2 3]\n"
        "Material \"coateddiffuse\" \"texture reflectance\" \"checks\" \"float temperature\" 1300\n"
        "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point3 P\" "
        "[-2 -2 1 2 -2 1 2 2 1.5 -2 2 1.5] \"normal N\" [0 0.2 -1 0.2 0 -1 0 -0.2 -1 -0.2 0 -1]"
        " \"point2 uv\" [0 0 1 0 1 1 0 1]\n"
        // An untextured material whose temperature texture filters with the footprint
        "Material \"diffuse\" \"texture temperature\" \"heat\"\n"
        "AttributeBegin Translate 0 0 -0.5 Shape \"disk\" \"float radius\" 0.3 AttributeEnd\n";
    Diagnostics diag(nullptr);
    std::unique_ptr<Scene> s = testing::BuildScene(scene, diag);
    ASSERT_GE(s->lights.size(), 4u);
    Point3f p(0.1f, 0.05f, -2);
    LightSampleContext ctx(p, Normal3f(0, 0, 1), Normal3f(0, 0, 1));
    RNG rng(3);
    int compared = 0, mismatches = 0;
    for (int k = 0; k < 20000; ++k) {
        SampledWavelengths lambda = SampledWavelengths::SampleVisible(rng.UniformFloat());
        const Light& light = s->lights[size_t(k) % s->lights.size()];
        std::optional<LightLiSample> ls =
            light.SampleLi(ctx, Point2f(rng.UniformFloat(), rng.UniformFloat()), lambda, true);
        if (!ls) continue;
        std::optional<ShapeIntersection> hit =
            s->aggregate->Intersect(Ray(p, ls->pLight.p - p), 1.001f);
        if (!hit || hit->tHit < 0.999f) continue;  // another emitter in front
        SampledWavelengths l = lambda;
        BSDF bsdf = s->GetBSDF(hit->intr, l);
        SampledSpectrum Le = s->SurfaceLe(hit->intr, bsdf, -ls->wi, lambda);
        SampledSpectrum Ls = light.DeferredL(*ls, lambda, *s->job->shader);
        ++compared;
        for (int i = 0; i < NSpectrumSamples; ++i)
            if (std::abs(Le[i] - Ls[i]) > 1e-3f * std::max(Le[i], Ls[i])) {
                ++mismatches;
                break;
            }
    }
    EXPECT_GT(compared, 10000);
    // Rounding may put the two points on different sides of a checker edge or of the mix's
    // rounding grid
    EXPECT_LE(mismatches, compared / 200) << mismatches << " of " << compared;
}

}  // namespace
}  // namespace kiln
#endif  // KILN_THERMAL_EMISSION
