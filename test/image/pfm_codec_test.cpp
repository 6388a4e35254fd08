// kiln's PFM codec (core/image/pfm_codec.h): RGB and grey images round-trip bit-exactly, rows
// bottom to top in the file; big-endian files (positive scale) read as little-endian ones;
// damaged headers and files whose size does not match their header are errors, not reads of
// what the header claims.
#include "core/image/pfm_codec.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/image/image.h"

namespace kiln {
namespace {

namespace fs = std::filesystem;

class PfmCodec : public ::testing::Test {
  protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("kiln_pfm_" + std::to_string(getpid()));
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    std::string File(const std::string& name, const std::string& bytes) {
        std::string path = (dir / name).string();
        std::ofstream(path, std::ios::binary) << bytes;
        return path;
    }
    fs::path dir;
};

TEST_F(PfmCodec, RGBAndGreyRoundTripExactly) {
    for (std::vector<std::string> channels :
         {std::vector<std::string>{"R", "G", "B"}, std::vector<std::string>{"Y"}}) {
        Image im(PixelFormat::Float, {5, 3}, channels);
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 5; ++x)
                for (int c = 0; c < im.NChannels(); ++c)
                    im.SetChannel({x, y}, c,
                                  Float(1e-3) * (x + 1) * (y + 7) * (c + 1) + 1e30f * (x == 4));
        std::string path = (dir / "a.pfm").string();
        im.Write(path);
        Image back = Image::Read(path);
        ASSERT_EQ(back.Resolution(), im.Resolution());
        ASSERT_EQ(back.NChannels(), im.NChannels());
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 5; ++x)
                for (int c = 0; c < im.NChannels(); ++c)
                    EXPECT_EQ(back.GetChannel({x, y}, c), im.GetChannel({x, y}, c));
        // The file's first row is the image's bottom row
        std::string bytes;
        {
            std::ifstream in(path, std::ios::binary);
            bytes.assign(std::istreambuf_iterator<char>(in), {});
        }
        std::string header = channels.size() == 3 ? "PF\n5 3\n-1\n" : "Pf\n5 3\n-1\n";
        ASSERT_EQ(bytes.substr(0, header.size()), header);
        float first;
        std::memcpy(&first, bytes.data() + header.size(), 4);
        EXPECT_EQ(first, im.GetChannel({0, 2}, 0));
    }
}

TEST_F(PfmCodec, BigEndianFilesRead) {
    std::string data = "Pf\n2 1\n1.0\n";
    for (float v : {1.5f, -2.25f}) {
        uint32_t bits = std::bit_cast<uint32_t>(v);
        for (int shift = 24; shift >= 0; shift -= 8) data.push_back(char((bits >> shift) & 0xff));
    }
    Image im = Image::Read(File("big.pfm", data));
    EXPECT_EQ(im.GetChannel({0, 0}, 0), 1.5f);
    EXPECT_EQ(im.GetChannel({1, 0}, 0), -2.25f);
    // The scale's magnitude multiplies the samples (as pbrt-v4 reads them)
    data.replace(data.find("1.0"), 3, "4.0");
    im = Image::Read(File("big4.pfm", data));
    EXPECT_EQ(im.GetChannel({0, 0}, 0), 6.f);
    EXPECT_EQ(im.GetChannel({1, 0}, 0), -9.f);
}

TEST_F(PfmCodec, DamagedFilesAreErrors) {
    std::string eight(8, '\0');
    for (const std::string& bytes :
         {std::string("PF\n2 1\n-1\n") + eight,  // 2 of 6 floats
          std::string("PF\n-2 1\n-1\n") + eight, std::string("PF\n2 x\n-1\n") + eight,
          std::string("PF\n2 1\n0\n") + std::string(24, '\0'),
          std::string("PF\n99999999 99999999\n-1\n") + eight, std::string("PF\n2 1"),
          std::string("Pf\n1e300 1\n-1\n") + eight})
        EXPECT_THROW(Image::Read(File("bad.pfm", bytes)), std::runtime_error) << bytes;
}

}  // namespace
}  // namespace kiln
