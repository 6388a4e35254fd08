// Goniometric and projection lights (pbrt-v4's): point lights whose intensity comes from an
// image. Their power against the integral of their intensity over the sphere (uniform
// directions, independent of Phi's sum over pixels), the orientation of the image about the
// light (the goniometric map's pole along the light's +y; the projector's top left pixel
// towards its -x and +y), "power" as luminous power, and bad input. (Emission sampling:
// emission_sampling_test.cpp; whole renders against pbrt-v4's: regression/pbrt_features.)
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>

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

std::optional<Light> CreateLight(const std::string& name, ParsedParameterVector params,
                                 ObjectArena& arena, Diagnostics& diag,
                                 const Transform& renderFromLight = Transform()) {
    ParameterDictionary dict(std::move(params), nullptr);
    return Light::Create(name, dict, renderFromLight, FileLoc(), arena, diag);
}

std::string TempFile(const std::string& name) { return ::testing::TempDir() + "/kiln_" + name; }

// Intensity of a delta light towards render-space direction w (unit), from a receiver at
// distance 2 along w
SampledSpectrum IntensityTowards(const Light& light, Point3f position, Vector3f w,
                                 const SampledWavelengths& lambda) {
    auto ls = light.SampleLi(LightSampleContext(position + Float(2) * w, {}, {}), {}, lambda);
    return ls ? ls->L * 4 : SampledSpectrum(0.f);
}

// The integral of the intensity over the sphere by uniform directions, and its standard error
// (averaged over the wavelengths)
std::pair<double, double> IntegratedIntensity(const Light& light, Point3f position, int n) {
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.4f);
    RNG rng(9);
    RunningStats s;
    for (int i = 0; i < n; ++i) {
        Vector3f w = SampleUniformSphere(Point2f(rng.UniformFloat(), rng.UniformFloat()));
        s.Add(IntensityTowards(light, position, w, lambda).Average() * 4 * Pi);
    }
    return {s.Mean(), s.StandardError()};
}

// A goniometric map: channels differing (the light takes their mean), bright towards the
// map's +z
Image GoniometricMap(int n) {
    Image image(PixelFormat::Float, {n, n}, {"R", "G", "B"});
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            Vector3f w = EqualAreaSquareToSphere(Point2f((x + 0.5f) / n, (y + 0.5f) / n));
            Float v = 0.1f + 2 * std::max<Float>(0, w.z) + 0.3f * ((x + y) % 3);
            image.SetChannel({x, y}, 0, 1.5f * v);
            image.SetChannel({x, y}, 1, v);
            image.SetChannel({x, y}, 2, 0.5f * v);
        }
    return image;
}

}  // namespace

TEST(GoniometricLight, PowerIsTheIntegralOfTheIntensity) {
    Transform t = Translate(Vector3f(1, -2, 0.5f)) * Rotate(35, Normalize(Vector3f(1, 2, 0.5f)));
    GoniometricLight gonio(t, Spectrum(ConstantSpectrum(2)), 0.7f,
                           GoniometricMap(16).SelectChannels({"G"}));
    Light light(&gonio);
    auto [integral, se] = IntegratedIntensity(light, Point3f(1, -2, 0.5f), 400000);
    double phi = light.Phi(SampledWavelengths::SampleVisible(0.4f)).Average();
    EXPECT_NEAR(integral, phi, 4 * se) << "se " << se;
    EXPECT_LT(4 * se, 0.01 * phi);
}

TEST(GoniometricLight, TheMapsPoleIsTheLightsY) {
    // A map lit only around its +z: the light shines along its +y, rotated into render space
    const int n = 16;
    Image image(PixelFormat::Float, {n, n}, {"Y"});
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            Vector3f w = EqualAreaSquareToSphere(Point2f((x + 0.5f) / n, (y + 0.5f) / n));
            image.SetChannel({x, y}, 0, w.z > 0.9f ? 1 : 0);
        }
    Transform rotation = Rotate(90, Vector3f(1, 0, 0));  // light +y -> render +z
    GoniometricLight gonio(rotation, Spectrum(ConstantSpectrum(1)), 1, image);
    Light light(&gonio);
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    EXPECT_FLOAT_EQ(IntensityTowards(light, Point3f(), Vector3f(0, 0, 1), lambda)[0], 1);
    for (Vector3f w :
         {Vector3f(0, 0, -1), Vector3f(0, 1, 0), Vector3f(0, -1, 0), Vector3f(1, 0, 0)})
        EXPECT_EQ(IntensityTowards(light, Point3f(), w, lambda)[0], 0) << w;
}

TEST(GoniometricLight, CreateReadsTheMapAndItsPower) {
    std::string rgbFile = TempFile("gonio_rgb.exr"), yFile = TempFile("gonio_y.exr"),
                flat = TempFile("gonio_flat.exr");
    Image map = GoniometricMap(16);
    map.Write(rgbFile);
    // The same map as one channel "Y" holding the mean of R, G, B (1.5 v + v + 0.5 v) / 3 = v
    Image luminance(PixelFormat::Float, map.Resolution(), {"Y"});
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) luminance.SetChannel({x, y}, 0, map.GetChannel({x, y}, 1));
    luminance.Write(yFile);
    Image(PixelFormat::Float, {32, 16}, {"Y"}).Write(flat);
    ObjectArena arena;
    std::ostringstream out;
    Diagnostics diag(&out);
    auto rgb = CreateLight("goniometric",
                           {StringParam("filename", rgbFile), FloatParam("float", "power", {40})},
                           arena, diag);
    auto y = CreateLight("goniometric",
                         {StringParam("filename", yFile), FloatParam("float", "power", {40})},
                         arena, diag);
    ASSERT_TRUE(rgb && y);
    for (const Light* l : {&*rgb, &*y}) {
        double Y = LuminanceOf([&](const SampledWavelengths& lambda) { return l->Phi(lambda); });
        EXPECT_NEAR(Y, 40, 0.05);
    }
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.3f);
    for (Vector3f w : {Vector3f(0, 1, 0), Normalize(Vector3f(1, -2, 3))})
        EXPECT_NEAR(IntensityTowards(*rgb, Point3f(), w, lambda)[1],
                    IntensityTowards(*y, Point3f(), w, lambda)[1],
                    1e-5f * IntensityTowards(*y, Point3f(), w, lambda)[1]);
    EXPECT_EQ(diag.WarningCount(), 0) << out.str();
    // No file: pbrt-v4 warns and the light emits nothing
    EXPECT_FALSE(CreateLight("goniometric", {}, arena, diag).has_value());
    EXPECT_EQ(diag.WarningCount(), 1);
    // Not an equal-area map
    EXPECT_THROW(CreateLight("goniometric", {StringParam("filename", flat)}, arena, diag),
                 SceneError);
    EXPECT_THROW(
        CreateLight("goniometric", {StringParam("filename", TempFile("missing.exr"))}, arena, diag),
        SceneError);
    for (const std::string& f : {rgbFile, yFile, flat}) std::remove(f.c_str());
}

// A 4 x 2 slide, white at its top left pixel only, or coloured
Image Slide(bool onePixel) {
    Image image(PixelFormat::Float, {4, 2}, {"R", "G", "B"});
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x)
            for (int c = 0; c < 3; ++c)
                image.SetChannel({x, y}, c,
                                 onePixel ? (x == 0 && y == 0) : 0.2f + 0.3f * x + 0.4f * y * c);
    return image;
}

TEST(ProjectionLight, PowerIsTheIntegralOfTheIntensity) {
    Transform t = Translate(Vector3f(0, 1, 0)) * Rotate(-25, Vector3f(0, 1, 0));
    ProjectionLight projector(t, Slide(false), &RGBColorSpace::sRGB(), 3, 70);
    Light light(&projector);
    auto [integral, se] = IntegratedIntensity(light, Point3f(0, 1, 0), 400000);
    double phi = light.Phi(SampledWavelengths::SampleVisible(0.4f)).Average();
    EXPECT_NEAR(integral, phi, 4 * se) << "se " << se;
    EXPECT_LT(4 * se, 0.02 * phi);
}

TEST(ProjectionLight, TopLeftPixelShinesTowardsMinusXPlusY) {
    // fov 60 across the shorter side (y); the screen spans x in [-2, 2], y in [-1, 1] at
    // tan 30 degrees per unit
    ProjectionLight projector(Transform(), Slide(true), &RGBColorSpace::sRGB(), 1, 60);
    Light light(&projector);
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    const Float t = std::tan(Radians(30.f));
    auto towards = [&](Float sx, Float sy) {
        return IntensityTowards(light, Point3f(), Normalize(Vector3f(sx * t, sy * t, 1)), lambda)
            .Average();
    };
    EXPECT_GT(towards(-1.7f, 0.6f), 0);  // the top left pixel: x in [-2, -1], y in [0, 1]
    EXPECT_EQ(towards(1.7f, 0.6f), 0);
    EXPECT_EQ(towards(-1.7f, -0.6f), 0);
    EXPECT_EQ(towards(-0.5f, 0.6f), 0);
    EXPECT_EQ(towards(-2.1f, 0.6f), 0);  // outside the image
    EXPECT_EQ(IntensityTowards(light, Point3f(), Vector3f(0, 0, -1), lambda).Average(), 0);
}

TEST(ProjectionLight, CreateReadsTheSlideAndItsPower) {
    std::string slide = TempFile("slide.exr"), grey = TempFile("slide_grey.exr");
    Slide(false).Write(slide);
    Image(PixelFormat::Float, {4, 4}, {"Y"}).Write(grey);
    ObjectArena arena;
    std::ostringstream out;
    Diagnostics diag(&out);
    auto light = CreateLight("projection",
                             {StringParam("filename", slide), FloatParam("float", "power", {25}),
                              FloatParam("float", "fov", {45})},
                             arena, diag);
    ASSERT_TRUE(light);
    double Y = LuminanceOf([&](const SampledWavelengths& lambda) { return light->Phi(lambda); });
    EXPECT_NEAR(Y, 25, 0.05);
    EXPECT_EQ(diag.WarningCount(), 0) << out.str();
    EXPECT_THROW(CreateLight("projection", {}, arena, diag), SceneError);
    EXPECT_THROW(CreateLight("projection", {StringParam("filename", grey)}, arena, diag),
                 SceneError);
    for (Float fov : {0.f, 180.f, -5.f, 1e-30f})
        EXPECT_THROW(
            CreateLight("projection",
                        {StringParam("filename", slide), FloatParam("float", "fov", {fov})}, arena,
                        diag),
            SceneError);
    for (const std::string& f : {slide, grey}) std::remove(f.c_str());
}
