// Image: pixel formats, wrap modes, OIIO round trips and atomic writes.
#include "core/image/image.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "image_test_util.h"
#include "spectral/color.h"

namespace kiln {
namespace {

namespace fs = std::filesystem;

// A fresh empty directory under the system temp directory, removed at the end of the test.
class TempDir {
  public:
    TempDir() {
        std::random_device rd;
        path = fs::temp_directory_path() / ("kiln_image_test_" + std::to_string(rd()));
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    std::string File(const std::string& name) const { return (path / name).string(); }
    int Count() const {
        int n = 0;
        for ([[maybe_unused]] auto& e : fs::directory_iterator(path)) ++n;
        return n;
    }
    fs::path path;
};

Image Ramp(PixelFormat format, Point2i res, std::vector<std::string> names,
           ColorEncoding enc = ColorEncoding::Linear()) {
    Image im(format, res, names, enc);
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x)
            for (int c = 0; c < im.NChannels(); ++c)
                im.SetChannel({x, y}, c, Float(x + 2 * y + 3 * c) / (res.x + 2 * res.y + 9));
    return im;
}

TEST(Image, ParseWrapMode) {
    EXPECT_EQ(ParseWrapMode("repeat"), WrapMode::Repeat);
    EXPECT_EQ(ParseWrapMode("clamp"), WrapMode::Clamp);
    EXPECT_EQ(ParseWrapMode("black"), WrapMode::Black);
    EXPECT_EQ(ParseWrapMode("octahedralsphere"), WrapMode::OctahedralSphere);
    EXPECT_FALSE(ParseWrapMode("mirror"));
}

TEST(Image, ColorEncodingParse) {
    EXPECT_EQ(ColorEncoding::Parse("sRGB"), ColorEncoding::SRGB());
    EXPECT_EQ(ColorEncoding::Parse("linear"), ColorEncoding::Linear());
    auto g = ColorEncoding::Parse("gamma 2.2");
    ASSERT_TRUE(g);
    EXPECT_FLOAT_EQ(g->GammaValue(), 2.2f);
    EXPECT_NEAR(g->ToLinear(0.5f), std::pow(0.5f, 2.2f), 1e-6f);
    EXPECT_NEAR(g->FromLinear(g->ToLinear(0.3f)), 0.3f, 1e-6f);
    EXPECT_FALSE(ColorEncoding::Parse("gamma -1"));
    EXPECT_FALSE(ColorEncoding::Parse("rec709"));
    // The sRGB curve: continuous at the breakpoint, 0.5 encoded is about 0.214 linear.
    EXPECT_NEAR(SRGBToLinear(0.5f), 0.214041f, 1e-5f);
    EXPECT_NEAR(LinearToSRGB(SRGBToLinear(0.04045f)), 0.04045f, 1e-6f);
}

TEST(Image, WrapModes) {
    Image im = Ramp(PixelFormat::Float, {4, 3}, {"Y"});
    EXPECT_EQ(im.GetChannel({-1, 0}, 0, WrapMode::Repeat), im.GetChannel({3, 0}, 0));
    EXPECT_EQ(im.GetChannel({5, 4}, 0, WrapMode::Repeat), im.GetChannel({1, 1}, 0));
    EXPECT_EQ(im.GetChannel({-3, 7}, 0, WrapMode::Clamp), im.GetChannel({0, 2}, 0));
    EXPECT_EQ(im.GetChannel({4, 0}, 0, WrapMode::Black), 0);
    EXPECT_NE(im.GetChannel({3, 0}, 0, WrapMode::Black), 0);
    // Octahedral: crossing the left edge mirrors vertically.
    EXPECT_EQ(im.GetChannel({-1, 0}, 0, WrapMode::OctahedralSphere), im.GetChannel({0, 2}, 0));
    EXPECT_EQ(im.GetChannel({4, 2}, 0, WrapMode::OctahedralSphere), im.GetChannel({3, 0}, 0));
}

TEST(Image, FormatsStoreValues) {
    Image h(PixelFormat::Half, {2, 2}, {"R"});
    h.SetChannel({1, 1}, 0, 0.1f);
    EXPECT_NEAR(h.GetChannel({1, 1}, 0), 0.1f, 1e-4f);
    h.SetChannel({0, 0}, 0, std::nanf(""));
    EXPECT_EQ(h.GetChannel({0, 0}, 0), 0);
    Image u(PixelFormat::U256, {2, 2}, {"R"}, ColorEncoding::SRGB());
    u.SetChannel({0, 1}, 0, 0.2f);
    // Quantised in the sRGB domain: within half a code value there.
    EXPECT_NEAR(LinearToSRGB(u.GetChannel({0, 1}, 0)), LinearToSRGB(0.2f), 0.5f / 255 + 1e-6f);
    u.SetChannel({1, 1}, 0, 2.0f);
    EXPECT_FLOAT_EQ(u.GetChannel({1, 1}, 0), 1);
}

TEST(Image, BilerpAndSelect) {
    Image im = Ramp(PixelFormat::Float, {4, 4}, {"R", "G", "B"});
    // Texel centres reproduce texels; midpoints average.
    EXPECT_FLOAT_EQ(im.BilerpChannel({1.5f / 4, 2.5f / 4}, 1), im.GetChannel({1, 2}, 1));
    EXPECT_NEAR(im.BilerpChannel({2.f / 4, 2.5f / 4}, 0),
                0.5f * (im.GetChannel({1, 2}, 0) + im.GetChannel({2, 2}, 0)), 1e-6f);
    Image s = im.SelectChannels({"B", "R"});
    ASSERT_EQ(s.NChannels(), 2);
    EXPECT_EQ(s.ChannelIndex("R"), 1);
    EXPECT_EQ(s.GetChannel({3, 1}, 0), im.GetChannel({3, 1}, 2));
    EXPECT_EQ(im.ChannelIndex("A"), -1);
    EXPECT_THROW(im.SelectChannels({"A"}), std::runtime_error);
}

TEST(Image, ExrFloatRoundTripWithMetadata) {
    TempDir dir;
    Image im = Ramp(PixelFormat::Float, {5, 3}, {"R", "G", "B", "albedo.R", "Z"});
    im.SetChannel({0, 0}, 0, 1e6f);  // beyond half range: float keeps it
    ImageMetadata md = testing::TileMetadata();
    std::string f = dir.File("a.exr");
    im.Write(f, md);
    ImageMetadata rd;
    Image back = Image::Read(f, &rd);
    EXPECT_EQ(back.Format(), PixelFormat::Float);
    ASSERT_EQ(back.Resolution(), im.Resolution());
    ASSERT_EQ(back.NChannels(), im.NChannels());
    for (const std::string& n : im.ChannelNames()) {
        int a = im.ChannelIndex(n), b = back.ChannelIndex(n);
        ASSERT_GE(b, 0) << n;
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 5; ++x)
                EXPECT_EQ(back.GetChannel({x, y}, b), im.GetChannel({x, y}, a)) << n;
    }
    EXPECT_EQ(rd.renderTimeSeconds, 12.5f);
    EXPECT_EQ(rd.samplesPerPixel, 64);
    ASSERT_TRUE(rd.fullResolution && rd.pixelBounds);
    EXPECT_EQ(*rd.fullResolution, Point2i(10, 8));
    EXPECT_EQ(rd.pixelBounds->pMin, Point2i(2, 4));
    EXPECT_EQ(rd.pixelBounds->pMax, Point2i(7, 7));
    EXPECT_EQ(rd.colorSpace, &RGBColorSpace::sRGB());
    EXPECT_EQ(rd.strings["kiln:scene"], "cornell.pbrt");
    EXPECT_EQ(dir.Count(), 1);  // no temporary left behind
}

TEST(Image, ExrHalfRoundTrip) {
    TempDir dir;
    Image im = Ramp(PixelFormat::Half, {4, 4}, {"R", "G", "B"});
    std::string f = dir.File("h.exr");
    im.Write(f);
    Image back = Image::Read(f);
    EXPECT_EQ(back.Format(), PixelFormat::Half);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            for (int c = 0; c < 3; ++c)
                EXPECT_EQ(back.GetChannel({x, y}, c), im.GetChannel({x, y}, c));
}

TEST(Image, PngRoundTrip) {
    TempDir dir;
    // 8-bit sRGB data survive exactly.
    Image im = Ramp(PixelFormat::U256, {6, 2}, {"R", "G", "B"}, ColorEncoding::SRGB());
    std::string f = dir.File("a.png");
    im.Write(f);
    Image back = Image::Read(f);
    EXPECT_EQ(back.Format(), PixelFormat::U256);
    EXPECT_EQ(back.Encoding(), ColorEncoding::SRGB());
    EXPECT_EQ(back.ChannelNames(), im.ChannelNames());
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 6; ++x)
            for (int c = 0; c < 3; ++c)
                EXPECT_EQ(back.GetChannel({x, y}, c), im.GetChannel({x, y}, c));
    // Float data are sRGB encoded: within half a code value in the encoded domain.
    Image fl = Ramp(PixelFormat::Float, {6, 2}, {"R", "G", "B"});
    fl.Write(f);
    back = Image::Read(f);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(LinearToSRGB(back.GetChannel({5, 1}, c)),
                    LinearToSRGB(fl.GetChannel({5, 1}, c)), 0.5f / 255 + 1e-5f);
    // An explicit encoding overrides the file's.
    back = Image::Read(f, nullptr, ColorEncoding::Linear());
    EXPECT_NEAR(back.GetChannel({5, 1}, 0), LinearToSRGB(fl.GetChannel({5, 1}, 0)), 0.003f);
}

TEST(Image, TiffRoundTrip) {
    TempDir dir;
    Image im = Ramp(PixelFormat::Float, {3, 5}, {"R", "G", "B"});
    im.SetChannel({1, 1}, 1, 7.25f);
    std::string f = dir.File("a.tif");
    im.Write(f);
    Image back = Image::Read(f);
    EXPECT_EQ(back.Format(), PixelFormat::Float);
    EXPECT_EQ(back.ChannelNames(), im.ChannelNames());
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 3; ++x)
            for (int c = 0; c < 3; ++c)
                EXPECT_EQ(back.GetChannel({x, y}, c), im.GetChannel({x, y}, c));
    Image u = Ramp(PixelFormat::U256, {3, 5}, {"R", "G", "B"}, ColorEncoding::SRGB());
    u.Write(dir.File("b.tiff"));
    Image ub = Image::Read(dir.File("b.tiff"));
    EXPECT_EQ(ub.Format(), PixelFormat::U256);
    EXPECT_EQ(ub.GetChannel({2, 4}, 2), u.GetChannel({2, 4}, 2));
}

// pbrt-v4 reads .tga, .jpg, .bmp, ... with stb_image and takes their 8-bit samples as sRGB
// whatever encoding a texture asks for (its "encoding" applies to PNG only); so does kiln.
TEST(Image, EightBitStbFormatsAreSRGBWhateverTheRequestedEncoding) {
    TempDir dir;
    Image im = Ramp(PixelFormat::U256, {6, 2}, {"R", "G", "B"}, ColorEncoding::SRGB());
    for (const char* name : {"a.tga", "a.bmp", "a.TGA"}) {
        im.Write(dir.File(name));
        Image back = Image::Read(dir.File(name), nullptr, ColorEncoding::Linear());
        ASSERT_EQ(back.Format(), PixelFormat::U256) << name;
        EXPECT_EQ(back.Encoding(), ColorEncoding::SRGB()) << name;
        EXPECT_EQ(back.GetChannel({4, 1}, 1), im.GetChannel({4, 1}, 1)) << name;
    }
    // PNG and TIFF keep the requested encoding: the same bytes then mean other values
    for (const char* name : {"a.png", "a.tif"}) {
        im.Write(dir.File(name));
        Image back = Image::Read(dir.File(name), nullptr, ColorEncoding::Linear());
        EXPECT_EQ(back.Encoding(), ColorEncoding::Linear()) << name;
        EXPECT_NEAR(back.GetChannel({4, 1}, 1), LinearToSRGB(im.GetChannel({4, 1}, 1)), 1e-5f)
            << name;
    }
    EXPECT_TRUE(IsPbrtV4SrgbOnlyFormat("dir.png/texture.JPEG"));
    EXPECT_FALSE(IsPbrtV4SrgbOnlyFormat("dir.tga/texture.png"));
}

// Colours with alpha are read as stored, as pbrt-v4 reads them, not multiplied by alpha.
TEST(Image, ColoursWithAlphaAreNotPremultiplied) {
    TempDir dir;
    Image im(PixelFormat::U256, {2, 2}, {"R", "G", "B", "A"}, ColorEncoding::SRGB());
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) {
            im.SetChannel({x, y}, 0, 0.5f), im.SetChannel({x, y}, 1, 0.25f);
            im.SetChannel({x, y}, 2, 0.125f), im.SetChannel({x, y}, 3, x == 0 ? 0.2f : 1.f);
        }
    for (const char* name : {"rgba.png", "rgba.tga"}) {
        im.Write(dir.File(name));
        Image back = Image::Read(dir.File(name));
        ASSERT_EQ(back.NChannels(), 4) << name;
        for (int c = 0; c < 4; ++c)
            EXPECT_NEAR(back.GetChannel({0, 1}, c), im.GetChannel({0, 1}, c), 1e-6f) << name;
    }
}

TEST(Image, ReadErrorsNameTheFile) {
    try {
        Image::Read("/nonexistent/kiln.exr");
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("/nonexistent/kiln.exr: ", 0), 0u) << e.what();
    }
}

TEST(Image, AtomicWriteFailures) {
    TempDir dir;
    Image im = Ramp(PixelFormat::Float, {2, 2}, {"R", "G", "B"});
    // Unwritable (missing) directory: error, nothing created.
    EXPECT_THROW(im.Write(dir.File("missing/a.exr")), std::runtime_error);
    EXPECT_EQ(dir.Count(), 0);
    // An existing target is not replaced by a failed write.
    std::string target = dir.File("keep.hdr");
    { std::ofstream(target) << "old"; }
    Image two = Ramp(PixelFormat::Float, {2, 2}, {"U", "V"});
    EXPECT_THROW(two.Write(target), std::runtime_error);
    std::ifstream in(target);
    std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(content, "old");
    // The rename fails (the target is a non-empty directory): the temporary is removed.
    fs::create_directories(dir.path / "d.exr" / "x");
    EXPECT_THROW(im.Write(dir.File("d.exr")), std::runtime_error);
    EXPECT_EQ(dir.Count(), 2);  // keep.hdr and d.exr only
    EXPECT_TRUE(fs::is_directory(dir.path / "d.exr"));
    // A good write replaces the target.
    im.Write(dir.File("keep.hdr"));
    EXPECT_EQ(Image::Read(target).NChannels(), 3);
    EXPECT_EQ(dir.Count(), 2);
}

}  // namespace
}  // namespace kiln
