// The film's wavelength distribution for scenes with hot matter
// (spectral/wavelength_distribution.h): its samples follow its density (chi-square), the
// density integrates to 1 and is what Sample reports, the path's wavelengths are stratified in
// its CDF, and Monte Carlo colour estimates with it are unbiased and less noisy for a glow.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "base/rng.h"
#include "base/statistics.h"
#include "spectral/cie.h"
#include "spectral/planck.h"
#include "spectral/wavelength_distribution.h"

namespace kiln {
namespace {

// Blackbody spectra at 1000 K and 1600 K (weights 1 : 3) at the bin centres
std::vector<Float> GlowSpectrum() {
    std::vector<Float> e(WavelengthDistribution::kBins);
    for (int i = 0; i < WavelengthDistribution::kBins; ++i) {
        double l = Lambda_min + i + 0.5;
        e[size_t(i)] = Float(planck_radiance(l, 1000) + 3 * planck_radiance(l, 1600));
    }
    return e;
}

TEST(WavelengthDistribution, SamplesFollowTheDensity) {
    WavelengthDistribution d(GlowSpectrum(), 0.5f);
    ASSERT_FALSE(d.IsVisible());
    constexpr int kBins = 94, kSamples = 200000;
    std::vector<double> observed(kBins, 0), expected(kBins, 0);
    const double width = (Lambda_max - Lambda_min) / kBins;
    RNG rng(3);
    for (int i = 0; i < kSamples; ++i) {
        SampledWavelengths swl = d.Sample(rng.UniformFloat());
        const Float l = swl[i % NSpectrumSamples];
        ASSERT_GE(l, Lambda_min);
        ASSERT_LT(l, Lambda_max);
        ASSERT_FLOAT_EQ(swl.PDF()[i % NSpectrumSamples], d.PDF(l));
        observed[std::min(kBins - 1, int((l - Lambda_min) / width))] += 1;
    }
    // The density is constant over each 1-nm bin: integrate it bin by bin
    for (int b = 0; b < kBins; ++b)
        for (int k = 0; k < 5; ++k)
            expected[size_t(b)] += kSamples * d.PDF(Float(Lambda_min + b * width + k + 0.5));
    ChiSquareResult r = ChiSquareTest(observed, expected);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(WavelengthDistribution, DensityIsNormalisedAndPositiveEverywhere) {
    WavelengthDistribution d(GlowSpectrum(), 0.5f);
    double integral = 0;
    for (int i = 0; i < WavelengthDistribution::kBins; ++i) {
        Float p = d.PDF(Lambda_min + i + 0.5f);
        // The visible share keeps every wavelength: at least half the visible density
        EXPECT_GE(p, 0.499f * SampledWavelengths::VisibleWavelengthPDF(Lambda_min + i + 0.5f));
        integral += p;
    }
    EXPECT_NEAR(integral, 1, 1e-5);
    EXPECT_EQ(d.PDF(Lambda_min - 1), 0);
    EXPECT_EQ(d.PDF(Lambda_max + 1), 0);
}

// The density is the stated mixture: half the visible density (normalised over the bins) and
// half e (xbar / X + ybar / Y + zbar / Z) / 3, X, Y, Z the integrals of e times each
TEST(WavelengthDistribution, DensityIsTheStatedMixture) {
    std::vector<Float> e = GlowSpectrum();
    WavelengthDistribution d(e, 0.5f);
    double X = 0, Y = 0, Z = 0, V = 0;
    for (int i = 0; i < WavelengthDistribution::kBins; ++i) {
        Float l = Lambda_min + i + 0.5f;
        X += e[size_t(i)] * CIE_X(l);
        Y += e[size_t(i)] * CIE_Y(l);
        Z += e[size_t(i)] * CIE_Z(l);
        V += SampledWavelengths::VisibleWavelengthPDF(l);
    }
    for (Float l : {362.5f, 450.5f, 555.5f, 620.5f, 700.5f, 829.5f}) {
        size_t i = size_t(l - Lambda_min);
        double hot = e[i] * (CIE_X(l) / X + CIE_Y(l) / Y + CIE_Z(l) / Z) / 3;
        double expected = 0.5 * SampledWavelengths::VisibleWavelengthPDF(l) / V + 0.5 * hot;
        EXPECT_NEAR(d.PDF(l) / expected, 1, 1e-4) << l << " nm";
    }
}

TEST(WavelengthDistribution, NoEmissionIsTheVisibleDensity) {
    std::vector<Float> none(WavelengthDistribution::kBins, 0.f);
    EXPECT_TRUE(WavelengthDistribution(none, 0.5f).IsVisible());
    EXPECT_TRUE(WavelengthDistribution().IsVisible());
    SampledWavelengths a = WavelengthDistribution().Sample(0.3f),
                       b = SampledWavelengths::SampleVisible(0.3f);
    for (int i = 0; i < NSpectrumSamples; ++i) EXPECT_EQ(a[i], b[i]);
}

// The path's wavelengths sit at CDF values u + i / NSpectrumSamples (mod 1)
TEST(WavelengthDistribution, WavelengthsAreStratifiedInTheCDF) {
    WavelengthDistribution d(GlowSpectrum(), 0.5f);
    auto cdf = [&](Float l) {
        double c = 0;
        int whole = int(l - Lambda_min);
        for (int i = 0; i < whole; ++i) c += d.PDF(Lambda_min + i + 0.5f);
        return c + (l - Lambda_min - whole) * d.PDF(l);
    };
    for (Float u : {0.f, 0.1f, 0.37f, 0.99f}) {
        SampledWavelengths swl = d.Sample(u);
        for (int i = 0; i < NSpectrumSamples; ++i) {
            double expected = std::fmod(u + double(i) / NSpectrumSamples, 1.0);
            EXPECT_NEAR(cdf(swl[i]), expected, 1e-4) << "u " << u << ", i " << i;
        }
    }
}

// X, Y, Z of a 1300 K blackbody estimated with the path's four wavelengths: unbiased with
// either density, and the glow's density has less than half the visible density's variance.
TEST(WavelengthDistribution, GlowColourIsUnbiasedAndLessNoisy) {
    std::vector<Float> e(WavelengthDistribution::kBins);
    for (int i = 0; i < WavelengthDistribution::kBins; ++i)
        e[size_t(i)] = Float(planck_radiance(Lambda_min + i + 0.5, 1300));
    WavelengthDistribution glow(e, 0.5f), visible;
    double exact[3] = {0, 0, 0};
    for (int i = 0; i < 47000; ++i) {  // 0.01-nm midpoint rule
        double l = Lambda_min + (i + 0.5) * 0.01, B = planck_radiance(l, 1300) * 0.01;
        exact[0] += B * CIE_X(Float(l));
        exact[1] += B * CIE_Y(Float(l));
        exact[2] += B * CIE_Z(Float(l));
    }
    double relVariance[2] = {0, 0};
    for (int which = 0; which < 2; ++which) {
        const WavelengthDistribution& d = which == 0 ? glow : visible;
        RunningStats s[3];
        RNG rng(11);
        for (int n = 0; n < 100000; ++n) {
            SampledWavelengths swl = d.Sample(rng.UniformFloat());
            double xyz[3] = {0, 0, 0};
            for (int i = 0; i < NSpectrumSamples; ++i) {
                double w = planck_radiance(swl[i], 1300) / swl.PDF()[i] / NSpectrumSamples;
                xyz[0] += w * CIE_X(swl[i]);
                xyz[1] += w * CIE_Y(swl[i]);
                xyz[2] += w * CIE_Z(swl[i]);
            }
            for (int c = 0; c < 3; ++c) s[c].Add(xyz[c] / exact[c]);
        }
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(s[c].Mean(), 1, 5 * s[c].StandardError()) << which << " channel " << c;
            relVariance[which] += s[c].Variance();
        }
    }
    std::printf("relative variance of X + Y + Z, glow / visible density: %.3f\n",
                relVariance[0] / relVariance[1]);
    EXPECT_LT(relVariance[0], 0.5 * relVariance[1]);
}

}  // namespace
}  // namespace kiln
