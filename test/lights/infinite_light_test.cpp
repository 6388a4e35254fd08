// Infinite lights: uniform
// environment radiance, and chi-square tests of the image light's direction sampling for both
// mappings (full and compensated distributions).
#include <gtest/gtest.h>

#include "base/object_arena.h"
#include "base/sampling.h"
#include "base/sphere_mappings.h"
#include "core/parser/diagnostics.h"
#include "light_test_util.h"
#include "lights/light.h"
#include "spectral/color.h"

using namespace kiln;
using namespace kiln::testing;

namespace {

// A small synthetic environment with a bright spot, a dim region and a black one.
Image SyntheticImage(int w, int h) {
    Image image(PixelFormat::Float, {w, h}, {"R", "G", "B"});
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            Float v = 0.2f + 0.1f * ((x * 7 + y * 3) % 5);
            if (x == w / 4 && y == h / 3) v = 20;
            if (y == h - 1) v = 0;
            image.SetChannel({x, y}, 0, v);
            image.SetChannel({x, y}, 1, 0.5f * v);
            image.SetChannel({x, y}, 2, 2 * v);
        }
    return image;
}

void CheckImageSampling(const Image& image, bool compensated) {
    Transform renderFromLight = Rotate(30, Vector3f(1, 1, 0));
    ImageInfiniteLight env(renderFromLight, image, &RGBColorSpace::sRGB(), 1);
    env.Preprocess(Bounds3f(Point3f(-1, -1, -1), Point3f(1, 1, 1)));
    LightSampleContext ctx(Point3f(0.2f, 0, 0), Normal3f(), Normal3f());
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.4f);
    auto sample = [&](Point2f u) -> std::optional<DirectionSample> {
        auto ls = env.SampleLi(ctx, u, lambda, compensated);
        if (!ls) return std::nullopt;
        return DirectionSample{ls->wi, ls->pdf};
    };
    auto pdf = [&](Vector3f w) { return env.PDF_Li(ctx, w, compensated); };
    ChiSquareResult r =
        DirectionChiSquare(sample, pdf, Vector3f(0, 0, 1), -1, 300000, 4, 24, 48, 64);
    EXPECT_TRUE(r.passed) << r.message;
}

}  // namespace

TEST(UniformInfiniteLight, LeIsLAndSampling) {
    UniformInfiniteLight light(Transform(), Spectrum(ConstantSpectrum(3)), 2);
    Light l(&light);
    l.Preprocess(Bounds3f(Point3f(0, 0, 0), Point3f(2, 0, 0)));
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.7f);
    EXPECT_EQ(l.Le(Ray(Point3f(), Vector3f(0.3f, -1, 0.2f)), lambda), SampledSpectrum(6));
    LightSampleContext ctx(Point3f(1, 0, 0), Normal3f(), Normal3f());
    auto ls = l.SampleLi(ctx, Point2f(0.2f, 0.9f), lambda);
    ASSERT_TRUE(ls.has_value());
    EXPECT_EQ(ls->L, SampledSpectrum(6));
    EXPECT_FLOAT_EQ(ls->pdf, Inv4Pi);
    EXPECT_FLOAT_EQ(l.PDF_Li(ctx, ls->wi), Inv4Pi);
    EXPECT_FALSE(l.SampleLi(ctx, Point2f(0.2f, 0.9f), lambda, true).has_value());
    EXPECT_EQ(l.PDF_Li(ctx, ls->wi, true), 0);
    EXPECT_FLOAT_EQ(l.Phi(lambda)[0], 4 * Pi * Pi * 1 * 6);
}

TEST(UniformInfiniteLight, CreateDefaultsToUnitLuminance) {
    ObjectArena arena;
    Diagnostics diag(nullptr);
    ParameterDictionary dict({FloatParam("float", "illuminance", {Pi * 2})}, nullptr);
    auto light = Light::Create("infinite", dict, Transform(), FileLoc(), arena, diag);
    ASSERT_TRUE(light.has_value());
    ASSERT_TRUE(light->Is<UniformInfiniteLight>());
    double Y = LuminanceOf([&](const SampledWavelengths& l) {
        return light->Le(Ray(Point3f(), Vector3f(0, 0, 1)), l);
    });
    EXPECT_NEAR(Y, 2, 2e-3);
}

TEST(ImageInfiniteLight, OctahedralSamplingChiSquare) {
    CheckImageSampling(SyntheticImage(8, 8), false);
    CheckImageSampling(SyntheticImage(8, 8), true);
}

TEST(ImageInfiniteLight, EquirectSamplingChiSquare) {
    CheckImageSampling(SyntheticImage(16, 8), false);
    CheckImageSampling(SyntheticImage(16, 8), true);
}

TEST(ImageInfiniteLight, LeLooksUpTheMapping) {
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    Image image = SyntheticImage(16, 8);
    ImageInfiniteLight equirect(Transform(), image, &RGBColorSpace::sRGB(), 1);
    EXPECT_EQ(equirect.Mapping(), EnvironmentMapping::Equirectangular);
    // Straight down (-z) is the bottom row, which is black; straight up is row 0
    EXPECT_FALSE(bool(equirect.Le(Ray(Point3f(), Vector3f(0, 0, -1)), lambda)));
    RGB top(image.GetChannel({0, 0}, 0), image.GetChannel({0, 0}, 1), image.GetChannel({0, 0}, 2));
    SampledSpectrum expected = RGBIlluminantSpectrum(RGBColorSpace::sRGB(), top).Sample(lambda);
    SampledSpectrum got = equirect.Le(Ray(Point3f(), Vector3f(0.001f, 0, 1)), lambda);
    for (int i = 0; i < NSpectrumSamples; ++i) EXPECT_NEAR(got[i], expected[i], 1e-4);
    ImageInfiniteLight octa(Transform(), SyntheticImage(8, 8), &RGBColorSpace::sRGB(), 1);
    EXPECT_EQ(octa.Mapping(), EnvironmentMapping::EqualAreaOctahedral);
    EXPECT_THROW(ImageInfiniteLight(Transform(), SyntheticImage(8, 5), &RGBColorSpace::sRGB(), 1),
                 std::invalid_argument);
}

TEST(ImageInfiniteLight, PhiOfConstantMapMatchesUniformLight) {
    Image image(PixelFormat::Float, {16, 8}, {"R", "G", "B"});
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x)
            for (int c = 0; c < 3; ++c) image.SetChannel({x, y}, c, 1);
    Bounds3f bounds(Point3f(-1, -1, -1), Point3f(1, 1, 1));
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    RGBIlluminantSpectrum white(RGBColorSpace::sRGB(), RGB(1, 1, 1));
    UniformInfiniteLight uniform(Transform(), Spectrum(white), 1);
    uniform.Preprocess(bounds);
    for (Point2i res : {Point2i(16, 8), Point2i(8, 8)}) {
        Image im(PixelFormat::Float, res, {"R", "G", "B"});
        for (int y = 0; y < res.y; ++y)
            for (int x = 0; x < res.x; ++x)
                for (int c = 0; c < 3; ++c) im.SetChannel({x, y}, c, 1);
        ImageInfiniteLight env(Transform(), im, &RGBColorSpace::sRGB(), 1);
        env.Preprocess(bounds);
        for (int i = 0; i < NSpectrumSamples; ++i)
            EXPECT_NEAR(env.Phi(lambda)[i], uniform.Phi(lambda)[i], 1e-4 * uniform.Phi(lambda)[i]);
    }
}

// pbrt-v4 compatibility under transforms that change lengths (a scale, a projective matrix):
// samples report the length of pbrt-v4's unnormalised direction and PDF_Li looks the map up
// with the unnormalised light-space direction; rotations keep everything unit.
TEST(ImageInfiniteLight, TransformsThatChangeLengthsAsPbrtV4) {
    Image image = SyntheticImage(8, 8);
    Bounds3f bounds(Point3f(-1, -1, -1), Point3f(1, 1, 1));
    LightSampleContext ctx(Point3f(0.2f, 0, 0), Normal3f(), Normal3f());
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.4f);
    ImageInfiniteLight rotated(Rotate(30, Vector3f(1, 1, 0)), image, &RGBColorSpace::sRGB(), 1);
    EXPECT_TRUE(rotated.PreservesLengths());
    Transform scale = Scale(2, 2, 2);
    ImageInfiniteLight scaled(scale, image, &RGBColorSpace::sRGB(), 1);
    EXPECT_FALSE(scaled.PreservesLengths());
    EXPECT_TRUE(Light(&scaled).HasUnnormalizedSamples());
    EXPECT_FALSE(Light(&rotated).HasUnnormalizedSamples());
    for (ImageInfiniteLight* env : {&rotated, &scaled}) {
        env->Preprocess(bounds);
        std::optional<LightLiSample> ls = env->SampleLi(ctx, Point2f(0.3f, 0.6f), lambda);
        ASSERT_TRUE(ls);
        EXPECT_NEAR(Length(ls->wi), 1, 1e-5f);
        EXPECT_NEAR(ls->wiLength, env == &scaled ? 2 : 1, 1e-5f);
    }
    // PDF_Li of a direction straight up: the light-space vector (0, 0, 1/2) maps, unnormalised,
    // to the square's point of height 1/2, not to its centre (the pole)
    Vector3f up(0, 0, 1);
    Float pdfScaled = scaled.PDF_Li(ctx, up), pdfRotated;
    Point2f st = EqualAreaSphereToSquare(Vector3f(0, 0, 0.5f));
    ImageInfiniteLight identity(Transform(), image, &RGBColorSpace::sRGB(), 1);
    identity.Preprocess(bounds);
    pdfRotated = identity.PDF_Li(ctx, EqualAreaSquareToSphere(st));
    EXPECT_NEAR(pdfScaled, pdfRotated, 1e-4f * pdfRotated);
}
