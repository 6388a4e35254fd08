// Shared helpers of the light tests: luminance of a spectral quantity, parameter lists and a
// chi-square test of sampled directions against a claimed density per steradian.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/rng.h"
#include "base/statistics.h"
#include "core/parser/parameter_dictionary.h"
#include "spectral/cie.h"
#include "spectral/sampled_spectrum.h"

namespace kiln::testing {

// Y = sum over 360..830 nm (1 nm) of f(lambda) ybar(lambda) / CIE_Y_integral for a function
// that evaluates at SampledWavelengths (f is called with 4 wavelengths at a time).
inline double LuminanceOf(const std::function<SampledSpectrum(const SampledWavelengths&)>& f) {
    double sum = 0;
    for (int l0 = 360; l0 <= 830; l0 += NSpectrumSamples) {
        SampledWavelengths lambda = SampledWavelengths::SampleUniform(0);
        for (int i = 0; i < NSpectrumSamples; ++i) lambda[i] = Float(std::min(l0 + i, 830));
        SampledSpectrum s = f(lambda);
        for (int i = 0; i < NSpectrumSamples; ++i)
            if (l0 + i <= 830) sum += double(s[i]) * CIE_Y(Float(l0 + i));
    }
    return sum / CIE_Y_integral;
}

inline ParsedParameter FloatParam(const std::string& type, const std::string& name,
                                  std::vector<Float> v) {
    ParsedParameter p;
    p.type = type;
    p.name = name;
    p.floats = std::move(v);
    return p;
}
inline ParsedParameter BoolParam(const std::string& name, bool b) {
    ParsedParameter p;
    p.type = "bool";
    p.name = name;
    p.bools = {uint8_t(b)};
    return p;
}
inline ParsedParameter StringParam(const std::string& name, const std::string& s) {
    ParsedParameter p;
    p.type = "string";
    p.name = name;
    p.strings = {s};
    return p;
}

// Samples directions with `sample` (nullopt counts as a sample that fell nowhere), bins them
// by (1 - cos theta, phi) about `axis` for cos theta in [cosMax, 1], and compares the counts with
// `pdf` (per sr) integrated over each bin on a sub x sub midpoint grid. Also checks that the
// pdf each sample reports equals pdf(w), allowing maxMismatchFraction of the samples to differ
// (piecewise-constant densities jump across cell edges, which rounding may straddle).
struct DirectionSample {
    Vector3f w;
    Float pdf;
};
inline ChiSquareResult DirectionChiSquare(
    const std::function<std::optional<DirectionSample>(Point2f)>& sample,
    const std::function<Float(Vector3f)>& pdf, Vector3f axis, Float cosMax, int nSamples,
    int numTests, int nCos = 16, int nPhi = 32, int sub = 32, double maxMismatchFraction = 1e-4) {
    Frame frame = Frame::FromZ(Normalize(axis));
    std::vector<double> observed(nCos * nPhi, 0), expected(nCos * nPhi, 0);
    RNG rng(17);
    int pdfMismatches = 0, outside = 0;
    for (int i = 0; i < nSamples; ++i) {
        std::optional<DirectionSample> s = sample(Point2f(rng.UniformFloat(), rng.UniformFloat()));
        if (!s) continue;
        Float claimed = pdf(s->w);
        if (std::abs(claimed - s->pdf) > 2e-3f * std::max(claimed, s->pdf)) ++pdfMismatches;
        // Bin by 1 - cos theta computed without cancellation (small cones need it)
        Vector3f wl = frame.ToLocal(s->w);
        double x = wl.x, y = wl.y, z = wl.z, len2 = x * x + y * y + z * z;
        double omc =
            z > 0 ? (x * x + y * y) / (len2 + z * std::sqrt(len2)) : 1 - z / std::sqrt(len2);
        if (omc > 1 - cosMax) {
            ++outside;
            continue;
        }
        int cb = std::min(nCos - 1, int(omc / (1 - cosMax) * nCos));
        int pb = std::min(nPhi - 1, int(SphericalPhi(wl) * Inv2Pi * nPhi));
        observed[cb * nPhi + pb] += 1;
    }
    EXPECT_LE(pdfMismatches, int(nSamples * maxMismatchFraction))
        << "sample pdfs disagree with PDF_Li";
    EXPECT_EQ(outside, 0) << "samples outside the tested cone";
    double dz = (1 - cosMax) / nCos, dphi = 2 * Pi / nPhi;
    for (int cb = 0; cb < nCos; ++cb)
        for (int pb = 0; pb < nPhi; ++pb) {
            double sum = 0;
            for (int a = 0; a < sub; ++a)
                for (int b = 0; b < sub; ++b) {
                    double omc = (cb + (a + 0.5) / sub) * dz;
                    double z = 1 - omc, phi = (pb + (b + 0.5) / sub) * dphi;
                    double r = std::sqrt(std::max(0.0, omc * (2 - omc)));
                    Vector3f wl(Float(r * std::cos(phi)), Float(r * std::sin(phi)), Float(z));
                    sum += pdf(frame.FromLocal(wl));
                }
            // A floor keeps bins that the support only grazes (missed by the midpoint grid) in
            // the pooled test instead of failing them outright
            expected[cb * nPhi + pb] = std::max(sum / (sub * sub) * dz * dphi * nSamples, 1e-6);
        }
    return ChiSquareTest(observed, expected, 0.01, numTests);
}

}  // namespace kiln::testing
