#include "core/image/tga_codec.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <vector>

#include "core/image/image.h"

namespace kiln {
namespace {

[[noreturn]] void Damaged(const std::string& why) {
    throw std::runtime_error("damaged or unsupported TGA file: " + why);
}

uint16_t U16(const uint8_t* p) { return uint16_t(p[0] | (p[1] << 8)); }

// One stored pixel value (bytes little-endian) as 8-bit samples: grey, grey and alpha, RGB or
// RGBA (bytes per pixel and channels from the pixel depth).
void DecodeValue(const uint8_t* p, int depth, bool grey, uint8_t* out) {
    if (grey) {
        out[0] = p[0];
        if (depth == 16) out[1] = p[1];
        return;
    }
    switch (depth) {
        case 15:
        case 16: {
            uint16_t v = U16(p);
            auto five = [](int x) { return uint8_t((x & 31) * 255 / 31); };
            out[0] = five(v >> 10), out[1] = five(v >> 5), out[2] = five(v);
            return;
        }
        case 24:
            out[0] = p[2], out[1] = p[1], out[2] = p[0];
            return;
        default:  // 32
            out[0] = p[2], out[1] = p[1], out[2] = p[0], out[3] = p[3];
    }
}

// The file's bytes and header; pixels are decoded by Read, after Image::Read has charged them
// to the memory budget.
struct TgaHeader {
    int width, height, depth, mapDepth, mapFirst, mapLength, descriptor;
    bool rle, mapped, grey;
    size_t pixelsAt;  // where the pixel data start
    int channels;
};

class TgaReader final : public ImageFileReader {
  public:
    TgaReader(ImageFileSpec spec, std::vector<uint8_t> file, std::vector<uint8_t> map, TgaHeader h)
        : spec(std::move(spec)), file(std::move(file)), map(std::move(map)), h(h) {}
    const ImageFileSpec& Spec() const override { return spec; }
    void Read(SampleType type, void* data) override {
        std::vector<uint8_t> pixels = Decode();
        if (type == SampleType::U8) {
            std::memcpy(data, pixels.data(), pixels.size());
        } else if (type == SampleType::Float) {
            auto out = static_cast<float*>(data);
            for (size_t i = 0; i < pixels.size(); ++i) out[i] = pixels[i] / 255.f;
        } else {
            throw std::runtime_error("TGA files hold 8-bit samples");
        }
    }

  private:
    std::vector<uint8_t> Decode() const;

    ImageFileSpec spec;
    std::vector<uint8_t> file, map;
    TgaHeader h;
};

// Pixels in file order (run-length decoded), then placed by the descriptor's origin bits
std::vector<uint8_t> TgaReader::Decode() const {
    const int pixelBytes = (h.depth + 7) / 8, mapBytes = (h.mapDepth + 7) / 8;
    const size_t count = size_t(h.width) * h.height;
    size_t pos = h.pixelsAt;
    std::vector<uint8_t> values(count * pixelBytes);
    if (!h.rle) {
        std::memcpy(values.data(), file.data() + pos, values.size());  // size checked on opening
    } else {
        size_t n = 0;
        while (n < count) {
            if (pos >= file.size()) Damaged("run-length data end early");
            const uint8_t packet = file[pos++];
            const size_t run = size_t(packet & 0x7f) + 1;
            if (n + run > count) Damaged("a run passes the last pixel");
            if (packet & 0x80) {  // one value repeated
                if (pos + pixelBytes > file.size()) Damaged("run-length data end early");
                for (size_t k = 0; k < run; ++k)
                    std::memcpy(&values[(n + k) * pixelBytes], &file[pos], size_t(pixelBytes));
                pos += size_t(pixelBytes);
            } else {  // run values as they are
                size_t bytes = run * pixelBytes;
                if (pos + bytes > file.size()) Damaged("run-length data end early");
                std::memcpy(&values[n * pixelBytes], &file[pos], bytes);
                pos += bytes;
            }
            n += run;
        }
    }
    const bool topToBottom = h.descriptor & 0x20, rightToLeft = h.descriptor & 0x10;
    const size_t width = size_t(h.width), height = size_t(h.height);
    std::vector<uint8_t> pixels(count * h.channels);
    for (size_t i = 0; i < count; ++i) {
        size_t fx = i % width, fy = i / width;
        size_t x = rightToLeft ? width - 1 - fx : fx, y = topToBottom ? fy : height - 1 - fy;
        uint8_t* out = &pixels[(y * width + x) * h.channels];
        const uint8_t* v = &values[i * pixelBytes];
        if (h.mapped) {
            int index = h.depth == 16 ? U16(v) : v[0];
            if (index < h.mapFirst || index - h.mapFirst >= h.mapLength)
                Damaged("a pixel's colour map index " + std::to_string(index) +
                        " is outside the map");
            DecodeValue(&map[size_t(index - h.mapFirst) * mapBytes], h.mapDepth, false, out);
        } else {
            DecodeValue(v, h.depth, h.grey, out);
        }
    }
    return pixels;
}

}  // namespace

std::unique_ptr<ImageFileReader> OpenTga(const std::string& filename) {
    if (FileExtension(filename) != "tga") return nullptr;
    std::ifstream in(filename, std::ios::binary);
    if (!in) return nullptr;
    std::vector<uint8_t> file((std::istreambuf_iterator<char>(in)),
                              std::istreambuf_iterator<char>());
    if (file.size() < 18) Damaged("shorter than its header");
    const uint8_t* h = file.data();
    const int idLength = h[0], mapType = h[1], imageType = h[2];
    const int mapFirst = U16(h + 3), mapLength = U16(h + 5), mapDepth = h[7];
    const int width = U16(h + 12), height = U16(h + 14), depth = h[16], descriptor = h[17];
    const bool rle = imageType >= 9, mapped = (imageType & 7) == 1, grey = (imageType & 7) == 3;
    if ((imageType & 7) < 1 || (imageType & 7) > 3 || (imageType > 3 && imageType < 9) ||
        imageType > 11)
        Damaged("image type " + std::to_string(imageType));
    if (width == 0 || height == 0) Damaged("no pixels");
    if (mapType > 1 || (mapped && mapType != 1)) Damaged("colour map type");
    if (mapped ? (depth != 8 && depth != 16)
        : grey ? (depth != 8 && depth != 16)
               : (depth != 15 && depth != 16 && depth != 24 && depth != 32))
        Damaged("pixel depth " + std::to_string(depth));
    const int valueDepth = mapped ? mapDepth : depth;  // what a pixel's value is stored as
    if (mapped && mapDepth != 15 && mapDepth != 16 && mapDepth != 24 && mapDepth != 32)
        Damaged("colour map entry depth " + std::to_string(mapDepth));

    // The colour map follows the image ID (a map in a true-colour file is skipped)
    size_t pos = 18 + size_t(idLength);
    const int mapBytes = (mapDepth + 7) / 8;
    std::vector<uint8_t> map;
    if (mapType == 1) {
        size_t bytes = size_t(mapLength) * mapBytes;
        if (pos + bytes > file.size()) Damaged("colour map beyond the end of the file");
        map.assign(file.begin() + std::ptrdiff_t(pos), file.begin() + std::ptrdiff_t(pos + bytes));
        pos += bytes;
    }

    // Channels of the decoded pixels
    int channels = grey ? (depth == 16 ? 2 : 1) : (valueDepth == 32 ? 4 : 3);
    ImageFileSpec spec;
    spec.width = spec.fullWidth = width;
    spec.height = spec.fullHeight = height;
    spec.type = SampleType::U8;
    spec.colorSpace = "sRGB";
    spec.channelNames = channels == 1   ? std::vector<std::string>{"Y"}
                        : channels == 2 ? std::vector<std::string>{"Y", "A"}
                        : channels == 3 ? std::vector<std::string>{"R", "G", "B"}
                                        : std::vector<std::string>{"R", "G", "B", "A"};

    // The pixel data must be there (raw) or could be there (run-length: at most 128 pixels
    // per packet), checked before anything the header claims is allocated
    const int pixelBytes = (depth + 7) / 8;
    const size_t count = size_t(width) * height, left = file.size() - std::min(pos, file.size());
    if (!rle && count * pixelBytes > left) Damaged("pixels beyond the end of the file");
    if (rle && count > left / size_t(1 + pixelBytes) * 128 + 128)
        Damaged("too little run-length data for its pixels");
    TgaHeader header{width,      height, depth,  mapDepth, mapFirst, mapLength,
                     descriptor, rle,    mapped, grey,     pos,      channels};
    return std::make_unique<TgaReader>(std::move(spec), std::move(file), std::move(map), header);
}

}  // namespace kiln
