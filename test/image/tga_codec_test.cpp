// kiln's own TGA reader (tga_codec.h) against OpenImageIO's, on files of every image type,
// pixel depth and origin the format defines (written byte by byte here, raw and run-length
// encoded), and on damaged files: a clear error, never a crash or a read past the data.
#include "core/image/tga_codec.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <random>
#include <vector>

#include "core/image/image.h"
#include "core/image/image_codec.h"
#include "image_test_util.h"

namespace kiln {
namespace {

struct Tga {
    int type = 2, depth = 24, descriptor = 0, width = 5, height = 3;
    int mapDepth = 0, mapFirst = 0;
    std::vector<uint8_t> map;     // colour map entries
    std::vector<uint8_t> pixels;  // stored values, file order, unencoded

    std::vector<uint8_t> Bytes(bool rle) const {
        std::vector<uint8_t> b = {3, uint8_t(map.empty() ? 0 : 1), uint8_t(rle ? type + 8 : type)};
        int entries = mapDepth ? int(map.size()) / ((mapDepth + 7) / 8) : 0;
        for (int v : {mapFirst, entries}) b.push_back(uint8_t(v)), b.push_back(uint8_t(v >> 8));
        b.push_back(uint8_t(mapDepth));
        for (int v : {0, 0, width, height}) b.push_back(uint8_t(v)), b.push_back(uint8_t(v >> 8));
        b.push_back(uint8_t(depth));
        b.push_back(uint8_t(descriptor | ((depth == 32 || (type == 3 && depth == 16)) ? 8 : 0)));
        for (char c : {'k', 'l', 'n'}) b.push_back(uint8_t(c));  // image ID
        b.insert(b.end(), map.begin(), map.end());
        const int bpp = (depth + 7) / 8;
        const size_t n = pixels.size() / bpp;
        if (!rle) {
            b.insert(b.end(), pixels.begin(), pixels.end());
            return b;
        }
        // Runs of equal values as run packets, the rest as raw packets
        for (size_t i = 0; i < n;) {
            size_t run = 1;
            while (i + run < n && run < 128 &&
                   std::equal(&pixels[i * bpp], &pixels[i * bpp] + bpp, &pixels[(i + run) * bpp]))
                ++run;
            if (run > 1) {
                b.push_back(uint8_t(0x80 | (run - 1)));
                b.insert(b.end(), &pixels[i * bpp], &pixels[i * bpp] + bpp);
                i += run;
            } else {
                size_t raw = 1;
                while (i + raw < n && raw < 128 &&
                       !std::equal(&pixels[(i + raw - 1) * bpp], &pixels[(i + raw) * bpp],
                                   &pixels[(i + raw) * bpp]))
                    ++raw;
                b.push_back(uint8_t(raw - 1));
                b.insert(b.end(), &pixels[i * bpp], &pixels[(i + raw) * bpp]);
                i += raw;
            }
        }
        return b;
    }
};

void WriteFile(const std::string& file, const std::vector<uint8_t>& bytes) {
    std::ofstream(file, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// Pixel values with repeats (for runs) and variety
std::vector<uint8_t> Values(int count, int bpp, uint8_t limit = 255) {
    std::vector<uint8_t> v;
    for (int i = 0; i < count; ++i)
        for (int c = 0; c < bpp; ++c)
            v.push_back(uint8_t(((i / 3) * 53 + c * 71 + 7) % (limit + 1)));
    return v;
}

// tolerance: 5-bit values expand as stb_image (pbrt-v4's reader) expands them, v * 255 / 31
// rounded down; OpenImageIO may round up by one level
void ExpectTgaAsOpenImageIO(const std::string& file, const std::string& what,
                            float tolerance = 0.5f / 255) {
    std::unique_ptr<ImageFileReader> ours = OpenTga(file), theirs = OIIOCodec().Open(file);
    ASSERT_TRUE(ours) << what;
    const ImageFileSpec &a = ours->Spec(), &b = theirs->Spec();
    ASSERT_EQ(a.width, b.width) << what;
    ASSERT_EQ(a.height, b.height) << what;
    ASSERT_EQ(a.channelNames.size(), b.channelNames.size()) << what;
    const size_t n = size_t(a.width) * a.height * a.channelNames.size();
    std::vector<float> pa(n), pb(n);
    ours->Read(SampleType::Float, pa.data());
    theirs->Read(SampleType::Float, pb.data());
    for (size_t i = 0; i < n; ++i) EXPECT_NEAR(pa[i], pb[i], tolerance) << what << " sample " << i;
}

}  // namespace

TEST(TgaCodec, ReadsEveryKindAsOpenImageIODoes) {
    const std::string file = testing::TempFile("kiln_tga_test.tga");
    for (bool rle : {false, true})
        for (int descriptor : {0x00, 0x20, 0x10}) {
            std::string how =
                std::string(rle ? "rle" : "raw") + " descriptor " + std::to_string(descriptor);
            for (int depth : {16, 24, 32}) {
                Tga t;
                t.depth = depth, t.descriptor = descriptor;
                t.pixels = Values(t.width * t.height, (depth + 7) / 8);
                WriteFile(file, t.Bytes(rle));
                ExpectTgaAsOpenImageIO(file, how + ", true colour " + std::to_string(depth),
                                       (depth == 16 ? 1.5f : 0.5f) / 255);
            }
            Tga grey;
            grey.type = 3, grey.depth = 8, grey.descriptor = descriptor;
            grey.pixels = Values(grey.width * grey.height, 1);
            WriteFile(file, grey.Bytes(rle));
            ExpectTgaAsOpenImageIO(file, how + ", grey");
            Tga mapped;
            mapped.type = 1, mapped.depth = 8, mapped.mapDepth = 24;
            mapped.descriptor = descriptor;
            mapped.map = Values(6, 3);
            mapped.pixels = Values(mapped.width * mapped.height, 1, 5);
            for (uint8_t& p : mapped.pixels) p = uint8_t(p % 6);
            WriteFile(file, mapped.Bytes(rle));
            ExpectTgaAsOpenImageIO(file, how + ", colour-mapped");
        }
    // Through Image::Read: 8-bit, sRGB, the orientation of OpenImageIO
    Image im = Image::Read(file);
    EXPECT_EQ(im.Format(), PixelFormat::U256);
    EXPECT_EQ(im.Encoding(), ColorEncoding::SRGB());
    std::remove(file.c_str());
}

TEST(TgaCodec, DamagedFilesAreErrors) {
    const std::string file = testing::TempFile("kiln_tga_damaged.tga");
    Tga t;
    t.depth = 32, t.width = 40, t.height = 20;
    t.pixels = Values(t.width * t.height, 4);
    for (bool rle : {false, true}) {
        std::vector<uint8_t> good = t.Bytes(rle);
        // Every truncation: an error when opening or reading, never a crash
        for (size_t size = 0; size < good.size(); size += (size < 40 ? 1 : 37)) {
            WriteFile(file,
                      std::vector<uint8_t>(good.begin(), good.begin() + std::ptrdiff_t(size)));
            EXPECT_THROW(
                {
                    auto r = OpenTga(file);
                    std::vector<float> px(size_t(t.width) * t.height * 4);
                    if (r) r->Read(SampleType::Float, px.data());
                },
                std::runtime_error)
                << size;
        }
        // Random bytes changed: read or refused, with a header that fits what it allocates
        std::mt19937 rng(5);
        for (int k = 0; k < 200; ++k) {
            std::vector<uint8_t> bad = good;
            for (int j = 0; j < 3; ++j) bad[rng() % bad.size()] = uint8_t(rng());
            WriteFile(file, bad);
            try {
                auto r = OpenTga(file);
                const ImageFileSpec& s = r->Spec();
                ASSERT_LE(size_t(s.width) * s.height, size_t(1) << 24);
                std::vector<float> px(size_t(s.width) * s.height * s.channelNames.size());
                r->Read(SampleType::Float, px.data());
            } catch (const std::runtime_error&) {
            }
        }
    }
    // A header claiming 65535 x 65535 pixels over a few bytes: refused before allocating
    std::vector<uint8_t> huge = {0,   0,   10,  0,   0,  0, 0,    0, 0, 0, 0, 0,
                                 255, 255, 255, 255, 32, 0, 0x80, 1, 2, 3, 4};
    WriteFile(file, huge);
    EXPECT_THROW(OpenTga(file), std::runtime_error);
    EXPECT_FALSE(OpenTga(testing::TempFile("kiln_not_a_tga.png")));
    std::remove(file.c_str());
}

}  // namespace kiln
