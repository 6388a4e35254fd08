// OpenEXR files through the OpenEXR library (see image_codec.h). Files are written as
// OpenImageIO wrote them before (ZIP compression, scanlines, the same attribute names), and
// channels are read in OpenImageIO's order, so images read as they did.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfChromaticitiesAttribute.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMatrixAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <set>
#include <stdexcept>

#include "core/image/image_codec.h"

namespace kiln {

namespace {

// OpenImageIO's channel order for EXR files (as OpenImageIO 2.4 reads them; established
// channel by channel with oiiotool): by layer (the part before the last '.'), then the special
// names below in this order, case-insensitive, then by name. Z is a coordinate (after Y) in a
// layer that also has X, else a depth (after the alpha variants).
constexpr const char* kSpecialChannels[] = {
    "r", "red",   "g",  "green", "b",  "blue", "x",  "y",  "z" /* with x */, "real",  "imag",
    "a", "alpha", "ar", "ra",    "ag", "ga",   "ab", "ba", "z" /* depth */,  "depth", "zback"};
constexpr int kCoordinateZ = 8, kDepthZ = 19;

std::string Lower(std::string s) {
    for (char& c : s) c = char(std::tolower((unsigned char)c));
    return s;
}

struct ChannelKey {
    std::string layer, suffix, name;
    int special;
    bool operator<(const ChannelKey& o) const {
        if (layer != o.layer) return layer < o.layer;
        if (special != o.special) return special < o.special;
        return name < o.name;
    }
};

std::vector<std::string> OpenImageIOChannelOrder(const std::vector<std::string>& names) {
    std::vector<ChannelKey> keys;
    std::set<std::string> layersWithX;
    for (const std::string& name : names) {
        size_t dot = name.rfind('.');
        ChannelKey k;
        k.name = name;
        k.layer = dot == std::string::npos ? "" : name.substr(0, dot);
        k.suffix = Lower(dot == std::string::npos ? name : name.substr(dot + 1));
        if (k.suffix == "x") layersWithX.insert(k.layer);
        keys.push_back(k);
    }
    for (ChannelKey& k : keys) {
        k.special = int(std::size(kSpecialChannels));
        for (int i = 0; i < int(std::size(kSpecialChannels)); ++i)
            if (k.suffix == kSpecialChannels[i]) {
                k.special = i;
                break;
            }
        if (k.suffix == "z") k.special = layersWithX.count(k.layer) ? kCoordinateZ : kDepthZ;
    }
    std::sort(keys.begin(), keys.end());
    std::vector<std::string> sorted;
    for (const ChannelKey& k : keys) sorted.push_back(k.name);
    return sorted;
}

Imf::PixelType ExrType(SampleType t) { return t == SampleType::Half ? Imf::HALF : Imf::FLOAT; }

size_t SampleBytes(SampleType t) { return t == SampleType::U8 ? 1 : t == SampleType::Half ? 2 : 4; }

class ExrReader final : public ImageFileReader {
  public:
    explicit ExrReader(const std::string& filename) : file(filename.c_str()) {
        const Imf::Header& h = file.header();
        const Imath::Box2i dw = h.dataWindow(), disp = h.displayWindow();
        spec.width = dw.max.x - dw.min.x + 1;
        spec.height = dw.max.y - dw.min.y + 1;
        spec.fullWidth = disp.max.x - disp.min.x + 1;
        spec.fullHeight = disp.max.y - disp.min.y + 1;
        spec.x = dw.min.x;
        spec.y = dw.min.y;
        spec.x -= disp.min.x;
        spec.y -= disp.min.y;
        std::vector<std::string> names;
        bool allHalf = true;
        for (Imf::ChannelList::ConstIterator c = h.channels().begin(); c != h.channels().end();
             ++c) {
            if (c.channel().xSampling != 1 || c.channel().ySampling != 1)
                throw std::runtime_error(std::string("channel \"") + c.name() +
                                         "\" is subsampled (not supported)");
            allHalf = allHalf && c.channel().type == Imf::HALF;
            names.push_back(c.name());
        }
        if (names.empty()) throw std::runtime_error("no channels");
        spec.channelNames = OpenImageIOChannelOrder(names);
        spec.type = allHalf ? SampleType::Half : SampleType::Float;

        for (Imf::Header::ConstIterator a = h.begin(); a != h.end(); ++a) {
            const std::string name = a.name();
            const Imf::Attribute& attr = a.attribute();
            if (auto* f = dynamic_cast<const Imf::FloatAttribute*>(&attr);
                f && name == "renderTimeSeconds")
                spec.renderTimeSeconds = f->value();
            else if (auto* i = dynamic_cast<const Imf::IntAttribute*>(&attr);
                     i && name == "samplesPerPixel")
                spec.samplesPerPixel = i->value();
            else if (auto* c = dynamic_cast<const Imf::ChromaticitiesAttribute*>(&attr)) {
                const Imf::Chromaticities& v = c->value();
                spec.chromaticities =
                    std::array<float, 8>{v.red.x,  v.red.y,  v.green.x, v.green.y,
                                         v.blue.x, v.blue.y, v.white.x, v.white.y};
            } else if (name == "worldToCamera" || name == "worldToNDC") {
                std::array<float, 16> m;
                if (auto* mf = dynamic_cast<const Imf::M44fAttribute*>(&attr))
                    for (int r = 0; r < 4; ++r)
                        for (int k = 0; k < 4; ++k) m[4 * r + k] = mf->value()[r][k];
                else if (auto* md = dynamic_cast<const Imf::M44dAttribute*>(&attr))
                    for (int r = 0; r < 4; ++r)
                        for (int k = 0; k < 4; ++k) m[4 * r + k] = float(md->value()[r][k]);
                else
                    continue;
                (name == "worldToCamera" ? spec.worldToCamera : spec.worldToNDC) = m;
            } else if (auto* s = dynamic_cast<const Imf::StringAttribute*>(&attr)) {
                spec.strings[name] = s->value();
            }
        }
    }

    const ImageFileSpec& Spec() const override { return spec; }

    void Read(SampleType type, void* data) override {
        if (type != SampleType::Float && type != SampleType::Half)
            throw std::runtime_error("EXR data cannot be read as 8- or 16-bit integers");
        const Imath::Box2i dw = file.header().dataWindow();
        const size_t nc = spec.channelNames.size(), bytes = SampleBytes(type);
        Imf::FrameBuffer fb;
        for (size_t c = 0; c < nc; ++c)
            fb.insert(spec.channelNames[c],
                      Imf::Slice::Make(ExrType(type), static_cast<char*>(data) + c * bytes, dw,
                                       nc * bytes, nc * bytes * size_t(spec.width)));
        try {
            file.setFrameBuffer(fb);
            file.readPixels(dw.min.y, dw.max.y);
        } catch (const std::exception& e) {  // OpenEXR's, e.g. a truncated file
            throw std::runtime_error(e.what());
        }
    }

  private:
    Imf::InputFile file;
    ImageFileSpec spec;
};

class ExrImageCodec final : public ImageCodec {
  public:
    std::unique_ptr<ImageFileReader> Open(const std::string& filename) const override {
        try {
            return std::make_unique<ExrReader>(filename);
        } catch (const std::exception& e) {  // OpenEXR's exceptions say what and where
            throw std::runtime_error(e.what());
        }
    }

    bool CanEncode(const std::string& format) const override { return format == "exr"; }
    std::string Encode(const std::string&, const ImageFileSpec& spec,
                       const void* data) const override {
        try {
            MemoryStream stream;
            Write(stream, spec, data);
            return std::move(stream.bytes);
        } catch (const std::exception& e) {  // OpenEXR's exceptions say what and where
            throw std::runtime_error(e.what());
        }
    }

  private:
    // An OpenEXR output stream into memory (the library seeks back to write the line offsets)
    class MemoryStream final : public Imf::OStream {
      public:
        MemoryStream() : Imf::OStream("memory") {}
        void write(const char c[], int n) override {
            if (position + size_t(n) > bytes.size()) bytes.resize(position + size_t(n));
            std::memcpy(bytes.data() + position, c, size_t(n));
            position += size_t(n);
        }
        uint64_t tellp() override { return position; }
        void seekp(uint64_t p) override { position = size_t(p); }
        std::string bytes;

      private:
        size_t position = 0;
    };

    static void Write(Imf::OStream& stream, const ImageFileSpec& spec, const void* data) {
        if (spec.type != SampleType::Half && spec.type != SampleType::Float)
            throw std::runtime_error("EXR files store half or float samples");
        const int fullW = spec.fullWidth > 0 ? spec.fullWidth : spec.width;
        const int fullH = spec.fullHeight > 0 ? spec.fullHeight : spec.height;
        const Imath::Box2i display({0, 0}, {fullW - 1, fullH - 1});
        const Imath::Box2i dw({spec.x, spec.y},
                              {spec.x + spec.width - 1, spec.y + spec.height - 1});
        Imf::Header h(display, dw, 1.f, Imath::V2f(0, 0), 1.f, Imf::INCREASING_Y,
                      Imf::ZIP_COMPRESSION);
        const size_t nc = spec.channelNames.size(), bytes = SampleBytes(spec.type);
        Imf::FrameBuffer fb;
        for (size_t c = 0; c < nc; ++c) {
            h.channels().insert(spec.channelNames[c], Imf::Channel(ExrType(spec.type)));
            fb.insert(
                spec.channelNames[c],
                Imf::Slice::Make(ExrType(spec.type), static_cast<const char*>(data) + c * bytes, dw,
                                 nc * bytes, nc * bytes * size_t(spec.width)));
        }
        if (spec.renderTimeSeconds)
            h.insert("renderTimeSeconds", Imf::FloatAttribute(*spec.renderTimeSeconds));
        if (spec.samplesPerPixel)
            h.insert("samplesPerPixel", Imf::IntAttribute(*spec.samplesPerPixel));
        if (spec.chromaticities) {
            const std::array<float, 8>& c = *spec.chromaticities;
            h.insert("chromaticities",
                     Imf::ChromaticitiesAttribute(Imf::Chromaticities({c[0], c[1]}, {c[2], c[3]},
                                                                      {c[4], c[5]}, {c[6], c[7]})));
        }
        for (auto [name, m] : {std::pair{"worldToCamera", spec.worldToCamera},
                               std::pair{"worldToNDC", spec.worldToNDC}})
            if (m) {
                Imath::M44f mm;
                for (int r = 0; r < 4; ++r)
                    for (int k = 0; k < 4; ++k) mm[r][k] = (*m)[4 * r + k];
                h.insert(name, Imf::M44fAttribute(mm));
            }
        for (const auto& [k, v] : spec.strings) h.insert(k, Imf::StringAttribute(v));
        Imf::OutputFile out(stream, h);  // its destructor writes the line offsets
        out.setFrameBuffer(fb);
        out.writePixels(spec.height);
    }
};

}  // namespace

const ImageCodec& ExrCodec() {
    static const ExrImageCodec codec;
    return codec;
}

}  // namespace kiln
