// HairBxDF (materials/bxdfs/hair_bxdf.h): a clear fibre (sigma_a = 0) conserves energy, and its
// sampling is exact, so every sample's weight f |cos| / pdf is 1; absorption only removes
// energy; f is the density PDF reports times what that weight says. (Sampling against PDF:
// sampling_chi2_test.cpp.)
#include <gtest/gtest.h>

#include <cmath>

#include "base/rng.h"
#include "base/statistics.h"
#include "materials/bxdfs/bxdf.h"

namespace kiln {
namespace {

Vector3f RandomDirection(RNG& rng) {
    Float z = 1 - 2 * rng.UniformFloat(), phi = 2 * Pi * rng.UniformFloat();
    Float r = SafeSqrt(1 - z * z);
    return Vector3f(r * std::cos(phi), r * std::sin(phi), z);
}

TEST(HairBxDF, ClearFibreSamplesWithWeightOne) {
    RNG rng(5);
    for (Float beta_m : {0.1f, 0.3f, 0.8f})
        for (Float beta_n : {0.1f, 0.4f, 0.9f}) {
            for (int i = 0; i < 200; ++i) {
                Float h = -1 + 2 * rng.UniformFloat();
                HairBxDF hair(h, 1.55f, SampledSpectrum(0.f), beta_m, beta_n, 2.f);
                Vector3f wo = RandomDirection(rng);
                auto bs = hair.Sample_f(wo, rng.UniformFloat(),
                                        Point2f(rng.UniformFloat(), rng.UniformFloat()),
                                        TransportMode::Radiance);
                if (!bs) continue;
                Float weight = bs->f[0] * std::abs(bs->wi.z) / bs->pdf;
                ASSERT_NEAR(weight, 1, 1e-3f)
                    << "beta_m " << beta_m << " beta_n " << beta_n << " h " << h;
                // PDF agrees with the sample's density
                ASSERT_NEAR(hair.PDF(wo, bs->wi, TransportMode::Radiance), bs->pdf,
                            1e-3f * bs->pdf);
            }
        }
}

// Directional albedo (integral of f |cos| over the sphere) by uniform sphere sampling, with
// its standard error.
std::pair<double, double> Albedo(const HairBxDF& hair, Vector3f wo, int n, uint64_t seed) {
    RNG rng(seed);
    RunningStats s;
    for (int i = 0; i < n; ++i) {
        Vector3f wi = RandomDirection(rng);
        s.Add(hair.f(wo, wi, TransportMode::Radiance)[0] * std::abs(wi.z) * 4 * Pi);
    }
    return {s.Mean(), s.StandardError()};
}

TEST(HairBxDF, WhiteFurnaceAndAbsorption) {
    // Uniform sampling (independent of the model's own sampling) of a clear fibre integrates
    // to 1; an absorbing one to less, and less the more it absorbs
    RNG rng(11);
    for (int k = 0; k < 6; ++k) {
        Float h = -0.9f + 0.35f * k, beta_m = 0.2f + 0.1f * k, beta_n = 0.3f + 0.1f * k;
        Vector3f wo = RandomDirection(rng);
        auto [clear, se] = Albedo(HairBxDF(h, 1.55f, SampledSpectrum(0.f), beta_m, beta_n, 0.f), wo,
                                  400000, 100 + k);
        EXPECT_NEAR(clear, 1, 5 * se + 0.01) << "h " << h << " beta_m " << beta_m;
        EXPECT_LT(5 * se, 0.06);  // the test sees a 6 % loss of energy
        auto [dark, seDark] = Albedo(HairBxDF(h, 1.55f, SampledSpectrum(2.f), beta_m, beta_n, 0.f),
                                     wo, 400000, 100 + k);
        EXPECT_LT(dark, clear - 5 * std::hypot(se, seDark));
    }
}

TEST(HairBxDF, MelaninAndReflectanceGiveAbsorption) {
    RGB brown = HairBxDF::SigmaAFromConcentration(1.3f, 0);
    EXPECT_NEAR(brown.r, 1.3f * 0.419f, 1e-6f);
    EXPECT_GT(brown.b, brown.g);
    EXPECT_GT(brown.g, brown.r);  // absorbs blue most: brown
    // White hair absorbs nothing, darker colours more
    SampledSpectrum white = HairBxDF::SigmaAFromReflectance(SampledSpectrum(1.f), 0.3f);
    EXPECT_EQ(white[0], 0);
    SampledSpectrum grey = HairBxDF::SigmaAFromReflectance(SampledSpectrum(0.5f), 0.3f);
    SampledSpectrum dark = HairBxDF::SigmaAFromReflectance(SampledSpectrum(0.1f), 0.3f);
    EXPECT_GT(dark[0], grey[0]);
    EXPECT_GT(grey[0], 0);
}

}  // namespace
}  // namespace kiln
