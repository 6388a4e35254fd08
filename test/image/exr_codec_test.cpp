// kiln's OpenEXR codec (core/image/exr_codec.cpp) against OpenImageIO, which read and wrote
// kiln's EXR files before: the same channel order on reading, the same pixels, and the same
// metadata both ways (OpenImageIO reads what kiln writes; kiln reads what OpenImageIO writes).
// A file named otherwise is still recognised as EXR by its magic number.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/image/image.h"
#include "image_test_util.h"
#include "spectral/color.h"

namespace kiln {
namespace {

namespace fs = std::filesystem;

// Pixel (x, y), channel c: a value that identifies all three
float Value(int x, int y, int c) { return float(x + 10 * y + 100 * c) + 0.25f; }

Image Labelled(const std::vector<std::string>& names, PixelFormat format) {
    Image im(format, {5, 3}, names);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x)
            for (int c = 0; c < int(names.size()); ++c) im.SetChannel({x, y}, c, Value(x, y, c));
    return im;
}

TEST(ExrCodec, ChannelsAndPixelsAsOpenImageIOReadsThem) {
    const std::vector<std::vector<std::string>> sets = {
        {"R", "G", "B"},
        {"B", "G", "R", "A"},
        {"Z", "N.X", "albedo.R", "R", "G", "B", "N.Y", "albedo.G", "A", "N.Z", "albedo.B", "Y"},
        {"V", "U", "Zback", "imag", "real", "Depth", "Alpha", "Red", "x.Z", "x.A", "x.U", "x.R"},
        {"b", "Z", "a", "AR", "RA"},
        {"Z", "A", "X"},
        {"N.Z", "N.A", "N.X", "N.Y", "N.R", "N.U"},
        {"real", "Z", "Y", "X", "Depth", "Zback"},
        {"x", "Z", "A"},
        {"B", "G", "R", "X", "x", "y", "z"},
        {"S0.R", "S0.G", "S0.B", "S1.R", "S1.G", "S1.B", "R", "G", "B"}};
    for (PixelFormat format : {PixelFormat::Half, PixelFormat::Float})
        for (const std::vector<std::string>& names : sets) {
            const std::string file = testing::TempFile("exr_order.exr");
            Image written = Labelled(names, format);
            written.Write(file);
            Image kiln = Image::Read(file);
            auto in = OIIO::ImageInput::open(file);
            ASSERT_TRUE(in) << OIIO::geterror();
            const OIIO::ImageSpec& spec = in->spec();
            ASSERT_EQ(kiln.ChannelNames(), spec.channelnames) << names[0];
            EXPECT_EQ(kiln.Format(), format);
            std::vector<float> oiio(size_t(spec.width) * spec.height * spec.nchannels);
            ASSERT_TRUE(
                in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, oiio.data()));
            size_t i = 0;
            for (int y = 0; y < 3; ++y)
                for (int x = 0; x < 5; ++x)
                    for (int c = 0; c < kiln.NChannels(); ++c, ++i) {
                        EXPECT_EQ(kiln.GetChannel({x, y}, c), oiio[i]);
                        // and each channel holds what was written under its name
                        int w = written.ChannelIndex(kiln.ChannelNames()[c]);
                        EXPECT_EQ(kiln.GetChannel({x, y}, c), written.GetChannel({x, y}, w));
                    }
            fs::remove(file);
        }
}

TEST(ExrCodec, OpenImageIOReadsKilnsMetadata) {
    const std::string file = testing::TempFile("exr_meta.exr");
    ImageMetadata md = testing::TileMetadata();
    md.cameraFromWorld = std::array<float, 16>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 0, 0, 0, 1};
    Labelled({"R", "G", "B"}, PixelFormat::Float).Write(file, md);

    auto in = OIIO::ImageInput::open(file);
    ASSERT_TRUE(in) << OIIO::geterror();
    const OIIO::ImageSpec& s = in->spec();
    EXPECT_EQ(s.full_width, 10);
    EXPECT_EQ(s.full_height, 8);
    EXPECT_EQ(s.x, 2);
    EXPECT_EQ(s.y, 4);
    EXPECT_EQ(s.get_float_attribute("renderTimeSeconds"), 12.5f);
    EXPECT_EQ(s.get_int_attribute("samplesPerPixel"), 64);
    EXPECT_EQ(s.get_string_attribute("kiln:scene"), "cornell.pbrt");
    EXPECT_EQ(s.get_string_attribute("compression"), "zip");
    float m[16];
    ASSERT_TRUE(s.getattribute("worldToCamera", OIIO::TypeMatrix44, m));
    for (int i = 0; i < 16; ++i) EXPECT_EQ(m[i], (*md.cameraFromWorld)[i]);
    float c[8];
    ASSERT_TRUE(s.getattribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), c));
    EXPECT_FLOAT_EQ(c[0], RGBColorSpace::sRGB().r.x);
    EXPECT_FLOAT_EQ(c[7], RGBColorSpace::sRGB().w.y);
    fs::remove(file);
}

TEST(ExrCodec, KilnReadsOpenImageIOsMetadata) {
    const std::string file = testing::TempFile("exr_oiio.exr");
    OIIO::ImageSpec s(3, 2, 3, OIIO::TypeDesc::HALF);
    s.full_width = 9;
    s.full_height = 7;
    s.x = 4;
    s.y = 5;
    s.attribute("renderTimeSeconds", 3.5f);
    s.attribute("samplesPerPixel", 16);
    s.attribute("kiln:seed", "42");
    float w2c[16] = {0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    s.attribute("worldToNDC", OIIO::TypeMatrix44, w2c);
    std::vector<float> px(3 * 2 * 3);
    for (size_t i = 0; i < px.size(); ++i) px[i] = float(i) * 0.5f;
    {
        auto out = OIIO::ImageOutput::create("exr");
        ASSERT_TRUE(out && out->open(file, s));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
        ASSERT_TRUE(out->close());
    }
    ImageMetadata md;
    Image im = Image::Read(file, &md);
    EXPECT_EQ(im.Format(), PixelFormat::Half);
    ASSERT_EQ(im.Resolution(), Point2i(3, 2));
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x)
            for (int c = 0; c < 3; ++c)
                EXPECT_EQ(im.GetChannel({x, y}, c), px[size_t(3 * (3 * y + x) + c)]);
    EXPECT_EQ(md.fullResolution, Point2i(9, 7));
    ASSERT_TRUE(md.pixelBounds);
    EXPECT_EQ(md.pixelBounds->pMin, Point2i(4, 5));
    EXPECT_EQ(md.pixelBounds->pMax, Point2i(7, 7));
    EXPECT_EQ(md.renderTimeSeconds, 3.5f);
    EXPECT_EQ(md.samplesPerPixel, 16);
    EXPECT_EQ(md.strings["kiln:seed"], "42");
    ASSERT_TRUE(md.NDCFromWorld);
    for (int i = 0; i < 16; ++i) EXPECT_EQ((*md.NDCFromWorld)[i], w2c[i]);

    // The same file under another name is still read as EXR (by its magic number)
    const std::string renamed = testing::TempFile("exr_oiio.data");
    fs::rename(file, renamed);
    EXPECT_EQ(Image::Read(renamed).Resolution(), Point2i(3, 2));
    fs::remove(renamed);
}

TEST(ExrCodec, DamagedFilesAreErrorsNamingTheFile) {
    const std::string file = testing::TempFile("exr_cut.exr");
    Labelled({"R", "G", "B"}, PixelFormat::Float).Write(file);
    const std::uintmax_t size = fs::file_size(file);
    for (std::uintmax_t keep : {size - 8, size / 2, std::uintmax_t(20)}) {
        fs::resize_file(file, keep);
        try {
            Image::Read(file);
            ADD_FAILURE() << "no error at " << keep << " bytes";
        } catch (const std::runtime_error& e) {
            EXPECT_EQ(std::string(e.what()).rfind(file + ": ", 0), 0u) << e.what();
        }
    }
    fs::remove(file);
}

// OpenEXR allocates what a header states before it reads anything else: a 1 kB file whose
// attribute claimed 1.6 GB made it allocate that (found by fuzz_exr_part), and a data window
// of 2^30 lines a line offset table of 8 GB. kiln checks the headers first: both are errors
// naming the file, raised before OpenEXR opens it.
TEST(ExrCodec, HeadersClaimingMoreThanTheFileHoldsAreRefused) {
    const std::string file = testing::TempFile("exr_claims.exr");
    Labelled({"R", "G", "B"}, PixelFormat::Half).Write(file);
    std::string bytes;
    {
        std::ifstream in(file, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    auto refused = [&](std::string damaged, const std::string& why) {
        std::ofstream(file, std::ios::binary) << damaged;
        try {
            Image::Read(file);
            ADD_FAILURE() << why << ": read";
        } catch (const std::runtime_error& e) {
            EXPECT_EQ(std::string(e.what()), file + ": damaged OpenEXR file: " + why);
        }
    };
    // The size of the first attribute's value (after its name and type)
    size_t channels = bytes.find("channels");
    ASSERT_NE(channels, std::string::npos);
    std::string huge = bytes;
    const int32_t claim = 0x60000000;
    std::memcpy(&huge[channels + 9 + 7], &claim, 4);  // "channels\0chlist\0"
    refused(huge, "an attribute claims bytes beyond the file's end");
    size_t window = bytes.find("dataWindow");
    ASSERT_NE(window, std::string::npos);
    std::string tall = bytes;
    const int32_t yMax = 1 << 30;
    std::memcpy(&tall[window + 11 + 6 + 4 + 12], &yMax, 4);  // "dataWindow\0box2i\0", size
    refused(tall,
            "its data window of 5 x 1073741825 pixels has more chunks than the file has "
            "room for");
    fs::remove(file);
}

// Issue 23: an EXR kiln wrote carries kiln:checksum over its samples; the same file with one
// sample changed by another program that keeps the metadata (OpenImageIO here) is refused,
// naming the file, while an unchanged rewrite reads back.
TEST(ExrCodec, SamplesChangedAfterKilnWroteThemAreRefused) {
    const std::string file = testing::TempFile("exr_sum.exr"),
                      copy = testing::TempFile("exr_sum2.exr");
    for (PixelFormat format : {PixelFormat::Float, PixelFormat::Half}) {
        Labelled({"R", "G", "B", "A"}, format).Write(file);
        for (bool change : {false, true}) {
            auto in = OIIO::ImageInput::open(file);
            ASSERT_TRUE(in);
            OIIO::ImageSpec spec = in->spec();
            EXPECT_FALSE(spec.get_string_attribute("kiln:checksum").empty());
            std::vector<float> pixels(size_t(spec.width) * spec.height * spec.nchannels);
            ASSERT_TRUE(
                in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
            in.reset();
            if (change) pixels[5] += 0.25f;
            auto out = OIIO::ImageOutput::create(copy);
            ASSERT_TRUE(out->open(copy, spec));
            ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
            out->close();
            if (!change) {
                EXPECT_NO_THROW(Image::Read(copy));
                continue;
            }
            try {
                Image::Read(copy);
                ADD_FAILURE() << "a changed sample was read";
            } catch (const std::runtime_error& e) {
                EXPECT_EQ(std::string(e.what()),
                          copy +
                              ": damaged: its pixels do not match the checksum kiln wrote "
                              "with them");
            }
        }
    }
    fs::remove(file);
    fs::remove(copy);
}

}  // namespace
}  // namespace kiln
