// Wavelength sampling (chi-square) and the Monte Carlo XYZ estimate of sampled spectra.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "base/rng.h"
#include "base/statistics.h"
#include "spectral/cie.h"
#include "spectral/color.h"
#include "spectral/named_spectra.h"

using namespace kiln;

namespace {

// Integral of f over [a, b] by Simpson's rule with n (even) intervals.
template <typename F>
double Simpson(F f, double a, double b, int n) {
    const double h = (b - a) / n;
    double s = f(a) + f(b);
    for (int i = 1; i < n; ++i) s += (i % 2 ? 4 : 2) * f(a + i * h);
    return s * h / 3;
}

}  // namespace

// Every one of the path's wavelengths has the density VisibleWavelengthPDF.
TEST(SampledWavelengths, SampleVisibleChiSquare) {
    constexpr int kBins = 94, kSamples = 200000;
    std::vector<double> observed(kBins, 0), expected(kBins, 0);
    const double width = (Lambda_max - Lambda_min) / kBins;
    RNG rng(5);
    for (int i = 0; i < kSamples; ++i) {
        SampledWavelengths swl = SampledWavelengths::SampleVisible(rng.UniformFloat());
        // Each lambda_i separately has the density; test the i-th in turn
        const Float l = swl[i % NSpectrumSamples];
        ASSERT_GE(l, Lambda_min);
        ASSERT_LE(l, Lambda_max);
        ASSERT_FLOAT_EQ(swl.PDF()[i % NSpectrumSamples],
                        SampledWavelengths::VisibleWavelengthPDF(l));
        observed[std::min(kBins - 1, int((l - Lambda_min) / width))] += 1;
    }
    for (int b = 0; b < kBins; ++b)
        expected[b] =
            kSamples *
            Simpson([](double l) { return SampledWavelengths::VisibleWavelengthPDF(Float(l)); },
                    Lambda_min + b * width, Lambda_min + (b + 1) * width, 8);
    ChiSquareResult r = ChiSquareTest(observed, expected);
    EXPECT_TRUE(r.passed) << r.message;
}

// The density integrates to 1 over the visible range (to the precision of its constants).
TEST(SampledWavelengths, VisiblePDFNormalised) {
    double integral =
        Simpson([](double l) { return SampledWavelengths::VisibleWavelengthPDF(Float(l)); },
                Lambda_min, Lambda_max, 2000);
    EXPECT_NEAR(integral, 1, 1e-4);
}

TEST(SampledWavelengths, UniformAndTerminate) {
    SampledWavelengths swl = SampledWavelengths::SampleUniform(0.9f);
    for (int i = 0; i < NSpectrumSamples; ++i) {
        EXPECT_GE(swl[i], Lambda_min);
        EXPECT_LE(swl[i], Lambda_max);
        EXPECT_FLOAT_EQ(swl.PDF()[i], 1 / (Lambda_max - Lambda_min));
    }
    swl.TerminateSecondary();
    EXPECT_TRUE(swl.SecondaryTerminated());
    EXPECT_FLOAT_EQ(swl.PDF()[0], 1 / (Lambda_max - Lambda_min) / NSpectrumSamples);
}

// SpectrumToXYZ of sampled spectra is an unbiased estimate of the spectrum's XYZ: the mean
// of many estimates lies within 5 standard errors (plus the 1 nm sum's quadrature error,
// below 1e-4 relative) of the exact value.
TEST(SampledSpectrum, ToXYZConverges) {
    const Spectrum specs[] = {*GetNamedSpectrum("stdillum-D65"), BlackbodySpectrum(2856),
                              RGBAlbedoSpectrum(RGBColorSpace::sRGB(), RGB(0.8f, 0.3f, 0.1f))};
    for (const Spectrum& s : specs) {
        const XYZ exact = SpectrumToXYZ(s);
        RunningStats st[3];
        RNG rng(9);
        for (int i = 0; i < 100000; ++i) {
            SampledWavelengths swl = SampledWavelengths::SampleVisible(rng.UniformFloat());
            XYZ e = SpectrumToXYZ(s.Sample(swl), swl);
            for (int c = 0; c < 3; ++c) st[c].Add(e[c]);
        }
        for (int c = 0; c < 3; ++c) {
            const double tol = 5 * st[c].StandardError() + 1e-4 * std::abs(exact[c]);
            EXPECT_NEAR(st[c].Mean(), exact[c], tol) << "component " << c;
            EXPECT_LT(st[c].StandardError(), 0.01 * std::abs(exact[c]));
        }
    }
}

// Uniform sampling gives the same answer.
TEST(SampledSpectrum, ToXYZUniform) {
    const Spectrum& s = *GetNamedSpectrum("stdillum-A");
    const XYZ exact = SpectrumToXYZ(s);
    RunningStats st;
    RNG rng(13);
    for (int i = 0; i < 100000; ++i) {
        SampledWavelengths swl = SampledWavelengths::SampleUniform(rng.UniformFloat());
        st.Add(SpectrumToXYZ(s.Sample(swl), swl).Y);
    }
    EXPECT_NEAR(st.Mean(), exact.Y, 5 * st.StandardError() + 1e-4);
}
