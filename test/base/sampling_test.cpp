// Chi-square tests of the warping functions in base/sampling.h: each sampler must draw
// directions or points with exactly the density its *PDF function reports.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "base/rng.h"
#include "base/sampling.h"
#include "base/statistics.h"

using namespace kiln;

namespace {

constexpr int kThetaBins = 20, kPhiBins = 40;
constexpr int kSamples = 400000;

// Bins sampled unit directions by (cos theta, phi) over the whole sphere and compares with the
// pdf integrated over each bin (midpoint rule on a 4x4 sub-grid).
ChiSquareResult TestDirectionSampler(const std::function<Vector3f(Point2f)>& sample,
                                     const std::function<Float(Vector3f)>& pdf) {
    std::vector<double> observed(kThetaBins * kPhiBins, 0), expected(kThetaBins * kPhiBins, 0);
    RNG rng(7);
    for (int i = 0; i < kSamples; ++i) {
        Vector3f w = sample(Point2f(rng.UniformFloat(), rng.UniformFloat()));
        Float z = Clamp(w.z, -1, 1);
        int tb = std::min(kThetaBins - 1, int((z + 1) / 2 * kThetaBins));
        int pb = std::min(kPhiBins - 1, int(SphericalPhi(w) * Inv2Pi * kPhiBins));
        observed[tb * kPhiBins + pb] += 1;
    }
    const int sub = 4;
    for (int tb = 0; tb < kThetaBins; ++tb)
        for (int pb = 0; pb < kPhiBins; ++pb) {
            double sum = 0;
            for (int a = 0; a < sub; ++a)
                for (int b = 0; b < sub; ++b) {
                    Float z = -1 + 2 * (tb + (a + 0.5f) / sub) / kThetaBins;
                    Float phi = 2 * Pi * (pb + (b + 0.5f) / sub) / kPhiBins;
                    Float r = SafeSqrt(1 - z * z);
                    sum += pdf(Vector3f(r * std::cos(phi), r * std::sin(phi), z));
                }
            double binSolidAngle = (2.0 / kThetaBins) * (2 * Pi / kPhiBins);
            expected[tb * kPhiBins + pb] = sum / (sub * sub) * binSolidAngle * kSamples;
        }
    return ChiSquareTest(observed, expected, 0.01, 6);
}

}  // namespace

TEST(Sampling, CosineHemisphereChiSquare) {
    auto r = TestDirectionSampler(
        SampleCosineHemisphere, [](Vector3f w) { return w.z > 0 ? CosineHemispherePDF(w.z) : 0; });
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(Sampling, UniformSphereChiSquare) {
    auto r = TestDirectionSampler(SampleUniformSphere, [](Vector3f) { return UniformSpherePDF(); });
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(Sampling, UniformHemisphereChiSquare) {
    auto r = TestDirectionSampler(SampleUniformHemisphere,
                                  [](Vector3f w) { return w.z > 0 ? UniformHemispherePDF() : 0; });
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(Sampling, UniformConeChiSquare) {
    const Float cosMax = 0.3f;
    auto r = TestDirectionSampler(
        [&](Point2f u) { return SampleUniformCone(u, cosMax); },
        [&](Vector3f w) { return w.z >= cosMax ? UniformConePDF(cosMax) : 0; });
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(Sampling, WrongPdfIsRejected) {
    // The test must be able to fail: cosine samples against a uniform-hemisphere pdf.
    auto r = TestDirectionSampler(SampleCosineHemisphere,
                                  [](Vector3f w) { return w.z > 0 ? UniformHemispherePDF() : 0; });
    EXPECT_FALSE(r.passed);
}

TEST(Sampling, UniformTriangleIsUniform) {
    // Barycentrics mapped onto the unit right triangle; count in a grid of cells fully inside.
    const int n = 16;
    std::vector<double> observed(n * n, 0), expected(n * n, 0);
    RNG rng(3);
    for (int i = 0; i < kSamples; ++i) {
        auto b = SampleUniformTriangle(Point2f(rng.UniformFloat(), rng.UniformFloat()));
        ASSERT_GE(b[0], 0);
        ASSERT_GE(b[1], 0);
        ASSERT_GE(b[2], -1e-6f);
        int x = std::min(n - 1, int(b[0] * n)), y = std::min(n - 1, int(b[1] * n));
        observed[y * n + x] += 1;
    }
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            // Area of the cell inside x + y <= 1 (full, half or empty).
            double area = (x + y + 2 <= n) ? 1.0 : (x + y + 1 == n ? 0.5 : 0.0);
            expected[y * n + x] = area / (n * n) * 2 * kSamples;
        }
    auto r = ChiSquareTest(observed, expected);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(Sampling, ConcentricDiskIsUniform) {
    const int nr = 10, np = 20;
    std::vector<double> observed(nr * np, 0), expected(nr * np, 0);
    RNG rng(11);
    for (int i = 0; i < kSamples; ++i) {
        Point2f p = SampleUniformDiskConcentric(Point2f(rng.UniformFloat(), rng.UniformFloat()));
        Float r2 = p.x * p.x + p.y * p.y;
        ASSERT_LE(r2, 1 + 1e-6f);
        int rb = std::min(nr - 1, int(r2 * nr));  // equal-area rings
        Float phi = std::atan2(p.y, p.x);
        if (phi < 0) phi += 2 * Pi;
        int pb = std::min(np - 1, int(phi * Inv2Pi * np));
        observed[rb * np + pb] += 1;
    }
    for (double& e : expected) e = double(kSamples) / (nr * np);
    auto r = ChiSquareTest(observed, expected);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(Sampling, LinearAndBilinearMatchPdf) {
    const int n = 32;
    std::vector<double> observed(n, 0), expected(n, 0);
    RNG rng(5);
    for (int i = 0; i < kSamples; ++i) {
        Float x = SampleLinear(rng.UniformFloat(), 0.2f, 3.0f);
        observed[std::min(n - 1, int(x * n))] += 1;
    }
    for (int i = 0; i < n; ++i) expected[i] = LinearPDF((i + 0.5f) / n, 0.2f, 3.0f) / n * kSamples;
    auto r = ChiSquareTest(observed, expected);
    EXPECT_TRUE(r.passed) << r.message;

    const Float w[4] = {0.1f, 2.0f, 0.5f, 4.0f};
    std::vector<double> obs2(n * n, 0), exp2(n * n, 0);
    for (int i = 0; i < kSamples; ++i) {
        Point2f p = SampleBilinear(Point2f(rng.UniformFloat(), rng.UniformFloat()), w);
        obs2[std::min(n - 1, int(p.y * n)) * n + std::min(n - 1, int(p.x * n))] += 1;
    }
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            exp2[y * n + x] =
                BilinearPDF(Point2f((x + 0.5f) / n, (y + 0.5f) / n), w) / (n * n) * kSamples;
    auto r2 = ChiSquareTest(obs2, exp2);
    EXPECT_TRUE(r2.passed) << r2.message;
}

// Sampling inverts the CDF: x's CDF (summed here in double) is u, x lies in the bin returned,
// which has a positive value, and x does not decrease with u (but for rounding); at the guide
// table's interval ends too, where u * n rounds, and for densities with zero runs, spikes and a
// single bin.
TEST(Sampling, PiecewiseConstant1DInvertsTheCdf) {
    RNG rng(29);
    std::vector<std::vector<Float>> cases;
    std::vector<Float> mixed(470);
    for (Float& v : mixed) v = rng.UniformFloat() < 0.2f ? 0 : rng.UniformFloat() * 10;
    cases.push_back(mixed);
    std::vector<Float> spike(300, 1e-3f);
    spike[217] = 1e6f;
    cases.push_back(spike);
    std::vector<Float> runs(64, 0.f);
    for (int i = 20; i < 30; ++i) runs[size_t(i)] = 1;
    runs[50] = 3;
    cases.push_back(runs);
    cases.push_back({2.f});
    // Uniform over 470 bins: the CDF's values are the guide's interval ends k / 470 exactly
    cases.push_back(std::vector<Float>(470, 1.f));
    for (const std::vector<Float>& f : cases) {
        const Float lo = 360, hi = 830;
        PiecewiseConstant1D dist(f, lo, hi);
        const size_t n = f.size();
        std::vector<double> cdf(n + 1, 0.0);
        for (size_t i = 0; i < n; ++i) cdf[i + 1] = cdf[i] + f[i];
        std::vector<Float> us;
        for (int i = 0; i < 20000; ++i) us.push_back(rng.UniformFloat());
        for (size_t k = 0; k < n; ++k) {
            Float edge = Float(k) / Float(n);
            us.push_back(edge);
            if (k > 0) us.push_back(std::nextafter(edge, 0.f));
            us.push_back(std::nextafter(edge, 1.f));
        }
        us.push_back(OneMinusEpsilon);
        std::sort(us.begin(), us.end());
        Float previous = lo;
        for (Float u : us) {
            int offset = -1;
            Float pdf = 0;
            Float x = dist.Sample(u, &pdf, &offset);
            ASSERT_GE(offset, 0);
            ASSERT_LT(size_t(offset), n);
            EXPECT_GT(f[size_t(offset)], 0) << "u " << u;
            Float binLo = lo + (hi - lo) * Float(offset) / Float(n);
            Float binHi = lo + (hi - lo) * Float(offset + 1) / Float(n);
            EXPECT_GE(x, binLo - 1e-3f);
            EXPECT_LE(x, binHi + 1e-3f);
            double t = (double(x) - lo) / (hi - lo) * double(n);
            size_t b = std::min(size_t(t), n - 1);
            double cdfX = (cdf[b] + (t - double(b)) * f[b]) / cdf[n];
            // Within float resolution: 2e-5, plus what the CDF climbs over two ulps of x
            double ulp = double(std::nextafter(x, hi) - x);
            double tolerance = 2e-5 + 2 * ulp * f[b] / cdf[n] * double(n) / (hi - lo);
            EXPECT_NEAR(cdfX, u, tolerance) << "u " << u << " bin " << offset;
            EXPECT_GE(x, previous - 1e-4f) << "u " << u;  // rounding at bin ends
            previous = x;
        }
    }
}

TEST(Sampling, PiecewiseConstant2DMatchesPdf) {
    const int nu = 8, nv = 6;
    std::vector<Float> f(nu * nv);
    RNG rng(13);
    for (Float& v : f) v = rng.UniformFloat() < 0.2f ? 0 : rng.UniformFloat() * 10;
    PiecewiseConstant2D dist(f, nu, nv);
    std::vector<double> observed(nu * nv, 0), expected(nu * nv, 0);
    for (int i = 0; i < kSamples; ++i) {
        Float pdf;
        Point2f p = dist.Sample(Point2f(rng.UniformFloat(), rng.UniformFloat()), &pdf);
        int iu = std::min(nu - 1, int(p.x * nu)), iv = std::min(nv - 1, int(p.y * nv));
        EXPECT_NEAR(pdf, dist.PDF(p), 1e-4f * pdf);
        observed[iv * nu + iu] += 1;
    }
    double total = 0;
    for (Float v : f) total += v;
    for (int i = 0; i < nu * nv; ++i) expected[i] = f[i] / total * kSamples;
    auto r = ChiSquareTest(observed, expected);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(Sampling, AliasTableMatchesWeights) {
    std::vector<Float> w = {0, 1, 5, 0.5f, 20, 0, 3, 7};
    AliasTable table(w);
    std::vector<double> observed(w.size(), 0), expected(w.size(), 0);
    RNG rng(17);
    double total = 0;
    for (Float v : w) total += v;
    for (int i = 0; i < kSamples; ++i) {
        Float pmf, ur;
        int idx = table.Sample(rng.UniformFloat(), &pmf, &ur);
        EXPECT_NEAR(pmf, w[idx] / total, 1e-6);
        EXPECT_GE(ur, 0);
        EXPECT_LT(ur, 1);
        observed[idx] += 1;
    }
    for (size_t i = 0; i < w.size(); ++i) expected[i] = w[i] / total * kSamples;
    auto r = ChiSquareTest(observed, expected);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(Statistics, GammaQMatchesKnownValues) {
    // Chi-square survival for k = 2 is exp(-x/2) exactly.
    for (double x : {0.1, 1.0, 5.0, 20.0})
        EXPECT_NEAR(ChiSquareSurvival(x, 2), std::exp(-x / 2), 1e-12);
    // k = 1: erfc(sqrt(x/2)).
    for (double x : {0.5, 3.84145882})
        EXPECT_NEAR(ChiSquareSurvival(x, 1), std::erfc(std::sqrt(x / 2)), 1e-10);
}
