// HairBxDF (materials/bxdfs/hair_bxdf.h): a clear fibre (sigma_a = 0) conserves energy, and its
// sampling is exact, so every sample's weight f |cos| / pdf is 1; absorption only removes
// energy; f is the density PDF reports times what that weight says. (Sampling against PDF:
// sampling_chi2_test.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

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

TEST(HairBxDF, AlbedoIsTheExpectedSampleWeight) {
    // Albedo(wo), the closed form a hot fibre's emissivity 1 - Albedo comes from, is what the
    // integrator's estimator of the integral of f |cos| converges to: the mean of Sample_f's
    // weights, per wavelength (four absorptions at once), with and without the scales' tilt
    RNG rng(23);
    const SampledSpectrum sigma_a(std::array<Float, NSpectrumSamples>{0.05f, 0.4f, 1.5f, 6.f});
    double worst = 0;
    for (int k = 0; k < 12; ++k) {
        Float h = -0.95f + 1.9f * rng.UniformFloat(), beta_m = 0.1f + 0.8f * rng.UniformFloat(),
              beta_n = 0.1f + 0.8f * rng.UniformFloat(), alpha = k % 2 ? 2.f : 0.f;
        Float eta = k % 3 ? 1.55f : 1.33f;
        HairBxDF hair(h, eta, sigma_a, beta_m, beta_n, alpha);
        Vector3f wo = RandomDirection(rng);
        SampledSpectrum albedo = hair.Albedo(wo);
        RunningStats s[NSpectrumSamples];
        for (int i = 0; i < 200000; ++i) {
            auto bs = hair.Sample_f(wo, rng.UniformFloat(),
                                    Point2f(rng.UniformFloat(), rng.UniformFloat()));
            for (int c = 0; c < NSpectrumSamples; ++c)
                s[c].Add(bs ? bs->f[c] * std::abs(bs->wi.z) / bs->pdf : 0);
        }
        for (int c = 0; c < NSpectrumSamples; ++c) {
            EXPECT_NEAR(s[c].Mean(), albedo[c], 4 * s[c].StandardError() + 2e-4)
                << "h " << h << " beta_m " << beta_m << " beta_n " << beta_n << " alpha " << alpha
                << " eta " << eta << " sigma_a " << sigma_a[c];
            EXPECT_LT(4 * s[c].StandardError(), 4e-3);
            worst = std::max(worst, std::abs(s[c].Mean() - albedo[c]));
        }
        // Absorption lowers it, within (0, 1)
        for (int c = 1; c < NSpectrumSamples; ++c) EXPECT_LT(albedo[c], albedo[c - 1]);
        EXPECT_GT(albedo[NSpectrumSamples - 1], 0);
        EXPECT_LT(albedo[0], 1);
    }
    std::printf("hair albedo: largest difference from the mean sample weight %.2e\n", worst);
    // A clear fibre scatters everything
    EXPECT_NEAR(HairBxDF(0.3f, 1.55f, SampledSpectrum(0.f), 0.3f, 0.3f, 2.f)
                    .Albedo(Normalize(Vector3f(0.3f, 0.5f, 0.8f)))[0],
                1, 1e-6f);
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
