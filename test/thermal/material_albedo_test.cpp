// Emissivity = 1 - directional albedo of a material's own BSDF (thermal/material_albedo.h): the
// closed forms and the tables MaterialAlbedo evaluates per sample, against the BSDF itself
// (the mean scattering weight f |cos| / pdf of Sample_f at the same point, for the same
// direction), for uniform and textured materials. The tables' goal is 1e-3 absolute.
#include "thermal/material_albedo.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "base/rng.h"
#include "base/statistics.h"
#include "materials/bxdfs/conductor_albedo.h"
#include "materials/bxdfs/fresnel.h"
#include "materials/materials.h"
#include "spectral/named_spectra.h"
#include "textures/texture_parameter_dictionary.h"
#include "thermal_test_util.h"

namespace kiln {
namespace {

using namespace kiln::test;

struct Fixture : ThermalFixture {
    Fixture() {
        // A float texture varying over uv from 0 to 1 ("ramp"), for roughness and amounts
        AddBilerpFloat("ramp", 0, 1, 0.2f, 0.7f);
        ParameterDictionary c(
            {Floats("rgb", "v00", {0.05f, 0.1f, 0.2f}), Floats("rgb", "v10", {0.9f, 0.8f, 0.7f}),
             Floats("rgb", "v01", {0.5f, 0.5f, 0.5f}), Floats("rgb", "v11", {0.95f, 0.95f, 0.95f})},
            nullptr);
        TextureParameterDictionary tc(&c, &named);
        named.albedoSpectrumTextures.insert_or_assign(
            "colours", CreateSpectrumTexture("bilerp", Transform(), tc, SpectrumType::Albedo,
                                             TestLoc(), arena, diag));
    }
};

// Largest deviation of the table albedo from the BSDF's sampled albedo beyond 4 standard
// errors, over points, directions and wavelengths.
double MaxTableError(const Material& material, const MaterialAlbedo& albedo, int points,
                     int samples, uint64_t seed) {
    RNG rng(seed);
    double worst = 0;
    for (int p = 0; p < points; ++p) {
        Point2f uv(rng.UniformFloat(), rng.UniformFloat());
        Float mu = std::max(0.02f, rng.UniformFloat()), phi = 2 * Pi * rng.UniformFloat();
        Float s = std::sqrt(1 - mu * mu);
        Vector3f wo(s * std::cos(phi), s * std::sin(phi), mu);
        SampledWavelengths lambda = SampledWavelengths::SampleVisible(rng.UniformFloat());
        MaterialEvalContext ctx = Context(uv, wo);
        const Material* leaf = material.ChooseMaterial(ctx);
        SampledWavelengths l = lambda;
        BSDF bsdf = leaf->GetBSDF(ctx, l);
        SampledSpectrum A = albedo.Evaluate(leaf, bsdf, wo, lambda);
        // The BSDF's own albedo, per wavelength
        RunningStats stats[NSpectrumSamples];
        for (int k = 0; k < samples; ++k) {
            std::optional<BSDFSample> bs = bsdf.Sample_f(
                wo, rng.UniformFloat(), Point2f(rng.UniformFloat(), rng.UniformFloat()));
            for (int i = 0; i < NSpectrumSamples; ++i)
                stats[i].Add(bs && bs->pdf > 0
                                 ? bs->f[i] * AbsDot(bs->wi, Vector3f(0, 0, 1)) / bs->pdf
                                 : 0.0);
        }
        int n = l.SecondaryTerminated() ? 1 : NSpectrumSamples;
        for (int i = 0; i < n; ++i) {
            double e = std::abs(A[i] - stats[i].Mean()) - 4 * stats[i].StandardError();
            worst = std::max(worst, e);
        }
    }
    return worst;
}

TEST(EmissivityTest, SmoothMetalsEmitOneMinusFresnel) {
    Fixture f;
    for (const char* metal : {"Ag", "Al", "Au", "Cu", "CuZn", "Pt", "Ni", "Fe", "W", "Cr", "Ti"}) {
        SCOPED_TRACE(metal);
        std::string m = std::string("metal-") + metal;
        const Material* material = f.Make("conductor", {Strings("spectrum", "eta", {m + "-eta"}),
                                                        Strings("spectrum", "k", {m + "-k"})});
        const MaterialAlbedo* albedo = MaterialAlbedo::Create(*material, f.tables, f.arena);
        for (Float l = 380; l <= 780; l += 20)
            for (Float mu : {1.f, 0.5f, 0.05f}) {
                SampledWavelengths lambda = SampledWavelengths::FromWavelength(l);
                Vector3f wo(std::sqrt(1 - mu * mu), 0, mu);
                BSDF bsdf = material->GetBSDF(Context(Point2f(0.5f, 0.5f), wo), lambda);
                Float emissivity = 1 - albedo->Evaluate(material, bsdf, wo, lambda)[0];
                std::complex<Float> n((*GetNamedSpectrum(m + "-eta"))(l),
                                      (*GetNamedSpectrum(m + "-k"))(l));
                EXPECT_NEAR(emissivity, 1 - FrComplex(mu, n), 1e-6) << l << " nm, mu " << mu;
            }
    }
}

TEST(EmissivityTest, DiffuseEmitsOneMinusReflectanceAndGlassNothing) {
    Fixture f;
    const Material* diffuse = f.Make("diffuse", {Texture("reflectance", "colours")});
    // Smooth glass (rough glass: dielectric_emissivity_test.cpp)
    const Material* glass = f.Make("dielectric", {});
    for (const Material* m : {diffuse, glass}) {
        const MaterialAlbedo* albedo = MaterialAlbedo::Create(*m, f.tables, f.arena);
        SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.3f);
        Vector3f wo = Normalize(Vector3f(0.3f, 0.1f, 0.8f));
        BSDF bsdf = m->GetBSDF(Context(Point2f(0.3f, 0.8f), wo), lambda);
        SampledSpectrum A = albedo->Evaluate(m, bsdf, wo, lambda);
        SampledSpectrum expected = m == diffuse ? bsdf.GetBxDF().GetIf<DiffuseBxDF>()->Reflectance()
                                                : SampledSpectrum(1.f);
        for (int i = 0; i < NSpectrumSamples; ++i) EXPECT_EQ(A[i], expected[i]);
    }
}

TEST(EmissivityTest, RoughConductorTablesMatchTheBSDF) {
    Fixture f;
    ParsedParameterVector gold = {Strings("spectrum", "eta", {"metal-Au-eta"}),
                                  Strings("spectrum", "k", {"metal-Au-k"})};
    struct Case {
        const char* what;
        ParsedParameterVector params;
    };
    std::vector<Case> cases;
    for (Float r : {0.001f, 0.01f, 0.1f, 0.5f, 1.f}) {
        ParsedParameterVector p = gold;
        p.push_back(Float1("roughness", r));
        cases.push_back({"uniform", p});
    }
    ParsedParameterVector textured = gold;
    textured.push_back(Texture("roughness", "ramp"));
    cases.push_back({"textured roughness", textured});
    cases.push_back(
        {"textured reflectance", {Texture("reflectance", "colours"), Float1("roughness", 0.2f)}});
    for (const Case& c : cases) {
        const Material* m = f.Make("conductor", c.params);
        const MaterialAlbedo* albedo = MaterialAlbedo::Create(*m, f.tables, f.arena);
        EXPECT_LT(MaxTableError(*m, *albedo, 12, 60000, 5), 1e-3) << c.what;
    }
}

// Named metals whose constants follow the surface's temperature: the tables over wavelength and
// temperature (100 K nodes) against the Fresnel factors of the BSDF's own constants, at random
// directions, wavelengths over the visible and temperatures up to the melting point
TEST(EmissivityTest, ConductorTablesFollowTheTemperature) {
    Fixture f;
    RNG rng(26);
    for (const char* metal : {"W", "Au", "Ag"})
        for (bool textured : {false, true}) {
            std::string s = metal;
            ParsedParameterVector p = {Strings("spectrum", "eta", {"metal-" + s + "-eta"}),
                                       Strings("spectrum", "k", {"metal-" + s + "-k"})};
            p.push_back(textured ? Texture("roughness", "ramp") : Float1("roughness", 0.3f));
            const Material* m = f.Make("conductor", p);
            ASSERT_TRUE(m->UsesTemperature());
            ConductorEmissivity e(*m->GetIf<ConductorMaterial>(), f.tables);
            ASSERT_TRUE(e.NeedsTemperature());
            double worst = 0;
            for (int i = 0; i < 400; ++i) {
                Float T = 300 + 3400 * rng.UniformFloat();
                Vector3f wo = SampleUniformHemisphere({rng.UniformFloat(), rng.UniformFloat()});
                MaterialEvalContext ctx = Context({rng.UniformFloat(), rng.UniformFloat()}, wo);
                ctx.temperature = T;
                SampledWavelengths lambda = SampledWavelengths::SampleVisible(rng.UniformFloat());
                BSDF bsdf = m->GetBSDF(ctx, lambda);
                const ConductorBxDF& c = *bsdf.GetBxDF().GetIf<ConductorBxDF>();
                Vector3f local = bsdf.RenderToLocal(wo);
                SampledSpectrum tabulated = e.Albedo(c, local, lambda, T);
                SampledSpectrum exact = e.Albedo(c, local, lambda, -1);
                for (int j = 0; j < NSpectrumSamples; ++j)
                    worst = std::max(worst, double(std::abs(tabulated[j] - exact[j])));
            }
            std::printf("%s, %s roughness: largest albedo difference %.2e\n", metal,
                        textured ? "textured" : "uniform", worst);
            EXPECT_LT(worst, 1e-3) << metal;  // as the tables of constant metals
        }
}

TEST(EmissivityTest, CoatedTablesMatchTheBSDF) {
    Fixture f;
    struct Case {
        const char* type;
        ParsedParameterVector params;
    };
    std::vector<Case> cases = {
        {"coateddiffuse", {Texture("reflectance", "colours")}},
        {"coateddiffuse", {Texture("reflectance", "colours"), Texture("roughness", "ramp")}},
        {"coateddiffuse",
         {Floats("rgb", "reflectance", {0, 0, 0}), Strings("spectrum", "eta", {"glass-SiO2"})}},
        {"coatedconductor",
         {Float1("interface.roughness", 0.1f), Float1("conductor.roughness", 0.2f)}},
        {"coatedconductor", {Texture("interface.roughness", "ramp")}},
        // Hot tungsten's constants (fixed at 2500 K) under a rough coat
        {"coatedconductor",
         {Strings("spectrum", "conductor.eta", {"metal-W-eta"}),
          Strings("spectrum", "conductor.k", {"metal-W-k"}), Float1("interface.roughness", 0.2f),
          Float1("conductor.roughness", 0.1f), Float1("opticaltemperature", 2500)}},
    };
    for (const Case& c : cases) {
        const Material* m = f.Make(c.type, c.params);
        const MaterialAlbedo* albedo = MaterialAlbedo::Create(*m, f.tables, f.arena);
        EXPECT_TRUE(albedo->Exact());
        EXPECT_LT(MaxTableError(*m, *albedo, 8, 60000, 11), 1e-3) << c.type;
    }
}

TEST(EmissivityTest, CoatedConductorTablesFollowTheTemperature) {
    // A coated named metal whose constants follow the surface's temperature: its tables over
    // temperature (200 K nodes) against tables built at the constants of one fixed temperature
    Fixture f;
    auto params = [](std::optional<Float> fixed) {
        ParsedParameterVector p = {Strings("spectrum", "conductor.eta", {"metal-W-eta"}),
                                   Strings("spectrum", "conductor.k", {"metal-W-k"}),
                                   Float1("interface.roughness", 0.15f),
                                   Float1("conductor.roughness", 0.3f)};
        if (fixed) p.push_back(Float1("opticaltemperature", *fixed));
        return p;
    };
    const Material* following = f.Make("coatedconductor", params(std::nullopt));
    ASSERT_TRUE(following->UsesTemperature());
    CoatedConductorEmissivity e(*following->GetIf<CoatedConductorMaterial>(), *following, f.tables);
    ASSERT_TRUE(e.NeedsTemperature());
    ASSERT_TRUE(e.Exact());
    RNG rng(31);
    double worst = 0, change = 0;
    for (int i = 0; i < 4; ++i) {
        Float T = 400 + 3200 * rng.UniformFloat();
        const Material* fixed = f.Make("coatedconductor", params(T));
        ASSERT_FALSE(fixed->UsesTemperature());
        CoatedConductorEmissivity at(*fixed->GetIf<CoatedConductorMaterial>(), *fixed, f.tables);
        ASSERT_FALSE(at.NeedsTemperature());
        for (int k = 0; k < 50; ++k) {
            Vector3f wo = SampleUniformHemisphere({rng.UniformFloat(), rng.UniformFloat()});
            SampledWavelengths lambda = SampledWavelengths::SampleVisible(rng.UniformFloat());
            MaterialEvalContext ctx = Context({0.5f, 0.5f}, wo);
            ctx.temperature = T;
            SampledWavelengths l = lambda;
            BSDF bsdf = following->GetBSDF(ctx, l);
            const CoatedConductorBxDF& c = *bsdf.GetBxDF().GetIf<CoatedConductorBxDF>();
            Vector3f local = bsdf.RenderToLocal(wo);
            SampledSpectrum interpolated = e.Albedo(c, local, lambda, T);
            SampledSpectrum exact = at.Albedo(c, local, lambda);
            SampledSpectrum room = e.Albedo(c, local, lambda, 0);
            for (int j = 0; j < NSpectrumSamples; ++j) {
                worst = std::max(worst, double(std::abs(interpolated[j] - exact[j])));
                change = std::max(change, double(std::abs(exact[j] - room[j])));
            }
        }
    }
    std::printf(
        "coated tungsten: largest albedo difference %.2e between temperature nodes; "
        "largest change from room temperature %.3f\n",
        worst, change);
    EXPECT_LT(worst, 2e-3);
    EXPECT_GT(change, 0.02);  // the temperature matters: the test can tell
}

TEST(EmissivityTest, MixUsesTheComponentChosenAtThePoint) {
    Fixture f;
    f.namedMaterials.emplace(
        "a", *f.Make("diffuse", {Floats("rgb", "reflectance", {0.2f, 0.2f, 0.2f})}));
    f.namedMaterials.emplace("b", *f.Make("conductor", {Float1("roughness", 0.3f)}));
    const Material* mix =
        f.Make("mix", {Strings("string", "materials", {"a", "b"}), Texture("amount", "ramp")});
    const MaterialAlbedo* albedo = MaterialAlbedo::Create(*mix, f.tables, f.arena);
    EXPECT_LT(MaxTableError(*mix, *albedo, 16, 40000, 23), 1e-3);
}

TEST(EmissivityTest, ParsesEmissionModels) {
    EXPECT_EQ(ParseEmissionModel("kirchhoff"), EmissionModel::Kirchhoff);
    EXPECT_EQ(ParseEmissionModel("additive"), EmissionModel::Additive);
    EXPECT_EQ(ParseEmissionModel("diffuse"), EmissionModel::Diffuse);
    EXPECT_EQ(ParseEmissionModel("none"), EmissionModel::None);
    EXPECT_FALSE(ParseEmissionModel("Kirchhoff"));
}

// The documented error of Kirchhoff emission from rough conductors: pbrt-v4's single-scattering
// microfacet model loses the energy of multiply scattered light, so 1 - albedo over-estimates
// emissivity by that loss. A perfect mirror metal (F = 1) shows the loss directly: about 12 %
// at alpha 0.3 and 69 % at alpha 1 at normal incidence (thermal/material_albedo.h,
// docs/guide/glowing-objects.md).
TEST(EmissivityTest, RoughConductorSingleScatteringLossIsAsDocumented) {
    auto mirror = [](double alpha) {
        return ConductorAlbedoMoments::Apply(ConductorAlbedoMoments::Compute(alpha, 1),
                                             [](double) { return 1.0; });
    };
    EXPECT_NEAR(1 - mirror(0.3), 0.12, 0.01);
    EXPECT_NEAR(1 - mirror(1.0), 0.69, 0.01);
}

}  // namespace
}  // namespace kiln
namespace kiln {
namespace {

// Largest deviation of a conductor's table albedo from the quadrature at the same point,
// direction and wavelengths (no Monte Carlo noise), over directions with cos theta >= muMin and
// points uv (fixed, or random when uv is negative).
double MaxQuadratureError(Fixture& f, const Material* m, Float muMin, int n, uint64_t seed,
                          Point2f uv = Point2f(-1, -1)) {
    const MaterialAlbedo* albedo = MaterialAlbedo::Create(*m, f.tables, f.arena);
    RNG rng(seed);
    double worst = 0;
    for (int k = 0; k < n; ++k) {
        Float mu = muMin + (1 - muMin) * rng.UniformFloat(), phi = 2 * Pi * rng.UniformFloat();
        Float s = std::sqrt(1 - mu * mu);
        Vector3f wo(s * std::cos(phi), s * std::sin(phi), mu);
        SampledWavelengths lambda = SampledWavelengths::SampleVisible(rng.UniformFloat());
        Point2f p = uv.x < 0 ? Point2f(rng.UniformFloat(), rng.UniformFloat()) : uv;
        MaterialEvalContext ctx = Context(p, wo);
        SampledWavelengths l = lambda;
        BSDF bsdf = m->GetBSDF(ctx, l);
        SampledSpectrum A = albedo->Evaluate(m, bsdf, wo, lambda);
        const ConductorBxDF* c = bsdf.GetBxDF().GetIf<ConductorBxDF>();
        const TrowbridgeReitzDistribution& d = c->Distribution();
        if (d.EffectivelySmooth()) continue;
        double w[3] = {wo.x, wo.y, wo.z};
        ConductorAlbedoMoments::Weights weights =
            ConductorAlbedoMoments::Compute(d.AlphaX(), d.AlphaY(), w);
        for (int i = 0; i < NSpectrumSamples; ++i) {
            std::complex<Float> eta(c->Eta()[i], c->K()[i]);
            double ref = ConductorAlbedoMoments::Apply(
                weights, [&](double x) { return double(FrComplex(Float(x), eta)); });
            worst = std::max(worst, std::abs(A[i] - ref));
        }
    }
    return worst;
}

TEST(EmissivityTest, ConductorTablesMatchTheQuadrature) {
    // Every kind of conductor table against the quadrature: the interpolation over cosine,
    // roughness and wavelength or reflectance, and the low-rank Fresnel factorisation
    Fixture f;
    struct Case {
        const char* what;
        ParsedParameterVector params;
    };
    auto metal = [](const char* name, ParsedParameterVector more) {
        ParsedParameterVector p = {
            Strings("spectrum", "eta", {std::string("metal-") + name + "-eta"}),
            Strings("spectrum", "k", {std::string("metal-") + name + "-k"})};
        p.insert(p.end(), more.begin(), more.end());
        return p;
    };
    std::vector<Case> cases = {
        {"gold 0.01", metal("Au", {Float1("roughness", 0.01f)})},
        {"copper 0.3", metal("Cu", {Float1("roughness", 0.3f)})},
        {"silver 1", metal("Ag", {Float1("roughness", 1.f)})},
        {"aluminium 0.1", metal("Al", {Float1("roughness", 0.1f)})},
        {"gold, textured roughness", metal("Au", {Texture("roughness", "ramp")})},
        {"constant reflectance",
         {Floats("rgb", "reflectance", {0.9f, 0.6f, 0.2f}), Float1("roughness", 0.2f)}},
        {"textured reflectance", {Texture("reflectance", "colours"), Float1("roughness", 0.2f)}},
        {"textured reflectance and roughness",
         {Texture("reflectance", "colours"), Texture("roughness", "ramp")}},
    };
    for (const Case& c : cases) {
        const Material* m = f.Make("conductor", c.params);
        double above10 = MaxQuadratureError(f, m, 0.1f, 400, 5);
        double above2 = MaxQuadratureError(f, m, 0.02f, 400, 6);
        printf("%s: largest table error %.2g (cos theta >= 0.1), %.2g (>= 0.02)\n", c.what, above10,
               above2);
        EXPECT_LT(above10, 5e-4) << c.what;
        EXPECT_LT(above2, 1.5e-3) << c.what;
    }
}

TEST(EmissivityTest, AnisotropicRoughConductorTablesMatchTheBSDF) {
    Fixture f;
    // Brushed metals, against the sampled BSDF
    for (auto [u, v] : {std::pair{0.05f, 0.3f}, {0.3f, 0.05f}, {0.02f, 0.2f}, {0.3f, 1.f}}) {
        ParsedParameterVector p = {
            Strings("spectrum", "eta", {"metal-Au-eta"}), Strings("spectrum", "k", {"metal-Au-k"}),
            Float1("uroughness", u), Float1("vroughness", v), Bool1("remaproughness", false)};
        const Material* m = f.Make("conductor", p);
        const MaterialAlbedo* albedo = MaterialAlbedo::Create(*m, f.tables, f.arena);
        EXPECT_LT(MaxTableError(*m, *albedo, 12, 60000, 11), 1e-3) << u << " " << v;
    }
    // The tables' interpolation (cosine, azimuth, wavelength) against the quadrature at the
    // same direction and wavelengths, up to extreme anisotropy
    for (auto [u, v] : {std::pair{0.05f, 0.3f}, {0.01f, 0.5f}, {1.f, 0.01f}, {0.002f, 1.f}}) {
        const Material* m =
            f.Make("conductor", {Strings("spectrum", "eta", {"metal-Au-eta"}),
                                 Strings("spectrum", "k", {"metal-Au-k"}), Float1("uroughness", u),
                                 Float1("vroughness", v), Bool1("remaproughness", false)});
        EXPECT_TRUE(MaterialAlbedo::Create(*m, f.tables, f.arena)->Exact());
        double above10 = MaxQuadratureError(f, m, 0.1f, 400, 3, Point2f(0.5f, 0.5f));
        double above2 = MaxQuadratureError(f, m, 0.02f, 400, 4, Point2f(0.5f, 0.5f));
        printf("alpha %g x %g: largest table error %.2g (cos theta >= 0.1), %.2g (>= 0.02)\n", u, v,
               above10, above2);
        EXPECT_LT(above10, 5e-4) << u << " " << v;
        EXPECT_LT(above2, 1.5e-3) << u << " " << v;
    }
}

TEST(EmissivityTest, TexturedAnisotropicRoughnessIsFlaggedApproximate) {
    Fixture f;
    // One texture for both directions: isotropic everywhere, exact
    const Material* same = f.Make("conductor", {Texture("roughness", "ramp")});
    EXPECT_TRUE(MaterialAlbedo::Create(*same, f.tables, f.arena)->Exact());
    // Different textures or values: the projected-roughness approximation, flagged
    const Material* aniso =
        f.Make("conductor", {Texture("uroughness", "ramp"), Float1("vroughness", 0.3f)});
    const MaterialAlbedo* approx = MaterialAlbedo::Create(*aniso, f.tables, f.arena);
    EXPECT_FALSE(approx->Exact());
    // Its error against the quadrature, where the ramp gives roughness 0.05 (alpha 0.22 by
    // pbrt's remapping) against 0.3 (alpha 0.55)
    RNG rng(9);
    double worst = 0;
    for (int k = 0; k < 200; ++k) {
        Float mu = 0.1f + 0.9f * rng.UniformFloat(), phi = 2 * Pi * rng.UniformFloat();
        Float s = std::sqrt(1 - mu * mu);
        Vector3f wo(s * std::cos(phi), s * std::sin(phi), mu);
        SampledWavelengths lambda = SampledWavelengths::SampleVisible(rng.UniformFloat());
        MaterialEvalContext ctx = Context(Point2f(0.05f, 0), wo);
        SampledWavelengths l = lambda;
        BSDF bsdf = aniso->GetBSDF(ctx, l);
        const ConductorBxDF* c = bsdf.GetBxDF().GetIf<ConductorBxDF>();
        const TrowbridgeReitzDistribution& d = c->Distribution();
        double w[3] = {wo.x, wo.y, wo.z};
        ConductorAlbedoMoments::Weights weights =
            ConductorAlbedoMoments::Compute(d.AlphaX(), d.AlphaY(), w);
        SampledSpectrum A = approx->Evaluate(aniso, bsdf, wo, lambda);
        std::complex<Float> eta(c->Eta()[0], c->K()[0]);
        double ref = ConductorAlbedoMoments::Apply(
            weights, [&](double x) { return double(FrComplex(Float(x), eta)); });
        worst = std::max(worst, std::abs(A[0] - ref));
    }
    printf("textured anisotropic roughness: largest albedo error %.3f\n", worst);
    EXPECT_GT(worst, 0);
    EXPECT_LT(worst, 0.1);  // the bound conductor_emissivity.h states
    // A uniform anisotropic material is exact
    const Material* brushed =
        f.Make("conductor", {Float1("uroughness", 0.1f), Float1("vroughness", 0.3f)});
    EXPECT_TRUE(MaterialAlbedo::Create(*brushed, f.tables, f.arena)->Exact());
}

}  // namespace
}  // namespace kiln
