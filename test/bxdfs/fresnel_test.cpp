// Fresnel equations against closed forms, limits and degenerate inputs.
#include <gtest/gtest.h>

#include <complex>
#include <iterator>

#include "materials/bxdfs/dielectric_bxdf.h"
#include "materials/bxdfs/fresnel.h"

using namespace kiln;

TEST(Fresnel, DielectricNormalIncidence) {
    for (Float n : {1.1f, 1.33f, 1.5f, 2.4f, 1 / 1.5f}) {
        Float expected = Sqr((n - 1) / (n + 1));
        EXPECT_NEAR(FrDielectric(1, n), expected, 1e-6f) << n;
        // From the other side the normal-incidence reflectance is the same.
        EXPECT_NEAR(FrDielectric(-1, 1 / n), expected, 1e-6f) << n;
    }
}

TEST(Fresnel, ComplexNormalIncidence) {
    const Float ns[] = {0.2f, 1.5f, 0.27f}, ks[] = {3.0f, 0.0f, 2.8f};
    for (int i = 0; i < 3; ++i) {
        std::complex<Float> eta(ns[i], ks[i]);
        Float expected = std::norm((eta - Float(1)) / (eta + Float(1)));
        EXPECT_NEAR(FrComplex(1, eta), expected, 1e-6f);
        SampledSpectrum r = FrComplex(1, SampledSpectrum(ns[i]), SampledSpectrum(ks[i]));
        for (int j = 0; j < NSpectrumSamples; ++j) EXPECT_NEAR(r[j], expected, 1e-6f);
    }
}

// The spectral form computes every wavelength's lanes together (selects instead of branches):
// each lane must be exactly the scalar form's value, in every case the scalar form branches on
// (eta = 0, k = 0, eta below 1 beyond the critical angle, grazing and normal incidence, huge
// and tiny constants).
TEST(Fresnel, SpectralComplexEqualsTheScalarFormLaneByLane) {
    const Float etas[] = {0, 0.05f, 0.2f, 0.27f, 0.6f, 1, 1.5f, 3.9f, 1e-20f, 1e20f};
    const Float ks[] = {0, 1e-6f, 0.5f, 2.8f, 3, 7.5f, 1e-20f, 1e20f};
    const Float cosines[] = {-0.5f, 0, 1e-7f, 0.01f, 0.3f, 0.5f, 0.70710677f, 0.99f, 1, 1.5f};
    int compared = 0;
    const size_t nEta = std::size(etas), nK = std::size(ks);
    for (Float c : cosines)
        for (size_t e = 0; e < nEta; ++e)
            for (size_t j = 0; j < nK; ++j) {
                // Four different constants per call, so lanes of each kind mix
                SampledSpectrum eta, k;
                for (int i = 0; i < NSpectrumSamples; ++i) {
                    eta[i] = etas[(e + 3 * size_t(i)) % nEta];
                    k[i] = ks[(j + 5 * size_t(i)) % nK];
                }
                SampledSpectrum r = FrComplex(c, eta, k);
                for (int i = 0; i < NSpectrumSamples; ++i, ++compared) {
                    Float scalar = FrComplex(c, std::complex<Float>(eta[i], k[i]));
                    EXPECT_EQ(r[i], scalar) << "cos " << c << ", eta " << eta[i] << ", k " << k[i];
                }
            }
    EXPECT_EQ(compared, 10 * 10 * 8 * NSpectrumSamples);
}

TEST(Fresnel, BrewsterAngle) {
    for (Float n : {1.33f, 1.5f, 2.0f}) {
        Float cosB = 1 / std::sqrt(1 + n * n);  // tan(theta_B) = n
        EXPECT_NEAR(FrDielectricPolarized(cosB, n).Rp, 0, 1e-6f);
        EXPECT_GT(FrDielectricPolarized(cosB, n).Rs, 0.01f);
        EXPECT_NEAR(FrComplexPolarized(cosB, {n, 0}).Rp, 0, 1e-6f);
    }
}

TEST(Fresnel, ComplexWithZeroKEqualsDielectric) {
    for (Float n : {1.2f, 1.5f, 2.5f, 1 / 1.5f, 0.8f})
        for (int i = 0; i <= 100; ++i) {
            Float c = i / 100.f;
            EXPECT_NEAR(FrComplex(c, std::complex<Float>(n, 0)), FrDielectric(c, n), 1e-6f)
                << "n " << n << " cos " << c;
        }
}

TEST(Fresnel, PolarizedAverageIsUnpolarized) {
    for (Float n : {1.5f, 1 / 1.5f, 3.0f})
        for (int i = -50; i <= 50; ++i) {
            Float c = i / 50.f;
            FresnelRsRp r = FrDielectricPolarized(c, n);
            EXPECT_NEAR((r.Rs + r.Rp) / 2, FrDielectric(c, n), 1e-6f);
        }
    for (int i = 0; i <= 50; ++i) {
        Float c = i / 50.f;
        std::complex<Float> eta(0.2f, 3.5f);
        FresnelRsRp r = FrComplexPolarized(c, eta);
        EXPECT_NEAR((r.Rs + r.Rp) / 2, FrComplex(c, eta), 1e-6f);
        FresnelAmplitudes a = FrComplexAmplitudes(c, eta);
        EXPECT_NEAR(std::norm(a.rs), r.Rs, 1e-6);
        EXPECT_NEAR(std::norm(a.rp), r.Rp, 1e-6);
    }
}

TEST(Fresnel, DegenerateInputsFiniteInUnitInterval) {
    const Float cosines[] = {0, 1e-12f, 1e-6f, 1, -1e-12f, -1e-6f, -1};
    const Float etas[] = {1, 1.5f, 1 / 1.5f, 1e-3f, 1e3f};
    for (Float c : cosines)
        for (Float e : etas) {
            Float r = FrDielectric(c, e);
            EXPECT_TRUE(std::isfinite(r) && r >= 0 && r <= 1) << c << " " << e << " " << r;
            FresnelRsRp p = FrDielectricPolarized(c, e);
            EXPECT_TRUE(p.Rs >= 0 && p.Rs <= 1 && p.Rp >= 0 && p.Rp <= 1);
            Float rc = FrComplex(c, std::complex<Float>(e, 2));
            EXPECT_TRUE(std::isfinite(rc) && rc >= 0 && rc <= 1) << c << " " << e;
            Float rc0 = FrComplex(c, std::complex<Float>(e, 0));
            EXPECT_TRUE(std::isfinite(rc0) && rc0 >= 0 && rc0 <= 1) << c << " " << e;
        }
    // Index-matched interface: no reflection except exactly at grazing incidence.
    EXPECT_NEAR(FrDielectric(0.5f, 1), 0, 1e-7f);
    // Grazing incidence reflects everything.
    EXPECT_NEAR(FrDielectric(0, 1.5f), 1, 1e-6f);
    EXPECT_NEAR(FrComplex(0, std::complex<Float>(0.2f, 3)), 1, 1e-6f);
}

TEST(Fresnel, TotalInternalReflection) {
    Float eta = 1 / 1.5f;  // leaving glass into air
    Float cosCritical = std::sqrt(1 - eta * eta);
    EXPECT_EQ(FrDielectric(cosCritical * 0.99f, eta), 1);
    EXPECT_LT(FrDielectric(cosCritical * 1.01f, eta), 1);
    EXPECT_NEAR(FrComplex(cosCritical * 0.99f, {eta, 0}), 1, 1e-6f);
    Float etap;
    Vector3f wt;
    Vector3f wi(SafeSqrt(1 - Sqr(cosCritical * 0.99f)), 0, cosCritical * 0.99f);
    EXPECT_FALSE(Refract(wi, Normal3f(0, 0, 1), eta, &etap, &wt));
}

TEST(Fresnel, RefractObeysSnell) {
    Float eta = 1.5f;
    for (Float c : {1.0f, 0.7f, 0.2f, 1e-3f, -0.9f, -0.5f}) {
        Vector3f wi(SafeSqrt(1 - c * c), 0, c);
        Float etap;
        Vector3f wt;
        bool ok = Refract(wi, Normal3f(0, 0, 1), eta, &etap, &wt);
        if (c < 0 && SafeSqrt(1 - c * c) * eta >= 1) {
            EXPECT_FALSE(ok);
            continue;
        }
        ASSERT_TRUE(ok) << c;
        EXPECT_NEAR(Length(wt), 1, 1e-5f);
        EXPECT_NEAR(SinTheta(wi), etap * SinTheta(wt), 1e-5f);  // sin_i = eta' sin_t
        EXPECT_LT(wi.z * wt.z, 0);
    }
    Vector3f wo = Normalize(Vector3f(0.3f, -0.2f, 0.8f));
    Vector3f r = Reflect(wo, Vector3f(0, 0, 1));
    EXPECT_NEAR(r.x, -wo.x, 1e-6f);
    EXPECT_NEAR(r.z, wo.z, 1e-6f);
}

TEST(Fresnel, DielectricReflectPlusTransmitIsOne) {
    for (Float eta : {1.5f, 1 / 1.5f})
        for (int i = -20; i <= 20; ++i) {
            Float c = i / 20.f;
            if (c == 0) continue;
            Float R = FrDielectric(c, eta);
            Float T = 1 - R;
            EXPECT_NEAR(R + T, 1, 1e-6f);
            // The smooth DielectricBxDF picks each lobe with probability R and T.
            DielectricBxDF bxdf(eta, TrowbridgeReitzDistribution(0, 0));
            Vector3f wo(SafeSqrt(1 - c * c), 0, c);
            auto r = bxdf.Sample_f(wo, 0, Point2f(0.5f, 0.5f), TransportMode::Importance);
            auto t =
                bxdf.Sample_f(wo, OneMinusEpsilon, Point2f(0.5f, 0.5f), TransportMode::Importance);
            Float pr = (r && r->IsReflection()) ? r->pdf : 0;
            Float pt = (t && t->IsTransmission()) ? t->pdf : 0;
            if (R < 1) {
                ASSERT_TRUE(r && t);
                EXPECT_NEAR(pr, R, 1e-6f);
                EXPECT_NEAR(pr + pt, 1, 1e-6f);
                // Importance-mode throughput f cos / pdf is 1 for both lobes.
                EXPECT_NEAR(r->f[0] * AbsCosTheta(r->wi) / r->pdf, 1, 1e-5f);
                EXPECT_NEAR(t->f[0] * AbsCosTheta(t->wi) / t->pdf, 1, 1e-5f);
            } else {
                EXPECT_NEAR(pr, 1, 1e-6f);
            }
        }
}

TEST(Fresnel, ComplexExtremeOpticalConstantsMatchThePolarisedForm) {
    // From the smallest subnormal to the largest float optical constants: finite, in [0, 1],
    // and equal to the mean of Rs and Rp from the complex-amplitude form
    const Float values[] = {1.4e-45f, 1e-30f, 1e-6f, 0.3f, 1, 7, 1e6f, 1e30f, 3e38f};
    for (Float n : values)
        for (Float k : values)
            for (Float c : {1e-6f, 0.1f, 0.7f, 1.f}) {
                std::complex<Float> eta(n, k);
                Float r = FrComplex(c, eta);
                ASSERT_TRUE(std::isfinite(r) && r >= 0 && r <= 1) << n << " " << k << " " << c;
                FresnelRsRp p = FrComplexPolarized(c, eta);
                if (std::isfinite(p.Rs) && std::isfinite(p.Rp)) {
                    EXPECT_NEAR(r, (p.Rs + p.Rp) / 2, 1e-5f) << n << " " << k << " " << c;
                }
            }
}

// Absorbing dielectrics (glass through the infrared): the complex Fresnel reflectance from
// outside, and from inside that of the outside direction refracting into the inside one
TEST(Fresnel, AbsorbingDielectricWithoutKIsDielectric) {
    for (Float n : {1.5f, 1 / 1.5f, 2.4f})
        for (int i = -100; i <= 100; ++i) {
            Float c = i / 100.f;
            EXPECT_EQ(FrAbsorbingDielectric(c, n, 0), FrDielectric(c, n)) << n << " " << c;
        }
}

TEST(Fresnel, AbsorbingDielectricFromOutsideIsComplex) {
    for (auto [n, k] : {std::pair{1.209f, 1.232f}, std::pair{0.4f, 0.3f}, std::pair{2.0f, 2.7f}})
        for (int i = 0; i <= 50; ++i) {
            Float c = i / 50.f;
            EXPECT_NEAR(FrAbsorbingDielectric(c, n, k), FrComplex(c, {n, k}), 1e-6f);
            FresnelRsRp p = FrAbsorbingDielectricPolarized(c, n, k);
            EXPECT_NEAR(0.5f * (p.Rs + p.Rp), FrAbsorbingDielectric(c, n, k), 1e-6f);
        }
    // Normal incidence: ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2)
    EXPECT_NEAR(FrAbsorbingDielectric(1, 1.209f, 1.232f),
                (Sqr(0.209f) + Sqr(1.232f)) / (Sqr(2.209f) + Sqr(1.232f)), 1e-6f);
}

TEST(Fresnel, AbsorbingDielectricIsReciprocal) {
    for (auto [n, k] : {std::pair{1.5f, 0.5f}, std::pair{1.209f, 1.232f}, std::pair{0.8f, 2.0f}})
        for (int i = 1; i <= 60; ++i) {
            // Outside at cos c_o refracts (real n) to inside at cos c_i
            Float c_o = i / 60.f;
            Float sin2_i = (1 - c_o * c_o) / (n * n);
            if (sin2_i >= 1) continue;
            Float c_i = std::sqrt(1 - sin2_i);
            // (the tolerance: the single-precision round trip of a grazing cosine)
            EXPECT_NEAR(FrAbsorbingDielectric(-c_i, n, k), FrAbsorbingDielectric(c_o, n, k), 1e-4f)
                << "n " << n << " k " << k << " cos " << c_o;
            FresnelRsRp in = FrAbsorbingDielectricPolarized(-c_i, n, k),
                        out = FrAbsorbingDielectricPolarized(c_o, n, k);
            EXPECT_NEAR(in.Rs, out.Rs, 1e-4f);
            EXPECT_NEAR(in.Rp, out.Rp, 1e-4f);
        }
    // Inside beyond the critical angle (n > 1): total internal reflection
    EXPECT_EQ(FrAbsorbingDielectric(-0.3f, 1.5f, 0.5f), 1);
    EXPECT_EQ(FrAbsorbingDielectricPolarized(-0.3f, 1.5f, 0.5f).Rp, 1);
    // Weak absorption is continuous with the plain dielectric on both sides
    for (Float c : {0.9f, 0.5f, 0.1f, -0.95f, -0.8f})
        EXPECT_NEAR(FrAbsorbingDielectric(c, 1.5f, 1e-5f), FrDielectric(c, 1.5f), 1e-5f) << c;
}
