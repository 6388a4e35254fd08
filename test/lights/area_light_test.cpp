// DiffuseAreaLight: solid-angle sampling densities (chi-square) on a sphere, a disk and a
// triangle, pbrt-v4's "power" normalisation, two-sidedness and zero-area robustness.
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

struct Scene {
    ObjectArena arena;
    Diagnostics diag{nullptr};

    Shape MakeSphere(Point3f c, Float r) {
        auto* t = arena.New<Transform>(Translate(Vector3f(c)));
        auto* ti = arena.New<Transform>(Inverse(*t));
        return Shape(arena.New<Sphere>(t, ti, false, r, -r, r, 360.f));
    }
    Shape MakeDisk(const Transform& xf, Float r) {
        auto* t = arena.New<Transform>(xf);
        auto* ti = arena.New<Transform>(Inverse(*t));
        return Shape(arena.New<Disk>(t, ti, false, 0.f, r, 0.f, 360.f));
    }
    Shape MakeTriangle(Point3f a, Point3f b, Point3f c) {
        auto* mesh = arena.New<TriangleMesh>(Transform(), false, std::vector<int>{0, 1, 2},
                                             std::vector<Point3f>{a, b, c}, std::vector<Normal3f>{},
                                             std::vector<Vector3f>{}, std::vector<Point2f>{},
                                             std::vector<int>{});
        return Shape(arena.New<Triangle>(mesh, 0));
    }
    Light Area(const Shape& shape, ParsedParameterVector params) {
        ParameterDictionary dict(std::move(params), nullptr);
        return Light::CreateArea("diffuse", dict, Transform(), shape, FileLoc(), arena, diag);
    }
};

// Chi-square of SampleLi against PDF_Li seen from p, over the cone about the direction to
// `towards` that holds the light.
void CheckSampling(const Light& light, Point3f p, Point3f towards, Float cosMax) {
    LightSampleContext ctx(p, Normal3f(), Normal3f());
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.3f);
    auto sample = [&](Point2f u) -> std::optional<DirectionSample> {
        auto ls = light.SampleLi(ctx, u, lambda);
        if (!ls) return std::nullopt;
        EXPECT_TRUE(ls->L.IsFinite() && ls->pdf > 0);
        return DirectionSample{ls->wi, ls->pdf};
    };
    auto pdf = [&](Vector3f w) { return light.PDF_Li(ctx, w); };
    ChiSquareResult r = DirectionChiSquare(sample, pdf, towards - p, cosMax, 200000, 3, 16, 32, 48);
    EXPECT_TRUE(r.passed) << r.message;
}

}  // namespace

// Radiance an area light sends from a surface point (p, n, uv) towards w.
SampledSpectrum Lat(const Light& light, Point3f p, Normal3f n, Point2f uv, Vector3f w,
                    const SampledWavelengths& lambda) {
    SurfaceInteraction si;
    si.p = p;
    si.n = si.shading.n = n;
    si.uv = uv;
    return light.L(si, BSDF(), w, lambda);
}

TEST(DiffuseAreaLight, SphereSamplingChiSquare) {
    Scene s;
    Light light = s.Area(s.MakeSphere(Point3f(0.5f, 0, 3), 1), {});
    // Sphere of radius 1 at distance ~3.04: half-angle asin(1 / 3.04) < acos(0.93)
    CheckSampling(light, Point3f(0, 0, 0), Point3f(0.5f, 0, 3), 0.93f);
}

TEST(DiffuseAreaLight, DiskSamplingChiSquare) {
    Scene s;
    Shape disk = s.MakeDisk(Translate(Vector3f(0, 0, 2)) * Rotate(50, Vector3f(1, 0, 0)), 1);
    Light light = s.Area(disk, {BoolParam("twosided", true)});
    CheckSampling(light, Point3f(0, 0, 0), Point3f(0, 0, 2), 0.85f);
}

TEST(DiffuseAreaLight, TriangleSamplingChiSquare) {
    Scene s;
    // Large enough for spherical triangle sampling...
    Light big = s.Area(s.MakeTriangle(Point3f(-1, -1, 2), Point3f(1, -1, 2), Point3f(0, 1, 2)),
                       {BoolParam("twosided", true)});
    CheckSampling(big, Point3f(0, 0, 0), Point3f(0, 0, 2), 0.7f);
    // ...and small enough for area sampling
    Light small = s.Area(
        s.MakeTriangle(Point3f(-.01f, -.01f, 2), Point3f(.01f, -.01f, 2), Point3f(0, .01f, 2)),
        {BoolParam("twosided", true)});
    CheckSampling(small, Point3f(0, 0, 0), Point3f(0, 0, 2), 0.99995f);
}

TEST(DiffuseAreaLight, DefaultEmissionHasUnitLuminance) {
    Scene s;
    Light light = s.Area(s.MakeSphere(Point3f(0, 0, 0), 1), {FloatParam("float", "scale", {3})});
    double Y = LuminanceOf([&](const SampledWavelengths& lambda) {
        return Lat(light, Point3f(0, 0, 1), Normal3f(0, 0, 1), Point2f(), Vector3f(0, 0, 1),
                   lambda);
    });
    EXPECT_NEAR(Y, 3, 3e-3);
}

TEST(DiffuseAreaLight, PowerGivesRequestedLuminousPower) {
    Scene s;
    Shape disk = s.MakeDisk(Transform(), 2);  // area 4 pi
    ASSERT_NEAR(disk.Area(), 4 * Pi, 1e-4);
    for (bool twoSided : {false, true})
        for (bool blackbody : {false, true}) {
            ParsedParameterVector params = {FloatParam("float", "power", {100}),
                                            BoolParam("twosided", twoSided)};
            if (blackbody) params.push_back(FloatParam("blackbody", "L", {2700}));
            Light light = s.Area(disk, params);
            double Y = LuminanceOf([&](const SampledWavelengths& l) { return light.Phi(l); });
            EXPECT_NEAR(Y, 100, 0.1) << "twosided " << twoSided << " blackbody " << blackbody;
            // Radiance then is power / (pi A (2 if two-sided))
            double YL = LuminanceOf([&](const SampledWavelengths& l) {
                return Lat(light, Point3f(), Normal3f(0, 0, 1), Point2f(), Vector3f(0, 0, 1), l);
            });
            EXPECT_NEAR(YL, 100 / (Pi * 4 * Pi * (twoSided ? 2 : 1)), 1e-3);
        }
}

TEST(DiffuseAreaLight, BlackbodyIsNormalisedToUnitLuminance) {
    Scene s;
    Light light = s.Area(s.MakeDisk(Transform(), 1), {FloatParam("blackbody", "L", {1500})});
    double Y = LuminanceOf([&](const SampledWavelengths& l) {
        return Lat(light, Point3f(), Normal3f(0, 0, 1), Point2f(), Vector3f(0, 0, 1), l);
    });
    EXPECT_NEAR(Y, 1, 2e-3);
}

TEST(DiffuseAreaLight, TwoSided) {
    Scene s;
    Shape disk = s.MakeDisk(Transform(), 1);
    Light one = s.Area(disk, {});
    Light two = s.Area(disk, {BoolParam("twosided", true)});
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    Normal3f n(0, 0, 1);
    Vector3f up = Normalize(Vector3f(0.3f, 0, 1)), down = Normalize(Vector3f(0.3f, 0, -1));
    EXPECT_TRUE(bool(Lat(one, Point3f(), n, Point2f(), up, lambda)));
    EXPECT_FALSE(bool(Lat(one, Point3f(), n, Point2f(), down, lambda)));
    EXPECT_EQ(Lat(two, Point3f(), n, Point2f(), up, lambda),
              Lat(two, Point3f(), n, Point2f(), down, lambda));
    EXPECT_EQ(Lat(two, Point3f(), n, Point2f(), down, lambda),
              Lat(one, Point3f(), n, Point2f(), up, lambda));
    SampledSpectrum ratio = SafeDiv(two.Phi(lambda), one.Phi(lambda));
    for (int i = 0; i < NSpectrumSamples; ++i) EXPECT_FLOAT_EQ(ratio[i], 2);
    // From below, a one-sided disk facing up sends nothing
    LightSampleContext below(Point3f(0, 0, -2), Normal3f(), Normal3f());
    EXPECT_FALSE(one.SampleLi(below, Point2f(0.3f, 0.6f), lambda).has_value());
    EXPECT_TRUE(two.SampleLi(below, Point2f(0.3f, 0.6f), lambda).has_value());
}

TEST(DiffuseAreaLight, ZeroAreaShapeIsHarmless) {
    Scene s;
    Shape disk = s.MakeDisk(Transform(), 0);
    Light light = s.Area(disk, {FloatParam("float", "power", {10})});
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    SampledSpectrum phi = light.Phi(lambda);
    EXPECT_FALSE(phi.HasNaN());
    EXPECT_FALSE(bool(phi));
    LightSampleContext ctx(Point3f(0, 0, 1), Normal3f(), Normal3f());
    auto ls = light.SampleLi(ctx, Point2f(0.5f, 0.5f), lambda);
    if (ls) {
        EXPECT_FALSE(ls->L.HasNaN() || std::isnan(ls->pdf));
    }
    EXPECT_FALSE(std::isnan(light.PDF_Li(ctx, Vector3f(0, 0, -1))));
}

TEST(DiffuseAreaLight, CreateRejectsUnknownTypeAndLWithFilename) {
    Scene s;
    Shape disk = s.MakeDisk(Transform(), 1);
    ParameterDictionary dict({}, nullptr);
    EXPECT_THROW(Light::CreateArea("glow", dict, Transform(), disk, FileLoc(), s.arena, s.diag),
                 SceneError);
    ParameterDictionary both({FloatParam("rgb", "L", {1, 1, 1}), StringParam("filename", "x.exr")},
                             nullptr);
    EXPECT_THROW(Light::CreateArea("diffuse", both, Transform(), disk, FileLoc(), s.arena, s.diag),
                 SceneError);
}

// pbrt-v4's invisible area lights: on a shape whose alpha is the constant 0 the light emits
// over the whole shape and is sampled without MIS (type DeltaPosition); alpha textures that
// merely evaluate to 0 cut the light out.
TEST(DiffuseAreaLight, ConstantZeroAlphaMakesAnInvisibleLight) {
    struct ConstantAlpha : AlphaMask {
        Float a;
        bool constant;
        ConstantAlpha(Float a, bool constant) : a(a), constant(constant) {}
        Float Alpha(const SurfaceInteraction&) const override { return a; }
        bool IsConstantZero() const override { return constant && a == 0; }
    };
    Scene s;
    Shape disk = s.MakeDisk(Translate(Vector3f(0, 0, 1)), 0.5f);
    ParameterDictionary dict(ParsedParameterVector{}, nullptr);
    ConstantAlpha invisible(0, true), cutOut(0, false);
    Light lInvisible = Light::CreateArea("diffuse", dict, Transform(), disk, FileLoc(), s.arena,
                                         s.diag, &invisible);
    Light lCutOut =
        Light::CreateArea("diffuse", dict, Transform(), disk, FileLoc(), s.arena, s.diag, &cutOut);
    EXPECT_EQ(lInvisible.Type(), LightType::DeltaPosition);
    EXPECT_EQ(lCutOut.Type(), LightType::Area);
    // Above the disk, on the side its normal (+z) emits to
    LightSampleContext ctx(Point3f(0, 0, 2), Normal3f(0, 0, -1), Normal3f(0, 0, -1));
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    int lit = 0, cut = 0;
    for (int i = 0; i < 64; ++i) {
        Point2f u((i % 8 + 0.5f) / 8, (i / 8 + 0.5f) / 8);
        auto a = lInvisible.SampleLi(ctx, u, lambda), b = lCutOut.SampleLi(ctx, u, lambda);
        lit += a && a->L;
        cut += b && b->L;
    }
    EXPECT_EQ(lit, 64);
    EXPECT_EQ(cut, 0);
}
