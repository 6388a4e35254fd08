// The rough dielectric's directional albedo (thermal/dielectric_emissivity.h): the tables
// against the BSDF itself (the mean power weight f |cos| / pdf of Sample_f in importance mode,
// from outside and from inside the body), the quadrature they are built with against a much
// finer one, and what the thermal module is told about the inside (eta^2).
#include "thermal/dielectric_emissivity.h"

#include <gtest/gtest.h>

#include <cmath>

#include "base/rng.h"
#include "base/statistics.h"
#include "thermal_test_util.h"

namespace kiln {
namespace {

using namespace kiln::test;

// Largest deviation of the tabulated albedo from the BxDF's sampled power albedo beyond 4
// standard errors, over random points, directions on both sides and visible wavelengths; and
// the smallest tabulated albedo seen (the loss the surface emits).
struct TableCheck {
    double worst = 0, smallest = 1;
};
TableCheck CheckTable(const Material& material, const MaterialAlbedo& albedo, int points,
                      int samples, uint64_t seed) {
    RNG rng(seed);
    TableCheck check;
    for (int p = 0; p < points; ++p) {
        Point2f uv(rng.UniformFloat(), rng.UniformFloat());
        Float mu = std::max(0.02f, rng.UniformFloat()), phi = 2 * Pi * rng.UniformFloat();
        Float s = std::sqrt(1 - mu * mu);
        Vector3f wo(s * std::cos(phi), s * std::sin(phi), p % 2 ? -mu : mu);
        SampledWavelengths lambda = SampledWavelengths::SampleVisible(rng.UniformFloat());
        SampledWavelengths l = lambda;
        BSDF bsdf = material.GetBSDF(Context(uv, wo), l);
        Float A = albedo.Evaluate(&material, bsdf, wo, l)[0];
        const DielectricBxDF* d = bsdf.GetBxDF().GetIf<DielectricBxDF>();
        RunningStats stats;
        for (int k = 0; k < samples; ++k) {
            std::optional<BSDFSample> bs =
                d->Sample_f(wo, rng.UniformFloat(), Point2f(rng.UniformFloat(), rng.UniformFloat()),
                            TransportMode::Importance);
            stats.Add(bs && bs->pdf > 0 ? bs->f[0] * AbsCosTheta(bs->wi) / bs->pdf : 0.0);
        }
        check.worst = std::max(check.worst, std::abs(A - stats.Mean()) - 4 * stats.StandardError());
        check.smallest = std::min(check.smallest, double(A));
    }
    return check;
}

TEST(DielectricEmissivity, TablesMatchTheBSDFFromEitherSide) {
    ThermalFixture f;
    f.AddBilerpFloat("ramp", 0.02f, 0.6f, 0.2f, 0.9f);
    struct Case {
        const char* what;
        ParsedParameterVector params;
        bool exact;
    };
    const Case cases[] = {
        {"eta 1.5, roughness 0.05", {Float1("roughness", 0.05f)}, true},
        {"eta 1.5, roughness 0.3", {Float1("roughness", 0.3f)}, true},
        {"eta 2.4, roughness 1", {Float1("eta", 2.4f), Float1("roughness", 1)}, true},
        {"dispersive BAF10, roughness 0.2",
         {Strings("spectrum", "eta", {"glass-BAF10"}), Float1("roughness", 0.2f)},
         true},
        {"constant k", {Float1("k", 0.05f), Float1("roughness", 0.3f)}, true},
        {"index below one, absorbing",
         {Float1("eta", 0.6f), Float1("k", 0.4f), Float1("roughness", 0.3f)},
         true},
        {"anisotropic", {Float1("uroughness", 0.1f), Float1("vroughness", 0.3f)}, false},
        {"textured roughness", {Texture("roughness", "ramp")}, false},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.what);
        const Material* m = f.Make("dielectric", c.params);
        const MaterialAlbedo* albedo = MaterialAlbedo::Create(*m, f.tables, f.arena);
        EXPECT_EQ(albedo->Exact(), c.exact);
        EXPECT_TRUE(albedo->SurfaceAbsorbs());
        TableCheck check = CheckTable(*m, *albedo, 16, 40000, 3);
        // Anisotropic roughness is approximated by the table of the isotropic alpha (0.038 at
        // alpha 0.32 x 0.55)
        EXPECT_LT(check.worst, c.exact ? 1.5e-3 : 0.05);
        // It loses something somewhere (and so emits)
        EXPECT_LT(check.smallest, 0.995);
    }
}

// The table's quadrature at its 64 x 64 points agrees with a 512 x 512 one within 2e-3
// (measured: at most 1.4e-3, at eta 0.7 and alpha 1; 5.6e-4 at eta 1.5)
TEST(DielectricEmissivity, QuadratureConvergesAtTheTablesPointCount) {
    for (Float eta : {1.5f, 0.7f})
        for (Float alpha : {0.05f, 0.3f, 1.f})
            for (Float mu : {1.f, 0.5f, 0.1f, -0.3f, -0.9f}) {
                DielectricBxDF bxdf(eta, TrowbridgeReitzDistribution(alpha, alpha), 0);
                Vector3f wo(std::sqrt(1 - mu * mu), 0, mu);
                Float fine = DielectricEmissivity::Quadrature(bxdf, wo, 512);
                EXPECT_NEAR(DielectricEmissivity::Quadrature(bxdf, wo, 64), fine, 2e-3)
                    << "eta " << eta << " alpha " << alpha << " mu " << mu;
                EXPECT_LE(fine, 1 + 1e-5);
            }
}

TEST(DielectricEmissivity, SmoothGlassLosesNothingAndTheInsideIsScaledByEtaSquared) {
    ThermalFixture f;
    const Material* smooth = f.Make("dielectric", {Float1("eta", 1.6f)});
    const Material* rough = f.Make("dielectric", {Float1("eta", 1.6f), Float1("roughness", 0.2f)});
    EXPECT_FALSE(MaterialAlbedo::Create(*smooth, f.tables, f.arena)->SurfaceAbsorbs());
    const MaterialAlbedo* albedo = MaterialAlbedo::Create(*rough, f.tables, f.arena);
    for (Float mu : {0.8f, -0.8f}) {
        Vector3f wo(0.6f, 0, mu);
        SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
        BSDF bsdf = rough->GetBSDF(Context(Point2f(0.5f, 0.5f), wo), lambda);
        BSDFReflectance r = albedo->Reflectance(rough, bsdf);
        EXPECT_FLOAT_EQ(r.EquilibriumScale(wo, lambda)[0], mu < 0 ? 1.6f * 1.6f : 1.f);
        EXPECT_LT(r.DirectionalAlbedo(wo, lambda)[0], 1);
    }
}

}  // namespace
}  // namespace kiln
