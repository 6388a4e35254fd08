// Polarised BxDFs and BSDFs: the Mueller matrix's M00 is the unpolarised value, matrices are
// physical, Brewster's angle, and render-space matrices do not depend on the shading frame.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

#include "base/rng.h"
#include "direction.h"
#include "materials/bxdfs/bsdf.h"
#include "materials/bxdfs/fresnel.h"
#include "materials/bxdfs/fresnel_mueller.h"

using namespace kiln;

namespace {

using test::Dir;

Vector3f RandomDir(RNG& rng) {
    return Dir(2 * rng.UniformFloat() - 1, 2 * Pi * rng.UniformFloat());
}

std::vector<BxDF> PolarisingAndDepolarisingBxDFs() {
    TrowbridgeReitzDistribution smooth(0, 0), rough(0.3f, 0.3f), aniso(0.1f, 0.7f);
    SampledSpectrum eta(0.2f), k(3.5f), one(1.f);
    eta[1] = 1.2f;
    k[2] = 0.5f;
    return {DiffuseBxDF(SampledSpectrum(0.7f)),
            ConductorBxDF(smooth, eta, k),
            ConductorBxDF(rough, eta, k),
            ConductorBxDF(aniso, eta, k),
            DielectricBxDF(1.5f, smooth),
            DielectricBxDF(1.5f, rough),
            DielectricBxDF(1 / 1.5f, rough),
            ThinDielectricBxDF(1.5f),
            CoatedDiffuseBxDF(DielectricBxDF(1.5f, rough), DiffuseBxDF(one), 0.1f,
                              SampledSpectrum(0.8f), 0.3f, 10, 1)};
}

// Largest |S1..S3| / S0 that M gives over pure input states (sampled): must not exceed 1.
Float MaxOutputDoP(const MuellerMatrix& M, int i, RNG& rng) {
    Float worst = 0;
    for (int n = 0; n < 64; ++n) {
        Vector3f p = RandomDir(rng);
        Stokes in(SampledSpectrum(1.f), SampledSpectrum(p.x), SampledSpectrum(p.y),
                  SampledSpectrum(p.z));
        Stokes out = M * in;
        if (out[0][i] < -1e-6f) return Infinity;
        if (out[0][i] > 1e-6f) worst = std::max(worst, DegreeOfPolarization(out)[i]);
    }
    return worst;
}

}  // namespace

TEST(PolarizedBxDF, M00IsTheUnpolarisedValue) {
    RNG rng(7);
    for (const BxDF& bxdf : PolarisingAndDepolarisingBxDFs())
        for (int n = 0; n < 400; ++n) {
            Vector3f wo = RandomDir(rng), wi = RandomDir(rng);
            for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
                SampledSpectrum f = bxdf.f(wo, wi, mode);
                MuellerMatrix M = bxdf.f<MuellerMatrix>(wo, wi, mode);
                for (int i = 0; i < NSpectrumSamples; ++i)
                    EXPECT_NEAR(M(0, 0)[i], f[i], 1e-4f * std::max<Float>(1, f[i])) << bxdf.Index();
            }
            Float uc = rng.UniformFloat();
            Point2f u(rng.UniformFloat(), rng.UniformFloat());
            auto bs = bxdf.Sample_f(wo, uc, u);
            auto bp = bxdf.Sample_f<MuellerMatrix>(wo, uc, u);
            ASSERT_EQ(bool(bs), bool(bp));
            if (!bs) continue;
            EXPECT_EQ(bs->wi, bp->wi);
            EXPECT_EQ(bs->pdf, bp->pdf);
            EXPECT_EQ(bs->flags, bp->flags);
            // The thin dielectric's exception (ThinSheetConservesEachPolarisation)
            if (bxdf.Is<ThinDielectricBxDF>()) continue;
            for (int i = 0; i < NSpectrumSamples; ++i)
                EXPECT_NEAR(bp->f(0, 0)[i], bs->f[i], 1e-4f * std::max<Float>(1, bs->f[i]))
                    << bxdf.Index();
        }
}

// A thin slab does not mix the s and p waves: for each, reflectance plus transmittance is 1,
// so unpolarised light stays unpolarised in an isothermal cavity. Its M00 is then the mean of
// the two waves' series; the unpolarised BxDF sums the series for the mean reflectance, as
// pbrt-v4 does, and differs at oblique incidence only.
TEST(PolarizedBxDF, ThinSheetConservesEachPolarisation) {
    RNG rng(5);
    for (Float eta : {1.33f, 1.5f, 2.4f})
        for (int n = 0; n < 100; ++n) {
            Vector3f wo = RandomDir(rng);
            BxDF sheet = ThinDielectricBxDF(eta);
            auto r = sheet.Sample_f<MuellerMatrix>(wo, 0, {0.5f, 0.5f});
            auto t = sheet.Sample_f<MuellerMatrix>(wo, 1, {0.5f, 0.5f});
            auto rs = sheet.Sample_f(wo, 0, {0.5f, 0.5f});
            ASSERT_TRUE(r && t && rs && r->IsReflection() && t->IsTransmission());
            MuellerMatrix M = r->f * AbsCosTheta(r->wi) + t->f * AbsCosTheta(t->wi);
            for (Float s1 : {-1.f, 0.f, 1.f}) {
                Stokes out = M * Stokes(SampledSpectrum(1.f), SampledSpectrum(s1), {}, {});
                EXPECT_NEAR(out[0][0], 1, 1e-4f) << eta << " S1 " << s1;
                EXPECT_NEAR(out[1][0], s1, 1e-4f) << eta << " S1 " << s1;
            }
            // A slab of single-surface reflectance x reflects 2x / (1 + x) in all: M00 is the
            // mean of that for the two waves, the unpolarised value that of the mean (no more,
            // since 2x / (1 + x) is concave)
            FresnelAmplitudes a = FrComplexAmplitudes(AbsCosTheta(wo), std::complex<Float>(eta, 0));
            double Rs = std::norm(a.rs), Rp = std::norm(a.rp), Rm = (Rs + Rp) / 2;
            Float R = rs->f[0] * AbsCosTheta(rs->wi), Rpol = r->f(0, 0)[0] * AbsCosTheta(r->wi);
            EXPECT_NEAR(Rpol, (Rs / (1 + Rs) + Rp / (1 + Rp)), 1e-4f) << eta << " cos " << wo.z;
            EXPECT_NEAR(R, 2 * Rm / (1 + Rm), 1e-4f) << eta << " cos " << wo.z;
            EXPECT_LE(Rpol, R + 1e-5f);
        }
}

TEST(PolarizedBxDF, MatricesArePhysical) {
    // No input state gives negative intensity or a degree of polarisation above 1
    RNG rng(11);
    for (const BxDF& bxdf : PolarisingAndDepolarisingBxDFs())
        for (int n = 0; n < 200; ++n) {
            Vector3f wo = RandomDir(rng);
            auto bp = bxdf.Sample_f<MuellerMatrix>(wo, rng.UniformFloat(),
                                                   {rng.UniformFloat(), rng.UniformFloat()});
            if (!bp) continue;
            for (int i = 0; i < NSpectrumSamples; ++i)
                EXPECT_LE(MaxOutputDoP(bp->f, i, rng), 1 + 1e-3f) << bxdf.Index();
        }
}

TEST(PolarizedBxDF, BrewsterAngle) {
    // Reflection from glass at Brewster's angle is polarised perpendicular to the plane of
    // incidence (S1 = S0 with the s axis), and p-polarised light is not reflected at all
    Float eta = 1.5f, thetaB = std::atan(eta);
    DielectricBxDF glass(eta, TrowbridgeReitzDistribution(0, 0));
    Vector3f wo = Dir(std::cos(thetaB), 0.4f);
    auto bs = BxDF(glass).Sample_f<MuellerMatrix>(wo, 0, {0.5f, 0.5f});
    ASSERT_TRUE(bs && bs->IsReflection());
    Stokes r = bs->f * Stokes(SampledSpectrum(1.f));
    EXPECT_NEAR(DegreeOfPolarization(r)[0], 1, 1e-4f);
    EXPECT_NEAR(r[1][0] / r[0][0], 1, 1e-4f);
    Stokes p = bs->f * Stokes(SampledSpectrum(1.f), SampledSpectrum(-1.f), {}, {});
    EXPECT_NEAR(p[0][0] / r[0][0], 0, 1e-5f);
    // Away from it the reflection is only partially polarised, the more the nearer
    Float previous = 0;
    for (Float degrees : {10.f, 30.f, 50.f}) {
        Float theta = degrees * Pi / 180;
        Stokes s = FresnelReflectionMueller(std::cos(theta), eta) * Stokes(SampledSpectrum(1.f));
        Float dop = DegreeOfPolarization(s)[0];
        EXPECT_LT(dop, 0.99f);
        EXPECT_GT(dop, previous);
        // The closed form (Rs - Rp) / (Rs + Rp)
        FresnelRsRp R = FrDielectricPolarized(std::cos(theta), eta);
        EXPECT_NEAR(dop, (R.Rs - R.Rp) / (R.Rs + R.Rp), 1e-5f);
        previous = dop;
    }
}

TEST(PolarizedBxDF, PerfectMirrorAtNormalIncidence) {
    ConductorBxDF mirror(TrowbridgeReitzDistribution(0, 0), SampledSpectrum(0.f),
                         SampledSpectrum(0.f));
    auto bs = BxDF(mirror).Sample_f<MuellerMatrix>(Vector3f(0, 0, 1), 0, {0, 0});
    ASSERT_TRUE(bs);
    const Float expected[4] = {1, 1, -1, -1};
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(bs->f(r, c)[0], r == c ? expected[r] : 0, 1e-6f);
}

TEST(PolarizedBSDF, RenderFrameMatricesDoNotDependOnTheShadingTangent) {
    // Isotropic BxDFs: the same surface with different tangents gives the same render-space
    // Mueller matrices (the frames are rotated consistently); also with folding
    RNG rng(3);
    Normal3f ns = Normal3f(Normalize(Vector3f(0.2f, -0.3f, 1)));
    Normal3f ng = Normal3f(Normalize(Vector3f(0.3f, -0.1f, 1)));
    for (const BxDF& bxdf : PolarisingAndDepolarisingBxDFs()) {
        // (Layered BxDFs estimate f stochastically, seeded by the local directions)
        if (bxdf.Is<CoatedDiffuseBxDF>()) continue;
        if (bxdf.Is<ConductorBxDF>() && bxdf.GetIf<ConductorBxDF>()->Distribution().AlphaX() !=
                                            bxdf.GetIf<ConductorBxDF>()->Distribution().AlphaY())
            continue;
        for (Normal3f geometric : {Normal3f(0, 0, 0), ng}) {
            BSDF a(ns, Vector3f(1, 0, 0), bxdf, geometric),
                b(ns, Vector3f(0.3f, 1, 0), bxdf, geometric);
            for (int n = 0; n < 100; ++n) {
                Vector3f wo = RandomDir(rng), wi = RandomDir(rng);
                MuellerMatrix Ma = a.f<MuellerMatrix>(wo, wi), Mb = b.f<MuellerMatrix>(wo, wi);
                Float scale = std::max<Float>(1, Ma(0, 0).MaxComponentValue());
                for (int r = 0; r < 4; ++r)
                    for (int c = 0; c < 4; ++c)
                        for (int i = 0; i < NSpectrumSamples; ++i)
                            EXPECT_NEAR(Ma(r, c)[i], Mb(r, c)[i], 2e-4f * scale)
                                << bxdf.Index() << " " << r << c;
                EXPECT_NEAR(Ma(0, 0)[0], a.f(wo, wi)[0], 1e-4f * scale);
            }
        }
    }
}

TEST(PolarizedBSDF, SmoothSamplesInRenderFramesMatchTheLocalMatrix) {
    // A smooth conductor seen along a tilted normal: the render-space matrix applied to light
    // polarised perpendicular to the plane of incidence gives the s reflectance
    SampledSpectrum eta(0.2f), k(3.5f);
    ConductorBxDF gold(TrowbridgeReitzDistribution(0, 0), eta, k);
    Vector3f n = Normalize(Vector3f(0.3f, 0.5f, 1));
    BSDF bsdf(Normal3f(n), Vector3f(1, 0, 0), gold);
    Vector3f wo = Normalize(Vector3f(-1, 0.2f, 0.6f));
    auto bs = bsdf.Sample_f<MuellerMatrix>(wo, 0, {0, 0});
    ASSERT_TRUE(bs);
    Vector3f s = Normalize(Cross(n, wo));
    // Incident light along -wi, polarised along s, written in the implicit frame of -wi
    Stokes in = RotateStokesBasis(Stokes(SampledSpectrum(1.f), SampledSpectrum(1.f), {}, {}),
                                  -bs->wi, s, StokesBasis(-bs->wi));
    Stokes out = RotateStokesBasis(bs->f * in, wo, StokesBasis(wo), s);
    FresnelRsRp R = FrComplexPolarized(Dot(wo, n), std::complex<Float>(0.2f, 3.5f));
    Float cosTheta = Dot(wo, n);
    EXPECT_NEAR(out[0][0] * cosTheta, R.Rs, 1e-4f);
    EXPECT_NEAR(out[1][0] * cosTheta, R.Rs, 1e-4f);
}

// What polarised transport does with a BxDF is declared, never a silent default: every BxDF of
// the closed set polarises or declares that it depolarises, and a BxDF that does neither (or
// both) is refused by the concept the closed set asserts.
namespace {
struct SilentBxDF {  // neither MuellerF nor kDepolarizes
    SampledSpectrum f(Vector3f, Vector3f, TransportMode) const { return {}; }
};
struct AmbiguousBxDF {  // both
    static constexpr bool kDepolarizes = true;
    MuellerMatrix MuellerF(Vector3f, Vector3f, TransportMode) const { return {}; }
    MuellerMatrix MuellerSample(Vector3f, const BSDFSample&, TransportMode) const { return {}; }
};
struct HalfPolarizingBxDF {  // MuellerF without MuellerSample
    MuellerMatrix MuellerF(Vector3f, Vector3f, TransportMode) const { return {}; }
};
}  // namespace

TEST(PolarizedBxDF, EveryBxDFDeclaresWhatItDoesToPolarisation) {
    static_assert(!PolarizationDefinedBxDF<SilentBxDF>);
    static_assert(!PolarizationDefinedBxDF<AmbiguousBxDF>);
    static_assert(!PolarizationDefinedBxDF<HalfPolarizingBxDF>);
    static_assert(PolarizingBxDF<ConductorBxDF> && PolarizingBxDF<DielectricBxDF> &&
                  PolarizingBxDF<ThinDielectricBxDF> && PolarizingBxDF<PolarizingFilterBxDF>);
    static_assert(DepolarizingBxDF<DiffuseBxDF> && DepolarizingBxDF<CoatedDiffuseBxDF> &&
                  DepolarizingBxDF<CoatedConductorBxDF> && DepolarizingBxDF<HairBxDF>);
    // A depolariser's Mueller matrix is f diag(1, 0, 0, 0)
    BxDF diffuse(DiffuseBxDF(SampledSpectrum(0.5f)));
    MuellerMatrix M = diffuse.f<MuellerMatrix>(Vector3f(0, 0, 1), Vector3f(0.6f, 0, 0.8f),
                                               TransportMode::Radiance);
    EXPECT_FLOAT_EQ(M(0, 0)[0], 0.5f / Pi);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (i || j) {
                EXPECT_EQ(M(i, j)[0], 0);
            }
}
