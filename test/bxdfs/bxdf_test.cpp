// BxDF and BSDF properties: reciprocity, energy conservation, albedos, robustness at grazing
// angles, and the BSDF's shading frame.
#include <gtest/gtest.h>

#include <vector>

#include "base/rng.h"
#include "base/sampling.h"
#include "base/statistics.h"
#include "direction.h"
#include "materials/bxdfs/bsdf.h"
#include "materials/bxdfs/fresnel.h"

using namespace kiln;

namespace {

using test::Dir;

// Mean and standard error of f cos / pdf over Sample_f (the directional albedo, reflection
// plus transmission), per wavelength 0. Importance mode: no 1/eta^2 radiance scaling.
RunningStats Albedo(const BxDF& bxdf, Vector3f wo, int n, uint64_t seed) {
    RunningStats stats;
    RNG rng(seed);
    for (int i = 0; i < n; ++i) {
        Float uc = rng.UniformFloat();
        Point2f u(rng.UniformFloat(), rng.UniformFloat());
        auto bs = bxdf.Sample_f(wo, uc, u, TransportMode::Importance);
        double v = (bs && bs->pdf > 0) ? bs->f[0] * AbsCosTheta(bs->wi) / bs->pdf : 0;
        stats.Add(v);
    }
    return stats;
}

std::vector<BxDF> AllBxDFs() {
    TrowbridgeReitzDistribution smooth(0, 0), rough(0.3f, 0.3f), aniso(0.1f, 0.7f);
    SampledSpectrum eta(0.2f), k(3.5f), one(1.f);
    return {DiffuseBxDF(SampledSpectrum(1.f)),
            ConductorBxDF(smooth, eta, k),
            ConductorBxDF(rough, eta, k),
            ConductorBxDF(aniso, eta, k),
            ConductorBxDF(TrowbridgeReitzDistribution(1, 1), one * 0.f, one * 0.f),
            DielectricBxDF(1.5f, smooth),
            DielectricBxDF(1.5f, rough),
            DielectricBxDF(1 / 1.5f, rough),
            DielectricBxDF(1.209f, smooth, 1.232f),  // soda-lime glass at 9.6 um
            DielectricBxDF(1.5f, rough, 0.5f),
            ThinDielectricBxDF(1.5f),
            CoatedDiffuseBxDF(DielectricBxDF(1.5f, smooth), DiffuseBxDF(one), 0.01f,
                              SampledSpectrum(0.f), 0, 10, 1),
            CoatedDiffuseBxDF(DielectricBxDF(1.5f, rough), DiffuseBxDF(one), 0.1f,
                              SampledSpectrum(0.8f), 0.3f, 10, 1),
            CoatedConductorBxDF(DielectricBxDF(1.5f, rough), ConductorBxDF(rough, eta, k), 0.01f,
                                SampledSpectrum(0.f), 0, 10, 1)};
}

}  // namespace

TEST(BxDF, EnergyConservation) {
    std::vector<BxDF> bxdfs = AllBxDFs();
    for (size_t b = 0; b < bxdfs.size(); ++b)
        for (Float c : {1.0f, 0.7f, 0.3f, 0.05f, -0.5f}) {
            RunningStats s = Albedo(bxdfs[b], Dir(c, 0.3f), 20000, 100 + b);
            EXPECT_LE(s.Mean(), 1 + 4 * s.StandardError() + 1e-4) << "bxdf " << b << " cos " << c;
            EXPECT_GE(s.Mean(), 0);
        }
}

TEST(BxDF, WhiteFurnaceLosslessBxDFs) {
    // Lossless BxDFs must return all energy (up to multiple scattering on rough ones, which a
    // single-scattering microfacet model loses: only check the smooth ones and diffuse).
    for (Float c : {0.9f, 0.4f, 0.1f}) {
        Vector3f wo = Dir(c, 1);
        for (BxDF bxdf : {BxDF(DiffuseBxDF(SampledSpectrum(1.f))),
                          BxDF(DielectricBxDF(1.5f, TrowbridgeReitzDistribution(0, 0))),
                          BxDF(ThinDielectricBxDF(1.5f))}) {
            RunningStats s = Albedo(bxdf, wo, 4000, 7);
            EXPECT_NEAR(s.Mean(), 1, 1e-5) << c;
        }
    }
}

TEST(BxDF, DiffuseAlbedoEqualsR) {
    BxDF bxdf = DiffuseBxDF(SampledSpectrum(0.37f));
    std::vector<Float> uc(256);
    std::vector<Point2f> u(256);
    RNG rng(3);
    for (int i = 0; i < 256; ++i)
        uc[i] = rng.UniformFloat(), u[i] = {rng.UniformFloat(), rng.UniformFloat()};
    for (Float c : {1.0f, 0.5f, 0.01f}) {
        EXPECT_NEAR(bxdf.rho(Dir(c, 0), uc, u)[0], 0.37f, 1e-5f);
    }
}

TEST(BxDF, SmoothConductorAlbedoEqualsFresnel) {
    SampledSpectrum eta({0.2f, 0.5f, 1.2f, 0.15f}), k({3.5f, 2.4f, 1.8f, 4.0f});
    BxDF bxdf = ConductorBxDF(TrowbridgeReitzDistribution(0, 0), eta, k);
    std::vector<Float> uc{0.5f};
    std::vector<Point2f> u{{0.5f, 0.5f}};
    for (Float c : {1.0f, 0.5f, 0.1f, 1e-3f}) {
        SampledSpectrum F = FrComplex(c, eta, k);
        SampledSpectrum rho = bxdf.rho(Dir(c, 0.2f), uc, u);
        for (int i = 0; i < NSpectrumSamples; ++i)
            EXPECT_NEAR(rho[i], F[i], 2e-5f * std::max<Float>(1, F[i]));
    }
}

TEST(BxDF, Reciprocity) {
    std::vector<BxDF> bxdfs = {DiffuseBxDF(SampledSpectrum(0.5f)),
                               ConductorBxDF(TrowbridgeReitzDistribution(0.3f, 0.3f),
                                             SampledSpectrum(0.2f), SampledSpectrum(3)),
                               ConductorBxDF(TrowbridgeReitzDistribution(0.1f, 0.6f),
                                             SampledSpectrum(1.2f), SampledSpectrum(1)),
                               DielectricBxDF(1.5f, TrowbridgeReitzDistribution(0.4f, 0.4f)),
                               DielectricBxDF(1 / 1.33f, TrowbridgeReitzDistribution(0.2f, 0.5f))};
    RNG rng(11);
    for (const BxDF& bxdf : bxdfs)
        for (int i = 0; i < 500; ++i) {
            Vector3f wo = Dir(rng.UniformFloat(), 2 * Pi * rng.UniformFloat());
            Vector3f wi = Dir(rng.UniformFloat(), 2 * Pi * rng.UniformFloat());
            Float a = bxdf.f(wo, wi, TransportMode::Radiance)[0];
            Float b = bxdf.f(wi, wo, TransportMode::Radiance)[0];
            EXPECT_NEAR(a, b, 1e-4f * std::max<Float>(1, a));
        }
}

TEST(BxDF, GrazingAndRoughnessExtremesFinite) {
    const Float alphas[] = {0, 1e-5f, 1e-3f, 0.01f, 0.1f, 0.5f, 1};
    const Float cosines[] = {1, 0.5f, 1e-2f, 1e-4f, 1e-6f, 0, -1e-6f, -0.5f};
    RNG rng(17);
    for (Float alpha : alphas) {
        TrowbridgeReitzDistribution d(alpha, alpha);
        for (BxDF bxdf : {BxDF(ConductorBxDF(d, SampledSpectrum(0.2f), SampledSpectrum(3))),
                          BxDF(DielectricBxDF(1.5f, d)), BxDF(DielectricBxDF(1 / 1.5f, d))})
            for (Float co : cosines)
                for (Float ci : cosines) {
                    Vector3f wo = Dir(co, 0.4f), wi = Dir(ci, 3.5f);
                    SampledSpectrum f = bxdf.f(wo, wi, TransportMode::Radiance);
                    Float pdf = bxdf.PDF(wo, wi, TransportMode::Radiance);
                    EXPECT_TRUE(f.IsFinite() && f.MinComponentValue() >= 0) << alpha;
                    EXPECT_TRUE(std::isfinite(pdf) && pdf >= 0) << alpha;
                    auto bs = bxdf.Sample_f(wo, rng.UniformFloat(),
                                            {rng.UniformFloat(), rng.UniformFloat()});
                    if (bs) {
                        EXPECT_TRUE(bs->f.IsFinite() && std::isfinite(bs->pdf) && bs->pdf >= 0)
                            << alpha << " " << co;
                        EXPECT_FALSE(bs->wi.HasNaN());
                    }
                }
        if (alpha > 0) {
            for (Float c : cosines) {
                Vector3f w = Dir(c, 0.9f);
                EXPECT_TRUE(std::isfinite(d.D(w)) && std::isfinite(d.G1(w)) &&
                            std::isfinite(d.Lambda(w)));
                EXPECT_FALSE(
                    d.Sample_wm(Dir(std::max<Float>(c, 1e-6f), 0.9f), {0.3f, 0.6f}).HasNaN());
            }
        }
    }
}

TEST(BxDF, MicrofacetNormalization) {
    // Projected-area normalisation: integral of D(wm) cos(theta_m) over the hemisphere is 1;
    // integral of D(w, wm) over visible normals is 1.
    for (auto [ax, ay] : {std::pair{0.2f, 0.2f}, std::pair{0.5f, 0.1f}, std::pair{1.0f, 1.0f}}) {
        TrowbridgeReitzDistribution d(ax, ay);
        Vector3f w = Dir(0.4f, 0.3f);
        double sumD = 0, sumV = 0;
        const int n = 400;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                // Equal-area grid in (cos theta, phi) on the upper hemisphere.
                Vector3f wm = Dir((i + 0.5f) / n, 2 * Pi * (j + 0.5f) / n);
                sumD += d.D(wm) * wm.z;
                if (Dot(w, wm) > 0) sumV += d.D(w, wm);
            }
        double dOmega = 2 * Pi / (double(n) * n);
        EXPECT_NEAR(sumD * dOmega, 1, 0.02) << ax << "," << ay;
        EXPECT_NEAR(sumV * dOmega, 1, 0.02) << ax << "," << ay;
    }
    EXPECT_FLOAT_EQ(TrowbridgeReitzDistribution::RoughnessToAlpha(0.25f), 0.5f);
    TrowbridgeReitzDistribution s(0, 0);
    EXPECT_TRUE(s.EffectivelySmooth());
    s.Regularize();
    EXPECT_FALSE(s.EffectivelySmooth());
}

TEST(BSDF, FrameRoundTripAndDispatch) {
    EXPECT_FALSE(BSDF());
    RNG rng(23);
    BxDF bxdf = ConductorBxDF(TrowbridgeReitzDistribution(0.3f, 0.3f), SampledSpectrum(0.2f),
                              SampledSpectrum(3));
    for (int i = 0; i < 100; ++i) {
        Vector3f n = Dir(2 * rng.UniformFloat() - 1, 2 * Pi * rng.UniformFloat());
        Vector3f dpdu = Vector3f(rng.UniformFloat(), rng.UniformFloat(), rng.UniformFloat()) * 3;
        BSDF bsdf(Normal3f(n), dpdu, bxdf);
        ASSERT_TRUE(bsdf);
        Vector3f zl = bsdf.RenderToLocal(n);
        EXPECT_NEAR(zl.z, 1, 1e-5f);
        // The local x axis lies along dpdu's component in the tangent plane.
        Vector3f xl = bsdf.RenderToLocal(Normalize(GramSchmidt(dpdu, n)));
        EXPECT_NEAR(xl.x, 1, 1e-4f);
        Vector3f v = Dir(2 * rng.UniformFloat() - 1, 2 * Pi * rng.UniformFloat());
        Vector3f rt = bsdf.LocalToRender(bsdf.RenderToLocal(v));
        EXPECT_NEAR(rt.x, v.x, 1e-5f);
        EXPECT_NEAR(rt.y, v.y, 1e-5f);
        EXPECT_NEAR(rt.z, v.z, 1e-5f);
        // Sample_f returns render-space directions consistent with f and PDF.
        Vector3f wo = bsdf.LocalToRender(Dir(0.7f, 1.0f));
        auto bs = bsdf.Sample_f(wo, 0.5f, {rng.UniformFloat(), rng.UniformFloat()});
        if (bs) {
            SampledSpectrum f = bsdf.f(wo, bs->wi);
            EXPECT_NEAR(f[0], bs->f[0], 1e-3f * std::max<Float>(1, f[0]));
            EXPECT_NEAR(bsdf.PDF(wo, bs->wi), bs->pdf, 1e-3f * std::max<Float>(1, bs->pdf));
        }
    }
    // Degenerate dpdu (parallel to n) still gives an orthonormal frame.
    BSDF d(Normal3f(0, 0, 1), Vector3f(0, 0, 2), bxdf);
    Vector3f l = d.RenderToLocal(Vector3f(0, 0, 1));
    EXPECT_NEAR(l.z, 1, 1e-6f);
    EXPECT_EQ(d.Flags(), BxDFFlags::GlossyReflection);
    // wo in the tangent plane yields nothing.
    BSDF axis(Normal3f(0, 0, 1), Vector3f(1, 0, 0), bxdf);
    EXPECT_FALSE(axis.Sample_f(Vector3f(1, 0, 0), 0.5f, {0.5f, 0.5f}));
    EXPECT_EQ(axis.PDF(Vector3f(0, 1, 0), Vector3f(0, 0, 1)), 0);
}

TEST(BxDF, LayeredEvaluationMatchesSampling) {
    // The albedo from integrating the stochastic f over the hemisphere must agree with the
    // albedo from Sample_f's throughput f cos / pdf (two independent estimators). maxDepth is
    // large so that the two walks' different truncation biases vanish.
    SampledSpectrum one(1.f);
    TrowbridgeReitzDistribution rough(0.3f, 0.3f);
    std::vector<BxDF> layered = {
        CoatedDiffuseBxDF(DielectricBxDF(1.5f, TrowbridgeReitzDistribution(0, 0)),
                          DiffuseBxDF(one * 0.6f), 0.01f, SampledSpectrum(0.f), 0, 100, 1),
        CoatedDiffuseBxDF(DielectricBxDF(1.5f, rough), DiffuseBxDF(one * 0.6f), 0.1f,
                          SampledSpectrum(0.5f), 0.2f, 100, 1)};
    for (const BxDF& bxdf : layered) {
        Vector3f wo = Dir(0.6f, 0.5f);
        RunningStats sampled = Albedo(bxdf, wo, 40000, 31), integrated;
        RNG rng(37);
        for (int i = 0; i < 40000; ++i) {
            Vector3f wi = SampleCosineHemisphere({rng.UniformFloat(), rng.UniformFloat()});
            // f cos / (cos / pi); the specular reflection of the smooth coat is not in f.
            integrated.Add(bxdf.f(wo, wi, TransportMode::Importance)[0] * Pi);
        }
        double specular = 0;
        if (bxdf.Flags() & BxDFFlags::Specular) specular = FrDielectric(wo.z, 1.5f);
        double sigma = std::sqrt(Sqr(sampled.StandardError()) + Sqr(integrated.StandardError()));
        EXPECT_NEAR(integrated.Mean() + specular, sampled.Mean(), 4 * sigma + 5e-3);
        EXPECT_GT(integrated.Mean(), 0.1);
    }
}
