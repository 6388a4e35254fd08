// kiln's PNG codec (core/image/png_codec.h) against OpenImageIO, which read and wrote kiln's
// PNGs before. Reading: for PNGs of every kind (grey and RGB, 1 to 16 bits, palettes,
// interlaced, sRGB, gamma or linear) kiln's reader gives the channels, sample type, colour
// space, text and pixels OpenImageIO's gives; files with transparency are left to OpenImageIO.
// Writing: OpenImageIO reads the same pixels, colour space and text attributes from a file kiln
// wrote as from one it wrote itself; images the writer does not handle (an alpha channel) still
// reach the OpenImageIO plugin and are written.
#include "core/image/png_codec.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <cstdlib>

#include <filesystem>
#include <string>
#include <vector>

#include "base/atomic_file.h"
#include "core/image/image.h"
#include "image_test_util.h"

namespace kiln {
namespace {

namespace fs = std::filesystem;

struct Read {
    std::vector<unsigned char> pixels;
    OIIO::ImageSpec spec;
};

Read ReadWithOIIO(const std::string& file) {
    Read r;
    auto in = OIIO::ImageInput::open(file);
    EXPECT_TRUE(in) << OIIO::geterror();
    if (!in) return r;
    r.spec = in->spec();
    r.pixels.resize(size_t(r.spec.width) * r.spec.height * r.spec.nchannels);
    EXPECT_TRUE(in->read_image(0, 0, 0, r.spec.nchannels, OIIO::TypeDesc::UINT8, r.pixels.data()));
    return r;
}

// A PNG written with libpng itself: for the kinds OpenImageIO cannot write
void WriteRawPng(const std::string& file, int w, int h, int colorType, int bitDepth,
                 bool interlaced, bool transparency, const std::vector<unsigned char>& rows) {
    FILE* f = std::fopen(file.c_str(), "wb");
    ASSERT_TRUE(f);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, f);
    png_set_IHDR(png, info, w, h, bitDepth, colorType,
                 interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_color palette[4] = {{0, 0, 0}, {255, 0, 0}, {10, 200, 30}, {90, 80, 250}};
    if (colorType == PNG_COLOR_TYPE_PALETTE) png_set_PLTE(png, info, palette, 4);
    png_byte alpha[4] = {255, 128, 0, 255};
    if (transparency) png_set_tRNS(png, info, alpha, 4, nullptr);
    png_text text{};
    text.compression = PNG_TEXT_COMPRESSION_NONE;
    text.key = const_cast<char*>("Comment");
    text.text = const_cast<char*>("made by libpng");
    png_set_text(png, info, &text, 1);
    png_write_info(png, info);
    const size_t stride = rows.size() / size_t(h);
    std::vector<png_bytep> pointers;
    for (int y = 0; y < h; ++y) pointers.push_back(const_cast<png_bytep>(&rows[y * stride]));
    png_write_image(png, pointers.data());
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
}

// Both readers' view of file: the same spec and the same pixels (as floats)
void ExpectPngAsOpenImageIO(const std::string& file, const std::string& what) {
    std::unique_ptr<ImageFileReader> ours = OpenPng(file), theirs = OIIOCodec().Open(file);
    ASSERT_TRUE(ours) << what;
    const ImageFileSpec &a = ours->Spec(), &b = theirs->Spec();
    EXPECT_EQ(a.width, b.width) << what;
    EXPECT_EQ(a.height, b.height) << what;
    EXPECT_EQ(a.channelNames, b.channelNames) << what;
    EXPECT_EQ(a.type, b.type) << what;
    // Colour spaces as kiln uses them: case aside, and gamma values as numbers
    std::string ca = a.colorSpace, cb = b.colorSpace;
    for (std::string* c : {&ca, &cb})
        for (char& ch : *c) ch = char(std::tolower((unsigned char)ch));
    if (ca.rfind("gamma", 0) == 0 && cb.rfind("gamma", 0) == 0)
        EXPECT_NEAR(std::atof(ca.c_str() + 5), std::atof(cb.c_str() + 5), 1e-6) << what;
    else
        EXPECT_EQ(ca, cb) << what;
    for (const auto& [k, v] : a.strings) {
        auto it = b.strings.find(k);
        if (it != b.strings.end()) {
            EXPECT_EQ(v, it->second) << what << " " << k;
        }
    }
    const size_t n = size_t(a.width) * a.height * a.channelNames.size();
    std::vector<float> pa(n), pb(n);
    ours->Read(SampleType::Float, pa.data());
    theirs->Read(SampleType::Float, pb.data());
    EXPECT_EQ(pa, pb) << what;
}

TEST(PngCodec, ReadsEveryOpaquePngAsOpenImageIODoes) {
    const int w = 9, h = 7;
    const std::string file = testing::TempFile("png_read.png");
    // Written by OpenImageIO: grey and RGB, 8 and 16 bits, sRGB, linear and gamma 2.2
    for (int nc : {1, 3})
        for (OIIO::TypeDesc type : {OIIO::TypeDesc::UINT8, OIIO::TypeDesc::UINT16})
            for (const char* colorSpace : {"sRGB", "Linear", "Gamma2.2"}) {
                OIIO::ImageSpec spec(w, h, nc, type);
                spec.attribute("oiio:ColorSpace", colorSpace);
                std::vector<float> px(size_t(w) * h * nc);
                for (size_t i = 0; i < px.size(); ++i) px[i] = float((i * 7919) % 1000) / 999.f;
                auto out = OIIO::ImageOutput::create("png");
                ASSERT_TRUE(out && out->open(file, spec));
                ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
                ASSERT_TRUE(out->close());
                ExpectPngAsOpenImageIO(
                    file, std::to_string(nc) + " channels, " + type.c_str() + ", " + colorSpace);
            }
    // Written by libpng: a palette, grey at 1, 2 and 4 bits, interlaced or not, no colour chunk
    std::vector<unsigned char> indices;
    for (int i = 0; i < w * h; ++i) indices.push_back((unsigned char)(i % 4));
    for (bool interlaced : {false, true}) {
        WriteRawPng(file, w, h, PNG_COLOR_TYPE_PALETTE, 8, interlaced, false, indices);
        ExpectPngAsOpenImageIO(file, "palette");
        for (int bits : {1, 2, 4}) {
            // packed rows of w samples of `bits` bits
            const int stride = (w * bits + 7) / 8;
            std::vector<unsigned char> rows(size_t(stride) * h);
            for (size_t i = 0; i < rows.size(); ++i) rows[i] = (unsigned char)(i * 151 + 17);
            WriteRawPng(file, w, h, PNG_COLOR_TYPE_GRAY, bits, interlaced, false, rows);
            ExpectPngAsOpenImageIO(file, "grey " + std::to_string(bits) + " bits");
        }
    }
    // Transparency: left to OpenImageIO (it premultiplies)
    WriteRawPng(file, w, h, PNG_COLOR_TYPE_PALETTE, 8, false, true, indices);
    EXPECT_FALSE(OpenPng(file));
    EXPECT_EQ(Image::Read(file).NChannels(), 4);
    std::vector<unsigned char> rgba(size_t(w) * h * 4, 200);
    WriteRawPng(file, w, h, PNG_COLOR_TYPE_RGBA, 8, false, false, rgba);
    EXPECT_FALSE(OpenPng(file));
    // Not a PNG at all: nullptr (another reader's business); a damaged PNG: an error
    EXPECT_FALSE(OpenPng(testing::TempFile("png_missing.png")));
    WriteRawPng(file, w, h, PNG_COLOR_TYPE_PALETTE, 8, false, false, indices);
    fs::resize_file(file, fs::file_size(file) - 30);
    EXPECT_THROW(
        {
            auto r = OpenPng(file);
            std::vector<float> px(size_t(w) * h * 3);
            if (r) r->Read(SampleType::Float, px.data());
        },
        std::runtime_error);
    fs::remove(file);
}

TEST(PngCodec, OpenImageIOReadsWhatItWouldHaveWritten) {
    const int w = 7, h = 5;
    for (int nc : {1, 3})
        for (const char* colorSpace : {"sRGB", "Linear", "Gamma2.2"}) {
            ImageFileSpec spec;
            spec.width = w;
            spec.height = h;
            spec.channelNames =
                nc == 1 ? std::vector<std::string>{"Y"} : std::vector<std::string>{"R", "G", "B"};
            spec.type = SampleType::U8;
            spec.colorSpace = colorSpace;
            spec.strings = {{"kiln:partial", "true"}, {"kiln:scene", "0123abcd"}};
            ASSERT_TRUE(PngWriterHandles(spec));
            std::vector<unsigned char> data(size_t(w) * h * nc);
            for (size_t i = 0; i < data.size(); ++i) data[i] = (unsigned char)(i * 37 % 256);
            const std::string ours = testing::TempFile("png_ours.png"),
                              theirs = testing::TempFile("png_theirs.png");
            WriteFileAtomically(ours, EncodePng(spec, data.data()));
            WriteFileAtomically(theirs, OIIOCodec().Encode("png", spec, data.data()));
            Read a = ReadWithOIIO(ours), b = ReadWithOIIO(theirs);
            EXPECT_EQ(a.pixels, data) << nc << " " << colorSpace;
            EXPECT_EQ(a.pixels, b.pixels);
            EXPECT_EQ(a.spec.nchannels, nc);
            EXPECT_EQ(a.spec.get_string_attribute("oiio:ColorSpace"),
                      b.spec.get_string_attribute("oiio:ColorSpace"))
                << colorSpace;
            EXPECT_EQ(a.spec.get_string_attribute("kiln:partial"), "true");
            EXPECT_EQ(a.spec.get_string_attribute("kiln:scene"), "0123abcd");
            // and kiln reads its own file back with the encoding it was written with
            ImageMetadata md;
            Image back = Image::Read(ours, &md);
            EXPECT_EQ(back.Format(), PixelFormat::U256);
            EXPECT_EQ(md.strings["kiln:partial"], "true");
            fs::remove(ours);
            fs::remove(theirs);
        }
}

TEST(PngCodec, ImagesWithAlphaAreWrittenThroughOpenImageIO) {
    ImageFileSpec spec;
    spec.type = SampleType::U8;
    spec.channelNames = {"R", "G", "B", "A"};
    EXPECT_FALSE(PngWriterHandles(spec));
    spec.channelNames = {"Y", "A"};
    EXPECT_FALSE(PngWriterHandles(spec));
    spec.channelNames = {"R", "G", "B"};
    spec.type = SampleType::Float;
    EXPECT_FALSE(PngWriterHandles(spec));

    // Written through Image::Write all the same (the plugin), and read back
    Image im(PixelFormat::U256, {4, 3}, {"R", "G", "B", "A"}, ColorEncoding::SRGB());
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x)
            for (int c = 0; c < 4; ++c) im.SetChannel({x, y}, c, c == 3 ? 1.f : 0.1f * (x + y));
    const std::string file = testing::TempFile("png_alpha.png");
    im.Write(file);
    Image back = Image::Read(file);
    ASSERT_EQ(back.NChannels(), 4);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x)
            for (int c = 0; c < 4; ++c)
                EXPECT_EQ(back.GetChannel({x, y}, c), im.GetChannel({x, y}, c));
    fs::remove(file);
}

}  // namespace
}  // namespace kiln
