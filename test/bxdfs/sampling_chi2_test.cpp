// Chi-square goodness-of-fit tests: every sampling routine must draw directions with the
// density its PDF reports (Sample_f vs PDF, Sample_wm vs D(w, wm)).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <vector>

#include "base/rng.h"
#include "base/statistics.h"
#include "materials/bxdfs/bxdf.h"
#include "rgl_test_data.h"

using namespace kiln;

namespace {

constexpr int kThetaBins = 80, kPhiBins = 160, kSub = 8;
constexpr int kSamples = 200000;
constexpr int kNumTests = 49;  // tests in this file, for the multiple-testing correction

// Bins directions by (theta, phi) over the sphere (bins narrow near the poles, where sharp
// lobes sit); sample() returns nullopt on failure (the lost mass must then be missing from the
// pdf too). Expected counts integrate the pdf over each bin with a kSub x kSub midpoint rule.
ChiSquareResult TestSampler(const std::function<std::optional<Vector3f>(Float, Point2f)>& sample,
                            const std::function<Float(Vector3f)>& pdf, uint64_t seed) {
    std::vector<double> observed(kThetaBins * kPhiBins, 0), expected(kThetaBins * kPhiBins, 0);
    RNG rng(seed);
    for (int i = 0; i < kSamples; ++i) {
        Float uc = rng.UniformFloat();
        Point2f u(rng.UniformFloat(), rng.UniformFloat());
        std::optional<Vector3f> w = sample(uc, u);
        if (!w) continue;
        // Binned in double: float acos puts directions 1e-8 above the horizon below it
        double theta = std::acos(std::clamp(double(w->z), -1.0, 1.0));
        double phi = std::atan2(double(w->y), double(w->x));
        if (phi < 0) phi += 2 * Pi;
        int tb = std::min(kThetaBins - 1, int(theta / Pi * kThetaBins));
        int pb = std::min(kPhiBins - 1, int(phi / (2 * Pi) * kPhiBins));
        observed[tb * kPhiBins + pb] += 1;
    }
    for (int tb = 0; tb < kThetaBins; ++tb)
        for (int pb = 0; pb < kPhiBins; ++pb) {
            double sum = 0;
            for (int a = 0; a < kSub; ++a)
                for (int b = 0; b < kSub; ++b) {
                    double theta = Pi * (tb + (a + 0.5) / kSub) / kThetaBins;
                    double phi = 2 * Pi * (pb + (b + 0.5) / kSub) / kPhiBins;
                    Vector3f w(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                               std::cos(theta));
                    sum += pdf(w) * std::sin(theta);  // dw = sin(theta) dtheta dphi
                }
            double dThetaDPhi = (Pi / kThetaBins) * (2 * Pi / kPhiBins);
            expected[tb * kPhiBins + pb] = sum / (kSub * kSub) * dThetaDPhi * kSamples;
        }
    return ChiSquareTest(observed, expected, 0.01, kNumTests);
}

Vector3f Wo(Float cosTheta, Float phi = 0.7f) {
    Float s = SafeSqrt(1 - cosTheta * cosTheta);
    return Vector3f(s * std::cos(phi), s * std::sin(phi), cosTheta);
}

ChiSquareResult TestBxDF(const BxDF& bxdf, Vector3f wo, uint64_t seed,
                         TransportMode mode = TransportMode::Radiance) {
    return TestSampler(
        [&](Float uc, Point2f u) -> std::optional<Vector3f> {
            auto bs = bxdf.Sample_f(wo, uc, u, mode);
            if (!bs || bs->pdf == 0) return std::nullopt;
            return bs->wi;
        },
        [&](Vector3f wi) { return bxdf.PDF(wo, wi, mode); }, seed);
}

SampledSpectrum Gold(Float v) { return SampledSpectrum(v); }

}  // namespace

TEST(SamplingChi2, Diffuse) {
    BxDF bxdf = DiffuseBxDF(SampledSpectrum(0.5f));
    auto r = TestBxDF(bxdf, Wo(0.6f), 1);
    EXPECT_TRUE(r.passed) << r.message;
    auto r2 = TestBxDF(bxdf, Wo(-0.3f), 2);  // from below: lobe on the lower side
    EXPECT_TRUE(r2.passed) << r2.message;
}

TEST(SamplingChi2, DiffuseTransmission) {
    SampledSpectrum R(0.2f), T(0.6f);
    R[1] = 0.7f;  // reflection picked by R's largest value, not its first
    BxDF bxdf = DiffuseTransmissionBxDF(R, T);
    for (Float cosTheta : {0.6f, -0.3f}) {
        auto r = TestBxDF(bxdf, Wo(cosTheta), 3);
        EXPECT_TRUE(r.passed) << r.message;
    }
    // Directional albedo R + T from either side
    std::vector<Float> uc(4096);
    std::vector<Point2f> u2(4096);
    for (size_t i = 0; i < uc.size(); ++i)
        uc[i] = (i + 0.5f) / uc.size(),
        u2[i] = Point2f(((i * 37) % 64 + 0.5f) / 64, ((i * 11) % 64 + 0.5f) / 64);
    for (Float cosTheta : {0.8f, -0.5f}) {
        SampledSpectrum rho = bxdf.rho(Wo(cosTheta), uc, u2);
        for (int i = 0; i < NSpectrumSamples; ++i) EXPECT_NEAR(rho[i], R[i] + T[i], 2e-3f);
    }
}

// The exit of a subsurface material (pbrt-v4's NormalizedFresnelBxDF): cosine sampling on the
// side of wo; its albedo for radiance is eta^2 times the exit fraction
TEST(SamplingChi2, NormalizedFresnel) {
    NormalizedFresnelBxDF exit(1.33f);
    BxDF bxdf = exit;
    for (Float cosTheta : {0.7f, -0.4f}) {
        auto r = TestBxDF(bxdf, Wo(cosTheta), 5);
        EXPECT_TRUE(r.passed) << r.message;
    }
    // integral f |cos| dwi by the midpoint rule in cos theta (f is isotropic in phi)
    double rho = 0;
    constexpr int kN = 20000;
    for (int i = 0; i < kN; ++i) {
        Float mu = (i + 0.5f) / kN;
        rho += bxdf.f(Wo(0.5f), Wo(mu), TransportMode::Radiance)[0] * mu * 2 * Pi / kN;
    }
    EXPECT_NEAR(rho, Sqr(1.33f) * exit.ExitFraction(), 1e-4);
}

TEST(SamplingChi2, RoughConductorIsotropic) {
    int seed = 10;
    for (Float alpha : {0.1f, 0.3f, 0.8f})
        for (Float cosTheta : {0.9f, 0.4f, 0.05f}) {
            BxDF bxdf =
                ConductorBxDF(TrowbridgeReitzDistribution(alpha, alpha), Gold(0.2f), Gold(3.0f));
            auto r = TestBxDF(bxdf, Wo(cosTheta), seed++);
            EXPECT_TRUE(r.passed) << "alpha " << alpha << " cos " << cosTheta << ": " << r.message;
        }
}

TEST(SamplingChi2, RoughConductorAnisotropic) {
    int seed = 30;
    for (auto [ax, ay] : {std::pair{0.1f, 0.5f}, std::pair{0.6f, 0.2f}})
        for (Float cosTheta : {0.8f, 0.1f}) {
            BxDF bxdf = ConductorBxDF(TrowbridgeReitzDistribution(ax, ay), Gold(1.5f), Gold(1));
            auto r = TestBxDF(bxdf, Wo(cosTheta, 1.1f), seed++);
            EXPECT_TRUE(r.passed) << ax << "," << ay << " cos " << cosTheta << ": " << r.message;
        }
}

// RGL measured BRDFs tabulated from rough conductors (rgl_test_data.h): the luminance warp
// followed by the visible-normal warp, against MeasuredBxDF::PDF
TEST(SamplingChi2, MeasuredIsotropic) {
    MeasuredBxDFData data = MeasuredBxDFData::FromTensor(
        TensorFile::Parse(test::WriteRGLConductor(test::KilnTestConductor())));
    BxDF bxdf = MeasuredBxDF(&data, SampledWavelengths::SampleUniform(0, 400, 800));
    int seed = 200;
    for (Float cosTheta : {0.9f, 0.3f, -0.6f}) {
        auto r = TestBxDF(bxdf, Wo(cosTheta), seed++);
        EXPECT_TRUE(r.passed) << "cos " << cosTheta << ": " << r.message;
    }
}

TEST(SamplingChi2, MeasuredAnisotropic) {
    test::RGLConductor model;
    model.alphaX = 0.2f, model.alphaY = 0.5f, model.nPhi = 9, model.nTheta = 6;
    MeasuredBxDFData data =
        MeasuredBxDFData::FromTensor(TensorFile::Parse(test::WriteRGLConductor(model)));
    BxDF bxdf = MeasuredBxDF(&data, SampledWavelengths::SampleUniform(0, 400, 800));
    int seed = 210;
    for (auto [cosTheta, phi] : {std::pair{0.7f, 1.1f}, std::pair{0.2f, -2.f}}) {
        auto r = TestBxDF(bxdf, Wo(cosTheta, phi), seed++);
        EXPECT_TRUE(r.passed) << "cos " << cosTheta << " phi " << phi << ": " << r.message;
    }
}

TEST(SamplingChi2, RoughDielectric) {
    int seed = 50;
    for (Float eta : {1.5f, 1 / 1.5f})
        for (Float alpha : {0.2f, 0.6f})
            for (Float cosTheta : {0.8f, 0.2f, -0.5f}) {
                BxDF bxdf = DielectricBxDF(eta, TrowbridgeReitzDistribution(alpha, alpha));
                auto r = TestBxDF(bxdf, Wo(cosTheta), seed++);
                EXPECT_TRUE(r.passed) << "eta " << eta << " alpha " << alpha << " cos " << cosTheta
                                      << ": " << r.message;
            }
    // An absorbing dielectric (glass in an infrared absorption band): the same sampling with
    // its complex Fresnel weights
    for (Float cosTheta : {0.8f, -0.5f}) {
        BxDF bxdf = DielectricBxDF(1.5f, TrowbridgeReitzDistribution(0.3f, 0.3f), 0.8f);
        auto r = TestBxDF(bxdf, Wo(cosTheta), seed++);
        EXPECT_TRUE(r.passed) << "k 0.8 cos " << cosTheta << ": " << r.message;
    }
}

TEST(SamplingChi2, TrowbridgeReitzVisibleNormals) {
    int seed = 70;
    for (auto [ax, ay] : {std::pair{0.3f, 0.3f}, std::pair{0.1f, 0.6f}, std::pair{1.0f, 1.0f}})
        for (Float cosTheta : {0.95f, 0.3f, -0.6f}) {
            TrowbridgeReitzDistribution d(ax, ay);
            Vector3f w = Wo(cosTheta, 2.0f);
            auto r = TestSampler(
                [&](Float, Point2f u) -> std::optional<Vector3f> { return d.Sample_wm(w, u); },
                [&](Vector3f wm) {
                    // Normals visible from w (or from -w when w is below): upper hemisphere,
                    // facing w.
                    Vector3f wv = w.z < 0 ? -w : w;
                    return (wm.z > 0 && Dot(wv, wm) > 0) ? d.D(wv, wm) : 0;
                },
                seed++);
            EXPECT_TRUE(r.passed) << ax << "," << ay << " cos " << cosTheta << ": " << r.message;
        }
}

TEST(SamplingChi2, Hair) {
    // Lobes around the fibre axis (x): wo off the axis, both sides of the fibre, absorbing
    // and clear fibres, smooth and rough
    int seed = 90;
    struct Case {
        Float h, beta_m, beta_n, sigma, cosTheta;
    };
    for (Case c : {Case{-0.7f, 0.2f, 0.2f, 0.f, 0.6f}, Case{0.3f, 0.5f, 0.6f, 0.f, 0.2f},
                   Case{0.9f, 0.3f, 0.3f, 1.5f, 0.9f}, Case{0.f, 0.25f, 0.8f, 0.4f, -0.4f},
                   Case{-0.2f, 0.8f, 0.25f, 3.f, 0.7f}, Case{0.5f, 0.35f, 0.4f, 0.1f, 0.05f}}) {
        BxDF bxdf = HairBxDF(c.h, 1.55f, SampledSpectrum(c.sigma), c.beta_m, c.beta_n, 2.f);
        auto r = TestBxDF(bxdf, Wo(c.cosTheta, 0.9f), seed++);
        EXPECT_TRUE(r.passed) << "h " << c.h << " beta_m " << c.beta_m << " beta_n " << c.beta_n
                              << " sigma_a " << c.sigma << ": " << r.message;
    }
}

TEST(SamplingChi2, WrongPdfIsRejected) {
    // The test must be able to fail: conductor samples against a slightly wrong roughness.
    BxDF sampled = ConductorBxDF(TrowbridgeReitzDistribution(0.3f, 0.3f), Gold(1.5f), Gold(1));
    BxDF claimed = ConductorBxDF(TrowbridgeReitzDistribution(0.33f, 0.33f), Gold(1.5f), Gold(1));
    Vector3f wo = Wo(0.7f);
    auto r = TestSampler(
        [&](Float uc, Point2f u) -> std::optional<Vector3f> {
            auto bs = sampled.Sample_f(wo, uc, u);
            if (!bs) return std::nullopt;
            return bs->wi;
        },
        [&](Vector3f wi) { return claimed.PDF(wo, wi, TransportMode::Radiance); }, 99);
    EXPECT_FALSE(r.passed);
}
