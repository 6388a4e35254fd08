// MIPMap: pyramid levels and filtered lookups.
#include "core/image/mipmap.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>

namespace kiln {
namespace {

Image Constant(Point2i res, RGB v) {
    Image im(PixelFormat::Float, res, {"R", "G", "B"});
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x)
            for (int c = 0; c < 3; ++c) im.SetChannel({x, y}, c, v[c]);
    return im;
}

Image Checker(Point2i res) {
    Image im(PixelFormat::Float, res, {"Y"});
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x) im.SetChannel({x, y}, 0, Float((x + y) % 2));
    return im;
}

TEST(MIPMap, ParseFilter) {
    EXPECT_EQ(ParseFilter("point"), FilterFunction::Point);
    EXPECT_EQ(ParseFilter("bilinear"), FilterFunction::Bilinear);
    EXPECT_EQ(ParseFilter("trilinear"), FilterFunction::Trilinear);
    EXPECT_EQ(ParseFilter("ewa"), FilterFunction::EWA);
    EXPECT_EQ(ParseFilter("EWA"), FilterFunction::EWA);
    EXPECT_FALSE(ParseFilter("gaussian"));
}

TEST(MIPMap, Levels) {
    MIPMap m(Checker({16, 8}), nullptr, WrapMode::Repeat, {});
    ASSERT_EQ(m.Levels(), 5);  // 16x8, 8x4, 4x2, 2x1, 1x1
    EXPECT_EQ(m.LevelResolution(1), Point2i(8, 4));
    EXPECT_EQ(m.LevelResolution(4), Point2i(1, 1));
    // Box filtering a checkerboard gives its mean from level 1 on.
    for (int l = 1; l < m.Levels(); ++l)
        EXPECT_FLOAT_EQ(m.GetLevel(l).GetChannel({0, 0}, 0), 0.5f) << l;
    MIPMap odd(Checker({5, 3}), nullptr, WrapMode::Clamp, {});
    EXPECT_EQ(odd.LevelResolution(1), Point2i(3, 2));
    EXPECT_EQ(odd.LevelResolution(odd.Levels() - 1), Point2i(1, 1));
    EXPECT_EQ(m.GetRGBColorSpace(), &RGBColorSpace::sRGB());
}

// An 8-bit texture's levels stay 8-bit in its encoding (as pbrt-v4 stores them): within half a
// code value of the levels computed in floats, and a third more memory than the image.
TEST(MIPMap, EightBitLevelsStayEightBit) {
    Image im(PixelFormat::U256, {37, 20}, {"R", "G", "B"}, ColorEncoding::SRGB());
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 37; ++x)
            for (int c = 0; c < 3; ++c)
                im.SetChannel({x, y}, c, Float((x * 13 + y * 7 + c * 5) % 17) / 16);
    MIPMap m8(im, nullptr, WrapMode::Repeat, {});
    MIPMap m32(im.ConvertToFormat(PixelFormat::Float), nullptr, WrapMode::Repeat, {});
    ASSERT_EQ(m8.Levels(), m32.Levels());
    size_t bytes = 0;
    for (int l = 0; l < m8.Levels(); ++l) {
        const Image& a = m8.GetLevel(l);
        EXPECT_EQ(a.Format(), PixelFormat::U256) << l;
        EXPECT_EQ(a.Encoding(), ColorEncoding::SRGB()) << l;
        Point2i r = a.Resolution();
        bytes += size_t(r.x) * r.y * 3;
        for (int y = 0; y < r.y; ++y)
            for (int x = 0; x < r.x; ++x)
                for (int c = 0; c < 3; ++c) {
                    Float v = m32.GetLevel(l).GetChannel({x, y}, c);
                    EXPECT_NEAR(LinearToSRGB(a.GetChannel({x, y}, c)), LinearToSRGB(v),
                                0.5f / 255 + 1e-5f)
                        << l;
                }
    }
    EXPECT_EQ(m8.MemoryBytes(), bytes);
    EXPECT_LT(double(bytes), 1.4 * 37 * 20 * 3);
    EXPECT_GT(m32.MemoryBytes(), 3 * bytes);
}

// Float lookups of colour images as pbrt-v4's: between texels (bilinear, trilinear) the mean
// of R, G and B, or alpha when it is not 1 everywhere; point lookups the first channel
TEST(MIPMap, FloatLookupsOfColourImagesAsPbrtV4) {
    for (bool withAlpha : {false, true})
        for (Float alpha : {1.f, 0.25f}) {
            Image im(PixelFormat::Float, {4, 4},
                     withAlpha ? std::vector<std::string>{"R", "G", "B", "A"}
                               : std::vector<std::string>{"R", "G", "B"});
            for (int y = 0; y < 4; ++y)
                for (int x = 0; x < 4; ++x) {
                    im.SetChannel({x, y}, 0, 0.1f), im.SetChannel({x, y}, 1, 0.5f);
                    im.SetChannel({x, y}, 2, 0.9f);
                    if (withAlpha) im.SetChannel({x, y}, 3, alpha);
                }
            Float expected = withAlpha && alpha < 1 ? alpha : 0.5f;
            for (FilterFunction f : {FilterFunction::Bilinear, FilterFunction::Trilinear}) {
                MIPMap m(im, nullptr, WrapMode::Repeat, {f, 8});
                EXPECT_NEAR(m.Filter<Float>({0.3f, 0.6f}, {0, 0}, {0, 0}), expected, 1e-6f);
                // RGB lookups ignore alpha
                EXPECT_NEAR(m.Filter<RGB>({0.3f, 0.6f}, {0, 0}, {0, 0}).b, 0.9f, 1e-6f);
            }
            MIPMap point(im, nullptr, WrapMode::Repeat, {FilterFunction::Point, 8});
            EXPECT_NEAR(point.Filter<Float>({0.3f, 0.6f}, {0, 0}, {0, 0}), 0.1f, 1e-6f);
        }
}

// Trilinear filtering reads level 0 alone for footprints under two texels (pbrt-v4)
TEST(MIPMap, TrilinearBelowLevelOneIsLevelZero) {
    Image im = Checker({16, 16});
    MIPMap tri(im, nullptr, WrapMode::Repeat, {FilterFunction::Trilinear, 8});
    MIPMap bi(im, nullptr, WrapMode::Repeat, {FilterFunction::Bilinear, 8});
    Point2f st(0.53f, 0.21f);
    Vector2f d(1.5f / 16 / 2, 0);  // a footprint 1.5 texels wide: level 0.58
    EXPECT_EQ(tri.Filter<Float>(st, d, d), bi.Filter<Float>(st, {0, 0}, {0, 0}));
}

TEST(MIPMap, ConstantFiltersToConstant) {
    RGB v(0.25f, 0.5f, 2.f);
    for (FilterFunction f : {FilterFunction::Point, FilterFunction::Bilinear,
                             FilterFunction::Trilinear, FilterFunction::EWA}) {
        MIPMap m(Constant({13, 7}, v), nullptr, WrapMode::Repeat, {f, 8});
        for (Float w : {0.f, 0.001f, 0.03f, 0.2f, 3.f}) {
            RGB r = m.Filter<RGB>({0.3f, 0.7f}, Vector2f(w, 0.1f * w), Vector2f(-0.3f * w, w));
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(r[c], v[c], 1e-5f) << ToString(f) << " w=" << w;
        }
        // Float lookups of one channel
        Image grey(PixelFormat::Float, {13, 7}, {"Y"});
        for (int y = 0; y < 7; ++y)
            for (int x = 0; x < 13; ++x) grey.SetChannel({x, y}, 0, v.r);
        MIPMap g(grey, nullptr, WrapMode::Repeat, {f, 8});
        for (Float w : {0.f, 0.001f, 0.03f, 0.2f, 3.f})
            EXPECT_NEAR(g.Filter<Float>({0.9f, 0.1f}, Vector2f(w, 0), Vector2f(0, w)), v.r, 1e-5f);
    }
}

TEST(MIPMap, BilinearAtTexelCentresReproducesTexels) {
    Image im(PixelFormat::Float, {8, 4}, {"R", "G", "B"});
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x)
            for (int c = 0; c < 3; ++c) im.SetChannel({x, y}, c, Float(x * 7 + y * 3 + c));
    MIPMap m(im, nullptr, WrapMode::Clamp, {FilterFunction::Bilinear, 8});
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) {
            Point2f st((x + 0.5f) / 8, (y + 0.5f) / 4);
            RGB r = m.Bilerp(st);
            EXPECT_FLOAT_EQ(r.g, im.GetChannel({x, y}, 1));
            Float mean =
                (im.GetChannel({x, y}, 0) + im.GetChannel({x, y}, 1) + im.GetChannel({x, y}, 2)) /
                3;
            EXPECT_FLOAT_EQ(m.BilerpFloat(st), mean);  // pbrt-v4: the mean of R, G, B
            RGB f = m.Filter<RGB>(st, Vector2f(0, 0), Vector2f(0, 0));
            EXPECT_FLOAT_EQ(f.b, im.GetChannel({x, y}, 2));
        }
}

TEST(MIPMap, WrapModesInLookups) {
    Image im(PixelFormat::Float, {4, 1}, {"Y"});
    for (int x = 0; x < 4; ++x) im.SetChannel({x, 0}, 0, Float(x + 1));
    // Half a texel left of the image: repeat blends the first and last texels, clamp keeps
    // the first, black blends with zero.
    Point2f st(0, 0.5f);
    EXPECT_FLOAT_EQ(MIPMap(im, nullptr, WrapMode::Repeat, {}).BilerpFloat(st), 2.5f);
    EXPECT_FLOAT_EQ(MIPMap(im, nullptr, WrapMode::Clamp, {}).BilerpFloat(st), 1.f);
    EXPECT_FLOAT_EQ(MIPMap(im, nullptr, WrapMode::Black, {}).BilerpFloat(st), 0.5f);
}

TEST(MIPMap, WideFootprintsAverage) {
    // A footprint covering the whole checkerboard returns its mean with every filter.
    for (FilterFunction f : {FilterFunction::Bilinear, FilterFunction::Trilinear,
                             FilterFunction::EWA, FilterFunction::Point}) {
        MIPMap m(Checker({32, 32}), nullptr, WrapMode::Repeat, {f, 8});
        EXPECT_NEAR(m.Filter<Float>({0.4f, 0.6f}, Vector2f(0.6f, 0), Vector2f(0, 0.6f)), 0.5f,
                    0.02f)
            << ToString(f);
        // A medium footprint (a few texels) blurs the checker towards its mean.
        Float mid = m.Filter<Float>({0.4f, 0.6f}, Vector2f(0.1f, 0), Vector2f(0, 0.1f));
        EXPECT_NEAR(mid, 0.5f, 0.1f) << ToString(f);
    }
}

TEST(MIPMap, CreateFromFile) {
    namespace fs = std::filesystem;
    fs::path file = fs::temp_directory_path() /
                    ("kiln_mipmap_" + std::to_string(std::random_device()()) + ".png");
    Image im(PixelFormat::U256, {4, 4}, {"R", "G", "B", "A"}, ColorEncoding::SRGB());
    for (int c = 0; c < 4; ++c) im.SetChannel({1, 2}, c, 0.5f);
    im.Write(file.string());
    ObjectArena arena;
    MIPMap* m =
        MIPMap::CreateFromFile(file.string(), {}, WrapMode::Clamp, ColorEncoding::SRGB(), arena);
    fs::remove(file);
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(m->GetLevel(0).NChannels(), 4);  // alpha kept: not 1 everywhere (pbrt-v4)
    EXPECT_EQ(m->Levels(), 3);
    EXPECT_NEAR(m->Bilerp({1.5f / 4, 2.5f / 4}).g, 0.5f, 0.003f);
    // The same bytes read as linear data.
    ObjectArena arena2;
    im.Write(file.string());
    MIPMap* lin =
        MIPMap::CreateFromFile(file.string(), {}, WrapMode::Clamp, ColorEncoding::Linear(), arena2);
    fs::remove(file);
    EXPECT_NEAR(lin->Bilerp({1.5f / 4, 2.5f / 4}).g, LinearToSRGB(0.5f), 0.003f);
    // Opaque everywhere: alpha dropped
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) im.SetChannel({x, y}, 3, 1);
    im.Write(file.string());
    ObjectArena arena3;
    MIPMap* opaque =
        MIPMap::CreateFromFile(file.string(), {}, WrapMode::Clamp, ColorEncoding::SRGB(), arena3);
    fs::remove(file);
    EXPECT_EQ(opaque->GetLevel(0).NChannels(), 3);
    EXPECT_THROW(MIPMap::CreateFromFile("/nonexistent.png", {}, WrapMode::Clamp,
                                        ColorEncoding::SRGB(), arena),
                 std::runtime_error);
}

TEST(MIPMap, EWAFollowsTheEllipse) {
    // Vertical stripes: a footprint long along the stripes keeps them, one across blurs them.
    Image im(PixelFormat::Float, {64, 64}, {"Y"});
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) im.SetChannel({x, y}, 0, Float((x / 4) % 2));
    MIPMap m(im, nullptr, WrapMode::Repeat, {FilterFunction::EWA, 16});
    Point2f st(6.f / 64, 0.5f);  // centre of the bright stripe x in [4, 8)
    Float along = m.Filter<Float>(st, Vector2f(0, 0.2f), Vector2f(0.3f / 64, 0));
    Float across = m.Filter<Float>(st, Vector2f(0.2f, 0), Vector2f(0, 0.3f / 64));
    EXPECT_GT(along, 0.9f);
    EXPECT_NEAR(across, 0.5f, 0.1f);
}

}  // namespace
}  // namespace kiln
