// CheckExrFile (image_codec.h): the structure of an OpenEXR file's headers, read before
// OpenEXR opens it. OpenEXR allocates what a header states before it reads the data: an
// attribute's size (a 1 kB file stating 1.6 GB), the line offset table (8 bytes per chunk of
// the data window), line buffers (the window's width times the lines of a chunk). Each must
// be possible for this file (values and offsets within it), and what the largest part takes
// to read is returned, for the caller to charge before OpenEXR allocates it.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/image/image_codec.h"

namespace kiln {

namespace {

class HeaderReader {
  public:
    HeaderReader(std::FILE* f, int64_t size) : f(f), size(size) {}
    int64_t Position() const { return position; }
    int64_t FileSize() const { return size; }
    // A null-terminated string of at most 255 characters (OpenEXR's long names)
    std::string String(const char* what) {
        std::string s;
        for (int c; (c = Byte()) != 0;) {
            if (s.size() >= 255) Fail(std::string(what) + " longer than 255 characters");
            s += char(c);
        }
        return s;
    }
    int32_t Int32() {
        uint32_t v = 0;
        for (int i = 0; i < 4; ++i) v |= uint32_t(Byte()) << (8 * i);
        return int32_t(v);
    }
    int Byte() {
        int c = std::fgetc(f);
        if (c == EOF) Fail("the header ends early");
        ++position;
        return c;
    }
    void Skip(int64_t n) {
        if (n < 0 || n > size - position) Fail("an attribute claims bytes beyond the file's end");
        if (std::fseek(f, long(n), SEEK_CUR) != 0) Fail("cannot read the header");
        position += n;
    }
    [[noreturn]] static void Fail(const std::string& why) {
        throw std::runtime_error("damaged OpenEXR file: " + why);
    }

  private:
    std::FILE* f;
    int64_t size, position = 0;
};

struct PartHeader {
    int64_t width = 0, height = 0, sampleBytes = 0;  // sampleBytes: of one pixel, all channels
    int channels = 0, compression = 0;
    int64_t tileWidth = 0, tileHeight = 0;
    bool hasWindow = false;
};

// Scan lines per chunk of each OpenEXR compression (ImfCompression.h order)
int64_t LinesPerChunk(int compression) {
    switch (compression) {
        case 3:
        case 5:
            return 16;  // ZIP, PXR24
        case 4:
        case 6:
        case 7:
        case 8:
            return 32;  // PIZ, B44, B44A, DWAA
        case 9:
            return 256;  // DWAB
        default:
            return 1;  // NONE, RLE, ZIPS
    }
}

// The value size OpenEXR's reader of a type reads whatever the header says (0: it reads the
// stated size, or a list of its own length, checked below). A header whose size differs would
// be read out of step with kiln's walk, so it is refused.
int FixedSize(const std::string& type) {
    static const std::pair<const char*, int> sizes[] = {
        {"box2i", 16},      {"box2f", 16},   {"chromaticities", 32},
        {"compression", 1}, {"double", 8},   {"envmap", 1},
        {"float", 4},       {"int", 4},      {"keycode", 28},
        {"lineOrder", 1},   {"m33f", 36},    {"m33d", 72},
        {"m44f", 64},       {"m44d", 128},   {"rational", 8},
        {"tiledesc", 9},    {"timecode", 8}, {"v2i", 8},
        {"v2f", 8},         {"v2d", 16},     {"v3i", 12},
        {"v3f", 12},        {"v3d", 24},     {"deepImageState", 1}};
    for (const auto& [name, size] : sizes)
        if (type == name) return size;
    return 0;
}

// One header's attributes, to its terminating null byte; false for the empty header that ends
// a multi-part file's list
bool ReadHeader(HeaderReader& in, PartHeader* h, bool multipart) {
    for (bool first = true;; first = false) {
        std::string name = in.String("an attribute name");
        if (name.empty()) return !(multipart && first);
        std::string type = in.String("an attribute type");
        int32_t size = in.Int32();
        if (size < 0) HeaderReader::Fail("attribute \"" + name + "\" has a negative size");
        if (int fixed = FixedSize(type); fixed > 0 && size != fixed)
            HeaderReader::Fail("attribute \"" + name + "\" of type " + type + " has size " +
                               std::to_string(size) + ", not " + std::to_string(fixed));
        int64_t end = in.Position() + size;
        if (size > 0 && end > in.FileSize())
            HeaderReader::Fail("an attribute claims bytes beyond the file's end");
        if (name == "dataWindow" && type == "box2i") {
            int64_t x0 = in.Int32(), y0 = in.Int32(), x1 = in.Int32(), y1 = in.Int32();
            h->width = x1 - x0 + 1, h->height = y1 - y0 + 1;
            h->hasWindow = true;
        } else if (type == "chlist") {  // OpenEXR reads entries to an empty name
            bool channels = name == "channels";
            while (!in.String("a channel name").empty()) {
                int32_t pixelType = in.Int32();
                for (int i = 0; i < 12; ++i) in.Byte();  // pLinear, reserved, sampling
                if (channels) h->sampleBytes += pixelType == 1 ? 2 : 4, ++h->channels;
            }
            if (in.Position() != end)
                HeaderReader::Fail("attribute \"" + name + "\" is not as long as its size");
        } else if (type == "preview") {  // width, height, then 4 bytes per pixel
            int64_t w = uint32_t(in.Int32()), ht = uint32_t(in.Int32());
            if (8 + 4.0 * double(w) * double(ht) != double(size))
                HeaderReader::Fail("attribute \"" + name + "\" is not as long as its size");
        } else if (type == "stringvector") {  // strings, each after its length
            while (in.Position() + 4 <= end) {
                int32_t length = in.Int32();
                if (length < 0 || length > end - in.Position())
                    HeaderReader::Fail("attribute \"" + name + "\" has a string beyond its size");
                in.Skip(length);
            }
        } else if (name == "compression" && type == "compression") {
            h->compression = in.Byte();
        } else if (name == "tiles" && type == "tiledesc") {
            h->tileWidth = uint32_t(in.Int32()), h->tileHeight = uint32_t(in.Int32());
            in.Byte();
        }
        if (in.Position() > end) HeaderReader::Fail("attribute \"" + name + "\" overruns its size");
        in.Skip(end - in.Position());
    }
}

}  // namespace

ExrHeaderSize CheckExrFile(const std::string& filename) {
    ExrHeaderSize largest;
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(filename.c_str(), "rb"),
                                                      std::fclose);
    if (!f) throw std::runtime_error("cannot open");
    std::fseek(f.get(), 0, SEEK_END);
    const int64_t fileSize = std::ftell(f.get());
    std::fseek(f.get(), 0, SEEK_SET);
    HeaderReader in(f.get(), fileSize);
    if (in.Int32() != 20000630) HeaderReader::Fail("no OpenEXR magic number");
    const int32_t version = in.Int32();
    const bool tiled = version & 0x200, multipart = version & 0x1000;
    for (int part = 0;; ++part) {
        PartHeader h;
        if (!ReadHeader(in, &h, multipart)) break;
        if (h.hasWindow) {
            if (h.width < 1 || h.height < 1) HeaderReader::Fail("an empty data window");
            // Offsets: one per chunk, all in the file
            double chunks = tiled || h.tileWidth > 0
                                ? double((h.width + std::max<int64_t>(h.tileWidth, 1) - 1) /
                                         std::max<int64_t>(h.tileWidth, 1)) *
                                      double((h.height + std::max<int64_t>(h.tileHeight, 1) - 1) /
                                             std::max<int64_t>(h.tileHeight, 1))
                                : double((h.height + LinesPerChunk(h.compression) - 1) /
                                         LinesPerChunk(h.compression));
            if (chunks * 8 > double(fileSize))
                HeaderReader::Fail("its data window of " + std::to_string(h.width) + " x " +
                                   std::to_string(h.height) +
                                   " pixels has more chunks than the file has room for");
            // What reading it takes: the samples as kiln holds them (4-byte floats), as OpenEXR
            // holds them, and OpenEXR's line buffers (a chunk's lines of the window's width)
            ExrHeaderSize size;
            size.width = h.width, size.height = h.height, size.channels = h.channels;
            size.bytes = std::max(
                {double(h.width) * double(h.height) * 4.0 * h.channels,
                 double(h.width) * double(h.height) * double(h.sampleBytes),
                 double(h.width) * double(h.sampleBytes) * double(LinesPerChunk(h.compression))});
            if (size.bytes > largest.bytes) largest = size;
        }
        if (!multipart) break;
        if (part > 1000) HeaderReader::Fail("more than 1000 parts");
    }
    return largest;
}

}  // namespace kiln
