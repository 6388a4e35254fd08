// Tests of "imagemap" textures on small images written to a temporary directory.
#include <gtest/gtest.h>
#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include <filesystem>

#include "core/image/color_encoding.h"
#include "core/image/mipmap.h"
#include "oiio_test_image.h"
#include "param_helpers.h"
#include "spectral/color.h"
#include "textures/image_texture.h"
#include "textures/texture_parameter_dictionary.h"

namespace kiln {
namespace {

using namespace kiln::test;
namespace fs = std::filesystem;

// A 4x2 RGB float image: R = x + 10 y, G = 0.5, B = 0.25 (pixel (0, 0) at the top left), and
// its R channel alone (float textures of colour images filter the mean of R, G and B, as
// pbrt-v4's: core/image/mipmap.cpp).
constexpr int kW = 4, kH = 2;

class ImageTextureTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("kiln_imagetex_" + std::to_string(::getpid()) + "_" +
                                           std::to_string(reinterpret_cast<uintptr_t>(this)));
        fs::create_directories(dir);
        exrPath = (dir / "ramp.exr").string();
        std::vector<float> px;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) px.insert(px.end(), {float(x + 10 * y), 0.5f, 0.25f});
        Write(exrPath, px, kW, kH, 3, OIIO::TypeDesc::FLOAT);
        greyExrPath = (dir / "ramp-grey.exr").string();
        std::vector<float> r;
        for (size_t i = 0; i < px.size(); i += 3) r.push_back(px[i]);
        Write(greyExrPath, r, kW, kH, 1, OIIO::TypeDesc::FLOAT);
        pngPath = (dir / "grey.png").string();
        std::vector<unsigned char> grey(2 * 2 * 3, 128);
        Write(pngPath, grey, 2, 2, 3, OIIO::TypeDesc::UINT8);
    }
    void TearDown() override { fs::remove_all(dir); }

    template <typename T>
    static void Write(const std::string& path, const std::vector<T>& px, int w, int h, int nc,
                      OIIO::TypeDesc type) {
        test::WriteWithOIIO(path, px, w, h, nc, type);
    }

    FloatTexture MakeFloat(std::initializer_list<ParsedParameter> extra) {
        ParsedParameterVector v(extra);
        if (std::none_of(v.begin(), v.end(), [](auto& p) { return p.name == "filename"; }))
            v.push_back(String1("filename", greyExrPath));
        dicts.push_back(std::make_unique<ParameterDictionary>(v, nullptr));
        TextureParameterDictionary params(dicts.back().get(), &named);
        return CreateFloatTexture("imagemap", Transform(), params, TestLoc(), arena, diag);
    }

    // Pixel centre (x, y) as uv: v = 0 is the bottom row (pbrt-v4's t flip).
    static TextureEvalContext Pixel(Float x, Float y) {
        TextureEvalContext ctx;
        ctx.uv = Point2f((x + 0.5f) / kW, 1 - (y + 0.5f) / kH);
        return ctx;
    }

    fs::path dir;
    std::string exrPath, greyExrPath, pngPath;
    ObjectArena arena;
    Diagnostics diag{nullptr};
    NamedTextures named;
    std::vector<std::unique_ptr<ParameterDictionary>> dicts;
};

TEST_F(ImageTextureTest, LookupsAtPixelCentresWithVFlip) {
    for (const char* filter : {"bilinear", "point"}) {
        FloatTexture t = MakeFloat({String1("filter", filter)});
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x)
                EXPECT_NEAR(t.Evaluate(Pixel(x, y)), x + 10 * y, 1e-4f) << filter;
        // uv = (0, 1) corner region is the top-left pixel
        TextureEvalContext ctx;
        ctx.uv = Point2f(0.1f, 0.9f);
        if (std::string(filter) == "point") {
            EXPECT_NEAR(t.Evaluate(ctx), 0, 1e-4f);
        }
    }
    // Bilinear halfway between pixels 1 and 2 of the top row
    FloatTexture t = MakeFloat({});
    TextureEvalContext mid;
    mid.uv = Point2f(0.5f, 0.75f);
    EXPECT_NEAR(t.Evaluate(mid), 1.5f, 1e-4f);
}

TEST_F(ImageTextureTest, WrapModes) {
    FloatTexture repeat = MakeFloat({});
    FloatTexture clamp = MakeFloat({String1("wrap", "clamp")});
    FloatTexture black = MakeFloat({String1("wrap", "black")});
    TextureEvalContext ctx = Pixel(0, 1);
    ctx.uv.x += 1;  // one period to the right: pixel 4 -> beyond the right edge
    EXPECT_NEAR(repeat.Evaluate(ctx), 10, 1e-4f);
    EXPECT_NEAR(clamp.Evaluate(ctx), 13, 1e-4f);
    EXPECT_NEAR(black.Evaluate(ctx), 0, 1e-4f);
    EXPECT_THROW(MakeFloat({String1("wrap", "mirror")}), SceneError);
}

TEST_F(ImageTextureTest, ScaleInvertAndCache) {
    FloatTexture a = MakeFloat({Float1("scale", 2)});
    EXPECT_NEAR(a.Evaluate(Pixel(3, 0)), 6, 1e-4f);
    FloatTexture inv = MakeFloat({Float1("scale", 0.1f), Bool1("invert", true)});
    EXPECT_NEAR(inv.Evaluate(Pixel(3, 0)), 0.7f, 1e-4f);
    EXPECT_NEAR(inv.Evaluate(Pixel(3, 1)), 0, 1e-4f);  // 1 - 1.3 clamped at 0
    // Same file and lookup options share one MIP map; scale and invert do not matter
    FloatTexture b = MakeFloat({});
    FloatTexture c = MakeFloat({String1("wrap", "clamp")});
    const MIPMap* ma = a.GetIf<FloatImageTexture>()->GetMIPMap();
    EXPECT_EQ(ma, b.GetIf<FloatImageTexture>()->GetMIPMap());
    EXPECT_EQ(ma, inv.GetIf<FloatImageTexture>()->GetMIPMap());
    EXPECT_NE(ma, c.GetIf<FloatImageTexture>()->GetMIPMap());
}

TEST_F(ImageTextureTest, PngEncoding) {
    FloatTexture srgb = MakeFloat({String1("filename", pngPath)});
    FloatTexture lin = MakeFloat({String1("filename", pngPath), String1("encoding", "linear")});
    TextureEvalContext ctx;
    ctx.uv = Point2f(0.3f, 0.6f);
    EXPECT_NEAR(srgb.Evaluate(ctx), SRGBToLinear(128 / 255.f), 1e-4f);
    EXPECT_NEAR(lin.Evaluate(ctx), 128 / 255.f, 1e-4f);
}

TEST_F(ImageTextureTest, SpectrumTypes) {
    ParameterDictionary d(ParsedParameterVector{String1("filename", exrPath)}, nullptr);
    TextureParameterDictionary params(&d, &named);
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.6f);
    const RGBColorSpace& cs = RGBColorSpace::sRGB();
    for (SpectrumType type :
         {SpectrumType::Albedo, SpectrumType::Unbounded, SpectrumType::Illuminant}) {
        SpectrumTexture t =
            CreateSpectrumTexture("imagemap", Transform(), params, type, TestLoc(), arena, diag);
        RGB rgb(2, 0.5f, 0.25f);  // pixel (2, 0)
        SampledSpectrum expected =
            type == SpectrumType::Albedo
                ? RGBAlbedoSpectrum(cs, RGB(1, 0.5f, 0.25f)).Sample(lambda)
                : (type == SpectrumType::Unbounded ? RGBUnboundedSpectrum(cs, rgb).Sample(lambda)
                                                   : RGBIlluminantSpectrum(cs, rgb).Sample(lambda));
        SampledSpectrum got = t.Evaluate(Pixel(2, 0), lambda);
        for (int i = 0; i < NSpectrumSamples; ++i)
            EXPECT_NEAR(got[i], expected[i], 1e-3f * std::max<Float>(1, expected[i]));
    }
}

TEST_F(ImageTextureTest, Errors) {
    EXPECT_THROW(MakeFloat({String1("filename", (dir / "missing.exr").string())}), SceneError);
    EXPECT_THROW(MakeFloat({String1("filter", "sinc")}), SceneError);
    ParameterDictionary d(ParsedParameterVector{}, nullptr);
    TextureParameterDictionary params(&d, &named);
    EXPECT_THROW(CreateFloatTexture("imagemap", Transform(), params, TestLoc(), arena, diag),
                 SceneError);
}

}  // namespace
}  // namespace kiln
