// libFuzzer target: the image files textures, environment maps and masks are read from, through
// kiln's own readers: TGA and PFM (kiln's parsers), PNG and JPEG (libpng and libjpeg behind
// kiln's code). The first byte picks the extension the rest is written under (tga, pfm, png,
// jpg; kiln tells formats by content, so a PFM named .png is still read as a PFM); the file is
// read as a texture is, by Image::Read with a 64 MB budget, then as an sRGB and a linear 8-bit
// image would be. Every input must end in an image (its samples finite, except a PFM's, which
// stores floats as they are) or in an exception naming the file, never a crash, a hang or an
// allocation a header merely claims. Inputs no kiln reader takes (a PNG with alpha, which
// OpenImageIO reads) are skipped: OpenImageIO is not instrumented.
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>

#include "base/memory_budget.h"
#include "core/image/image.h"
#include "core/image/jpeg_codec.h"
#include "core/image/pfm_codec.h"
#include "core/image/png_codec.h"
#include "core/image/tga_codec.h"

using namespace kiln;

namespace {

void Check(bool ok) {
    if (!ok) __builtin_trap();
}

// Whether one of kiln's own readers takes the file (Image::Read would then use it, trying them
// in this order: formats are told by content, not by the extension).
bool KilnReads(const std::string& file) {
    try {
        return OpenPng(file) || OpenPfm(file) || OpenTga(file) || OpenJpeg(file);
    } catch (const std::exception&) {
        return true;  // a reader took it and found it damaged: Image::Read must say so too
    }
}

// Whether Image::Read reads the file as a PFM (the only format here that stores floats as
// they are).
bool ReadsAsPfm(const std::string& file) {
    try {
        return !OpenPng(file) && OpenPfm(file);
    } catch (const std::exception&) {
        return false;
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 1) return 0;
    static const char* const kExtensions[] = {"tga", "pfm", "png", "jpg"};
    const std::string extension = kExtensions[data[0] % 4];
    const std::string file = "/tmp/kiln_fuzz_image_" + std::to_string(getpid()) + "." + extension;
    if (std::FILE* f = std::fopen(file.c_str(), "wb")) {
        std::fwrite(data + 1, 1, size - 1, f);
        std::fclose(f);
    } else {
        return 0;
    }
    if (!KilnReads(file)) {
        std::remove(file.c_str());
        return 0;
    }
    const bool pfm = ReadsAsPfm(file);
    for (std::optional<ColorEncoding> encoding :
         {std::optional<ColorEncoding>(), std::optional<ColorEncoding>(ColorEncoding::Linear())}) {
        try {
            MemoryBudget budget(64e6);
            Image image = Image::Read(file, nullptr, encoding, &budget);
            Check(image.Resolution().x > 0 && image.Resolution().y > 0 && image.NChannels() > 0);
            for (int y = 0; y < image.Resolution().y; ++y)
                for (int x = 0; x < image.Resolution().x; ++x)
                    for (int c = 0; c < image.NChannels(); ++c) {
                        float v = image.GetChannel({x, y}, c);
                        // PFM stores floats as they are: infinities and NaNs are data there
                        // (area and environment lights refuse such images; reflectance,
                        // roughness and temperature textures of all-NaN or all-infinite PFMs
                        // rendered finite pixels, the infinite ones as pbrt-v4 renders them)
                        Check(std::isfinite(v) || pfm);
                    }
        } catch (const std::runtime_error&) {
        }
    }
    std::remove(file.c_str());
    return 0;
}
