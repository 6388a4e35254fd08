// Image input and output through OpenImageIO; atomic writes.
#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <Imath/half.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>

#include "core/base/file_reading.h"
#include "core/base/system_memory.h"
#include "core/image/image.h"

#include "core/base/memory_budget.h"
#include "spectral/color.h"

namespace kiln {

namespace {

[[noreturn]] void Fail(const std::string& filename, const std::string& reason) {
    throw std::runtime_error(filename + ": " + reason);
}

std::string OIIOError(const std::string& fallback) {
    std::string e = OIIO::geterror();
    return e.empty() ? fallback : e;
}

// Encoding an 8-bit file declares through OIIO's "oiio:ColorSpace" (sRGB if none).
ColorEncoding FileEncoding(const OIIO::ImageSpec& spec) {
    std::string cs = spec.get_string_attribute("oiio:ColorSpace");
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

// A unique temporary name in the directory of `filename`, keeping its extension. The stem is
// shortened where needed so that the name fits the file-name limit whenever `filename` does.
std::string TemporaryName(const std::string& filename) {
    namespace fs = std::filesystem;
    fs::path p(filename);
    std::random_device rd;
    uint64_t r = (uint64_t(rd()) << 32) ^ rd();
    std::string suffix =
        ".tmp" + std::to_string(getpid()) + "_" + std::to_string(r) + p.extension().string();
    std::string stem = p.stem().string();
    constexpr size_t kMaxName = 255;  // NAME_MAX on Linux file systems
    if (1 + stem.size() + suffix.size() > kMaxName)
        stem.resize(kMaxName > 1 + suffix.size() ? kMaxName - 1 - suffix.size() : 0);
    return (p.parent_path() / ("." + stem + suffix)).string();
}

// The temporary file Image::Write is writing, for RemovePendingTemporaryFile (read from a
// signal handler: a fixed buffer and a lock-free flag)
char pendingTemporary[4096];
std::atomic<bool> hasPendingTemporary{false};

void SetPendingTemporary(const std::string& tmp) {
    hasPendingTemporary.store(false);
    if (tmp.size() >= sizeof(pendingTemporary)) return;
    std::memcpy(pendingTemporary, tmp.c_str(), tmp.size() + 1);
    hasPendingTemporary.store(true);
}

}  // namespace

void RemovePendingTemporaryFile() noexcept {
    if (hasPendingTemporary.load()) unlink(pendingTemporary);
}

// Image Reading
Image Image::Read(const std::string& filename, ImageMetadata* metadata,
                  std::optional<ColorEncoding> encoding, MemoryBudget* budget) {
    std::string notRegular;
    if (!IsRegularFile(filename, &notRegular)) Fail(filename, notRegular);  // e.g. /dev/zero
    auto in = OIIO::ImageInput::open(filename);
    if (!in) Fail(filename, OIIOError("cannot open"));
    const OIIO::ImageSpec& spec = in->spec();
    int nc = spec.nchannels;
    if (spec.width <= 0 || spec.height <= 0 || nc <= 0) Fail(filename, "empty image");
    // A header may claim any size: check what the pixels would take before reading them
    double bytes = double(spec.width) * spec.height * nc * sizeof(float);
    if (budget)
        budget->Charge(bytes, "image \"" + filename + "\" (" + std::to_string(spec.width) + " x " +
                                  std::to_string(spec.height) + " pixels, " + std::to_string(nc) +
                                  " channels)");
    else if (double memory = PhysicalMemoryBytes(); memory > 0 && bytes > memory / 2)
        Fail(filename, std::to_string(spec.width) + " x " + std::to_string(spec.height) +
                           " pixels would take " + FormatBytes(bytes) + " of memory");
    std::vector<std::string> names;
    for (int c = 0; c < nc; ++c) {
        std::string n = c < int(spec.channelnames.size()) ? spec.channelnames[c] : "";
        if (n.empty()) n = std::string("C").append(std::to_string(c));
        names.push_back(n);
    }
    Point2i res(spec.width, spec.height);
    OIIO::TypeDesc::BASETYPE bt = OIIO::TypeDesc::BASETYPE(spec.format.basetype);
    ColorEncoding enc = encoding ? *encoding : FileEncoding(spec);
    Image image;
    size_t n = size_t(res.x) * res.y * nc;
    if (bt == OIIO::TypeDesc::UINT8) {
        image = Image(PixelFormat::U256, res, names, enc);
        if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::UINT8, image.p8.data()))
            Fail(filename, in->geterror());
    } else if (bt == OIIO::TypeDesc::HALF) {
        image = Image(PixelFormat::Half, res, names);
        if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::HALF, image.p16.data()))
            Fail(filename, in->geterror());
    } else if (bt == OIIO::TypeDesc::UINT16 || bt == OIIO::TypeDesc::INT8 ||
               bt == OIIO::TypeDesc::INT16) {
        // Integer data other than 8 bit: normalised by OIIO to [0, 1], then decoded.
        image = Image(PixelFormat::Float, res, names);
        if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, image.p32.data()))
            Fail(filename, in->geterror());
        for (size_t i = 0; i < n; ++i) image.p32[i] = enc.ToLinear(image.p32[i]);
    } else {
        image = Image(PixelFormat::Float, res, names);
        if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, image.p32.data()))
            Fail(filename, in->geterror());
    }

    if (metadata) {
        *metadata = ImageMetadata();
        if (float t; spec.getattribute("renderTimeSeconds", OIIO::TypeFloat, &t))
            metadata->renderTimeSeconds = t;
        if (int spp; spec.getattribute("samplesPerPixel", OIIO::TypeInt, &spp))
            metadata->samplesPerPixel = spp;
        metadata->fullResolution = Point2i(spec.full_width, spec.full_height);
        metadata->pixelBounds = Bounds2i{
            Point2i(spec.x - spec.full_x, spec.y - spec.full_y),
            Point2i(spec.x - spec.full_x + spec.width, spec.y - spec.full_y + spec.height)};
        if (float c[8];
            spec.getattribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), c))
            metadata->colorSpace = MatchColorSpace(c);
        std::array<float, 16> m;
        if (spec.getattribute("worldToCamera", OIIO::TypeMatrix44, m.data()))
            metadata->cameraFromWorld = m;
        if (spec.getattribute("worldToNDC", OIIO::TypeMatrix44, m.data()))
            metadata->NDCFromWorld = m;
        for (const OIIO::ParamValue& p : spec.extra_attribs)
            if (p.type() == OIIO::TypeString) metadata->strings[p.name().string()] = p.get_string();
    }
    return image;
}

// Image Writing
void Image::Write(const std::string& filename, const ImageMetadata& metadata) const {
    std::string ext = FileExtension(filename);
    if (ext.empty()) Fail(filename, "no file extension to choose the format");
    if (!*this) Fail(filename, "empty image");
    Image out = *this;
    OIIO::TypeDesc type = OIIO::TypeDesc::UINT8;
    bool isExr = ext == "exr";
    if (isExr) {
        if (format == PixelFormat::Float) {
            type = OIIO::TypeDesc::FLOAT;
        } else {
            out = ConvertToFormat(PixelFormat::Half);
            type = OIIO::TypeDesc::HALF;
        }
    } else if (ext == "hdr" || ext == "pfm") {
        // RGB (or a single channel) as float.
        if (NChannels() != 1 && NChannels() != 3) {
            if (ChannelIndex("R") < 0 || ChannelIndex("G") < 0 || ChannelIndex("B") < 0)
                Fail(filename, "needs 1 channel or R, G, B channels");
            out = SelectChannels({"R", "G", "B"});
        }
        out = out.ConvertToFormat(PixelFormat::Float);
        type = OIIO::TypeDesc::FLOAT;
    } else if ((ext == "tif" || ext == "tiff") && format != PixelFormat::U256) {
        out = ConvertToFormat(PixelFormat::Float);
        type = OIIO::TypeDesc::FLOAT;
    } else {
        // 8-bit formats: floating-point data are sRGB encoded.
        if (format != PixelFormat::U256) out = ConvertToFormat(PixelFormat::U256);
        type = OIIO::TypeDesc::UINT8;
    }

    OIIO::ImageSpec spec(out.resolution.x, out.resolution.y, out.NChannels(), type);
    spec.channelnames = out.channelNames;
    spec.alpha_channel = out.ChannelIndex("A");
    spec.z_channel = out.ChannelIndex("Z");
    if (type == OIIO::TypeDesc::UINT8) {
        const ColorEncoding& e = out.encoding;
        if (e.GetKind() == ColorEncoding::Kind::Linear)
            spec.attribute("oiio:ColorSpace", "Linear");
        else if (e.GetKind() == ColorEncoding::Kind::SRGB)
            spec.attribute("oiio:ColorSpace", "sRGB");
        else
            spec.attribute("oiio:ColorSpace", "Gamma" + std::to_string(e.GammaValue()));
    }
    if (isExr) {
        spec.attribute("compression", "zip");
        if (metadata.fullResolution) {
            spec.full_width = metadata.fullResolution->x;
            spec.full_height = metadata.fullResolution->y;
        }
        if (metadata.pixelBounds) {
            spec.x = metadata.pixelBounds->pMin.x;
            spec.y = metadata.pixelBounds->pMin.y;
        }
    }
    if (metadata.renderTimeSeconds)
        spec.attribute("renderTimeSeconds", *metadata.renderTimeSeconds);
    if (metadata.samplesPerPixel) spec.attribute("samplesPerPixel", *metadata.samplesPerPixel);
    if (metadata.colorSpace) {
        const RGBColorSpace& cs = *metadata.colorSpace;
        float c[8] = {cs.r.x, cs.r.y, cs.g.x, cs.g.y, cs.b.x, cs.b.y, cs.w.x, cs.w.y};
        spec.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), c);
    }
    if (metadata.cameraFromWorld)
        spec.attribute("worldToCamera", OIIO::TypeMatrix44, metadata.cameraFromWorld->data());
    if (metadata.NDCFromWorld)
        spec.attribute("worldToNDC", OIIO::TypeMatrix44, metadata.NDCFromWorld->data());
    for (const auto& [k, v] : metadata.strings) spec.attribute(k, v);

    auto output = OIIO::ImageOutput::create(ext);
    if (!output) Fail(filename, OIIOError("no writer for ." + ext + " files"));
    const void* data = type == OIIO::TypeDesc::UINT8  ? (const void*)out.p8.data()
                       : type == OIIO::TypeDesc::HALF ? (const void*)out.p16.data()
                                                      : (const void*)out.p32.data();
    std::string tmp = TemporaryName(filename);
    std::error_code ec;
    SetPendingTemporary(tmp);
    struct Done {
        ~Done() { hasPendingTemporary.store(false); }
    } done;
    if (!output->open(tmp, spec)) {
        std::string err = output->geterror();
        std::filesystem::remove(tmp, ec);
        Fail(filename, err.empty() ? "cannot open for writing" : err);
    }
    bool ok = output->write_image(type, data);
    std::string err = ok ? "" : output->geterror();
    if (!output->close() && ok) {
        ok = false;
        err = output->geterror();
    }
    output.reset();
    if (!ok) {
        std::filesystem::remove(tmp, ec);
        Fail(filename, err.empty() ? "write failed" : err);
    }
    std::filesystem::rename(tmp, filename, ec);
    if (ec) {
        std::string msg = ec.message();
        std::filesystem::remove(tmp, ec);
        Fail(filename, "cannot rename temporary file: " + msg);
    }
}

}  // namespace kiln
