// Tests of material creation from scene parameters and of Material::GetBSDF.
#include <gtest/gtest.h>

#include <cmath>

#include "../textures/param_helpers.h"
#include "base/rng.h"
#include "base/statistics.h"
#include "materials/material.h"
#include "materials/materials.h"
#include "spectral/color.h"
#include "spectral/named_spectra.h"
#include "textures/basic_textures.h"
#include "textures/texture_parameter_dictionary.h"

namespace kiln {
namespace {

using namespace kiln::test;

struct Fixture {
    ObjectArena arena;
    Diagnostics diag{nullptr};
    NamedTextures named;
    std::map<std::string, Material> namedMaterials;

    Material Make(const std::string& type, const ParameterDictionary& d) {
        TextureParameterDictionary params(&d, &named);
        return Material::Create(type, params, namedMaterials, TestLoc(), arena, diag);
    }
};

MaterialEvalContext Context(Point3f p = Point3f(0.1f, 0.2f, 0.3f),
                            Vector3f wo = Vector3f(0, 0, 1)) {
    MaterialEvalContext ctx;
    ctx.p = p;
    ctx.n = Normal3f(0, 0, 1);
    ctx.ns = Normal3f(0, 0, 1);
    ctx.dpdus = Vector3f(1, 0, 0);
    ctx.uv = Point2f(0.5f, 0.5f);
    ctx.wo = wo;
    return ctx;
}

SampledWavelengths Lambda() { return SampledWavelengths::SampleVisible(0.41f); }

BSDF GetBSDF(const Material& m, SampledWavelengths* lambda = nullptr) {
    SampledWavelengths l = Lambda();
    BSDF bsdf = m.GetBSDF(Context(), lambda ? *lambda : l);
    return bsdf;
}

TEST(Materials, EachTypeCreatesItsBxDF) {
    Fixture f;
    EXPECT_TRUE(GetBSDF(f.Make("diffuse", Dict({}))).GetBxDF().Is<DiffuseBxDF>());
    EXPECT_TRUE(GetBSDF(f.Make("conductor", Dict({}))).GetBxDF().Is<ConductorBxDF>());
    EXPECT_TRUE(GetBSDF(f.Make("dielectric", Dict({}))).GetBxDF().Is<DielectricBxDF>());
    EXPECT_TRUE(GetBSDF(f.Make("thindielectric", Dict({}))).GetBxDF().Is<ThinDielectricBxDF>());
    EXPECT_TRUE(GetBSDF(f.Make("coateddiffuse", Dict({}))).GetBxDF().Is<CoatedDiffuseBxDF>());
    EXPECT_TRUE(GetBSDF(f.Make("coatedconductor", Dict({}))).GetBxDF().Is<CoatedConductorBxDF>());
    EXPECT_TRUE(f.Make("diffuse", Dict({})).Is<DiffuseMaterial>());
    EXPECT_EQ(f.diag.WarningCount(), 0);
}

TEST(Materials, DiffuseReflectance) {
    Fixture f;
    BSDF def = GetBSDF(f.Make("diffuse", Dict({})));
    EXPECT_EQ(def.GetBxDF().GetIf<DiffuseBxDF>()->Reflectance(), SampledSpectrum(0.5f));
    SampledWavelengths lambda = Lambda();
    BSDF rgb = GetBSDF(f.Make("diffuse", Dict({Rgb("reflectance", 0.2f, 0.4f, 0.6f)})), &lambda);
    SampledSpectrum expected =
        RGBAlbedoSpectrum(RGBColorSpace::sRGB(), RGB(0.2f, 0.4f, 0.6f)).Sample(lambda);
    SampledSpectrum got = rgb.GetBxDF().GetIf<DiffuseBxDF>()->Reflectance();
    for (int i = 0; i < NSpectrumSamples; ++i) EXPECT_NEAR(got[i], expected[i], 1e-5f);
    // Textured reflectance goes through the named albedo texture
    f.named.albedoSpectrumTextures.emplace(
        "t", f.arena.New<SpectrumConstantTexture>(Spectrum(ConstantSpectrum(0.3f))));
    BSDF tex = GetBSDF(f.Make("diffuse", Dict({Tex("reflectance", "t")})));
    EXPECT_EQ(tex.GetBxDF().GetIf<DiffuseBxDF>()->Reflectance(), SampledSpectrum(0.3f));
}

TEST(Materials, ConductorNamedMetals) {
    Fixture f;
    SampledWavelengths lambda = Lambda();
    // Default: copper
    BSDF cuBSDF = GetBSDF(f.Make("conductor", Dict({})), &lambda);
    const ConductorBxDF* cu = cuBSDF.GetBxDF().GetIf<ConductorBxDF>();
    ASSERT_TRUE(cu);
    EXPECT_EQ(cu->Eta(), GetNamedSpectrum("metal-Cu-eta")->Sample(lambda));
    EXPECT_EQ(cu->K(), GetNamedSpectrum("metal-Cu-k")->Sample(lambda));
    // Named gold
    Material au = f.Make("conductor", Dict({Strings("spectrum", "eta", {"metal-Au-eta"}),
                                            Strings("spectrum", "k", {"metal-Au-k"})}));
    BSDF bsdf = GetBSDF(au, &lambda);
    const ConductorBxDF* c = bsdf.GetBxDF().GetIf<ConductorBxDF>();
    EXPECT_EQ(c->Eta(), GetNamedSpectrum("metal-Au-eta")->Sample(lambda));
    EXPECT_EQ(c->K(), GetNamedSpectrum("metal-Au-k")->Sample(lambda));
    EXPECT_FALSE(lambda.SecondaryTerminated());
    // The material's textures are reachable from outside
    const ConductorMaterial* m = au.GetIf<ConductorMaterial>();
    ASSERT_TRUE(m && m->Eta() && m->K());
    EXPECT_FALSE(m->Reflectance());
}

// Spectra given as wavelength-value pairs are 0 outside them: a conductor whose eta and k are
// both 0 at some rendered wavelength is a perfect mirror there, which kiln says (pbrt-v4 drops
// such samples as not-a-number); the named metals, k alone 0 (a dielectric-like conductor) and
// coated conductors' own "conductor." constants are checked alike.
TEST(Materials, ConductorWithZeroConstantsSomewhereWarns) {
    Fixture f;
    f.Make("conductor", Dict({Strings("spectrum", "eta", {"metal-Ag-eta"}),
                              Strings("spectrum", "k", {"metal-Ag-k"})}));
    f.Make("conductor", Dict({Floats("spectrum", "eta", {300, 1.5f, 900, 1.5f}),
                              Floats("spectrum", "k", {300, 0, 900, 0})}));
    EXPECT_EQ(f.diag.WarningCount(), 0);
    f.Make("conductor", Dict({Floats("spectrum", "eta", {400, 1.5f, 700, 1.5f}),
                              Floats("spectrum", "k", {400, 3, 700, 3})}));
    ASSERT_EQ(f.diag.WarningCount(), 1);
    EXPECT_NE(f.diag.Warnings()[0].message.find("both 0 at 360 nm"), std::string::npos)
        << f.diag.Warnings()[0].message;
    f.Make("coatedconductor", Dict({Floats("spectrum", "conductor.eta", {300, 0.2f, 800, 0.2f}),
                                    Floats("spectrum", "conductor.k", {300, 3, 800, 3})}));
    EXPECT_EQ(f.diag.WarningCount(), 2);
}

TEST(Materials, ConductorReflectance) {
    Fixture f;
    Material m = f.Make("conductor", Dict({Rgb("reflectance", 0.64f, 0.64f, 0.64f)}));
    BSDF bsdf = GetBSDF(m);
    const ConductorBxDF* c = bsdf.GetBxDF().GetIf<ConductorBxDF>();
    ASSERT_TRUE(c);
    for (int i = 0; i < NSpectrumSamples; ++i) {
        EXPECT_FLOAT_EQ(c->Eta()[i], 1);
        // k = 2 sqrt(r) / sqrt(1 - r) with r = 0.64 (grey albedo spectra are nearly flat)
        EXPECT_NEAR(c->K()[i], 2 * 0.8f / 0.6f, 0.02f);
    }
    // Both reflectance and eta: error
    EXPECT_THROW(f.Make("conductor", Dict({Rgb("reflectance", 0.5f, 0.5f, 0.5f),
                                           Strings("spectrum", "eta", {"metal-Au-eta"})})),
                 SceneError);
}

TEST(Materials, RoughnessRemapping) {
    Fixture f;
    auto alphas = [&](const ParameterDictionary& d) {
        BSDF bsdf = GetBSDF(f.Make("conductor", d));
        const ConductorBxDF* c = bsdf.GetBxDF().GetIf<ConductorBxDF>();
        return std::pair(c->Distribution().AlphaX(), c->Distribution().AlphaY());
    };
    auto [ax, ay] = alphas(Dict({Float1("roughness", 0.25f)}));
    EXPECT_FLOAT_EQ(ax, TrowbridgeReitzDistribution::RoughnessToAlpha(0.25f));
    EXPECT_FLOAT_EQ(ay, TrowbridgeReitzDistribution::RoughnessToAlpha(0.25f));
    std::tie(ax, ay) = alphas(Dict({Float1("roughness", 0.25f), Bool1("remaproughness", false)}));
    EXPECT_FLOAT_EQ(ax, 0.25f);
    EXPECT_FLOAT_EQ(ay, 0.25f);
    // u/v roughness override "roughness"
    std::tie(ax, ay) = alphas(Dict(
        {Float1("uroughness", 0.04f), Float1("roughness", 0.09f), Bool1("remaproughness", false)}));
    EXPECT_FLOAT_EQ(ax, 0.04f);
    EXPECT_FLOAT_EQ(ay, 0.09f);
    // Dielectric roughness goes the same way
    BSDF rough = GetBSDF(f.Make("dielectric", Dict({Float1("roughness", 0.16f)})));
    const DielectricBxDF* d = rough.GetBxDF().GetIf<DielectricBxDF>();
    EXPECT_FLOAT_EQ(d->Distribution().AlphaX(),
                    TrowbridgeReitzDistribution::RoughnessToAlpha(0.16f));
}

TEST(Materials, DispersionTerminatesSecondaryWavelengths) {
    Fixture f;
    // Constant eta: all wavelengths continue
    SampledWavelengths lambda = Lambda();
    BSDF water = GetBSDF(f.Make("dielectric", Dict({Float1("eta", 1.33f)})), &lambda);
    const DielectricBxDF* d = water.GetBxDF().GetIf<DielectricBxDF>();
    EXPECT_FLOAT_EQ(d->Eta(), 1.33f);
    EXPECT_FALSE(lambda.SecondaryTerminated());
    // Default 1.5
    lambda = Lambda();
    EXPECT_FLOAT_EQ(
        GetBSDF(f.Make("dielectric", Dict({})), &lambda).GetBxDF().GetIf<DielectricBxDF>()->Eta(),
        1.5f);
    EXPECT_FALSE(lambda.SecondaryTerminated());
    // Named glass: eta at the hero wavelength, secondary wavelengths terminated
    const Spectrum* bk7 = GetNamedSpectrum("glass-BK7");
    for (const char* type : {"dielectric", "thindielectric", "coateddiffuse"}) {
        lambda = Lambda();
        Float hero = lambda[0];
        Material m = f.Make(type, Dict({Strings("spectrum", "eta", {"glass-BK7"})}));
        BSDF bsdf = GetBSDF(m, &lambda);
        EXPECT_TRUE(lambda.SecondaryTerminated()) << type;
        EXPECT_EQ(lambda[0], hero);
        Float eta = 0;
        if (auto* de = bsdf.GetBxDF().GetIf<DielectricBxDF>()) eta = de->Eta();
        if (auto* th = bsdf.GetBxDF().GetIf<ThinDielectricBxDF>()) eta = th->Eta();
        if (auto* cd = bsdf.GetBxDF().GetIf<CoatedDiffuseBxDF>()) eta = cd->Top().Eta();
        EXPECT_FLOAT_EQ(eta, (*bk7)(hero)) << type;
    }
}

TEST(Materials, InterfaceGivesInvalidBSDF) {
    Fixture f;
    for (const char* type : {"interface", "none", ""}) {
        Material m = f.Make(type, Dict({}));
        EXPECT_TRUE(m.IsInterface());
        EXPECT_FALSE(GetBSDF(m)) << type;
    }
    EXPECT_TRUE(GetBSDF(f.Make("diffuse", Dict({}))));
}

TEST(Materials, MixChoiceDeterministicAndProportional) {
    Fixture f;
    f.namedMaterials.emplace("red", f.Make("diffuse", Dict({})));
    f.namedMaterials.emplace("metal", f.Make("conductor", Dict({})));
    EXPECT_THROW(f.Make("mix", Dict({Strings("string", "materials", {"red"})})), SceneError);
    EXPECT_THROW(f.Make("mix", Dict({Strings("string", "materials", {"red", "nosuch"})})),
                 SceneError);

    const Float amount = 0.3f;
    Material mix = f.Make(
        "mix", Dict({Strings("string", "materials", {"red", "metal"}), Float1("amount", amount)}));
    ASSERT_TRUE(mix.IsMix());
    RNG rng(7);
    const int n = 20000;
    double counts[2] = {0, 0};
    for (int i = 0; i < n; ++i) {
        MaterialEvalContext ctx =
            Context(Point3f(rng.UniformFloat(), rng.UniformFloat(), rng.UniformFloat()),
                    Normalize(Vector3f(rng.UniformFloat() - 0.5f, 0.3f, 1)));
        const Material* m = mix.ChooseMaterial(ctx);
        ASSERT_FALSE(m->IsMix());
        // Same point and direction: same choice
        EXPECT_EQ(m, mix.ChooseMaterial(ctx));
        counts[m->Is<ConductorMaterial>() ? 1 : 0] += 1;
        if (i < 100) {
            SampledWavelengths lambda = Lambda();
            EXPECT_EQ(mix.GetBSDF(ctx, lambda).GetBxDF().Is<ConductorBxDF>(),
                      m->Is<ConductorMaterial>());
        }
    }
    double expected[2] = {n * (1 - amount), n * amount};
    ChiSquareResult r = ChiSquareTest(counts, expected);
    EXPECT_TRUE(r.passed) << r.message;

    // amount 0 and 1 pick one side always
    Material m0 = f.Make(
        "mix", Dict({Strings("string", "materials", {"red", "metal"}), Float1("amount", 0)}));
    Material m1 = f.Make(
        "mix", Dict({Strings("string", "materials", {"red", "metal"}), Float1("amount", 1)}));
    EXPECT_TRUE(m0.ChooseMaterial(Context())->Is<DiffuseMaterial>());
    EXPECT_TRUE(m1.ChooseMaterial(Context())->Is<ConductorMaterial>());

    // Nested mixes resolve to a leaf, each level choosing independently: P(metal) = 0.5 * 0.5
    f.namedMaterials.emplace(
        "inner", f.Make("mix", Dict({Strings("string", "materials", {"red", "metal"})})));
    Material outer = f.Make("mix", Dict({Strings("string", "materials", {"red", "inner"})}));
    double nested[2] = {0, 0};
    for (int i = 0; i < n; ++i) {
        MaterialEvalContext ctx =
            Context(Point3f(rng.UniformFloat(), rng.UniformFloat(), 0), Vector3f(0, 0, 1));
        nested[outer.ChooseMaterial(ctx)->Is<ConductorMaterial>() ? 1 : 0] += 1;
    }
    double nestedExpected[2] = {n * 0.75, n * 0.25};
    r = ChiSquareTest(nested, nestedExpected);
    EXPECT_TRUE(r.passed) << r.message;
}

// "measured": an RGL .bsdf file, read once however many materials name it; what is wrong with
// the file is an error at the "filename" parameter
TEST(Materials, Measured) {
    Fixture f;
    const std::string file =
        std::string(KILN_SOURCE_DIR) + "/test/regression/pbrt_features/measured-ggx.bsdf";
    Material a = f.Make("measured", Dict({Strings("string", "filename", {file})}));
    Material b = f.Make("measured", Dict({Strings("string", "filename", {file})}));
    ASSERT_TRUE(a.Is<MeasuredMaterial>());
    EXPECT_EQ(a.GetIf<MeasuredMaterial>()->Data(), b.GetIf<MeasuredMaterial>()->Data());
    BSDF bsdf = GetBSDF(a);
    ASSERT_TRUE(bsdf.GetBxDF().Is<MeasuredBxDF>());
    EXPECT_GT(bsdf.f(Vector3f(0.3f, 0, 1), Vector3f(-0.3f, 0, 1))[0], 0);
    EXPECT_EQ(f.diag.WarningCount(), 0);
    auto error = [&](const ParameterDictionary& d) -> std::string {
        try {
            f.Make("measured", d);
        } catch (const SceneError& e) {
            return e.what();
        }
        return "";
    };
    EXPECT_NE(error(Dict({})).find("needs \"string filename\""), std::string::npos);
    std::string e = error(Dict({Strings("string", "filename", {"/nonexistent.bsdf"})}));
    EXPECT_NE(e.find("test.pbrt:3"), std::string::npos) << e;
    EXPECT_NE(e.find("/nonexistent.bsdf"), std::string::npos) << e;
    // A file that is no tensor file (a scene of the test folder)
    e = error(Dict({Strings(
        "string", "filename",
        {std::string(KILN_SOURCE_DIR) + "/test/regression/pbrt_features/measured.pbrt"})}));
    EXPECT_NE(e.find("not a tensor file"), std::string::npos) << e;
}

TEST(Materials, EveryPbrtMaterialAndUnknownOnes) {
    Fixture f;
    // pbrt-v4's last two materials are supported (no stand-in, no warning)
    EXPECT_TRUE(f.Make("subsurface", Dict({})).Is<SubsurfaceMaterial>());
    EXPECT_EQ(f.diag.WarningCount(), 0);
    // Hair is supported: brown by default
    Material hair = f.Make("hair", Dict({}));
    ASSERT_TRUE(hair.Is<HairMaterial>());
    EXPECT_TRUE(GetBSDF(hair).GetBxDF().Is<HairBxDF>());
    EXPECT_FLOAT_EQ(hair.GetIf<HairMaterial>()->Parameters().eumelanin->Evaluate(Context()), 1.3f);
    EXPECT_EQ(f.diag.WarningCount(), 0);
    // Two sources of absorption: the first wins, with a warning
    f.Make("hair", Dict({Rgb("sigma_a", 0.1f, 0.2f, 0.3f), Float1("eumelanin", 2)}));
    EXPECT_EQ(f.diag.WarningCount(), 1);
    // Bump mapping is supported: no warning
    Material bumped = f.Make("diffuse", Dict({Float1("displacement", 0.1f)}));
    EXPECT_TRUE(bumped.Perturbation().displacement);
    EXPECT_EQ(f.diag.WarningCount(), 1);
    try {
        f.Make("plastic", Dict({}));
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("plastic"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("test.pbrt:1"), std::string::npos) << e.what();
    }
}

TEST(Materials, CoatedDiffuseParameters) {
    Fixture f;
    Material m = f.Make("coateddiffuse",
                        Dict({Float1("thickness", 0.2f), Int1("maxdepth", 3), Int1("nsamples", 2),
                              Float1("g", 0.4f), Rgb("albedo", 0.5f, 0.5f, 0.5f)}));
    const CoatedDiffuseMaterial* cd = m.GetIf<CoatedDiffuseMaterial>();
    ASSERT_TRUE(cd);
    EXPECT_EQ(cd->MaxDepth(), 3);
    EXPECT_EQ(cd->NSamples(), 2);
    EXPECT_FLOAT_EQ(cd->Thickness().Evaluate(Context()), 0.2f);
    EXPECT_FLOAT_EQ(cd->G().Evaluate(Context()), 0.4f);
    BSDF bsdf = GetBSDF(m);
    const CoatedDiffuseBxDF* b = bsdf.GetBxDF().GetIf<CoatedDiffuseBxDF>();
    ASSERT_TRUE(b);
    EXPECT_EQ(b->Bottom().Reflectance(), SampledSpectrum(0.5f));
    EXPECT_FLOAT_EQ(b->Top().Eta(), 1.5f);
}

}  // namespace
}  // namespace kiln
