// pbrt-v4's photon beam diffusion table and TabulatedBSSRDF (bssrdf_table.h,
// tabulated_bssrdf.h): the table against closed forms, its interpolation's integrals, and the
// exit-point sampling against its density (chi-square).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "base/rng.h"
#include "base/statistics.h"
#include "materials/bxdfs/bssrdf_table.h"
#include "materials/bxdfs/normalized_fresnel_bxdf.h"
#include "materials/bxdfs/tabulated_bssrdf.h"

using namespace kiln;

namespace {

// integral_0^R f(r) 2 pi r dr by the midpoint rule on log-spaced radii from 1e-6 R (f finite
// at 0, so the innermost disc is negligible)
template <typename F>
double PlaneIntegral(F f, double R, int n = 4000) {
    double sum = 0, lo = std::log(1e-6 * R), hi = std::log(R);
    for (int i = 0; i < n; ++i) {
        double a = std::exp(lo + (hi - lo) * i / n), b = std::exp(lo + (hi - lo) * (i + 1) / n);
        double r = (a + b) / 2;
        sum += f(r) * Pi * (b * b - a * a);
    }
    return sum;
}

const BSSRDFTable& Table() {
    static const BSSRDFTable table(0, 1.33f);
    return table;
}

}  // namespace

TEST(BSSRDFTable, EffectiveAlbedoIsMonotoneFromZero) {
    const BSSRDFTable& t = Table();
    auto start = std::chrono::steady_clock::now();
    BSSRDFTable again(0.3f, 1.5f);
    std::printf(
        "table built in %.1f ms\n",
        1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    const BSSRDFTable* tables[] = {&t, &again};
    for (const BSSRDFTable* table : tables) {
        std::span<const Float> rhoEff = table->RhoEff();
        EXPECT_EQ(rhoEff[0], 0);  // no scattering, nothing returns
        for (size_t i = 1; i < rhoEff.size(); ++i) EXPECT_GT(rhoEff[i], rhoEff[i - 1]) << i;
        // Without absorption all light returns: photon beam diffusion gives 1 within a few
        // percent (1.019 at g = 0, eta = 1.33; 0.969 at g = 0.3, eta = 1.5)
        EXPECT_NEAR(rhoEff.back(), 1, 0.05);
        std::printf("rhoEff(rho = 0.5, 0.9, 0.99, 1) = %.4f %.4f %.4f %.4f\n",
                    table->EffectiveAlbedo(0.5f), table->EffectiveAlbedo(0.9f),
                    table->EffectiveAlbedo(0.99f), table->EffectiveAlbedo(1));
    }
}

// Single scattering under an index-matched boundary (eta = 1, isotropic): a collimated beam
// at normal incidence on a semi-infinite medium of albedo rho reflects
// (rho / 2) integral_0^1 mu / (1 + mu) dmu = (rho / 2)(1 - ln 2) of its power after one
// scattering (Chandrasekhar's first-order term). The beam integral's 100 stratified samples
// reproduce it to about 1 %.
TEST(BSSRDFTable, SingleScatteringMatchesClosedForm) {
    for (Float rho : {0.3f, 0.8f, 1.0f}) {
        double total = PlaneIntegral(
            [&](double r) { return BeamDiffusionSS(rho, 1 - rho, 0, 1, Float(r)); }, 200);
        double expected = rho / 2 * (1 - std::log(2.0));
        EXPECT_NEAR(total, expected, 0.01 * expected) << "rho " << rho;
    }
}

TEST(BSSRDFTable, InversionRecoversTheAlbedo) {
    const BSSRDFTable& t = Table();
    for (Float rho : {0.05f, 0.3f, 0.7f, 0.95f, 0.999f})
        EXPECT_NEAR(t.InvertEffectiveAlbedo(t.EffectiveAlbedo(rho)), rho, 1e-4f);
    SampledSpectrum sigma_a, sigma_s;
    SampledSpectrum target(0.4f), mfp(0.2f);
    target[2] = 0.8f;
    SubsurfaceFromDiffuse(t, target, mfp, &sigma_a, &sigma_s);
    for (int i = 0; i < NSpectrumSamples; ++i) {
        EXPECT_NEAR(1 / (sigma_a[i] + sigma_s[i]), mfp[i], 1e-5f);
        EXPECT_NEAR(t.EffectiveAlbedo(sigma_s[i] / (sigma_a[i] + sigma_s[i])), target[i], 1e-4f);
    }
    // No mean free path (a spectrum that is 0 there): no medium, not a division by 0
    mfp[1] = 0;
    SubsurfaceFromDiffuse(t, target, mfp, &sigma_a, &sigma_s);
    EXPECT_EQ(sigma_a[1], 0);
    EXPECT_EQ(sigma_s[1], 0);
}

// Sp integrates over a plane to the effective albedo, and PDF_Sr to 1, per wavelength.
TEST(TabulatedBSSRDF, ProfileIntegrals) {
    const BSSRDFTable& t = Table();
    SampledSpectrum sigma_a(0.5f), sigma_s(20.f);
    sigma_a[1] = 2, sigma_s[2] = 5, sigma_a[3] = 0.05f;
    TabulatedBSSRDF b(Point3f(0, 0, 0), Normal3f(0, 0, 1), 1.33f, sigma_a, sigma_s, &t);
    for (int i = 0; i < NSpectrumSamples; ++i) {
        double R = t.RadiusSamples().back() / b.SigmaT()[i];
        double sp = PlaneIntegral([&](double r) { return b.Sr(Float(r))[i]; }, R, 20000);
        double pdf = PlaneIntegral([&](double r) { return b.PDF_Sr(Float(r))[i]; }, R, 20000);
        EXPECT_NEAR(sp, t.EffectiveAlbedo(b.Rho()[i]), 2e-3) << i;
        EXPECT_NEAR(pdf, 1, 2e-3) << i;
    }
}

// Exit points: probe segments (three projection axes) intersected with a plane through the
// entry point tilted 40 degrees from the entry's normal, binned by polar coordinates in the
// plane, against PDF_Sp integrated over each bin where the probes reach (every segment lies
// within r_max of the entry point).
TEST(TabulatedBSSRDF, ExitPointSamplingChiSquare) {
    const BSSRDFTable& t = Table();
    SampledSpectrum sigma_a(0.3f), sigma_s(3.f);
    TabulatedBSSRDF b(Point3f(0, 0, 0), Normal3f(0, 0, 1), 1.33f, sigma_a, sigma_s, &t);
    const Float tilt = Radians(40);
    const Vector3f planeN(std::sin(tilt), 0, std::cos(tilt));
    const Frame plane = Frame::FromZ(planeN);
    const Float rMax = *b.SampleSr(0.999f);
    const double extent = rMax;  // hits lie within r_max of the entry point
    constexpr int kRadial = 40, kAngular = 16, kSamples = 200000, kSub = 6;
    auto binOf = [&](double r, double phi) {
        int rb = std::min(kRadial - 1, int(std::sqrt(r / extent) * kRadial));
        int pb = std::min(kAngular - 1, int(phi / (2 * Pi) * kAngular));
        return rb * kAngular + pb;
    };
    std::vector<double> observed(kRadial * kAngular, 0), expected(kRadial * kAngular, 0);
    RNG rng(7);
    for (int i = 0; i < kSamples; ++i) {
        Float u1 = rng.UniformFloat();
        Point2f u2(rng.UniformFloat(), rng.UniformFloat());
        std::optional<BSSRDFProbeSegment> seg = b.SampleSp(u1, u2);
        if (!seg) continue;
        Vector3f d = seg->p1 - seg->p0;
        Float denom = Dot(d, planeN);
        if (denom == 0) continue;
        Float s = -Dot(Vector3f(seg->p0), planeN) / denom;
        if (s < 0 || s > 1) continue;
        Vector3f local = plane.ToLocal(Vector3f(seg->p0 + s * d));
        double r = std::hypot(double(local.x), double(local.y));
        if (r >= extent) continue;
        double phi = std::atan2(double(local.y), double(local.x));
        observed[size_t(binOf(r, phi < 0 ? phi + 2 * Pi : phi))] += 1;
    }
    // Each axis's density at a point of the plane, where that axis can sample it
    const Frame f = Frame::FromZ(Vector3f(0, 0, 1));
    const Vector3f nLocal = f.ToLocal(planeN);
    auto density = [&](Vector3f p) {
        Vector3f q = f.ToLocal(p);
        const double rProj[3] = {std::hypot(q.y, q.z), std::hypot(q.z, q.x), std::hypot(q.x, q.y)};
        const double prob[3] = {0.25, 0.25, 0.5}, n[3] = {nLocal.x, nLocal.y, nLocal.z};
        double sum = 0;
        if (Length(p) >= rMax) return sum;
        for (int a = 0; a < 3; ++a) sum += prob[a] * std::abs(n[a]) * b.PDF_Sr(Float(rProj[a]))[0];
        return sum;
    };
    for (int rb = 0; rb < kRadial; ++rb)
        for (int pb = 0; pb < kAngular; ++pb) {
            double sum = 0;
            for (int a = 0; a < kSub; ++a)
                for (int c = 0; c < kSub; ++c) {
                    // Bins are uniform in sqrt(r): r = extent v^2, dA = 2 extent^2 v^3 dv dphi
                    double v = (rb + (a + 0.5) / kSub) / kRadial;
                    double phi = 2 * Pi * (pb + (c + 0.5) / kSub) / kAngular;
                    double r = extent * v * v;
                    Vector3f p = plane.FromLocal(
                        Vector3f(Float(r * std::cos(phi)), Float(r * std::sin(phi)), 0));
                    sum += density(p) * 2 * extent * extent * v * v * v;
                }
            expected[size_t(rb * kAngular + pb)] =
                sum / (kSub * kSub) * (1.0 / kRadial) * (2 * Pi / kAngular) * kSamples;
        }
    ChiSquareResult result = ChiSquareTest(observed, expected, 0.01, 1);
    EXPECT_TRUE(result.passed) << result.message;
    // PDF_Sp is the sum of the three axes' densities
    Vector3f p = plane.FromLocal(Vector3f(0.3f * rMax, 0.2f * rMax, 0));
    EXPECT_NEAR(b.PDF_Sp(Point3f(p), Normal3f(planeN))[0], density(p), 1e-4 * density(p));
}

// The exit's BxDF lets out (1 - 2 integral F mu dmu) / c of what reaches it, c from pbrt-v4's
// polynomial fit of the Fresnel moment: close to 1, not exactly
TEST(NormalizedFresnelBxDF, ExitFraction) {
    for (Float eta : {1.33f, 1.5f}) {
        Float C = NormalizedFresnelBxDF(eta).ExitFraction();
        std::printf("eta %.2f: exit fraction %.5f\n", eta, C);
        EXPECT_NEAR(C, 1, 0.05f);
    }
}

// The whole exit estimator on a sphere (probe segments intersected analytically, one hit chosen
// uniformly, weight hits Sp / PDF_Sp): its mean is the integral of Sp over the sphere within
// the probe radius r_max, which for a sphere of diameter above r_max equals the plane's (a cap
// within chord d has area pi d^2): 0.999 rhoEff, the albedo the thermal module gives the
// BSSRDF (thermal/material_albedo.h). Tolerance: 4 standard errors of the measured variance.
TEST(TabulatedBSSRDF, ExitEstimatorOnASphereReturnsTheEffectiveAlbedo) {
    const BSSRDFTable& t = Table();
    for (Float rho : {0.6f, 0.99f}) {
        SampledSpectrum sigma_a(10 * (1 - rho)), sigma_s(10 * rho);
        const Point3f po(0, 0, 0);
        const Normal3f ns(0, 0.6f, 0.8f);
        TabulatedBSSRDF b(po, ns, 1.33f, sigma_a, sigma_s, &t);
        const Float R = 2 * *b.SampleSr(0.999f);
        const Point3f center = po - R * Vector3f(ns);
        RunningStats stats;
        RNG rng(11);
        for (int i = 0; i < 250000; ++i) {
            std::optional<BSSRDFProbeSegment> seg =
                b.SampleSp(rng.UniformFloat(), Point2f(rng.UniformFloat(), rng.UniformFloat()));
            double w = 0;
            if (seg) {
                // |p0 + s d - c|^2 = R^2 for s in [0, 1]
                Vector3f d = seg->p1 - seg->p0, oc = seg->p0 - center;
                double A = Dot(d, d), B = 2 * Dot(oc, d), C = Dot(oc, oc) - double(R) * R;
                double disc = B * B - 4 * A * C;
                std::vector<Point3f> hits;
                if (disc > 0)
                    for (double s :
                         {(-B - std::sqrt(disc)) / (2 * A), (-B + std::sqrt(disc)) / (2 * A)})
                        if (s >= 0 && s <= 1) hits.push_back(seg->p0 + Float(s) * d);
                if (!hits.empty()) {
                    Point3f p =
                        hits[std::min(hits.size() - 1, size_t(rng.UniformFloat() * hits.size()))];
                    Normal3f n(Normalize(p - center));
                    w = hits.size() * b.Sp(p)[0] / b.PDF_Sp(p, n)[0];
                }
            }
            stats.Add(w);
        }
        double expected = 0.999 * t.EffectiveAlbedo(rho);
        std::printf("rho %.2f: estimator %.5f +- %.5f, 0.999 rhoEff %.5f\n", rho, stats.Mean(),
                    stats.StandardError(), expected);
        EXPECT_NEAR(stats.Mean(), expected, 4 * stats.StandardError());
        EXPECT_LT(stats.StandardError(), 0.002 * expected);  // the test can see 0.8 %
    }
}
