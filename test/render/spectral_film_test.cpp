// pbrt-v4's Film "spectral": its buckets are the mean spectral radiance over equal intervals
// of [lambdamin, lambdamax], named as pbrt-v4 names them; they survive a checkpoint; bad
// parameters are located errors. A sky at a temperature is B(lambda, T): each bucket must be
// the band radiance over the bucket's width (planck_band_radiance), within the pixels' noise.
#include <gtest/gtest.h>

#include <sstream>

#include "base/statistics.h"
#include "render_test_util.h"
#include "spectral/planck.h"

namespace kiln {
namespace {

// 8 x 8 pixels, each its own samples (too few pixels for testing::BlockStats), or 16 x 16 with
// samples spread over the pixels within the filter's radius
std::string SkyScene(double T, const std::string& film, int spp, bool spread = false) {
    std::ostringstream s;
    s << "Film \"spectral\" "
      << (spread ? "\"integer xresolution\" 16 \"integer yresolution\" 16 "
                 : "\"integer xresolution\" 8 \"integer yresolution\" 8 "
                   "\"string reconstruction\" \"importance\" ")
      << film << "\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" " << spp << "\n"
      << "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
      << "LightSource \"infinite\" \"float temperature\" " << T << "\n";
    return s.str();
}

void ExpectBandRadiance(const std::string& film, double lambdaMin, double lambdaMax, int n,
                        bool spread = false) {
    const double T = 2500;
    testing::RenderedScene r = testing::RenderText(SkyScene(T, film, spread ? 64 : 256, spread));
    ASSERT_EQ(r.scene->features.spreadSamples, spread);
    for (const auto& w : r.warnings) ADD_FAILURE() << w.message;
    Image image = r.scene->job->film->GetImage(nullptr);
    ASSERT_EQ(image.NChannels(), 3 + n);
    for (int b = 0; b < n; ++b) {
        double l0 = lambdaMin + b * (lambdaMax - lambdaMin) / n;
        double l1 = lambdaMin + (b + 1) * (lambdaMax - lambdaMin) / n;
        double expected = planck_band_radiance(l0, l1, T) / (l1 - l0);
        // Blocks of spread pixels (neighbours share samples); independent pixels otherwise
        auto value = [&](Point2i p) { return image.GetChannel(p, 3 + b) / expected; };
        RunningStats s;
        if (spread)
            s = testing::BlockStats(Bounds2i{{0, 0}, image.Resolution()}, value);
        else
            for (int y = 0; y < 8; ++y)
                for (int x = 0; x < 8; ++x) s.Add(value({x, y}));
        SCOPED_TRACE(image.ChannelNames()[size_t(3 + b)]);
        EXPECT_NEAR(s.Mean(), 1, 4 * s.StandardError() + 1e-4);
        EXPECT_LT(s.StandardError(), 0.02);
    }
}

TEST(SpectralFilm, BucketsAreTheBandRadianceOfASkyAtATemperature) {
    ExpectBandRadiance("", 360, 830, 16);
    ExpectBandRadiance("\"integer nbuckets\" 5 \"float lambdamin\" 500 \"float lambdamax\" 600",
                       500, 600, 5);
}

// The buckets take spread samples with the same weights as R, G, B
TEST(SpectralFilm, BucketsOfSpreadSamplesAreTheBandRadianceToo) {
    ExpectBandRadiance("", 360, 830, 16, true);
}

TEST(SpectralFilm, ChannelsAreNamedAsPbrtV4NamesThem) {
    testing::RenderedScene r = testing::RenderText(SkyScene(1000, "", 1));
    std::vector<std::string> names = r.scene->job->film->GetImage(nullptr).ChannelNames();
    ASSERT_EQ(names.size(), 19u);
    EXPECT_EQ(names[0], "R");
    EXPECT_EQ(names[3], "S0.374,688nm");
    EXPECT_EQ(names[18], "S0.815,312nm");
}

TEST(SpectralFilm, BucketsSurviveACheckpoint) {
    testing::RenderedScene r = testing::RenderText(SkyScene(1800, "", 4));
    RGBFilm& film = *r.scene->job->film;
    std::string state = film.SaveState();
    Image before = film.GetImage(nullptr);
    film.Clear();
    EXPECT_EQ(film.GetImage(nullptr).GetChannel({3, 3}, 10), 0);
    ASSERT_TRUE(film.LoadState(state));
    Image after = film.GetImage(nullptr);
    for (int c = 0; c < before.NChannels(); ++c)
        EXPECT_EQ(after.GetChannel({3, 3}, c), before.GetChannel({3, 3}, c)) << c;
    // A state with the buckets cut off is another film's
    EXPECT_FALSE(film.LoadState(state.substr(0, state.size() - 8)));
}

TEST(SpectralFilm, BadParametersAreLocatedErrors) {
    for (std::string film :
         {"\"integer nbuckets\" 0", "\"float lambdamax\" 900",
          "\"float lambdamin\" 600 \"float lambdamax\" 500", "\"string filename\" \"out.png\""}) {
        SCOPED_TRACE(film);
        Diagnostics diag(nullptr);
        try {
            testing::BuildScene(SkyScene(1000, film, 1), diag);
            ADD_FAILURE() << "accepted";
        } catch (const SceneError& e) {
            EXPECT_EQ(e.Loc().line, 1);
            EXPECT_NE(std::string(e.what()).find("spectral film"), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace kiln
