// The gbuffer film's layers (pbrt-v4's GBufferFilm): channel list, output spaces, averaging
// and the per-pixel variance of the sensor RGB.
#include "core/film/gbuffer_layers.h"

#include <gtest/gtest.h>

#include "core/film/film.h"
#include "core/parser/parameter_dictionary.h"
#include "film_test_util.h"

namespace kiln {
namespace {

RGBFilm* MakeGBuffer(FilmFixture& f, const std::string& space, const RGBFilm::Request& request) {
    ParsedParameterVector params = SmallRes();
    if (!space.empty()) params.push_back(Param("string", "coordinatesystem", {}, {}, {space}));
    ParameterDictionary dict(std::move(params), nullptr);
    return RGBFilm::Create("gbuffer", dict, 1, f.filter, &RGBColorSpace::sRGB(), FileLoc(), f.arena,
                           f.diag, request);
}

Float Channel(const Image& im, Point2i p, const char* name) {
    int c = im.ChannelIndex(name);
    EXPECT_GE(c, 0) << name;
    return im.GetChannel(p, c);
}

TEST(GBufferFilm, ChannelsAreThoseOfPbrtV4) {
    FilmFixture f;
    Image im = MakeGBuffer(f, "", {})->GetImage(nullptr);
    std::vector<std::string> expected = {"R",
                                         "G",
                                         "B",
                                         "Albedo.R",
                                         "Albedo.G",
                                         "Albedo.B",
                                         "P.X",
                                         "P.Y",
                                         "P.Z",
                                         "dzdx",
                                         "dzdy",
                                         "N.X",
                                         "N.Y",
                                         "N.Z",
                                         "Ns.X",
                                         "Ns.Y",
                                         "Ns.Z",
                                         "u",
                                         "v",
                                         "Variance.R",
                                         "Variance.G",
                                         "Variance.B",
                                         "RelativeVariance.R",
                                         "RelativeVariance.G",
                                         "RelativeVariance.B"};
    EXPECT_EQ(im.ChannelNames(), expected);
}

TEST(GBufferFilm, CameraAndWorldSpaces) {
    // Render space = world moved by -(1, 2, 3); the camera is rotated 90 degrees about y.
    Transform cameraFromRender = Rotate(90, Vector3f(0, 1, 0)),
              worldFromRender = Translate(Vector3f(1, 2, 3));
    RGBFilm::Request request;
    request.cameraFromRender = cameraFromRender;
    request.worldFromRender = worldFromRender;
    VisibleSurface vs;
    vs.set = true;
    vs.p = Point3f(0.5f, -1, 2);
    vs.n = Normal3f(1, 0, 0);
    vs.ns = Normal3f(0, 1, 0);
    vs.uv = Point2f(0.25f, 0.75f);
    vs.dpdx = Vector3f(0.1f, 0, 0);
    vs.dpdy = Vector3f(0, 0, -0.2f);
    vs.albedo = SampledSpectrum(1.f);
    for (const char* space : {"camera", "world"}) {
        FilmFixture f;
        RGBFilm* film = MakeGBuffer(f, space, request);
        const Transform& t = std::string(space) == "camera" ? cameraFromRender : worldFromRender;
        SampledWavelengths lambda = film->SampleWavelengths(0.5f);
        // Two samples with a surface, one escaped: geometry averages over the two, albedo
        // over all three (pbrt-v4)
        film->AddSample({2, 1}, SampledSpectrum(1.f), lambda, &vs, 1);
        film->AddSample({2, 1}, SampledSpectrum(1.f), lambda, &vs, 1);
        film->AddSample({2, 1}, SampledSpectrum(1.f), lambda, nullptr, 1);
        Image im = film->GetImage(nullptr);
        Point2i px(2, 1);
        Point3f p = t(vs.p);
        Normal3f n = t(vs.n), ns = t(vs.ns);
        EXPECT_NEAR(Channel(im, px, "P.X"), p.x, 1e-5f) << space;
        EXPECT_NEAR(Channel(im, px, "P.Y"), p.y, 1e-5f) << space;
        EXPECT_NEAR(Channel(im, px, "P.Z"), p.z, 1e-5f) << space;
        EXPECT_NEAR(Channel(im, px, "N.X"), n.x, 1e-5f) << space;
        EXPECT_NEAR(Channel(im, px, "N.Z"), n.z, 1e-5f) << space;
        EXPECT_NEAR(Channel(im, px, "Ns.Y"), ns.y, 1e-5f) << space;
        EXPECT_NEAR(Channel(im, px, "dzdx"), std::abs(t(vs.dpdx).z), 1e-5f) << space;
        EXPECT_NEAR(Channel(im, px, "dzdy"), std::abs(t(vs.dpdy).z), 1e-5f) << space;
        EXPECT_NEAR(Channel(im, px, "u"), 0.25f, 1e-6f);
        EXPECT_NEAR(Channel(im, px, "v"), 0.75f, 1e-6f);
        // A unit albedo is RGB (1, 1, 1) under the illuminant; 2 of 3 samples hit
        EXPECT_NEAR(Channel(im, px, "Albedo.G"), 2.f / 3, 0.02f);
        // Pixels without samples: zeros
        EXPECT_EQ(Channel(im, {0, 0}, "N.Z"), 0);
        EXPECT_EQ(Channel(im, {0, 0}, "P.Z"), 0);
    }
    // Camera space is the default
    FilmFixture f;
    RGBFilm* film = MakeGBuffer(f, "", request);
    film->AddSample({0, 0}, SampledSpectrum(1.f), film->SampleWavelengths(0.5f), &vs, 1);
    EXPECT_NEAR(Channel(film->GetImage(nullptr), {0, 0}, "P.Z"), cameraFromRender(vs.p).z, 1e-5f);
}

TEST(GBufferFilm, UnknownCoordinateSystemIsAnError) {
    FilmFixture f;
    EXPECT_THROW(MakeGBuffer(f, "screen", {}), SceneError);
}

TEST(GBufferFilm, VarianceOfSensorRGB) {
    // Sample variance (n - 1) of the unweighted sensor RGB of the samples with a surface, and
    // the variance over the mean, per channel (pbrt-v4's VarianceEstimator).
    FilmFixture f;
    RGBFilm* film = MakeGBuffer(f, "", {});
    VisibleSurface vs;
    vs.set = true;
    vs.n = vs.ns = Normal3f(0, 0, 1);
    SampledWavelengths lambda = film->SampleWavelengths(0.3f);
    RGB k = film->Sensor().ToSensorRGB(SampledSpectrum(1.f), lambda);
    const Float values[] = {1, 3, 2, 6};
    for (Float v : values) film->AddSample({1, 1}, SampledSpectrum(v), lambda, &vs, 0.5f + v);
    film->AddSample({1, 1}, SampledSpectrum(100.f), lambda, nullptr, 1);  // escaped: not counted
    Image im = film->GetImage(nullptr);
    // mean 3, squared deviations 4 + 0 + 1 + 9 = 14, / 3
    const double var = 14.0 / 3, mean = 3;
    const char* names[3][2] = {{"Variance.R", "RelativeVariance.R"},
                               {"Variance.G", "RelativeVariance.G"},
                               {"Variance.B", "RelativeVariance.B"}};
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(Channel(im, {1, 1}, names[c][0]), var * k[c] * k[c], 1e-4 * var * k[c] * k[c]);
        EXPECT_NEAR(Channel(im, {1, 1}, names[c][1]), var / mean * k[c], 1e-4 * var / mean * k[c]);
    }
    // One sample: no variance
    film->AddSample({2, 2}, SampledSpectrum(1.f), lambda, &vs, 1);
    EXPECT_EQ(Channel(film->GetImage(nullptr), {2, 2}, "Variance.G"), 0);
}

TEST(GBufferFilm, CheckpointStateKeepsTheLayers) {
    // A film resumed from SaveState writes the same gbuffer channels, variance included
    FilmFixture f;
    RGBFilm* a = MakeGBuffer(f, "", {});
    RGBFilm* b = MakeGBuffer(f, "", {});
    VisibleSurface vs;
    vs.set = true;
    vs.p = Point3f(1, 2, 3);
    vs.n = vs.ns = Normal3f(0, 0, 1);
    vs.uv = Point2f(0.5f, 0.25f);
    vs.dpdx = Vector3f(0, 0, 0.1f);
    vs.albedo = SampledSpectrum(0.5f);
    SampledWavelengths lambda = a->SampleWavelengths(0.7f);
    for (Float v : {1.f, 2.f, 4.f}) a->AddSample({3, 2}, SampledSpectrum(v), lambda, &vs, 1);
    ASSERT_TRUE(b->LoadState(a->SaveState()));
    Image ia = a->GetImage(nullptr), ib = b->GetImage(nullptr);
    for (int c = 0; c < ia.NChannels(); ++c)
        EXPECT_EQ(ia.GetChannel({3, 2}, c), ib.GetChannel({3, 2}, c)) << ia.ChannelNames()[c];
    EXPECT_GT(Channel(ib, {3, 2}, "Variance.G"), 0);
    // An rgb film's state does not load into a gbuffer film
    RGBFilm* plain = f.Make(SmallRes());
    EXPECT_FALSE(b->LoadState(plain->SaveState()));
}

}  // namespace
}  // namespace kiln
