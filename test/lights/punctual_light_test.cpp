// Point, spot and distant lights: radiometry (inverse square law, Phi = 4 pi I, pbrt-v4's
// smoothstep spotlight falloff), creation from scene parameters and their normalisation.
#include <gtest/gtest.h>

#include "base/object_arena.h"
#include "core/parser/diagnostics.h"
#include "light_test_util.h"
#include "lights/light.h"

using namespace kiln;
using namespace kiln::testing;

namespace {

std::optional<Light> Create(const std::string& name, ParsedParameterVector params,
                            ObjectArena& arena, Diagnostics& diag) {
    ParameterDictionary dict(std::move(params), nullptr);
    return Light::Create(name, dict, Transform(), FileLoc(), arena, diag);
}

}  // namespace

TEST(PointLight, InverseSquareAndPower) {
    PointLight point(Translate(Vector3f(1, 2, 3)), Spectrum(ConstantSpectrum(5)), 2);
    Light light(&point);
    EXPECT_EQ(light.Type(), LightType::DeltaPosition);
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.25f);
    LightSampleContext ctx(Point3f(1, 2, 0), Normal3f(), Normal3f());
    auto ls = light.SampleLi(ctx, Point2f(0.5f, 0.5f), lambda);
    ASSERT_TRUE(ls.has_value());
    EXPECT_FLOAT_EQ(ls->L[0], 10.f / 9);
    EXPECT_FLOAT_EQ(ls->wi.z, 1);
    EXPECT_EQ(ls->pdf, 1);
    EXPECT_EQ(light.PDF_Li(ctx, ls->wi), 0);
    EXPECT_FLOAT_EQ(light.Phi(lambda)[2], 4 * Pi * 10);
    // A receiver at the light itself gets nothing rather than NaN
    EXPECT_FALSE(light.SampleLi(LightSampleContext(Point3f(1, 2, 3), {}, {}), {}, lambda));
}

TEST(PointLight, CreateWithPowerAndFrom) {
    ObjectArena arena;
    Diagnostics diag(nullptr);
    auto light = Create(
        "point", {FloatParam("float", "power", {50}), FloatParam("point3", "from", {0, 0, 4})},
        arena, diag);
    ASSERT_TRUE(light.has_value());
    double Y = LuminanceOf([&](const SampledWavelengths& l) { return light->Phi(l); });
    EXPECT_NEAR(Y, 50, 0.05);
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    auto ls = light->SampleLi(LightSampleContext(Point3f(0, 0, 2), {}, {}), {}, lambda);
    ASSERT_TRUE(ls.has_value());
    EXPECT_NEAR(ls->pLight.p.z, 4, 1e-6);
    // Default: luminous intensity = scale
    auto unit = Create("point", {FloatParam("float", "scale", {2})}, arena, diag);
    double Yi = LuminanceOf([&](const SampledWavelengths& l) { return unit->Phi(l); });
    EXPECT_NEAR(Yi, 2 * 4 * Pi, 0.02);
    EXPECT_EQ(diag.WarningCount(), 0);
}

TEST(SpotLight, SmoothstepFalloff) {
    // Cone 30 degrees, falloff starts at 20 degrees; pointing along +z from the origin
    SpotLight spot(Transform(), Spectrum(ConstantSpectrum(1)), 1, 30, 20);
    Light light(&spot);
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    Float cosStart = std::cos(Radians(20)), cosEnd = std::cos(Radians(30));
    for (Float deg : {0.f, 10.f, 19.f, 21.f, 25.f, 29.f, 31.f, 90.f, 170.f}) {
        Float th = Radians(deg);
        Point3f p(2 * std::sin(th), 0, 2 * std::cos(th));
        auto ls = light.SampleLi(LightSampleContext(p, {}, {}), {}, lambda);
        Float t = Clamp((std::cos(th) - cosEnd) / (cosStart - cosEnd), 0, 1);
        Float expected = t * t * (3 - 2 * t) / 4;
        Float got = ls ? ls->L[0] : 0;
        EXPECT_NEAR(got, expected, 1e-5) << deg << " degrees";
    }
    // Phi equals the intensity integrated over the sphere
    double sum = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        Float cosTheta = -1 + 2 * (i + 0.5f) / n;
        sum += spot.I(Vector3f(SafeSqrt(1 - Sqr(cosTheta)), 0, cosTheta), lambda)[0];
    }
    EXPECT_NEAR(light.Phi(lambda)[0], sum * 2 * Pi * 2 / n, 1e-4);
}

TEST(SpotLight, CreateAimsFromTo) {
    ObjectArena arena;
    Diagnostics diag(nullptr);
    auto light =
        Create("spot",
               {FloatParam("point3", "from", {1, 1, 1}), FloatParam("point3", "to", {1, 1, 5}),
                FloatParam("float", "coneangle", {10}), FloatParam("float", "conedeltaangle", {2})},
               arena, diag);
    ASSERT_TRUE(light.has_value());
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    EXPECT_TRUE(light->SampleLi(LightSampleContext(Point3f(1, 1, 3), {}, {}), {}, lambda));
    EXPECT_FALSE(light->SampleLi(LightSampleContext(Point3f(1, 1, -3), {}, {}), {}, lambda));
    EXPECT_FALSE(light->SampleLi(LightSampleContext(Point3f(3, 1, 2), {}, {}), {}, lambda));
    auto powered = Create("spot", {FloatParam("float", "power", {20})}, arena, diag);
    double Y = LuminanceOf([&](const SampledWavelengths& l) { return powered->Phi(l); });
    EXPECT_NEAR(Y, 20, 0.02);
}

TEST(DistantLight, DirectionRadianceAndPower) {
    ObjectArena arena;
    Diagnostics diag(nullptr);
    auto light =
        Create("distant",
               {FloatParam("point3", "from", {0, 0, 0}), FloatParam("point3", "to", {0, -1, 0}),
                FloatParam("float", "illuminance", {7})},
               arena, diag);
    ASSERT_TRUE(light.has_value());
    EXPECT_EQ(light->Type(), LightType::DeltaDirection);
    light->Preprocess(Bounds3f(Point3f(-1, -1, -1), Point3f(1, 1, 1)));
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    auto ls = light->SampleLi(LightSampleContext(Point3f(0, 0, 0), {}, {}), {}, lambda);
    ASSERT_TRUE(ls.has_value());
    EXPECT_NEAR(ls->wi.y, 1, 1e-6);
    EXPECT_GT(ls->pLight.p.y, std::sqrt(3.f));
    // Illuminance on a surface facing the light is the requested one
    double E = LuminanceOf([&](const SampledWavelengths& l) {
        return light->SampleLi(LightSampleContext(Point3f(), {}, {}), {}, l)->L;
    });
    EXPECT_NEAR(E, 7, 0.01);
    double Y = LuminanceOf([&](const SampledWavelengths& l) { return light->Phi(l); });
    EXPECT_NEAR(Y, 7 * Pi * 3, 0.05);
}

TEST(Light, CreateUnknown) {
    ObjectArena arena;
    std::ostringstream out;
    Diagnostics diag(&out);
    EXPECT_THROW(Create("laser", {}, arena, diag), SceneError);
    EXPECT_EQ(diag.WarningCount(), 0);
}
