// Film splats (RGBFilm::AddSplat, pbrt-v4's): a splat lands in the pixels the filter covers,
// weighted by the filter and divided by its integral on output, scaled by SetSplatScale, added
// to the pixel's samples; concurrent splats all count; checkpoint state keeps them.
#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "film_test_util.h"

namespace kiln {
namespace {

TEST(FilmSplat, BoxFilterLandsInOnePixelAndScales) {
    FilmFixture f;
    RGBFilm* film = f.Make(SmallRes());
    film->EnableSplats();
    ASSERT_TRUE(film->HasSplats());
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.3f);
    SampledSpectrum L(2.f);
    film->AddSplat(Point2f(3.25f, 1.75f), L, lambda);
    RGB once = film->GetPixelRGB({3, 1});
    EXPECT_GT(once.g, 0);
    EXPECT_EQ(film->GetPixelRGB({2, 1}).g, 0);
    EXPECT_EQ(film->GetPixelRGB({3, 2}).g, 0);
    // A sample in the same pixel adds its mean; the splat scale divides the splats alone
    film->AddSample({3, 1}, L, lambda, nullptr, 1);
    RGB both = film->GetPixelRGB({3, 1});
    film->SetSplatScale(0.5);
    RGB half = film->GetPixelRGB({3, 1});
    EXPECT_NEAR(both.g - half.g, 0.5f * once.g, 1e-5f * both.g);
    EXPECT_NEAR(both.g, 2 * once.g, 1e-5f * both.g);  // the sample's mean equals one splat
}

TEST(FilmSplat, WideFilterSpreadsWithItsWeights) {
    FilmFixture f;
    TriangleFilter tri(Vector2f(1.5f, 1.5f));
    f.filter = Filter(&tri);
    RGBFilm* film = f.Make(SmallRes());
    film->EnableSplats();
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.6f);
    film->AddSplat(Point2f(4.5f, 2.f), SampledSpectrum(1.f), lambda);
    // Pixel centres at x 3.5, 4.5, 5.5 and y 1.5, 2.5: weights (1.5 - |dx|)(1.5 - |dy|)
    Float g = film->GetPixelRGB({4, 1}).g;
    EXPECT_NEAR(film->GetPixelRGB({3, 1}).g / g, 0.5f / 1.5f, 1e-5f);
    EXPECT_NEAR(film->GetPixelRGB({4, 2}).g / g, 1, 1e-5f);
    EXPECT_EQ(film->GetPixelRGB({6, 1}).g, 0);
}

TEST(FilmSplat, ConcurrentSplatsAllCount) {
    FilmFixture f;
    RGBFilm* film = f.Make(SmallRes());
    film->EnableSplats();
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    film->AddSplat(Point2f(1.5f, 1.5f), SampledSpectrum(1.f), lambda);
    Float one = film->GetPixelRGB({1, 1}).g;
    film->Clear();
    EXPECT_EQ(film->GetPixelRGB({1, 1}).g, 0);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
        threads.emplace_back([&] {
            for (int i = 0; i < 10000; ++i)
                film->AddSplat(Point2f(1.5f, 1.5f), SampledSpectrum(1.f), lambda);
        });
    for (std::thread& t : threads) t.join();
    EXPECT_NEAR(film->GetPixelRGB({1, 1}).g, 40000 * one, 1e-4f * 40000 * one);
}

TEST(FilmSplat, StateKeepsSplats) {
    FilmFixture f;
    RGBFilm* a = f.Make(SmallRes());
    a->EnableSplats();
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    a->AddSplat(Point2f(2.5f, 0.5f), SampledSpectrum(3.f), lambda);
    std::string state = a->SaveState();
    RGBFilm* b = f.Make(SmallRes());
    EXPECT_FALSE(b->LoadState(state));  // a film without splats does not take it
    b->EnableSplats();
    ASSERT_TRUE(b->LoadState(state));
    EXPECT_EQ(b->GetPixelRGB({2, 0}).g, a->GetPixelRGB({2, 0}).g);
    EXPECT_GT(b->GetPixelRGB({2, 0}).g, 0);
}

TEST(FilmSplat, NonFiniteSplatsAreDropped) {
    FilmFixture f;
    RGBFilm* film = f.Make(SmallRes());
    film->EnableSplats();
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    film->AddSplat(Point2f(2.5f, 0.5f), SampledSpectrum(std::nanf("")), lambda);
    EXPECT_EQ(film->NonFiniteSampleCount(), 1);
    EXPECT_EQ(film->GetPixelRGB({2, 0}).g, 0);
}

}  // namespace
}  // namespace kiln
