// Tests of the procedural textures, texture mappings and texture parameters.
#include <gtest/gtest.h>

#include <cmath>

#include "base/rng.h"

#include "param_helpers.h"
#include "spectral/color.h"
#include "textures/basic_textures.h"
#include "textures/checkerboard_texture.h"
#include "textures/noise.h"
#include "textures/noise_textures.h"
#include "textures/texture_parameter_dictionary.h"

namespace kiln {
namespace {

using namespace kiln::test;

TextureEvalContext UVContext(Float u, Float v) {
    TextureEvalContext ctx;
    ctx.uv = Point2f(u, v);
    ctx.n = Normal3f(0, 0, 1);
    return ctx;
}

struct Fixture {
    ObjectArena arena;
    Diagnostics diag{nullptr};
    NamedTextures named;

    FloatTexture MakeFloat(const std::string& cls, const ParameterDictionary& d,
                           const Transform& t = Transform()) {
        TextureParameterDictionary params(&d, &named);
        return CreateFloatTexture(cls, t, params, TestLoc(), arena, diag);
    }
    SpectrumTexture MakeSpectrum(const std::string& cls, const ParameterDictionary& d,
                                 SpectrumType type, const Transform& t = Transform()) {
        TextureParameterDictionary params(&d, &named);
        return CreateSpectrumTexture(cls, t, params, type, TestLoc(), arena, diag);
    }
};

const SampledWavelengths kLambda = SampledWavelengths::SampleVisible(0.37f);

void ExpectSpectraNear(const SampledSpectrum& a, const SampledSpectrum& b, Float tol = 1e-5f) {
    for (int i = 0; i < NSpectrumSamples; ++i) EXPECT_NEAR(a[i], b[i], tol) << "sample " << i;
}

TEST(Textures, ConstantFloat) {
    Fixture f;
    EXPECT_EQ(f.MakeFloat("constant", Dict({Float1("value", 0.25f)})).Evaluate(UVContext(0, 0)),
              0.25f);
    EXPECT_EQ(f.MakeFloat("constant", Dict({})).Evaluate(UVContext(0, 0)), 1.f);
}

TEST(Textures, ConstantSpectrumPerType) {
    Fixture f;
    const RGBColorSpace& cs = RGBColorSpace::sRGB();
    RGB albedo(0.2f, 0.4f, 0.6f), big(2, 1, 0.5f);
    ExpectSpectraNear(
        f.MakeSpectrum("constant", Dict({Rgb("value", 0.2f, 0.4f, 0.6f)}), SpectrumType::Albedo)
            .Evaluate(UVContext(0, 0), kLambda),
        RGBAlbedoSpectrum(cs, albedo).Sample(kLambda));
    ExpectSpectraNear(
        f.MakeSpectrum("constant", Dict({Rgb("value", 2, 1, 0.5f)}), SpectrumType::Unbounded)
            .Evaluate(UVContext(0, 0), kLambda),
        RGBUnboundedSpectrum(cs, big).Sample(kLambda));
    ExpectSpectraNear(
        f.MakeSpectrum("constant", Dict({Rgb("value", 2, 1, 0.5f)}), SpectrumType::Illuminant)
            .Evaluate(UVContext(0, 0), kLambda),
        RGBIlluminantSpectrum(cs, big).Sample(kLambda));
    // Albedo RGB above 1 is an error in the scene
    EXPECT_THROW(f.MakeSpectrum("constant", Dict({Rgb("value", 2, 1, 0.5f)}), SpectrumType::Albedo),
                 SceneError);
    // Default: constant 1
    ExpectSpectraNear(f.MakeSpectrum("constant", Dict({}), SpectrumType::Albedo)
                          .Evaluate(UVContext(0, 0), kLambda),
                      SampledSpectrum(1));
}

TEST(Textures, ScaleAndNamedReferences) {
    Fixture f;
    f.named.floatTextures.emplace("half", f.arena.New<FloatConstantTexture>(0.5f));
    FloatTexture t = f.MakeFloat("scale", Dict({Tex("tex", "half"), Float1("scale", 3)}));
    EXPECT_FLOAT_EQ(t.Evaluate(UVContext(0, 0)), 1.5f);
    // A constant scale of 1 returns the texture itself
    FloatTexture same = f.MakeFloat("scale", Dict({Tex("tex", "half")}));
    EXPECT_TRUE(same.Is<FloatConstantTexture>());
    EXPECT_FLOAT_EQ(same.Evaluate(UVContext(0, 0)), 0.5f);
    // Spectrum scale by a float texture
    f.named.albedoSpectrumTextures.emplace(
        "grey", f.arena.New<SpectrumConstantTexture>(Spectrum(ConstantSpectrum(0.4f))));
    SpectrumTexture s = f.MakeSpectrum("scale", Dict({Tex("tex", "grey"), Tex("scale", "half")}),
                                       SpectrumType::Albedo);
    ExpectSpectraNear(s.Evaluate(UVContext(0, 0), kLambda), SampledSpectrum(0.2f));
    // The named texture must exist for the requested spectrum type
    EXPECT_THROW(f.MakeSpectrum("scale", Dict({Tex("tex", "grey")}), SpectrumType::Unbounded),
                 SceneError);
    try {
        f.MakeFloat("scale", Dict({Tex("tex", "nosuch")}));
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("nosuch"), std::string::npos) << e.what();
    }
}

TEST(Textures, Mix) {
    Fixture f;
    FloatTexture t =
        f.MakeFloat("mix", Dict({Float1("tex1", 2), Float1("tex2", 6), Float1("amount", 0.25f)}));
    EXPECT_FLOAT_EQ(t.Evaluate(UVContext(0, 0)), 3);
    // Defaults: tex1 0, tex2 1, amount 0.5
    EXPECT_FLOAT_EQ(f.MakeFloat("mix", Dict({})).Evaluate(UVContext(0, 0)), 0.5f);
    SpectrumTexture s =
        f.MakeSpectrum("mix", Dict({Float1("amount", 0.75f)}), SpectrumType::Unbounded);
    ExpectSpectraNear(s.Evaluate(UVContext(0, 0), kLambda), SampledSpectrum(0.75f));
}

TEST(Textures, DirectionMix) {
    Fixture f;
    // dir = +z in texture space, rotated to +x in render space
    Transform renderFromTexture = Rotate(90, Vector3f(0, 1, 0));
    FloatTexture t = f.MakeFloat(
        "directionmix",
        Dict({Float1("tex1", 10), Float1("tex2", 20), Floats("vector3", "dir", {0, 0, 1})}),
        renderFromTexture);
    TextureEvalContext ctx;
    ctx.n = Normal3f(1, 0, 0);
    EXPECT_NEAR(t.Evaluate(ctx), 10, 1e-4f);
    ctx.n = Normal3f(0, 0, 1);
    EXPECT_NEAR(t.Evaluate(ctx), 20, 1e-4f);
    ctx.n = Normal3f(0.5f, 0, std::sqrt(0.75f));
    EXPECT_NEAR(t.Evaluate(ctx), 15, 1e-4f);
}

TEST(Textures, UVMappingParameters) {
    Fixture f;
    ParameterDictionary d = Dict(
        {Float1("uscale", 2), Float1("vscale", 3), Float1("udelta", 0.5f), Float1("vdelta", -1)});
    TextureParameterDictionary params(&d, nullptr);
    TextureMapping2D m = TextureMapping2D::Create(params, Transform(), TestLoc());
    TextureEvalContext ctx = UVContext(0.25f, 0.5f);
    ctx.dudx = 0.1f, ctx.dudy = 0.2f, ctx.dvdx = 0.3f, ctx.dvdy = 0.4f;
    TexCoord2D c = m.Map(ctx);
    EXPECT_FLOAT_EQ(c.st.x, 2 * 0.25f + 0.5f);
    EXPECT_FLOAT_EQ(c.st.y, 3 * 0.5f - 1);
    EXPECT_FLOAT_EQ(c.dsdx, 0.2f);
    EXPECT_FLOAT_EQ(c.dsdy, 0.4f);
    EXPECT_FLOAT_EQ(c.dtdx, 0.9f);
    EXPECT_FLOAT_EQ(c.dtdy, 1.2f);

    ParameterDictionary bad = Dict({String1("mapping", "toroidal")});
    TextureParameterDictionary badParams(&bad, nullptr);
    EXPECT_THROW(TextureMapping2D::Create(badParams, Transform(), TestLoc()), SceneError);
}

TEST(Textures, SphericalCylindricalPlanarMappings) {
    // The texture space is render space shifted by (10, 0, 0)
    Transform textureFromRender = Translate(Vector3f(-10, 0, 0));
    auto at = [](Point3f p) {
        TextureEvalContext ctx;
        ctx.p = p;
        return ctx;
    };
    SphericalMapping sph(textureFromRender);
    TexCoord2D c = sph.Map(at(Point3f(11, 0, 0)));  // +x: theta = pi/2, phi = 0
    EXPECT_NEAR(c.st.x, 0.5f, 1e-5f);
    EXPECT_NEAR(c.st.y, 0, 1e-5f);
    c = sph.Map(at(Point3f(10, 2, 0)));  // +y: phi = pi/2
    EXPECT_NEAR(c.st.y, 0.25f, 1e-5f);
    c = sph.Map(at(Point3f(10, 0, 3)));  // +z: theta = 0
    EXPECT_NEAR(c.st.x, 0, 1e-5f);

    CylindricalMapping cyl(textureFromRender);
    c = cyl.Map(at(Point3f(11, 0, 0.3f)));
    EXPECT_NEAR(c.st.x, 0.5f, 1e-5f);
    EXPECT_NEAR(c.st.y, 0.3f, 1e-5f);

    PlanarMapping pl(textureFromRender, Vector3f(1, 0, 0), Vector3f(0, 0, 2), 0.5f, 0.25f);
    TextureEvalContext ctx = at(Point3f(10.2f, 7, 0.3f));
    ctx.dpdx = Vector3f(0.1f, 0, 0);
    ctx.dpdy = Vector3f(0, 0, 0.1f);
    c = pl.Map(ctx);
    EXPECT_NEAR(c.st.x, 0.5f + 0.2f, 1e-5f);
    EXPECT_NEAR(c.st.y, 0.25f + 0.6f, 1e-5f);
    EXPECT_NEAR(c.dsdx, 0.1f, 1e-6f);
    EXPECT_NEAR(c.dtdy, 0.2f, 1e-6f);
    EXPECT_NEAR(c.dsdy, 0, 1e-6f);
}

TEST(Textures, SphericalMappingDerivatives) {
    // Finite differences of st along dpdx agree with the analytic derivatives
    SphericalMapping sph{Transform()};
    TextureEvalContext ctx;
    ctx.p = Point3f(0.3f, 0.5f, 0.4f);
    ctx.dpdx = Vector3f(1e-3f, -2e-3f, 0.5e-3f);
    ctx.dpdy = Vector3f(0, 0, 0);
    TexCoord2D c0 = sph.Map(ctx);
    TextureEvalContext ctx1 = ctx;
    ctx1.p = ctx.p + ctx.dpdx;
    TexCoord2D c1 = sph.Map(ctx1);
    EXPECT_NEAR(c1.st.x - c0.st.x, c0.dsdx, 2e-5f);
    EXPECT_NEAR(c1.st.y - c0.st.y, c0.dtdx, 2e-5f);
}

TEST(Textures, Checkerboard2D) {
    Fixture f;
    FloatTexture t = f.MakeFloat("checkerboard", Dict({Float1("uscale", 4), Float1("vscale", 4),
                                                       Float1("tex1", 3), Float1("tex2", 7)}));
    EXPECT_FLOAT_EQ(t.Evaluate(UVContext(0.1f, 0.1f)), 3);   // cell (0, 0)
    EXPECT_FLOAT_EQ(t.Evaluate(UVContext(0.3f, 0.1f)), 7);   // cell (1, 0)
    EXPECT_FLOAT_EQ(t.Evaluate(UVContext(0.3f, 0.3f)), 3);   // cell (1, 1)
    EXPECT_FLOAT_EQ(t.Evaluate(UVContext(-0.1f, 0.1f)), 7);  // cell (-1, 0)
    // A footprint much larger than a cell averages the two textures
    TextureEvalContext wide = UVContext(0.37f, 0.61f);
    wide.dudx = wide.dvdy = 10;
    EXPECT_NEAR(t.Evaluate(wide), 5, 0.05f);
    // Filtering is continuous: near an edge the value lies between the two
    TextureEvalContext edge = UVContext(0.25f, 0.1f);
    edge.dudx = edge.dvdy = 0.01f;
    Float v = t.Evaluate(edge);
    EXPECT_GT(v, 3.5f);
    EXPECT_LT(v, 6.5f);
    // Defaults: tex1 = 1, tex2 = 0
    FloatTexture d = f.MakeFloat("checkerboard", Dict({}));
    EXPECT_FLOAT_EQ(d.Evaluate(UVContext(0.5f, 0.5f)), 1);
    EXPECT_FLOAT_EQ(d.Evaluate(UVContext(1.5f, 0.5f)), 0);
    EXPECT_THROW(f.MakeFloat("checkerboard", Dict({Int1("dimension", 4)})), SceneError);
}

TEST(Textures, Checkerboard3D) {
    Fixture f;
    SpectrumTexture t = f.MakeSpectrum(
        "checkerboard", Dict({Int1("dimension", 3), Rgb("tex2", 0.25f, 0.25f, 0.25f)}),
        SpectrumType::Albedo, Scale(2, 2, 2));
    auto at = [&](Point3f p) {
        TextureEvalContext ctx;
        ctx.p = p;
        return t.Evaluate(ctx, kLambda)[0];
    };
    // Cells are 2 units wide in render space
    EXPECT_FLOAT_EQ(at(Point3f(1, 1, 1)), 1);
    EXPECT_NEAR(at(Point3f(3, 1, 1)), 0.25f, 2e-3f);
    EXPECT_FLOAT_EQ(at(Point3f(3, 3, 1)), 1);
    EXPECT_NEAR(at(Point3f(-1, 1, 1)), 0.25f, 2e-3f);
    // A wide footprint averages the two
    TextureEvalContext wide;
    wide.p = Point3f(1.3f, 0.7f, 5.1f);
    wide.dpdx = Vector3f(30, 0, 30);
    wide.dpdy = Vector3f(0, 30, 0);
    EXPECT_NEAR(t.Evaluate(wide, kLambda)[0], 0.625f, 0.02f);
}

TEST(Textures, Bilerp) {
    Fixture f;
    FloatTexture t = f.MakeFloat("bilerp", Dict({}));
    EXPECT_FLOAT_EQ(t.Evaluate(UVContext(0.25f, 0.75f)), 0.75f);
    FloatTexture t2 = f.MakeFloat(
        "bilerp", Dict({Float1("v00", 1), Float1("v01", 2), Float1("v10", 3), Float1("v11", 4)}));
    // (1-s)(1-t) 1 + (1-s) t 2 + s (1-t) 3 + s t 4 at s = 0.5, t = 0.25
    EXPECT_FLOAT_EQ(t2.Evaluate(UVContext(0.5f, 0.25f)),
                    0.375f * 1 + 0.125f * 2 + 0.375f * 3 + 0.125f * 4);
    SpectrumTexture s = f.MakeSpectrum("bilerp", Dict({}), SpectrumType::Unbounded);
    ExpectSpectraNear(s.Evaluate(UVContext(0.9f, 0.4f), kLambda), SampledSpectrum(0.4f));
}

TEST(Textures, UnknownAndUnsupportedClasses) {
    Fixture f;
    EXPECT_THROW(f.MakeFloat("swirl", Dict({})), SceneError);
    EXPECT_THROW(f.MakeSpectrum("swirl", Dict({}), SpectrumType::Albedo), SceneError);
    FloatTexture t = f.MakeFloat("ptex", Dict({}));
    EXPECT_FLOAT_EQ(t.Evaluate(UVContext(0.3f, 0.2f)), 0.5f);
    SpectrumTexture s = f.MakeSpectrum("fbm", Dict({}), SpectrumType::Albedo);
    ExpectSpectraNear(s.Evaluate(UVContext(0.3f, 0.2f), kLambda), SampledSpectrum(0.5f));
    EXPECT_EQ(f.diag.WarningCount(), 2);
}

TEST(Textures, ParameterDictionaryLookups) {
    Fixture f;
    ParameterDictionary d = Dict({Float1("a", 2), Floats("blackbody", "b", {3000}),
                                  Floats("spectrum", "c", {400, 1, 700, 3})});
    TextureParameterDictionary params(&d, &f.named);
    EXPECT_FALSE(params.GetFloatTextureOrNull("missing", f.arena));
    EXPECT_FLOAT_EQ(params.GetFloatTexture("missing", 4, f.arena).Evaluate({}), 4);
    EXPECT_FLOAT_EQ(params.GetFloatTexture("a", 4, f.arena).Evaluate({}), 2);
    std::optional<SpectrumTexture> b =
        params.GetSpectrumTextureOrNull("b", SpectrumType::Illuminant, f.arena);
    ASSERT_TRUE(b);
    ExpectSpectraNear(b->Evaluate({}, kLambda), BlackbodySpectrum(3000).Sample(kLambda));
    SpectrumTexture c =
        params.GetSpectrumTexture("c", std::nullopt, SpectrumType::Unbounded, f.arena);
    SampledWavelengths l = SampledWavelengths::SampleUniform(0.5f, 400, 700);
    for (int i = 0; i < NSpectrumSamples; ++i)
        EXPECT_NEAR(c.Evaluate({}, l)[i], 1 + 2 * (l[i] - 400) / 300, 1e-4f);
}

TEST(Textures, PerlinNoise) {
    // Zero on the lattice, bounded, continuous across cell faces, not constant
    EXPECT_EQ(Noise(3, -2, 7), 0);
    RNG rng(3);
    double sum = 0, sum2 = 0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
        Point3f p(20 * rng.UniformFloat() - 10, 20 * rng.UniformFloat() - 10,
                  20 * rng.UniformFloat() - 10);
        Float v = Noise(p);
        ASSERT_LE(std::abs(v), 1.1f);
        sum += v;
        sum2 += v * v;
    }
    double mean = sum / n, var = sum2 / n - mean * mean;
    EXPECT_GT(var, 0.01);
    // Noise is symmetric about 0: the mean is within 5 standard errors of it
    EXPECT_LT(std::abs(mean), 5 * std::sqrt(var / n));
    EXPECT_NEAR(Noise(0.9999f, 0.3f, 0.6f), Noise(1.0001f, 0.3f, 0.6f), 1e-3f);
    // Turbulence is non-negative; fbm with a huge footprint keeps no octaves
    Point3f p(0.37f, 1.3f, -2.2f);
    EXPECT_GE(Turbulence(p, Vector3f(0, 0, 0), Vector3f(0, 0, 0), 0.5f, 8), 0);
    EXPECT_EQ(FBm(p, Vector3f(100, 0, 0), Vector3f(0, 0, 0), 0.5f, 8), 0);
}

TEST(Textures, NoiseTextures) {
    Fixture f;
    auto at = [](Point3f p) {
        TextureEvalContext ctx;
        ctx.p = p;
        ctx.uv = Point2f(p.x, p.y);
        return ctx;
    };
    FloatTexture fbm = f.MakeFloat("fbm", Dict({Int1("octaves", 4)}));
    FloatTexture wr = f.MakeFloat("wrinkled", Dict({}));
    FloatTexture windy = f.MakeFloat("windy", Dict({}));
    SpectrumTexture marble = f.MakeSpectrum("marble", Dict({}), SpectrumType::Albedo);
    FloatTexture dots = f.MakeFloat("dots", Dict({Float1("inside", 5), Float1("outside", 2)}));
    RNG rng(11);
    int inDots = 0;
    const int n = 4000;
    for (int i = 0; i < n; ++i) {
        Point3f p(10 * rng.UniformFloat(), 10 * rng.UniformFloat(), 10 * rng.UniformFloat());
        EXPECT_NEAR(fbm.Evaluate(at(p)), FBm(p, {}, {}, 0.5f, 4), 1e-6f);
        EXPECT_GE(wr.Evaluate(at(p)), 0);
        EXPECT_TRUE(std::isfinite(windy.Evaluate(at(p))));
        SampledSpectrum m = marble.Evaluate(at(p), kLambda);
        EXPECT_GE(m.MinComponentValue(), 0);
        EXPECT_LE(m.MaxComponentValue(), 1);
        Float d = dots.Evaluate(at(p));
        EXPECT_TRUE(d == 5 || d == 2);
        inDots += d == 2;
    }
    // Half the cells hold a dot covering pi 0.35^2 of the cell: about 19% of points. The dots
    // show "outside", as pbrt-v4 renders them (noise_textures.cpp)
    EXPECT_GT(inDots, n / 10);
    EXPECT_LT(inDots, n * 3 / 10);
    EXPECT_EQ(f.diag.WarningCount(), 0);
}

// Which textures need the screen-space footprint: those that filter or antialias, and those
// that hold one (mix, scale, dots); dots with a checkerboard inside used to say no, so the
// checkerboard was evaluated without its footprint
TEST(Textures, FootprintUseFollowsWhatATextureHolds) {
    Fixture f;
    f.named.floatTextures.emplace("checks", f.MakeFloat("checkerboard", Dict({})));
    f.named.floatTextures.emplace("half", f.arena.New<FloatConstantTexture>(0.5f));
    EXPECT_TRUE(f.named.floatTextures.at("checks").UsesFootprint());
    EXPECT_FALSE(f.named.floatTextures.at("half").UsesFootprint());
    EXPECT_TRUE(f.MakeFloat("dots", Dict({Tex("inside", "checks")})).UsesFootprint());
    EXPECT_FALSE(f.MakeFloat("dots", Dict({Tex("inside", "half")})).UsesFootprint());
    EXPECT_TRUE(f.MakeFloat("mix", Dict({Tex("tex2", "checks")})).UsesFootprint());
    EXPECT_TRUE(f.MakeFloat("fbm", Dict({})).UsesFootprint());
    EXPECT_FALSE(f.MakeFloat("bilerp", Dict({})).UsesFootprint());
}

}  // namespace
}  // namespace kiln
