// Comparison of noisy Monte Carlo renders with a reference image, with a tolerance derived
// from the renders' own variance (reusable by any image regression test).
//
// Method: K independent renders (different sampler seeds, n spp each) give, for every pixel
// value i, the mean m_i and the unbiased sample variance s_i^2 of the K per-render values. The
// reference (nRef spp, same estimator) has variance ~ s_i^2 n / nRef, so the expected squared
// difference of m_i and the reference for an unbiased renderer is
//     v_i = s_i^2 / K * (1 + K n / nRef).
// The statistic is the weighted ratio R = sum_i w_i (m_i - ref_i)^2 / sum_i w_i v_i: 1 for pure
// noise, larger by sum_i w_i bias_i^2 / sum_i w_i v_i for a biased render (wrong brightness,
// colour, material). The weights w_i = 1 / (|ref_i| + 0.5 mean|ref|)^2 make errors relative
// (as relMSE does) so that a few bright, very noisy pixels (emitter edges) do not dominate.
// A ratio
// of sums rather than the mean of per-value z^2 = (m - ref)^2 / v: with few seeds and skewed
// Monte Carlo estimates (a pixel's rare bright samples raise its mean and its variance together)
// the per-value z^2 is heavy-tailed and biased, the sums are not. Its standard deviation, with
// the per-value means close to normal (CLT over n spp) and values independent, is
//     sd(R) = sqrt(2 sum_i (w_i v_i)^2 (1 + 1 / (K - 1))) / sum_i w_i v_i
// (numerator's noise, and the denominator's: s^2 has relative variance 2 / (K - 1)), counting
// the R, G, B values of a pixel as one independent value (they are strongly correlated;
// conservative): the sum of squares is multiplied by nc. Accepted: |R - 1| <= `sigmas` sd(R).
// Values with s^2 = 0 (black background, pixels seeing only a constant) are compared directly:
// |m - ref| <= 1e-3 (|ref| + mean|ref|) (half-float rounding of the reference); a few may
// differ (a rare path never sampled by the K renders), at most
// `maxZeroVarianceMismatchFraction` of the values.
//
// Second check, on overall brightness (powerful against global regressions such as a wrong
// scale or a lost light): each render's total T_k = sum of its values; their mean against the
// reference's total, with the standard error from the spread of the T_k (and the reference's
// own noise, smaller by its spp ratio): z = (mean T - T_ref) / sqrt(var(T) / K (1 + K n /
// nRef)). Accepted: |z| <= `sigmas`.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <ostream>
#include <stdexcept>
#include <vector>

#include "core/image/image.h"

namespace kiln::testing {

struct NoiseComparison {
    double ratio = 0;      // R = sum w (m - ref)^2 / sum w v over the values with s^2 > 0
    double tolerance = 0;  // allowed |R - 1|
    int64_t values = 0;    // (pixel, channel) values with s^2 > 0
    int64_t zeroVarianceValues = 0, zeroVarianceMismatches = 0;
    double maxZeroVarianceMismatchFraction = 0.005;
    double totalZ = 0;       // z-score of the mean image total against the reference's
    double totalSigmas = 4;  // allowed |totalZ|

    bool Pass() const {
        int64_t all = values + zeroVarianceValues;
        return std::abs(ratio - 1) <= tolerance && std::abs(totalZ) <= totalSigmas &&
               zeroVarianceMismatches <= maxZeroVarianceMismatchFraction * double(all);
    }
};

inline std::ostream& operator<<(std::ostream& os, const NoiseComparison& c) {
    return os << "noise ratio " << c.ratio << " (expected 1 +- " << c.tolerance << ", " << c.values
              << " values; " << c.zeroVarianceMismatches << " of " << c.zeroVarianceValues
              << " zero-variance values differ; total z " << c.totalZ << ")";
}

// renders: K >= 6 images (same resolution and channels as reference) rendered with different
// seeds at sppPerRender each; referenceSpp: samples per pixel of the reference; scale: factor
// applied to the renders before comparison (1 for the real test; e.g. 1.05 to check that the
// comparison detects a 5 % brightness regression).
inline NoiseComparison CompareWithNoise(const std::vector<Image>& renders, const Image& reference,
                                        int sppPerRender, int referenceSpp, double sigmas = 4,
                                        double scale = 1) {
    const int K = int(renders.size());
    if (K < 6) throw std::invalid_argument("CompareWithNoise needs at least 6 renders");
    Point2i res = reference.Resolution();
    int nc = reference.NChannels();
    for (const Image& r : renders)
        if (r.Resolution() != res || r.NChannels() != nc)
            throw std::invalid_argument("CompareWithNoise: render and reference differ in size");
    const double refRatio = double(K) * sppPerRender / referenceSpp;
    double meanAbsRef = 0;
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x)
            for (int c = 0; c < nc; ++c) meanAbsRef += std::abs(reference.GetChannel({x, y}, c));
    meanAbsRef /= double(res.x) * res.y * nc;

    NoiseComparison out;
    out.totalSigmas = sigmas;
    // Overall brightness: per-render totals against the reference's total
    {
        std::vector<double> totals;
        for (const Image& r : renders) {
            double t = 0;
            for (int y = 0; y < res.y; ++y)
                for (int x = 0; x < res.x; ++x)
                    for (int c = 0; c < nc; ++c) t += scale * r.GetChannel({x, y}, c);
            totals.push_back(t);
        }
        double refTotal = 0;
        for (int y = 0; y < res.y; ++y)
            for (int x = 0; x < res.x; ++x)
                for (int c = 0; c < nc; ++c) refTotal += reference.GetChannel({x, y}, c);
        double mean = 0, var = 0;
        for (double t : totals) mean += t / K;
        for (double t : totals) var += Sqr(t - mean) / (K - 1);
        double se = std::sqrt(var / K * (1 + refRatio));
        out.totalZ = se > 0 ? (mean - refTotal) / se : (mean == refTotal ? 0 : 1e9);
    }
    double sumD2 = 0, sumV = 0, sumV2 = 0;
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x)
            for (int c = 0; c < nc; ++c) {
                double sum = 0, sum2 = 0;
                for (const Image& r : renders) {
                    double v = scale * r.GetChannel({x, y}, c);
                    sum += v;
                    sum2 += v * v;
                }
                double m = sum / K;
                double s2 = std::max(0.0, (sum2 - K * m * m) / (K - 1));
                double ref = reference.GetChannel({x, y}, c);
                // Below this the variance is float round-off of identical values.
                if (s2 <= 1e-12 * std::max(m * m, 1e-30)) {
                    ++out.zeroVarianceValues;
                    if (std::abs(m - ref) > 1e-3 * (std::abs(ref) + meanAbsRef))
                        ++out.zeroVarianceMismatches;
                    continue;
                }
                double v = s2 / K * (1 + refRatio);
                double w = 1 / Sqr(std::abs(ref) + 0.5 * meanAbsRef);
                sumD2 += w * (m - ref) * (m - ref);
                sumV += w * v;
                sumV2 += Sqr(w * v);
                ++out.values;
            }
    if (out.values == 0) throw std::invalid_argument("CompareWithNoise: no noisy pixel");
    out.ratio = sumD2 / sumV;
    out.tolerance = sigmas * std::sqrt(2 * nc * sumV2 * (1 + 1.0 / (K - 1))) / sumV;
    return out;
}

}  // namespace kiln::testing
