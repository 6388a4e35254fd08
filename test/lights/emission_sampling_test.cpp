// Emission sampling for light tracing (Light::SampleLe, PDF_Le; pbrt-v4's): for every light
// kind, chi-square tests of the sampled directions against PDF_Le, the densities a sample
// reports against PDF_Le's, and the power estimate E[L |cos| / (pdfPos pdfDir)] against Phi
// (which integrates the same emission independently: Phi = integral of L cos over area and
// directions, or pi r^2 times the integral of L over directions for lights at infinity).
#include <gtest/gtest.h>

#include "base/object_arena.h"
#include "core/geometry/shape.h"
#include "core/parser/diagnostics.h"
#include "light_test_util.h"
#include "lights/light.h"
#include "spectral/color.h"

using namespace kiln;
using namespace kiln::testing;

namespace {

// Lights other than thermal ones take no shader
struct NoShader {
    BSDF GetBSDF(SurfaceInteraction&, SampledWavelengths&) const { return BSDF(); }
};

const SampledWavelengths& Lambda() {
    static SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.37f);
    return lambda;
}

// Chi-square of SampleLe's directions against PDF_Le (by ray, or at the sampled point for
// area lights) over the cone about axis; u2 is drawn from its own stream
void CheckDirections(const Light& light, Vector3f axis, Float cosMax, int n = 200000) {
    RNG rng2(5);
    auto sample = [&](Point2f u) -> std::optional<DirectionSample> {
        Point2f u2(rng2.UniformFloat(), rng2.UniformFloat());
        auto les = light.SampleLe(u, u2, Lambda(), NoShader());
        if (!les) return std::nullopt;
        EXPECT_NEAR(Length(les->ray.d), 1, 1e-4);
        LightLePDF pdf = les->intr ? light.PDF_Le(*les->intr, les->ray.d) : light.PDF_Le(les->ray);
        // (Point and spot lights report pdfPos 0 there, 1 in the sample: pbrt-v4's convention
        // for a delta in position)
        if (light.Type() != LightType::DeltaPosition) {
            EXPECT_NEAR(pdf.pos, les->pdfPos, 1e-4 * les->pdfPos);
        }
        return DirectionSample{les->ray.d, les->pdfDir};
    };
    // The density PDF_Le reports for a ray leaving the light along w (area lights: from a
    // fixed point of the shape, whose normal is the same everywhere on the flat shapes tested)
    std::optional<Interaction> at;
    if (light.Type() == LightType::Area)
        at = light.SampleLe({0.5f, 0.5f}, {0.3f, 0.3f}, Lambda(), NoShader())->intr;
    auto pdf = [&](Vector3f w) {
        return at ? light.PDF_Le(*at, w).dir : light.PDF_Le(Ray(Point3f(), w)).dir;
    };
    ChiSquareResult r = DirectionChiSquare(sample, pdf, axis, cosMax, n, 3, 16, 32, 32);
    EXPECT_TRUE(r.passed) << r.message;
}

// E[L |cos| / (pdfPos pdfDir)] over n samples, luminance-weighted over lambda, against Phi's
// at the same wavelengths; the tolerance is 5 standard errors of the estimate
void CheckPower(const Light& light, int n = 100000) {
    RNG rng(11);
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; ++i) {
        Point2f u1(rng.UniformFloat(), rng.UniformFloat()),
            u2(rng.UniformFloat(), rng.UniformFloat());
        auto les = light.SampleLe(u1, u2, Lambda(), NoShader());
        double v = 0;
        if (les) {
            Float pdf = les->pdfPos * les->pdfDir;  // pdfDir is 1 for distant lights
            v = les->L.Average() * les->AbsCosTheta(les->ray.d) / pdf;
        }
        sum += v;
        sum2 += v * v;
    }
    double mean = sum / n, sd = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
    double phi = light.Phi(Lambda()).Average();
    EXPECT_NEAR(mean, phi, 5 * sd + 1e-5 * phi) << "sd " << sd;
}

Image Environment() {
    Image image(PixelFormat::Float, {8, 8}, {"R", "G", "B"});
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            Float v = 0.2f + 0.1f * ((x * 7 + y * 3) % 5) + (x == 2 && y == 3 ? 20 : 0);
            for (int c = 0; c < 3; ++c) image.SetChannel({x, y}, c, v * (1 + c));
        }
    return image;
}

}  // namespace

TEST(EmissionSampling, PointLight) {
    PointLight point(Translate(Vector3f(1, 2, 3)), Spectrum(ConstantSpectrum(5)), 2);
    Light light(&point);
    auto les = light.SampleLe({0.3f, 0.6f}, {0.5f, 0.5f}, Lambda(), NoShader());
    ASSERT_TRUE(les);
    EXPECT_EQ(les->ray.o, Point3f(1, 2, 3));
    EXPECT_FLOAT_EQ(les->L[0], 10);
    CheckDirections(light, Vector3f(0, 0, 1), -1);
    CheckPower(light);
}

TEST(EmissionSampling, SpotLight) {
    SpotLight spot(Translate(Vector3f(0, 1, 0)) * Rotate(40, Vector3f(1, 0, 0)),
                   Spectrum(ConstantSpectrum(3)), 1, 35, 20);
    Light light(&spot);
    // The cone of 35 degrees about the spot's axis holds every sample
    Vector3f axis = Rotate(40, Vector3f(1, 0, 0))(Vector3f(0, 0, 1));
    CheckDirections(light, axis, std::cos(Radians(35.01f)), 100000);
    CheckPower(light);
}

TEST(EmissionSampling, GoniometricLight) {
    // A map with a bright patch and a dark hemisphere, rotated
    const int n = 16;
    Image image(PixelFormat::Float, {n, n}, {"Y"});
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            image.SetChannel({x, y}, 0,
                             (x < n / 2 ? 0.1f : 1.f) + (x == 3 && y == 11 ? 30.f : 0.f));
    GoniometricLight gonio(Translate(Vector3f(0, 1, 2)) * Rotate(30, Vector3f(1, 1, 0)),
                           Spectrum(ConstantSpectrum(2)), 1.5f, image);
    Light light(&gonio);
    CheckDirections(light, Vector3f(0, 0, 1), -1);
    CheckPower(light);
}

TEST(EmissionSampling, ProjectionLight) {
    Image image(PixelFormat::Float, {6, 3}, {"R", "G", "B"});
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 6; ++x)
            for (int c = 0; c < 3; ++c)
                image.SetChannel({x, y}, c, 0.1f + 0.4f * ((x + y + c) % 3));
    Transform t = Translate(Vector3f(1, 0, 0)) * Rotate(-20, Vector3f(1, 0, 0));
    ProjectionLight projector(t, image, &RGBColorSpace::sRGB(), 2, 50);
    Light light(&projector);
    // The image's corners lie within 50 degrees of the axis (tan 25 x (2, 1))
    Vector3f axis = t(Vector3f(0, 0, 1));
    CheckDirections(light, axis, std::cos(Radians(50.f)), 100000);
    CheckPower(light);
}

TEST(EmissionSampling, DistantLight) {
    DistantLight distant(Rotate(30, Vector3f(0, 1, 0)), Spectrum(ConstantSpectrum(2)), 1);
    distant.Preprocess(Bounds3f(Point3f(-1, -2, -1), Point3f(3, 2, 1)));
    Light light(&distant);
    Point3f c(1, 0, 0);
    Float r = std::sqrt(4.f + 4 + 1);
    RNG rng(3);
    for (int i = 0; i < 1000; ++i) {
        auto les = light.SampleLe({rng.UniformFloat(), rng.UniformFloat()}, {0.5f, 0.5f}, Lambda(),
                                  NoShader());
        ASSERT_TRUE(les);
        EXPECT_NEAR(Dot(les->ray.d, -distant.Direction()), 1, 1e-5);
        // Origins on the disk of radius r, one radius out towards the light
        Vector3f off = les->ray.o - c;
        EXPECT_NEAR(Dot(off, distant.Direction()), r, 1e-4 * r);
        EXPECT_LE(LengthSquared(off - Dot(off, distant.Direction()) * distant.Direction()),
                  r * r * (1 + 1e-4f));
        EXPECT_FLOAT_EQ(les->pdfPos, 1 / (Pi * r * r));
    }
    CheckPower(light);
}

TEST(EmissionSampling, DiffuseAreaLight) {
    ObjectArena arena;
    Diagnostics diag(nullptr);
    auto* t = arena.New<Transform>(Translate(Vector3f(0, 0, 2)) * Rotate(50, Vector3f(1, 0, 0)));
    auto* ti = arena.New<Transform>(Inverse(*t));
    Shape disk(arena.New<Disk>(t, ti, false, 0.f, 1.f, 0.f, 360.f));
    Vector3f normal = Normalize((*t)(Vector3f(0, 0, 1)));
    for (bool twoSided : {false, true}) {
        ParameterDictionary dict({BoolParam("twosided", twoSided)}, nullptr);
        Light light = Light::CreateArea("diffuse", dict, Transform(), disk, FileLoc(), arena, diag);
        CheckDirections(light, normal, twoSided ? -1 : 0);
        CheckPower(light);
    }
}

TEST(EmissionSampling, UniformInfiniteLight) {
    UniformInfiniteLight env(Transform(), Spectrum(ConstantSpectrum(0.7f)), 1);
    env.Preprocess(Bounds3f(Point3f(-1, -1, -1), Point3f(1, 1, 2)));
    Light light(&env);
    CheckDirections(light, Vector3f(0, 1, 0), -1);
    CheckPower(light);
}

TEST(EmissionSampling, ImageInfiniteLight) {
    ImageInfiniteLight env(Rotate(30, Vector3f(1, 1, 0)), Environment(), &RGBColorSpace::sRGB(), 1);
    env.Preprocess(Bounds3f(Point3f(-1, -1, -1), Point3f(1, 1, 1)));
    Light light(&env);
    CheckDirections(light, Vector3f(0, 0, 1), -1, 300000);
    CheckPower(light, 200000);
}

// A portal light's rays enter through the portal's side: directions over the hemisphere
// facing into the room (its outward normal is +y here)
TEST(EmissionSampling, PortalInfiniteLight) {
    std::array<Point3f, 4> portal = {Point3f(-0.8f, 2, 1), Point3f(0.8f, 2, 1), Point3f(0.8f, 2, 2),
                                     Point3f(-0.8f, 2, 2)};
    PortalInfiniteLight env(Rotate(30, Vector3f(1, 1, 0)), Environment(), &RGBColorSpace::sRGB(), 1,
                            portal);
    env.Preprocess(Bounds3f(Point3f(-2, -2, 0), Point3f(2, 2, 3)));
    Light light(&env);
    CheckDirections(light, Vector3f(0, -1, 0), -1, 400000);
}
