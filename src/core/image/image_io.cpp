// Image input and output: EXR through kiln's OpenEXR codec, PNG without transparency through
// libpng, everything else through the OpenImageIO plugin (image_codec.h); atomic writes.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <new>

#include "base/atomic_file.h"
#include "base/file_reading.h"
#include "base/memory_budget.h"
#include "base/plugin.h"
#include "base/rng.h"
#include "base/system_memory.h"
#include "core/image/image.h"
#include "core/image/image_codec.h"
#include "core/image/jpeg_codec.h"
#include "core/image/pfm_codec.h"
#include "core/image/png_codec.h"
#include "core/image/tga_codec.h"
#include "spectral/color.h"

namespace kiln {

namespace {

[[noreturn]] void Fail(const std::string& filename, const std::string& reason) {
    throw std::runtime_error(filename + ": " + reason);
}

// An EXR file: named .exr, or starting with OpenEXR's magic number (76 2f 31 01)
bool IsExrFile(const std::string& filename) {
    if (FileExtension(filename) == "exr") return true;
    unsigned char magic[4] = {};
    if (FILE* f = std::fopen(filename.c_str(), "rb")) {
        size_t n = std::fread(magic, 1, 4, f);
        std::fclose(f);
        return n == 4 && magic[0] == 0x76 && magic[1] == 0x2f && magic[2] == 0x31 &&
               magic[3] == 0x01;
    }
    return false;
}

// Encoding an 8-bit file declares through OIIO's "oiio:ColorSpace" (sRGB if none).
ColorEncoding FileEncoding(const std::string& cs) {
    std::string lower = cs;
    for (char& c : lower) c = char(std::tolower((unsigned char)c));
    if (lower == "linear" || lower == "lin_srgb" || lower == "scene_linear")
        return ColorEncoding::Linear();
    if (lower.rfind("gamma", 0) == 0) {
        double g = std::atof(lower.c_str() + 5);
        if (g > 0 && std::isfinite(g)) return ColorEncoding::Gamma(Float(g));
    }
    return ColorEncoding::SRGB();
}

}  // namespace

bool IsPbrtV4SrgbOnlyFormat(const std::string& filename) {
    static constexpr std::string_view kStbFormats[] = {"jpg", "jpeg", "tga", "bmp", "gif",
                                                       "psd", "pic",  "pnm", "ppm", "pgm"};
    std::string ext = FileExtension(filename);
    return std::find(std::begin(kStbFormats), std::end(kStbFormats), ext) != std::end(kStbFormats);
}

namespace {

// The named colour space whose chromaticities match (within 1e-3), if any.
const RGBColorSpace* MatchColorSpace(const float c[8]) {
    for (std::string_view name : RGBColorSpace::Names()) {
        const RGBColorSpace* cs = RGBColorSpace::GetNamed(name);
        if (!cs) continue;
        Point2f pts[4] = {cs->r, cs->g, cs->b, cs->w};
        bool match = true;
        for (int i = 0; i < 4; ++i)
            match = match && std::abs(pts[i].x - c[2 * i]) < 1e-3f &&
                    std::abs(pts[i].y - c[2 * i + 1]) < 1e-3f;
        if (match) return cs;
    }
    return nullptr;
}

// The metadata key of the checksum kiln writes with an EXR's samples, and its value: the sum
// of one hash per channel (of its name and samples), as EXR files store channels by name and
// readers may return them in another order
constexpr char kChecksumKey[] = "kiln:checksum";
std::string SampleChecksum(const void* data, size_t pixels,
                           const std::vector<std::string>& channels, size_t sampleBytes) {
    uint64_t sum = 0;
    size_t nc = channels.size();
    std::vector<unsigned char> channel(pixels * sampleBytes);
    auto bytes = static_cast<const unsigned char*>(data);
    for (size_t c = 0; c < nc; ++c) {
        for (size_t i = 0; i < pixels; ++i)
            std::memcpy(&channel[i * sampleBytes], bytes + (i * nc + c) * sampleBytes, sampleBytes);
        sum += HashLargeBytes(channel.data(), channel.size(), HashString(channels[c]));
    }
    char hex[17];
    std::snprintf(hex, sizeof(hex), "%016llx", static_cast<unsigned long long>(sum));
    return hex;
}

}  // namespace

const ImageCodec& OIIOCodec() {
    static const ImageCodec* const codec = [] {
        using Factory = const ImageCodec* (*)();
        return reinterpret_cast<Factory>(PluginSymbol("libkiln_oiio.so", kOIIOCodecSymbol))();
    }();
    return *codec;
}

std::vector<float> NamedColorMap(const std::string& name, const std::vector<float>& values) {
    using ColorMap = void (*)(const char*, const float*, size_t, float*);
    auto map = reinterpret_cast<ColorMap>(PluginSymbol("libkiln_oiio.so", kOIIOColorMapSymbol));
    std::vector<float> rgb(3 * values.size());
    map(name.c_str(), values.data(), values.size(), rgb.data());
    return rgb;
}

// Image Reading
Image Image::Read(const std::string& filename, ImageMetadata* metadata,
                  std::optional<ColorEncoding> encoding, MemoryBudget* budget) {
    std::string notRegular;
    if (!IsRegularFile(filename, &notRegular)) Fail(filename, notRegular);  // e.g. /dev/zero
    // A header may claim any size: what reading the pixels takes is checked before they are
    // read (an OpenEXR file's before OpenEXR itself allocates it)
    auto charge = [&](int64_t width, int64_t height, int channels, double bytes) {
        std::string pixels = std::to_string(width) + " x " + std::to_string(height) + " pixels";
        if (budget)
            budget->Charge(bytes, "image \"" + filename + "\" (" + pixels + ", " +
                                      std::to_string(channels) + " channels)");
        else if (double memory = PhysicalMemoryBytes(); memory > 0 && bytes > memory / 2)
            Fail(filename, pixels + " would take " + FormatBytes(bytes) + " of memory");
    };
    std::unique_ptr<ImageFileReader> in;
    bool charged = false;
    try {
        if (IsExrFile(filename)) {
            ExrHeaderSize size = CheckExrFile(filename);
            charge(size.width, size.height, size.channels, size.bytes);
            charged = true;
            in = ExrCodec().Open(filename);
        } else if (!(in = OpenPng(filename)) && !(in = OpenPfm(filename)) &&
                   !(in = OpenTga(filename)) && !(in = OpenJpeg(filename))) {
            in = OIIOCodec().Open(filename);
        }
    } catch (const MemoryLimitError&) {
        throw;
    } catch (const std::runtime_error& e) {
        Fail(filename, e.what());
    } catch (const std::bad_alloc&) {  // a codec's own allocation for what a header states
        Fail(filename, "out of memory opening it (its header states more than there is)");
    }
    const ImageFileSpec& spec = in->Spec();
    int nc = int(spec.channelNames.size());
    if (spec.width <= 0 || spec.height <= 0 || nc <= 0) Fail(filename, "empty image");
    if (!charged) {
        // As stored: 8-bit data stay 8-bit, half stays half, the rest become floats
        double sampleBytes = spec.type == SampleType::U8     ? 1
                             : spec.type == SampleType::Half ? 2
                                                             : 4;
        charge(spec.width, spec.height, nc, double(spec.width) * spec.height * nc * sampleBytes);
    }
    Point2i res(spec.width, spec.height);
    ColorEncoding enc = encoding ? *encoding : FileEncoding(spec.colorSpace);
    if (spec.type == SampleType::U8 && IsPbrtV4SrgbOnlyFormat(filename))
        enc = ColorEncoding::SRGB();
    Image image;
    size_t n = size_t(res.x) * res.y * nc;
    try {
        if (spec.type == SampleType::U8) {
            image = Image(PixelFormat::U256, res, spec.channelNames, enc);
            in->Read(SampleType::U8, image.p8.data());
        } else if (spec.type == SampleType::Half) {
            image = Image(PixelFormat::Half, res, spec.channelNames);
            in->Read(SampleType::Half, image.p16.data());
        } else {
            image = Image(PixelFormat::Float, res, spec.channelNames);
            in->Read(SampleType::Float, image.p32.data());
            // Integer data other than 8 bit: normalised to [0, 1] by the reader, then decoded
            if (spec.type == SampleType::U16)
                for (size_t i = 0; i < n; ++i) image.p32[i] = enc.ToLinear(image.p32[i]);
        }
    } catch (const std::runtime_error& e) {
        Fail(filename, e.what());
    } catch (const std::bad_alloc&) {
        Fail(filename, "out of memory reading its pixels");
    }
    // A file kiln wrote: its samples as written (a changed byte in an uncompressed or
    // recompressed block would otherwise be read as a valid pixel)
    if (auto sum = spec.strings.find(kChecksumKey); sum != spec.strings.end()) {
        const void* data = spec.type == SampleType::U8     ? (const void*)image.p8.data()
                           : spec.type == SampleType::Half ? (const void*)image.p16.data()
                                                           : (const void*)image.p32.data();
        size_t sampleBytes = spec.type == SampleType::U8     ? 1
                             : spec.type == SampleType::Half ? 2
                                                             : 4;
        if (spec.type == SampleType::U16 ||
            SampleChecksum(data, size_t(res.x) * size_t(res.y), spec.channelNames, sampleBytes) !=
                sum->second)
            Fail(filename, "damaged: its pixels do not match the checksum kiln wrote with them");
    }

    if (metadata) {
        *metadata = ImageMetadata();
        metadata->renderTimeSeconds = spec.renderTimeSeconds;
        metadata->samplesPerPixel = spec.samplesPerPixel;
        metadata->fullResolution = Point2i(spec.fullWidth, spec.fullHeight);
        metadata->pixelBounds =
            Bounds2i{Point2i(spec.x, spec.y), Point2i(spec.x + spec.width, spec.y + spec.height)};
        if (spec.chromaticities)
            metadata->colorSpace = MatchColorSpace(spec.chromaticities->data());
        metadata->cameraFromWorld = spec.worldToCamera;
        metadata->NDCFromWorld = spec.worldToNDC;
        metadata->strings = spec.strings;
    }
    return image;
}

// Image Writing
bool CanWriteImageFormat(const std::string& ext) {
    if (ext == "exr" || ext == "png" || ext == "pfm") return true;
    if (ext.empty()) return false;
    return OIIOCodec().CanEncode(ext);
}

void Image::Write(const std::string& filename, const ImageMetadata& metadata) const {
    std::string ext = FileExtension(filename);
    if (ext.empty()) Fail(filename, "no file extension to choose the format");
    if (!*this) Fail(filename, "empty image");
    Image out = *this;
    SampleType type = SampleType::U8;
    bool isExr = ext == "exr";
    if (isExr) {
        if (format == PixelFormat::Float) {
            type = SampleType::Float;
        } else {
            out = ConvertToFormat(PixelFormat::Half);
            type = SampleType::Half;
        }
    } else if (ext == "hdr" || ext == "pfm") {
        // RGB (or a single channel) as float.
        if (NChannels() != 1 && NChannels() != 3) {
            if (ChannelIndex("R") < 0 || ChannelIndex("G") < 0 || ChannelIndex("B") < 0)
                Fail(filename, "needs 1 channel or R, G, B channels");
            out = SelectChannels({"R", "G", "B"});
        }
        out = out.ConvertToFormat(PixelFormat::Float);
        type = SampleType::Float;
    } else if ((ext == "tif" || ext == "tiff") && format != PixelFormat::U256) {
        out = ConvertToFormat(PixelFormat::Float);
        type = SampleType::Float;
    } else {
        // 8-bit formats: floating-point data are sRGB encoded.
        if (format != PixelFormat::U256) out = ConvertToFormat(PixelFormat::U256);
        type = SampleType::U8;
    }

    ImageFileSpec spec;
    spec.width = out.resolution.x;
    spec.height = out.resolution.y;
    spec.channelNames = out.channelNames;
    spec.type = type;
    if (type == SampleType::U8) {
        const ColorEncoding& e = out.encoding;
        if (e.GetKind() == ColorEncoding::Kind::Linear)
            spec.colorSpace = "Linear";
        else if (e.GetKind() == ColorEncoding::Kind::SRGB)
            spec.colorSpace = "sRGB";
        else
            spec.colorSpace = "Gamma" + std::to_string(e.GammaValue());
    }
    if (isExr) {
        if (metadata.fullResolution) {
            spec.fullWidth = metadata.fullResolution->x;
            spec.fullHeight = metadata.fullResolution->y;
        }
        if (metadata.pixelBounds) {
            spec.x = metadata.pixelBounds->pMin.x;
            spec.y = metadata.pixelBounds->pMin.y;
        }
    }
    spec.renderTimeSeconds = metadata.renderTimeSeconds;
    spec.samplesPerPixel = metadata.samplesPerPixel;
    if (metadata.colorSpace) {
        const RGBColorSpace& cs = *metadata.colorSpace;
        spec.chromaticities = {cs.r.x, cs.r.y, cs.g.x, cs.g.y, cs.b.x, cs.b.y, cs.w.x, cs.w.y};
    }
    spec.worldToCamera = metadata.cameraFromWorld;
    spec.worldToNDC = metadata.NDCFromWorld;
    spec.strings = metadata.strings;

    const void* data = type == SampleType::U8     ? (const void*)out.p8.data()
                       : type == SampleType::Half ? (const void*)out.p16.data()
                                                  : (const void*)out.p32.data();
    // An EXR carries the checksum of its samples, which Image::Read verifies
    if (isExr)
        spec.strings[kChecksumKey] =
            SampleChecksum(data, size_t(spec.width) * size_t(spec.height), spec.channelNames,
                           type == SampleType::Half ? 2 : 4);
    else
        spec.strings.erase(kChecksumKey);
    // Encoded in memory, then written beside the target and renamed over it only once written,
    // flushed and closed: a full disk is an error and leaves an existing file untouched
    std::string bytes;
    try {
        if (isExr)
            bytes = ExrCodec().Encode(ext, spec, data);
        else if (ext == "png" && PngWriterHandles(spec))
            bytes = EncodePng(spec, data);
        else if (ext == "pfm" && PfmWriterHandles(spec))
            bytes = EncodePfm(spec, data);
        else
            bytes = OIIOCodec().Encode(ext, spec, data);
    } catch (const std::runtime_error& e) {
        Fail(filename, e.what());
    }
    RemoveStaleTemporaries(filename);
    WriteFileAtomically(filename, bytes);
}

}  // namespace kiln
