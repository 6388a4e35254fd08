// The BSDF with a shading normal that differs from the geometric one (bsdf.h): directions on
// the wrong side of the geometric surface for their lobe are folded back, and a refraction
// from a direction the shading frame puts on the other side than the geometry does carries the
// radiance scaling of the crossing the light makes.
#include <gtest/gtest.h>

#include <cmath>

#include "base/rng.h"
#include "base/sampling.h"
#include "base/statistics.h"
#include "materials/bxdfs/bsdf.h"

using namespace kiln;

namespace {

// Geometric normal +z; shading normal tilted by 0.4 rad towards +x
const Normal3f kNg(0, 0, 1);
const Normal3f kNs(std::sin(0.4f), 0, std::cos(0.4f));
const Vector3f kDpdu(0, 1, 0);

// Above the geometric surface, below the shading one (near a smooth-shaded silhouette)
Vector3f MismatchedWo() { return Normalize(Vector3f(-1, 0.2f, 0.15f)); }
// Above both
Vector3f OutsideWo() { return Normalize(Vector3f(0.3f, -0.4f, 0.8f)); }

BSDF Folded(const BxDF& bxdf) { return BSDF(kNs, kDpdu, bxdf, kNg); }
BSDF Unfolded(const BxDF& bxdf) { return BSDF(kNs, kDpdu, bxdf); }

DielectricBxDF RoughGlass() {
    return DielectricBxDF(1.5f, TrowbridgeReitzDistribution(0.5f, 0.5f));
}

TEST(BSDFFold, PointsInsideFollowsTheGeometricSurface) {
    BSDF folded = Folded(RoughGlass()), unfolded = Unfolded(RoughGlass());
    Vector3f wo = MismatchedWo();
    EXPECT_LT(folded.RenderToLocal(wo).z, 0);  // the shading frame calls it inside
    EXPECT_FALSE(folded.PointsInside(folded.RenderToLocal(wo)));
    EXPECT_TRUE(unfolded.PointsInside(unfolded.RenderToLocal(wo)));
    EXPECT_FALSE(folded.PointsInside(folded.RenderToLocal(OutsideWo())));
    EXPECT_TRUE(folded.PointsInside(folded.RenderToLocal(-OutsideWo())));
}

// An opaque BSDF sends nothing below the geometric surface, by sampling or evaluation, and its
// samples keep the unfolded BSDF's weights (so its albedo, and Kirchhoff emission, stay).
TEST(BSDFFold, OpaqueSurfaceNeitherLeaksNorLosesEnergy) {
    ConductorBxDF metal(TrowbridgeReitzDistribution(0.4f, 0.4f), SampledSpectrum(0.2f),
                        SampledSpectrum(3.5f));
    BSDF folded = Folded(metal), unfolded = Unfolded(metal);
    for (Vector3f wo : {OutsideWo(), Normalize(Vector3f(0.95f, 0, 0.1f))}) {
        RNG rng(5);
        int foldedSamples = 0;
        for (int i = 0; i < 20000; ++i) {
            Float uc = rng.UniformFloat();
            Point2f u(rng.UniformFloat(), rng.UniformFloat());
            auto a = folded.Sample_f(wo, uc, u), b = unfolded.Sample_f(wo, uc, u);
            ASSERT_EQ(bool(a), bool(b));
            if (!a) continue;
            EXPECT_GT(Dot(a->wi, Vector3f(kNg)), 0);
            foldedSamples += Dot(b->wi, Vector3f(kNg)) < 0;
            Float wa = a->f[0] * AbsDot(a->wi, Vector3f(kNs)) / a->pdf;
            Float wb = b->f[0] * AbsDot(b->wi, Vector3f(kNs)) / b->pdf;
            EXPECT_NEAR(wa, wb, 1e-4f * std::max<Float>(1, wb));
            Vector3f below = Normalize(Vector3f(b->wi.x, b->wi.y, -std::abs(b->wi.z) - 0.01f));
            EXPECT_FALSE(folded.f(wo, below));
        }
        if (wo.x > 0.9f) {
            EXPECT_GT(foldedSamples, 100);  // the case the test is about
        }
    }
}

// The sample weights f |cos| / pdf of rough glass with and without folding, Radiance mode:
// equal where the shading and geometric surfaces agree on wo's side; where they do not,
// refractions carry eta'^4 more (eta' seen from the shading frame's side: the 1 / eta'^2 of the
// wrong crossing replaced by that of the right one), reflections the same.
TEST(BSDFFold, RefractionFromAMismatchedSideScalesForTheRealCrossing) {
    const Float eta = 1.5f;
    BSDF folded = Folded(RoughGlass()), unfolded = Unfolded(RoughGlass());
    for (Vector3f wo : {OutsideWo(), MismatchedWo()}) {
        bool mismatched = wo == MismatchedWo();
        Float etap = unfolded.RenderToLocal(wo).z > 0 ? eta : 1 / eta;
        Float expected = mismatched ? Sqr(Sqr(etap)) : 1;
        RNG rng(9);
        int transmissions = 0;
        for (int i = 0; i < 20000; ++i) {
            Float uc = rng.UniformFloat();
            Point2f u(rng.UniformFloat(), rng.UniformFloat());
            auto a = folded.Sample_f(wo, uc, u), b = unfolded.Sample_f(wo, uc, u);
            if (!a || !b) continue;
            ASSERT_EQ(a->IsTransmission(), b->IsTransmission());
            Float wa = a->f[0] * AbsDot(a->wi, Vector3f(kNs)) / a->pdf;
            Float wb = b->f[0] * AbsDot(b->wi, Vector3f(kNs)) / b->pdf;
            Float ratio = a->IsTransmission() ? expected : 1;
            EXPECT_NEAR(wa, wb * ratio, 1e-4f * std::max<Float>(1, wb * ratio));
            if (a->IsTransmission()) {
                ++transmissions;
                // Transmitted light crosses the geometric surface, and bs.eta is that crossing's
                EXPECT_LT(Dot(a->wi, Vector3f(kNg)) * Dot(wo, Vector3f(kNg)), 0);
                EXPECT_FLOAT_EQ(a->eta, mismatched ? 1 / b->eta : b->eta);
            }
            // Importance mode has no radiance scaling to correct
            auto c = folded.Sample_f(wo, uc, u, TransportMode::Importance);
            auto d = unfolded.Sample_f(wo, uc, u, TransportMode::Importance);
            if (c && d) {
                EXPECT_NEAR(c->f[0] * AbsDot(c->wi, Vector3f(kNs)) / c->pdf,
                            d->f[0] * AbsDot(d->wi, Vector3f(kNs)) / d->pdf, 1e-4f);
            }
        }
        EXPECT_GT(transmissions, 1000);
    }
}

// f() agrees with Sample_f: the integral of f |cos| over the sphere (uniform directions)
// equals the mean sample weight, for the mismatched wo where the scaling applies, refraction
// and reflection separately.
TEST(BSDFFold, EvaluationMatchesSamplingWithTheCrossingScale) {
    BSDF bsdf = Folded(RoughGlass());
    Vector3f wo = MismatchedWo();
    RunningStats fT, fR, sT, sR;
    RNG rng(13);
    const int n = 400000;
    for (int i = 0; i < n; ++i) {
        Vector3f wi = SampleUniformSphere({rng.UniformFloat(), rng.UniformFloat()});
        double v = bsdf.f(wo, wi)[0] * AbsDot(wi, Vector3f(kNs)) / UniformSpherePDF();
        bool transmit = Dot(wi, Vector3f(kNg)) * Dot(wo, Vector3f(kNg)) < 0;
        fT.Add(transmit ? v : 0);
        fR.Add(transmit ? 0 : v);
        auto bs = bsdf.Sample_f(wo, rng.UniformFloat(), {rng.UniformFloat(), rng.UniformFloat()});
        double w = bs ? bs->f[0] * AbsDot(bs->wi, Vector3f(kNs)) / bs->pdf : 0;
        sT.Add(bs && bs->IsTransmission() ? w : 0);
        sR.Add(bs && !bs->IsTransmission() ? w : 0);
    }
    std::printf(
        "refraction: f %.4f +- %.4f, sampled %.4f +- %.4f; reflection: f %.4f +- %.4f, "
        "sampled %.4f +- %.4f\n",
        fT.Mean(), fT.StandardError(), sT.Mean(), sT.StandardError(), fR.Mean(), fR.StandardError(),
        sR.Mean(), sR.StandardError());
    EXPECT_GT(sT.Mean(), 0.01);
    EXPECT_NEAR(fT.Mean(), sT.Mean(), 4 * std::hypot(fT.StandardError(), sT.StandardError()));
    EXPECT_NEAR(fR.Mean(), sR.Mean(), 4 * std::hypot(fR.StandardError(), sR.StandardError()));
}

}  // namespace
