// The layered BxDFs' two stochastic estimators must describe the same BSDF at every angle:
// integrating f (its random walk with next-event estimation towards wi) over the hemisphere
// must give the albedo that Sample_f's random walk gives (f cos / pdf), for rough and smooth
// coats, bright and dark bases, with and without a scattering layer, from normal to grazing
// incidence. pbrt-v4's f weighs directions sampled inside the layer against the virtual-light
// strategy with exitInterface.PDF(-w, wi) instead of that strategy's density for the same
// direction, PDF(wi, -w, !mode), so its weights do not sum to one. With pbrt-v4's weight in
// kiln's layered_bxdf.cpp, f came out brighter than the walk by 1-2 % (alpha 0.05 coat),
// 6-8 % (alpha 0.3 over a 0.8 base), 9-12 % (alpha 0.8) and 10-14 % (the coated conductor),
// and 20 of these 24 cases failed; kiln's weight passes them all. pbrt-v4's weight stays
// available (LayeredMIS::PbrtV4, kiln --layered-mis pbrt-v4) for images that match pbrt-v4's:
// the second test checks that it reproduces that bias, and only where MIS is involved.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "base/rng.h"
#include "base/sampling.h"
#include "base/statistics.h"
#include "materials/bxdfs/bxdf.h"

namespace kiln {
namespace {

struct Estimates {
    RunningStats sampled, integrated;
};

// The albedo from n Sample_f walks, and from integrating f with wi drawn half the time
// cosine-distributed and half the time from the coat's own reflection lobe (exact densities
// both: the sharp lobes of smooth coats at grazing angles are sampled where they are).
Estimates Compare(const BxDF& bxdf, const DielectricBxDF& coat, Float cosTheta, int n,
                  uint64_t seed) {
    Vector3f wo(SafeSqrt(1 - cosTheta * cosTheta), 0, cosTheta);
    Estimates e;
    RNG rng(seed);
    const auto refl = BxDFReflTransFlags::Reflection;
    for (int i = 0; i < n; ++i) {
        auto bs = bxdf.Sample_f(wo, rng.UniformFloat(), {rng.UniformFloat(), rng.UniformFloat()},
                                TransportMode::Radiance);
        e.sampled.Add(bs && bs->pdf > 0 ? bs->f[0] * std::abs(bs->wi.z) / bs->pdf : 0);
        Float uc = rng.UniformFloat();
        Point2f u(rng.UniformFloat(), rng.UniformFloat());
        Vector3f wi;
        if (rng.UniformFloat() < 0.5f) {
            wi = SampleCosineHemisphere(u);
        } else {
            auto cs = coat.Sample_f(wo, uc, u, TransportMode::Radiance, refl);
            if (!cs) {
                e.integrated.Add(0);
                continue;
            }
            wi = cs->wi;
        }
        Float pdf = 0.5f * std::max<Float>(wi.z, 0) / Pi +
                    0.5f * coat.PDF(wo, wi, TransportMode::Radiance, refl);
        Float v = pdf > 0 ? bxdf.f(wo, wi, TransportMode::Radiance)[0] * std::abs(wi.z) / pdf : 0;
        e.integrated.Add(v);
    }
    return e;
}

TEST(LayeredConsistency, EvaluationMatchesTheRandomWalkAtAllAngles) {
    SampledSpectrum one(1.f);
    struct Case {
        const char* name;
        BxDF bxdf;
        DielectricBxDF coat;
        int n = 100000;  // walks per angle
    };
    auto coat = [](Float alpha) {
        return DielectricBxDF(1.5f, TrowbridgeReitzDistribution(alpha, alpha));
    };
    auto coated = [&](Float alpha, Float reflectance, Float albedo) {
        return CoatedDiffuseBxDF(coat(alpha), DiffuseBxDF(one * reflectance), 0.01f, one * albedo,
                                 0, 10, 1);
    };
    const Case cases[] = {
        {"coateddiffuse, alpha 0.05, base 0.8", coated(0.05f, 0.8f, 0), coat(0.05f)},
        {"coateddiffuse, alpha 0.3, base 0.8", coated(0.3f, 0.8f, 0), coat(0.3f)},
        {"coateddiffuse, alpha 0.8, base 0.8", coated(0.8f, 0.8f, 0), coat(0.8f)},
        {"coateddiffuse, alpha 0.3, base 0.1", coated(0.3f, 0.1f, 0), coat(0.3f), 250000},
        {"coateddiffuse, alpha 0.3, base 0.6, layer albedo 0.5", coated(0.3f, 0.6f, 0.5f),
         coat(0.3f)},
        {"coatedconductor, alpha 0.3 over 0.2",
         CoatedConductorBxDF(
             coat(0.3f),
             ConductorBxDF(TrowbridgeReitzDistribution(0.2f, 0.2f), one * 0.2f, one * 3.5f), 0.01f,
             one * 0, 0, 10, 1),
         coat(0.3f)},
    };
    uint64_t seed = 1;
    for (const Case& c : cases)
        for (Float cosTheta : {0.95f, 0.5f, 0.2f, 0.08f}) {
            Estimates e = Compare(c.bxdf, c.coat, cosTheta, c.n, seed++);
            double s = e.sampled.Mean(), f = e.integrated.Mean();
            double sigma = std::hypot(e.sampled.StandardError(), e.integrated.StandardError());
            std::printf("%-52s cos %.2f: walk %.4f, f integrated %.4f (ratio %.4f, sigma %.4f)\n",
                        c.name, cosTheta, s, f, f / s, sigma);
            // Both walks stop after 10 bounces, at different points: allow 0.5 %
            EXPECT_NEAR(f, s, 4 * sigma + 0.005 * s) << c.name << ", cos " << cosTheta;
            // Precise enough to see pbrt-v4's bias (2.5 %, or 0.0025 of a dark base's albedo)
            EXPECT_LT(4 * sigma, std::max(0.025 * s, 0.0025)) << c.name << ", cos " << cosTheta;
        }
}

TEST(LayeredConsistency, PbrtV4WeightsAreAsBrightAsPbrtV4) {
    SampledSpectrum one(1.f);
    auto coat = [](Float alpha) {
        return DielectricBxDF(1.5f, TrowbridgeReitzDistribution(alpha, alpha));
    };
    auto coated = [&](Float alpha, LayeredMIS mis) {
        return CoatedDiffuseBxDF(coat(alpha), DiffuseBxDF(one * 0.8f), 0.01f, one * 0, 0, 10, 1,
                                 mis);
    };
    auto coatedConductor = [&](LayeredMIS mis) {
        return CoatedConductorBxDF(
            coat(0.3f),
            ConductorBxDF(TrowbridgeReitzDistribution(0.2f, 0.2f), one * 0.2f, one * 3.5f), 0.01f,
            one * 0, 0, 10, 1, mis);
    };
    // f over the hemisphere against the walk's albedo, at cos 0.5: brighter by about what
    // pbrt-v4 renders brighter (1-14 %, see above; measured here 8.0 %, 11.2 % and 14.6 %, each
    // with sigma <= 0.6 %), with lower bounds and a 20 % upper bound at 4 sigma
    struct Case {
        const char* name;
        BxDF bxdf;
        DielectricBxDF coat;
        double atLeast;  // ratio f / walk, lower bound
    };
    const Case cases[] = {
        {"coateddiffuse, alpha 0.3, base 0.8", coated(0.3f, LayeredMIS::PbrtV4), coat(0.3f), 1.04},
        {"coateddiffuse, alpha 0.8, base 0.8", coated(0.8f, LayeredMIS::PbrtV4), coat(0.8f), 1.06},
        {"coatedconductor, alpha 0.3 over 0.2", coatedConductor(LayeredMIS::PbrtV4), coat(0.3f),
         1.06}};
    uint64_t seed = 1000;
    for (const Case& c : cases) {
        Estimates e = Compare(c.bxdf, c.coat, 0.5f, 100000, seed++);
        double s = e.sampled.Mean(), f = e.integrated.Mean();
        double sigma = std::hypot(e.sampled.StandardError(), e.integrated.StandardError());
        std::printf(
            "pbrt-v4 weights, %-40s: walk %.4f, f integrated %.4f (ratio %.4f, sigma %.4f)\n",
            c.name, s, f, f / s, sigma);
        EXPECT_GT(f - 4 * sigma, c.atLeast * s) << c.name;
        EXPECT_LT(f + 4 * sigma, 1.2 * s) << c.name;
    }
    // A smooth coat: no MIS in the walk, so both weights give the same f, bit for bit
    CoatedDiffuseBxDF kiln = coated(0, LayeredMIS::Kiln), pbrt = coated(0, LayeredMIS::PbrtV4);
    RNG rng(7);
    for (int i = 0; i < 1000; ++i) {
        Vector3f wo = SampleUniformHemisphere({rng.UniformFloat(), rng.UniformFloat()});
        Vector3f wi = SampleUniformHemisphere({rng.UniformFloat(), rng.UniformFloat()});
        EXPECT_EQ(kiln.f(wo, wi, TransportMode::Radiance)[0],
                  pbrt.f(wo, wi, TransportMode::Radiance)[0]);
    }
}

}  // namespace
}  // namespace kiln
