// Polarised Kirchhoff emission (thermal/material_albedo.h): the linear polarisation a1 that
// MaterialAlbedo gives for conductors against the polarised BSDF itself (the mean S1 of
// M(wo, wi) (1, 0, 0, 0) |cos| / pdf over Sample_f, with the reference axis perpendicular to
// the plane of the normal and wo), smooth (Fresnel's closed form) and rough (the tables).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "base/rng.h"
#include "base/statistics.h"
#include "materials/bxdfs/fresnel.h"
#include "materials/bxdfs/fresnel_mueller.h"
#include "materials/materials.h"
#include "spectral/named_spectra.h"
#include "textures/texture_parameter_dictionary.h"
#include "thermal/material_albedo.h"
#include "thermal_test_util.h"

namespace kiln {
namespace {

using namespace kiln::test;

struct PolarizedFixture : ThermalFixture {
    PolarizedFixture() {
        tables.polarized = true;
        AddBilerpFloat("ramp", 0.001f, 0.5f, 0.1f, 0.3f);  // roughness over uv
    }
};

MaterialEvalContext Context(Vector3f wo, Point2f uv = Point2f(0.5f, 0.5f)) {
    return test::Context(uv, wo);
}

ParsedParameterVector Gold(Float roughness) {
    return {Strings("spectrum", "eta", {"metal-Au-eta"}), Strings("spectrum", "k", {"metal-Au-k"}),
            Float1("roughness", roughness)};
}

}  // namespace

TEST(PolarizedEmissivity, SmoothConductorsHaveTheFresnelDifference) {
    PolarizedFixture f;
    const Material* m = f.Make("conductor", Gold(0));
    const MaterialAlbedo* albedo = MaterialAlbedo::Create(*m, f.tables, f.arena);
    for (Float l : {400.f, 550.f, 700.f})
        for (Float mu : {1.f, 0.6f, 0.2f, 0.03f}) {
            SampledWavelengths lambda = SampledWavelengths::FromWavelength(l);
            Vector3f wo(std::sqrt(1 - mu * mu), 0, mu);
            BSDF bsdf = m->GetBSDF(Context(wo), lambda);
            Float a1 = albedo->LinearPolarization(m, bsdf, wo).s1[0];
            FresnelRsRp R =
                FrComplexPolarized(mu, std::complex<Float>((*GetNamedSpectrum("metal-Au-eta"))(l),
                                                           (*GetNamedSpectrum("metal-Au-k"))(l)));
            EXPECT_NEAR(a1, (R.Rs - R.Rp) / 2, 1e-6f) << l << " nm, mu " << mu;
            // Reflection is polarised perpendicular to the plane (Rs >= Rp), except at normal
            // incidence where it is not polarised
            EXPECT_GE(a1, -1e-7f);
            if (mu == 1) {
                EXPECT_NEAR(a1, 0, 1e-6f);
            }
        }
}

TEST(PolarizedEmissivity, RoughConductorTablesMatchThePolarisedBSDF) {
    PolarizedFixture f;
    RNG rng(17);
    struct Case {
        std::string what;
        ParsedParameterVector params;
        bool anisotropic;
    };
    std::vector<Case> cases;
    for (Float roughness : {0.01f, 0.05f, 0.2f, 0.6f})
        cases.push_back({"roughness " + std::to_string(roughness), Gold(roughness), false});
    ParsedParameterVector brushed = Gold(0);
    brushed.pop_back();
    brushed.push_back(Float1("uroughness", 0.02f));
    brushed.push_back(Float1("vroughness", 0.4f));
    cases.push_back({"anisotropic", brushed, true});
    ParsedParameterVector textured = Gold(0);
    textured.pop_back();
    textured.push_back(Texture("roughness", "ramp"));
    cases.push_back({"textured roughness", textured, false});
    for (const Case& c : cases) {
        const Material* m = f.Make("conductor", c.params);
        const MaterialAlbedo* albedo = MaterialAlbedo::Create(*m, f.tables, f.arena);
        double largestA1 = 0, largestS2 = 0;
        for (Float mu : {0.95f, 0.6f, 0.3f, 0.1f}) {
            Float phi = 2 * Pi * rng.UniformFloat(), s = std::sqrt(1 - mu * mu);
            Vector3f wo(s * std::cos(phi), s * std::sin(phi), mu);
            SampledWavelengths lambda = SampledWavelengths::SampleVisible(rng.UniformFloat());
            SampledWavelengths l = lambda;
            BSDF bsdf = m->GetBSDF(Context(wo, Point2f(rng.UniformFloat(), rng.UniformFloat())), l);
            ReflectedPolarization a = albedo->LinearPolarization(m, bsdf, wo);
            // The BSDF's own: S1 and S2 of the reflected light about the plane of n and wo
            Vector3f axis = PlaneAxis(Vector3f(0, 0, 1), wo);
            RunningStats s1[NSpectrumSamples], s2[NSpectrumSamples];
            for (int k = 0; k < 100000; ++k) {
                auto bs = bsdf.Sample_f<MuellerMatrix>(
                    wo, rng.UniformFloat(), Point2f(rng.UniformFloat(), rng.UniformFloat()));
                Stokes out;
                if (bs && bs->pdf > 0)
                    out = RotateStokesBasis(bs->f * Stokes(SampledSpectrum(1.f)), wo,
                                            StokesBasis(wo), axis) *
                          (AbsCosTheta(bs->wi) / bs->pdf);
                for (int i = 0; i < NSpectrumSamples; ++i) {
                    s1[i].Add(out[1][i]);
                    s2[i].Add(out[2][i]);
                }
            }
            for (int i = 0; i < NSpectrumSamples; ++i) {
                EXPECT_NEAR(a.s1[i], s1[i].Mean(), 4 * s1[i].StandardError() + 1e-3)
                    << c.what << " mu " << mu;
                EXPECT_NEAR(a.s2[i], s2[i].Mean(), 4 * s2[i].StandardError() + 1e-3)
                    << c.what << " mu " << mu;
                largestS2 = std::max(largestS2, std::abs(s2[i].Mean()));
                largestA1 = std::max(largestA1, std::abs(s1[i].Mean()));
            }
        }
        // The test can see what it checks: rough gold's reflection is polarised, and for
        // anisotropic roughness not only about the plane of the normal and wo
        EXPECT_GT(largestA1, 0.01) << c.what;
        if (c.anisotropic) {
            EXPECT_GT(largestS2, 0.005);
        }
    }
}

TEST(PolarizedEmissivity, UnpolarisedRenderingBuildsNoPolarisationTable) {
    PolarizedFixture f;
    f.tables.polarized = false;
    const Material* m = f.Make("conductor", Gold(0.2f));
    const MaterialAlbedo* albedo = MaterialAlbedo::Create(*m, f.tables, f.arena);
    Vector3f wo = Normalize(Vector3f(1, 0, 0.3f));
    SampledWavelengths lambda = SampledWavelengths::FromWavelength(550);
    BSDF bsdf = m->GetBSDF(Context(wo), lambda);
    EXPECT_FALSE(bool(albedo->LinearPolarization(m, bsdf, wo)));
}

}  // namespace kiln
