// Tests of the thermal module's temperature fields: gradient, noise, heatmap (8-bit, float,
// sequences), vertexattribute (trianglemesh and PLY meshes), cooling, keyframes, their
// animation, and their composition with kiln's float textures scale and mix.
#include <gtest/gtest.h>
#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "../textures/oiio_test_image.h"
#include "../textures/param_helpers.h"
#include "base/rng.h"
#include "core/geometry/shape.h"
#include "core/geometry/triangle.h"
#include "textures/texture_parameter_dictionary.h"
#include "thermal/cooling.h"
#include "thermal/heat_map_field.h"
#include "thermal/temperature_field.h"
#include "thermal/time_temperature_fields.h"

namespace kiln {
namespace {

using namespace kiln::test;
namespace fs = std::filesystem;

ParsedParameter Point3(const std::string& name, Point3f p) {
    return Floats("point3", name, {p.x, p.y, p.z});
}

TextureEvalContext At(Point3f p) {
    TextureEvalContext ctx;
    ctx.p = p;
    ctx.n = Normal3f(0, 0, 1);
    return ctx;
}

class TemperatureFieldsTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("kiln_temperature_" + std::to_string(getpid()) + "_" +
                                           std::to_string(reinterpret_cast<uintptr_t>(this)));
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }

    // A temperature field or one of kiln's float textures, as scene creation makes them.
    FloatTexture Make(const std::string& cls, ParsedParameterVector v,
                      const Transform& renderFromTexture = Transform(),
                      const TemperatureAnimation& animation = {}) {
        dicts.push_back(std::make_unique<ParameterDictionary>(std::move(v), nullptr));
        TextureParameterDictionary params(dicts.back().get(), &named);
        if (IsTemperatureFieldClass(cls))
            return CreateTemperatureField(cls, renderFromTexture, params, TestLoc(), arena, diag,
                                          animation, &animated);
        return CreateFloatTexture(cls, renderFromTexture, params, TestLoc(), arena, diag);
    }
    // Declares a named float texture (as a Texture directive would).
    void Declare(const std::string& name, const std::string& cls, ParsedParameterVector v) {
        named.floatTextures.insert_or_assign(name, Make(cls, std::move(v)));
    }

    template <typename T>
    static void WriteImage(const std::string& path, const std::vector<T>& px, int w, int h, int nc,
                           OIIO::TypeDesc type) {
        test::WriteWithOIIO(path, px, w, h, nc, type);
    }

    std::vector<Shape> MakeShapes(const std::string& name, ParsedParameterVector v) {
        dicts.push_back(std::make_unique<ParameterDictionary>(std::move(v), nullptr));
        return Shape::Create(name, &identity, &identity, false, *dicts.back(), TestLoc(), arena,
                             diag);
    }
    // Texture context of the first hit of a ray straight down at (x, y), from z = 10.
    static std::optional<TextureEvalContext> HitFromAbove(const std::vector<Shape>& shapes, Float x,
                                                          Float y) {
        Ray ray(Point3f(x, y, 10), Vector3f(0, 0, -1));
        for (const Shape& s : shapes)
            if (auto hit = s.Intersect(ray)) return TextureEvalContext(hit->intr);
        return std::nullopt;
    }

    fs::path dir;
    ObjectArena arena;
    Diagnostics diag{nullptr};
    NamedTextures named;
    Transform identity;
    std::vector<std::unique_ptr<ParameterDictionary>> dicts;
    std::vector<TemperatureField*> animated;  // the animated fields Make created
};

TEST_F(TemperatureFieldsTest, GradientObjectSpaceClampAndLinear) {
    ParsedParameterVector common = {Point3("p0", {0, 0, 0}), Point3("p1", {0, 0, 2}),
                                    Float1("t0", 1000), Float1("t1", 2000)};
    FloatTexture clamp = Make("gradient", common);
    ParsedParameterVector lin = common;
    lin.push_back(String1("extrapolate", "linear"));
    FloatTexture linear = Make("gradient", lin);
    EXPECT_FLOAT_EQ(clamp.Evaluate(At({0, 0, 0})), 1000);
    EXPECT_FLOAT_EQ(clamp.Evaluate(At({0, 0, 2})), 2000);
    EXPECT_FLOAT_EQ(clamp.Evaluate(At({0, 0, 1})), 1500);
    EXPECT_FLOAT_EQ(clamp.Evaluate(At({5, -3, 1})), 1500);  // only the projection counts
    EXPECT_FLOAT_EQ(clamp.Evaluate(At({0, 0, 3})), 2000);
    EXPECT_FLOAT_EQ(clamp.Evaluate(At({0, 0, -1})), 1000);
    EXPECT_FLOAT_EQ(linear.Evaluate(At({0, 0, 3})), 2500);
    EXPECT_FLOAT_EQ(linear.Evaluate(At({0, 0, -1})), 500);
    EXPECT_FLOAT_EQ(linear.Evaluate(At({0, 0, 0.5f})), 1250);

    // Object space follows the CTM at the Texture directive: texture z = 1 is render (10, 0, 2)
    Transform renderFromTexture = Translate(Vector3f(10, 0, 0)) * Scale(2, 2, 2);
    FloatTexture moved = Make("gradient", common, renderFromTexture);
    EXPECT_FLOAT_EQ(moved.Evaluate(At({10, 0, 2})), 1500);
    EXPECT_FLOAT_EQ(moved.Evaluate(At({10, 0, 4})), 2000);
    EXPECT_FLOAT_EQ(moved.Evaluate(At({0, 0, 1})), 1250);
}

TEST_F(TemperatureFieldsTest, GradientWorldSpace) {
    // Render space is world translated by -camera position ("cameraworld"); the CTM scales.
    named.renderFromWorld = Translate(Vector3f(-5, 1, 0));
    Transform renderFromTexture = named.renderFromWorld * Scale(3, 3, 3);
    ParsedParameterVector v = {Point3("p0", {0, 0, 0}), Point3("p1", {0, 0, 2}), Float1("t0", 1000),
                               Float1("t1", 2000), String1("space", "world")};
    FloatTexture world = Make("gradient", v, renderFromTexture);
    // World (0, 0, 1) is render (-5, 1, 1)
    EXPECT_FLOAT_EQ(world.Evaluate(At({-5, 1, 1})), 1500);
    EXPECT_FLOAT_EQ(world.Evaluate(At({-5, 1, 2})), 2000);
    EXPECT_FLOAT_EQ(world.Evaluate(At({0, 0, 0.5f})), 1250);
    v.back() = String1("space", "object");
    FloatTexture object = Make("gradient", v, renderFromTexture);
    EXPECT_FLOAT_EQ(object.Evaluate(At({-5, 1, 3})), 1500);  // texture z = 1 is render z = 3

    EXPECT_THROW(Make("gradient", {String1("space", "camera")}), SceneError);
    EXPECT_THROW(Make("gradient", {Point3("p0", {1, 1, 1}), Point3("p1", {1, 1, 1})}), SceneError);
}

TEST_F(TemperatureFieldsTest, NoiseRangeDeterminismAndSeeds) {
    auto make = [&](int seed) {
        return Make("noise", {Float1("frequency", 3), Int1("octaves", 5), Float1("gain", 0.5f),
                              Float1("lacunarity", 2), Int1("seed", seed), Float1("min", 800),
                              Float1("max", 1200)});
    };
    FloatTexture a = make(7), b = make(7), c = make(8);
    RNG rng(3);
    double sum = 0, sum2 = 0, lo = 1e9, hi = -1e9;
    int n = 4000, differ = 0;
    for (int i = 0; i < n; ++i) {
        Point3f p(rng.UniformFloat() * 4, rng.UniformFloat() * 4, rng.UniformFloat() * 4);
        Float va = a.Evaluate(At(p));
        ASSERT_GE(va, 800);
        ASSERT_LE(va, 1200);
        EXPECT_EQ(va, b.Evaluate(At(p)));  // same seed, same field
        differ += std::abs(va - c.Evaluate(At(p))) > 1;
        sum += va, sum2 += double(va) * va;
        lo = std::min<double>(lo, va), hi = std::max<double>(hi, va);
    }
    double mean = sum / n, sd = std::sqrt(std::max(0.0, sum2 / n - mean * mean));
    // Centred on the middle of the range (fBm has zero mean; 4 standard errors of a sample
    // whose points are correlated over ~1/3 unit: a loose bound), with a real spread.
    EXPECT_NEAR(mean, 1000, 10);
    EXPECT_GT(sd, 15);
    EXPECT_GT(hi - lo, 150);
    EXPECT_GT(differ, n * 9 / 10);  // another seed, another field
    EXPECT_THROW(Make("noise", {Int1("octaves", 0)}), SceneError);
}

TEST_F(TemperatureFieldsTest, HeatMap8BitWithRange) {
    // 4 x 1 grey PNG: code values 0, 51, 153, 255.
    std::string png = (dir / "heat.png").string();
    WriteImage(png, std::vector<unsigned char>{0, 51, 153, 255}, 4, 1, 1, OIIO::TypeDesc::UINT8);
    FloatTexture t = Make("heatmap", {String1("filename", png), String1("filter", "point"),
                                      Float1("tmin", 300), Float1("tmax", 1300)});
    const Float codes[4] = {0, 51, 153, 255};
    for (int x = 0; x < 4; ++x) {
        TextureEvalContext ctx;
        ctx.uv = Point2f((x + 0.5f) / 4, 0.5f);
        EXPECT_NEAR(t.Evaluate(ctx), 300 + codes[x] / 255 * 1000, 1e-3) << "pixel " << x;
    }
    // Bilinear halfway between pixels 1 and 2
    FloatTexture bl =
        Make("heatmap", {String1("filename", png), Float1("tmin", 300), Float1("tmax", 1300)});
    TextureEvalContext mid;
    mid.uv = Point2f(0.5f, 0.5f);
    EXPECT_NEAR(bl.Evaluate(mid), 300 + (51 + 153) / 2.f / 255 * 1000, 1e-2);
    // Without a range an 8-bit image warns; tmin alone is an error.
    int warnings = diag.WarningCount();
    Make("heatmap", {String1("filename", png)});
    EXPECT_EQ(diag.WarningCount(), warnings + 1);
    EXPECT_THROW(Make("heatmap", {String1("filename", png), Float1("tmin", 300)}), SceneError);
    EXPECT_THROW(Make("heatmap", {String1("filename", (dir / "none.png").string())}), SceneError);
}

TEST_F(TemperatureFieldsTest, HeatMapFloatKelvinAndSequences) {
    // 2 x 2 float heat maps in kelvin; rows top to bottom.
    auto write = [&](const std::string& name, Float add) {
        std::vector<float> px = {1000 + add, 1100 + add, 1200 + add, 1300 + add};
        WriteImage((dir / name).string(), px, 2, 2, 1, OIIO::TypeDesc::FLOAT);
    };
    write("heat.0001.exr", 0);
    write("heat.0002.exr", 400);
    auto pixel = [](int x, int y) {
        TextureEvalContext ctx;
        ctx.uv = Point2f((x + 0.5f) / 2, 1 - (y + 0.5f) / 2);  // v = 0 is the bottom row
        return ctx;
    };
    std::string single = (dir / "heat.0001.exr").string();
    FloatTexture t = Make("heatmap", {String1("filename", single), String1("filter", "point")});
    EXPECT_FLOAT_EQ(t.Evaluate(pixel(0, 0)), 1000);
    EXPECT_FLOAT_EQ(t.Evaluate(pixel(1, 0)), 1100);
    EXPECT_FLOAT_EQ(t.Evaluate(pixel(0, 1)), 1200);
    EXPECT_FLOAT_EQ(t.Evaluate(pixel(1, 1)), 1300);

    std::string pattern = (dir / "heat.####.exr").string();
    EXPECT_EQ(HeatMapField::FrameFilename(pattern, 2), (dir / "heat.0002.exr").string());
    EXPECT_EQ(HeatMapField::FrameFilename("a#b/c.exr", 3), "a#b/c.exr");
    EXPECT_EQ(HeatMapField::FrameFilename("f##.exr", 123), "f123.exr");
    FloatTexture f2 = Make(
        "heatmap", {String1("filename", pattern), Float1("frame", 2), String1("filter", "point")});
    EXPECT_FLOAT_EQ(f2.Evaluate(pixel(1, 0)), 1500);
    FloatTexture f125 = Make("heatmap", {String1("filename", pattern), Float1("frame", 1.25f),
                                         String1("filter", "point")});
    EXPECT_FLOAT_EQ(f125.Evaluate(pixel(1, 1)), 1300 + 0.25f * 400);
    // A range maps float images too
    FloatTexture ranged = Make("heatmap", {String1("filename", single), Float1("tmin", 10),
                                           Float1("tmax", 11), String1("filter", "point")});
    EXPECT_FLOAT_EQ(ranged.Evaluate(pixel(0, 0)), 1010);
    EXPECT_THROW(Make("heatmap", {String1("filename", pattern), Float1("frame", 3)}), SceneError);
}

TEST_F(TemperatureFieldsTest, VertexAttributeOnTriangleMesh) {
    // Two triangles covering [0, 2] x [0, 1] at z = 0
    std::vector<Shape> shapes =
        MakeShapes("trianglemesh", {Floats("point3", "P", {0, 0, 0, 2, 0, 0, 2, 1, 0, 0, 1, 0}),
                                    ParsedParameter([] {
                                        ParsedParameter p;
                                        p.type = "integer";
                                        p.name = "indices";
                                        p.ints = {0, 1, 2, 0, 2, 3};
                                        return p;
                                    }()),
                                    Floats("float", "temperature", {1000, 2000, 3000, 1500})});
    ASSERT_EQ(shapes.size(), 2u);
    FloatTexture t = Make("vertexattribute", {});
    // The attribute is linear in each triangle; at a vertex it is the vertex value.
    auto expected = [](Float x, Float y) {
        // Triangle 0 (0,1,2): T = 1000 + 500 x + 1000 y (below the diagonal y = x / 2)
        if (y <= x / 2) return 1000 + 500 * x + 1000 * y;
        // Triangle 1 (0,2,3): (0,0) = 1000, (2,1) = 3000, (0,1) = 1500
        return 1000 + 750 * x + 500 * y;
    };
    for (auto [x, y] : {std::pair<Float, Float>{0.5f, 0.1f},
                        {1.5f, 0.5f},
                        {0.2f, 0.8f},
                        {1.9f, 0.95f},
                        {1.0f, 0.25f}}) {
        auto ctx = HitFromAbove(shapes, x, y);
        ASSERT_TRUE(ctx) << x << " " << y;
        ASSERT_NE(ctx->mesh, nullptr);
        EXPECT_NEAR(t.Evaluate(*ctx), expected(x, y), 0.05f) << x << " " << y;
    }
    // No mesh or no such attribute: the default
    FloatTexture other =
        Make("vertexattribute", {String1("name", "pressure"), Float1("default", 7)});
    EXPECT_EQ(other.Evaluate(*HitFromAbove(shapes, 0.5f, 0.1f)), 7);
    EXPECT_EQ(t.Evaluate(At({0, 0, 0})), 0);
}

TEST_F(TemperatureFieldsTest, VertexAttributeFromPLYRoundTrip) {
    std::string ply = (dir / "hot.ply").string();
    {
        std::ofstream f(ply);
        f << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
             "property float z\nproperty float temperature\nelement face 1\n"
             "property list uchar int vertex_indices\nend_header\n"
             "0 0 0 900\n4 0 0 1700\n0 4 0 2100\n3 0 1 2\n";
    }
    std::vector<Shape> shapes = MakeShapes("plymesh", {String1("filename", ply)});
    ASSERT_EQ(shapes.size(), 1u);
    const Triangle* tri = shapes[0].GetIf<Triangle>();
    ASSERT_NE(tri, nullptr);
    EXPECT_TRUE(tri->GetMesh()->HasAttribute("temperature"));
    FloatTexture t = Make("vertexattribute", {String1("name", "temperature")});
    // T = 900 + 200 x + 300 y
    for (auto [x, y] : {std::pair<Float, Float>{1, 1}, {0.1f, 0.1f}, {3.5f, 0.25f}, {0.5f, 3}}) {
        auto ctx = HitFromAbove(shapes, x, y);
        ASSERT_TRUE(ctx);
        EXPECT_NEAR(t.Evaluate(*ctx), 900 + 200 * x + 300 * y, 0.05f) << x << " " << y;
    }
    // A context built from a shape sample, as a light does: barycentrics from the point.
    TextureEvalContext ctx = At(Point3f(2, 1, 0));
    ctx.mesh = tri->GetMesh();
    ctx.triIndex = tri->TriangleIndex();
    ctx.b = tri->Barycentrics(ctx.p);
    EXPECT_NEAR(t.Evaluate(ctx), 900 + 400 + 300, 0.05f);
}

TEST_F(TemperatureFieldsTest, CoolingAndKeyframes) {
    CoolingParameters p;
    p.T0 = 1500;
    p.emissivity = 0.8;
    p.area = 0.02;
    p.mass = 0.785;
    p.specificHeat = 500;
    p.h = 10;
    p.Tambient = 300;
    ParsedParameterVector v = {Float1("T0", 1500),          Float1("emissivity", 0.8f),
                               Float1("area", 0.02f),       Float1("mass", 0.785f),
                               Float1("specificheat", 500), Float1("h", 10),
                               Float1("Tambient", 300),     Float1("time", 600)};
    Float T = Make("cooling", v).Evaluate(At({0, 0, 0}));
    EXPECT_NEAR(T, CoolingModel(p).Temperature(600), 1e-3);
    EXPECT_LT(T, 1500);
    EXPECT_GT(T, 300);
    // density x thickness x area = mass
    ParsedParameterVector slab = v;
    slab.erase(slab.begin() + 3);
    slab.push_back(Float1("density", 7850));
    slab.push_back(Float1("thickness", 0.005f));
    EXPECT_NEAR(Make("cooling", slab).Evaluate(At({0, 0, 0})), T, 1e-2);
    ParsedParameterVector noMass = v;
    noMass.erase(noMass.begin() + 3);
    EXPECT_THROW(Make("cooling", noMass), SceneError);

    auto key = [&](Float time) {
        return Make("keyframes",
                    {Floats("float", "times", {0, 10, 10, 30}),
                     Floats("float", "values", {1000, 2000, 500, 700}), Float1("time", time)})
            .Evaluate(At({0, 0, 0}));
    };
    EXPECT_FLOAT_EQ(key(-5), 1000);
    EXPECT_FLOAT_EQ(key(5), 1500);
    EXPECT_FLOAT_EQ(key(10), 500);  // a step: the later keyframe wins at the shared time
    EXPECT_FLOAT_EQ(key(20), 600);
    EXPECT_FLOAT_EQ(key(99), 700);
    EXPECT_THROW(Make("keyframes",
                      {Floats("float", "times", {0, 2, 1}), Floats("float", "values", {1, 2, 3})}),
                 SceneError);
}

TEST_F(TemperatureFieldsTest, CompositionWithScaleAndMix) {
    Declare(
        "grad", "gradient",
        {Point3("p0", {0, 0, 0}), Point3("p1", {0, 0, 1}), Float1("t0", 1000), Float1("t1", 2000)});
    Declare("key", "keyframes", {Floats("float", "times", {0}), Floats("float", "values", {600})});
    FloatTexture scaled = Make("scale", {Tex("tex", "grad"), Float1("scale", 0.5f)});
    EXPECT_FLOAT_EQ(scaled.Evaluate(At({0, 0, 0.5f})), 750);
    FloatTexture mixed =
        Make("mix", {Tex("tex1", "grad"), Tex("tex2", "key"), Float1("amount", 0.25f)});
    EXPECT_FLOAT_EQ(mixed.Evaluate(At({0, 0, 1})), 0.75f * 2000 + 0.25f * 600);
    // Mixing by a texture: amount from a 0..1 gradient along x
    Declare("ramp", "gradient", {Point3("p0", {0, 0, 0}), Point3("p1", {1, 0, 0})});
    FloatTexture blend =
        Make("mix", {Tex("tex1", "grad"), Tex("tex2", "key"), Tex("amount", "ramp")});
    EXPECT_FLOAT_EQ(blend.Evaluate(At({0.5f, 0, 0})), 0.5f * 1000 + 0.5f * 600);
    // Float-only: a spectrum "gradient" warns and gives grey
    int warnings = diag.WarningCount();
    dicts.push_back(std::make_unique<ParameterDictionary>(ParsedParameterVector{}, nullptr));
    TextureParameterDictionary params(dicts.back().get(), &named);
    CreateSpectrumTexture("gradient", Transform(), params, SpectrumType::Albedo, TestLoc(), arena,
                          diag);
    EXPECT_EQ(diag.WarningCount(), warnings + 1);
}

}  // namespace
}  // namespace kiln

namespace kiln {
namespace {

TEST_F(TemperatureFieldsTest, AnimatedFieldsFollowTheAnimationAndPinnedOnesDoNot) {
    // Three frames of a 1 x 1 float heat map
    for (int f = 0; f < 3; ++f)
        WriteImage((dir / ("seq." + std::to_string(f) + ".exr")).string(),
                   std::vector<float>{1000.f + 100 * f}, 1, 1, 1, OIIO::TypeDesc::FLOAT);
    std::string pattern = (dir / "seq.#.exr").string();
    TemperatureAnimation at1{1, 0.5f};
    FloatTexture seq = Make("heatmap", {String1("filename", pattern)}, Transform(), at1);
    FloatTexture pinned =
        Make("heatmap", {String1("filename", pattern), Float1("frame", 0)}, Transform(), at1);
    FloatTexture still =
        Make("heatmap", {String1("filename", (dir / "seq.2.exr").string())}, Transform(), at1);
    ParsedParameterVector coolingParams = {Float1("T0", 1500), Float1("mass", 1),
                                           Float1("area", 0.1f)};
    FloatTexture cool = Make("cooling", coolingParams, Transform(), at1);
    ParsedParameterVector pinnedCooling = coolingParams;
    pinnedCooling.push_back(Float1("time", 0));
    FloatTexture coolPinned = Make("cooling", pinnedCooling, Transform(), at1);
    ParsedParameterVector keys = {Floats("float", "times", {0, 1}),
                                  Floats("float", "values", {500, 1500})};
    FloatTexture key = Make("keyframes", keys, Transform(), at1);
    Make("gradient", {}, Transform(), at1);  // spatial: never animated
    // Only the fields without their own frame or time are animated
    EXPECT_EQ(animated.size(), 3u);

    TextureEvalContext ctx = At({0, 0, 0});
    ctx.uv = Point2f(0.5f, 0.5f);
    EXPECT_FLOAT_EQ(seq.Evaluate(ctx), 1100);
    EXPECT_FLOAT_EQ(pinned.Evaluate(ctx), 1000);
    EXPECT_FLOAT_EQ(still.Evaluate(ctx), 1200);
    EXPECT_FLOAT_EQ(key.Evaluate(ctx), 1000);
    Float coolAtHalf = cool.Evaluate(ctx);
    EXPECT_LT(coolAtHalf, 1500);
    EXPECT_FLOAT_EQ(coolPinned.Evaluate(ctx), 1500);

    // Moved to frame 2.5 at 1.25 s: as if created there
    TemperatureAnimation at2{2, 1.25f};
    for (TemperatureField* f : animated) f->SetAnimation(at2);
    EXPECT_FLOAT_EQ(seq.Evaluate(ctx), 1200);
    EXPECT_FLOAT_EQ(pinned.Evaluate(ctx), 1000);
    EXPECT_FLOAT_EQ(key.Evaluate(ctx), 1500);
    EXPECT_FLOAT_EQ(coolPinned.Evaluate(ctx), 1500);
    Float coolLater = cool.Evaluate(ctx);
    EXPECT_LT(coolLater, coolAtHalf);
    EXPECT_EQ(coolLater, Make("cooling", coolingParams, Transform(), at2).Evaluate(ctx));
    EXPECT_EQ(seq.Evaluate(ctx),
              Make("heatmap", {String1("filename", pattern)}, Transform(), at2).Evaluate(ctx));
    // A frame that does not exist is an error naming the file; the field keeps its frame
    try {
        for (TemperatureField* f : animated) f->SetAnimation({7, 0});
        ADD_FAILURE() << "frame 7 has no heat map";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("seq.7.exr"), std::string::npos) << e.what();
    }
    EXPECT_FLOAT_EQ(seq.Evaluate(ctx), 1200);
}

}  // namespace
}  // namespace kiln
