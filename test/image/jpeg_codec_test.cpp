// kiln's JPEG reader (jpeg_codec.h) against OpenImageIO's on files OpenImageIO writes (colour and
// grey), and damaged files: an error, never grey filler.
#include "core/image/jpeg_codec.h"

#include <gtest/gtest.h>

#include <fstream>
#include <vector>

#include "core/image/image.h"
#include "core/image/image_codec.h"
#include "image_test_util.h"

namespace kiln {
namespace {

std::string WriteJpeg(const std::string& name, int channels) {
    ImageFileSpec spec;
    spec.width = 37, spec.height = 21;
    spec.type = SampleType::U8;
    spec.channelNames =
        channels == 1 ? std::vector<std::string>{"Y"} : std::vector<std::string>{"R", "G", "B"};
    std::vector<unsigned char> px(size_t(spec.width) * spec.height * channels);
    for (size_t i = 0; i < px.size(); ++i) px[i] = (unsigned char)((i * 37 + i / 111 * 13) % 256);
    std::string bytes = OIIOCodec().Encode("jpg", spec, px.data());
    std::string file = testing::TempFile(name);
    std::ofstream(file, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    return file;
}

}  // namespace

TEST(JpegCodec, ReadsAsOpenImageIODoes) {
    for (int channels : {1, 3}) {
        std::string file = WriteJpeg("kiln_jpeg_" + std::to_string(channels) + ".jpg", channels);
        std::unique_ptr<ImageFileReader> ours = OpenJpeg(file), theirs = OIIOCodec().Open(file);
        ASSERT_TRUE(ours);
        const ImageFileSpec &a = ours->Spec(), &b = theirs->Spec();
        ASSERT_EQ(a.width, b.width);
        ASSERT_EQ(a.height, b.height);
        ASSERT_EQ(a.channelNames, b.channelNames);
        const size_t n = size_t(a.width) * a.height * a.channelNames.size();
        std::vector<unsigned char> pa(n), pb(n);
        ours->Read(SampleType::U8, pa.data());
        theirs->Read(SampleType::U8, pb.data());
        for (size_t i = 0; i < n; ++i) ASSERT_NEAR(int(pa[i]), int(pb[i]), 1) << i;
        // Through Image::Read: 8-bit sRGB, whatever encoding is asked (pbrt-v4's reader)
        Image im = Image::Read(file, nullptr, ColorEncoding::Linear());
        EXPECT_EQ(im.Format(), PixelFormat::U256);
        EXPECT_EQ(im.Encoding(), ColorEncoding::SRGB());
        std::remove(file.c_str());
    }
}

TEST(JpegCodec, DamagedFilesAreErrors) {
    std::string file = WriteJpeg("kiln_jpeg_damaged.jpg", 3);
    std::ifstream in(file, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (size_t size : {size_t(3), size_t(40), bytes.size() / 2, bytes.size() - 10}) {
        std::ofstream(file, std::ios::binary).write(bytes.data(), std::streamsize(size));
        EXPECT_THROW(
            {
                auto r = OpenJpeg(file);
                std::vector<float> px(37 * 21 * 3);
                if (r) r->Read(SampleType::Float, px.data());
            },
            std::runtime_error)
            << size;
    }
    std::ofstream(file, std::ios::binary) << "not a JPEG";
    EXPECT_FALSE(OpenJpeg(file));
    std::remove(file.c_str());
}

}  // namespace kiln
