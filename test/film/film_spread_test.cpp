// Spread reconstruction (RGBFilm::SpreadSample, PixelReconstruction::Spread): a sample counts
// for every pixel of the bounds whose centre lies within the filter's radius, with the filter's
// weight there, and a pixel is the weighted mean of its samples; the choice of reconstruction
// and the margin of pixels whose samples reach the bounds.
#include <gtest/gtest.h>

#include "film_test_util.h"

namespace kiln {
namespace {

TEST(FilmSpread, ASampleCountsForThePixelsWithinTheRadiusWithTheFilterWeights) {
    FilmFixture f;
    TriangleFilter tri(Vector2f(1.5f, 1.5f));
    f.filter = Filter(&tri);
    RGBFilm* film = f.Make(SmallRes());
    ASSERT_EQ(film->Reconstruction(), PixelReconstruction::Spread);
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.6f);
    film->SpreadSample(Point2f(4.5f, 2.f), SampledSpectrum(1.f), lambda, nullptr);
    // One sample: every pixel it reaches shows it, the others nothing
    Float one = film->GetPixelRGB({4, 1}).g;
    EXPECT_GT(one, 0);
    for (Point2i p : {Point2i(3, 1), Point2i(5, 2), Point2i(3, 2), Point2i(5, 1)})
        EXPECT_NEAR(film->GetPixelRGB(p).g, one, 1e-5f * one) << p.x << "," << p.y;
    // (beyond the radius, or on it where the triangle is 0)
    for (Point2i p : {Point2i(2, 1), Point2i(6, 2), Point2i(4, 0), Point2i(4, 3)})
        EXPECT_EQ(film->GetPixelRGB(p).g, 0) << p.x << "," << p.y;
    // A second sample of three times the radiance: pixel (4, 1) (centre 4.5, 1.5) weighs the
    // first by (1.5 - 0)(1.5 - 0.5) = 1.5 and the second, at (3.5, 1.5), by (1.5 - 1)(1.5 - 0)
    // = 0.75
    film->SpreadSample(Point2f(3.5f, 1.5f), SampledSpectrum(3.f), lambda, nullptr);
    EXPECT_NEAR(film->GetPixelRGB({4, 1}).g, one * (1.5f * 1 + 0.75f * 3) / 2.25f, 1e-5f * one);
    // Pixel (2, 1) sees only the second; (5, 2) only the first
    EXPECT_NEAR(film->GetPixelRGB({2, 1}).g, 3 * one, 1e-5f * one);
    EXPECT_NEAR(film->GetPixelRGB({5, 2}).g, one, 1e-5f * one);
}

TEST(FilmSpread, ANonFiniteSampleIsCountedOnceAndReachesNoPixel) {
    FilmFixture f;
    GaussianFilter gauss(Vector2f(1.5f, 1.5f));
    f.filter = Filter(&gauss);
    RGBFilm* film = f.Make(SmallRes());
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.4f);
    SampledSpectrum bad(1.f);
    bad[1] = std::numeric_limits<Float>::quiet_NaN();
    film->SpreadSample(Point2f(2.2f, 1.7f), bad, lambda, nullptr);
    EXPECT_EQ(film->NonFiniteSampleCount(), 1);
    ASSERT_TRUE(film->FirstNonFinitePixel());
    EXPECT_EQ(*film->FirstNonFinitePixel(), Point2i(2, 1));
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) EXPECT_EQ(film->GetPixelRGB({x, y}).g, 0);
}

TEST(FilmSpread, TheReconstructionIsChosenOnceAtCreation) {
    FilmFixture f;
    GaussianFilter gauss(Vector2f(1.5f, 1.5f));
    f.filter = Filter(&gauss);
    // Default: spread, with the pixels up to the radius beyond the bounds sampled, which the
    // sampler must tell apart
    RGBFilm* film = f.Make(SmallRes());
    EXPECT_EQ(film->Reconstruction(), PixelReconstruction::Spread);
    EXPECT_EQ(film->SpreadMargin(), Vector2i(1, 1));
    EXPECT_EQ(film->SpreadPixelBounds().pMin, Point2i(-1, -1));
    EXPECT_EQ(film->SpreadPixelBounds().pMax, Point2i(9, 5));
    EXPECT_EQ(film->SamplerResolution(), Point2i(10, 6));
    // "importance": pbrt-v4's filter importance sampling, no margin
    ParsedParameterVector p = SmallRes();
    p.push_back(Param("string", "reconstruction", {}, {}, {"importance"}));
    film = f.Make(p);
    EXPECT_EQ(film->Reconstruction(), PixelReconstruction::FilterImportance);
    EXPECT_EQ(film->SpreadMargin(), Vector2i(0, 0));
    EXPECT_EQ(film->SamplerResolution(), Point2i(8, 4));
    // A film with AOV layers keeps pbrt-v4's per-pixel statistics unless told otherwise
    EXPECT_EQ(f.Make(SmallRes(), "gbuffer")->Reconstruction(),
              PixelReconstruction::FilterImportance);
    // A filter wider than kMaxSpreadRadius is importance-sampled whatever is asked
    GaussianFilter wide(Vector2f(6, 1.5f));
    f.filter = Filter(&wide);
    EXPECT_EQ(f.Make(SmallRes())->Reconstruction(), PixelReconstruction::FilterImportance);
    // A box narrower than a pixel too: most samples spread over the pixel would reach no
    // pixel centre
    BoxFilter narrow(Vector2f(0.5f, 0.1f));
    f.filter = Filter(&narrow);
    EXPECT_EQ(f.Make(SmallRes())->Reconstruction(), PixelReconstruction::FilterImportance);
    BoxFilter pixel(Vector2f(0.5f, 0.5f));
    f.filter = Filter(&pixel);
    EXPECT_EQ(f.Make(SmallRes())->Reconstruction(), PixelReconstruction::Spread);
    EXPECT_EQ(f.Make(SmallRes())->SpreadMargin(), Vector2i(0, 0));
    // The triangle's radius 2 reaches two pixels beyond
    TriangleFilter tri(Vector2f(2, 2));
    f.filter = Filter(&tri);
    EXPECT_EQ(f.Make(SmallRes())->SpreadMargin(), Vector2i(2, 2));
    // An unknown reconstruction names itself
    ParsedParameterVector bad = SmallRes();
    bad.push_back(Param("string", "reconstruction", {}, {}, {"splat"}));
    try {
        f.Make(bad);
        ADD_FAILURE() << "no error";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("splat"), std::string::npos) << e.what();
    }
}

TEST(FilmSpread, RequestsOverrideTheSceneAndJitterOffKeepsSamplesInTheirPixel) {
    FilmFixture f;
    GaussianFilter gauss(Vector2f(1.5f, 1.5f));
    f.filter = Filter(&gauss);
    ParameterDictionary dict(SmallRes(), nullptr);
    RGBFilm::Request request;
    request.reconstruction = PixelReconstruction::FilterImportance;
    EXPECT_EQ(
        RGBFilm::Create("rgb", dict, 1, f.filter, nullptr, FileLoc(), f.arena, f.diag, request)
            ->Reconstruction(),
        PixelReconstruction::FilterImportance);
    RGBFilm::Request noJitter;
    noJitter.pixelJitter = false;
    EXPECT_EQ(
        RGBFilm::Create("rgb", dict, 1, f.filter, nullptr, FileLoc(), f.arena, f.diag, noJitter)
            ->Reconstruction(),
        PixelReconstruction::FilterImportance);
}

}  // namespace
}  // namespace kiln
