// The OpenImageIO plugin (libkiln_oiio.so): every image format but EXR, read and written
// through OpenImageIO (see ../image_codec.h). Loaded by OIIOCodec() on first use; it uses
// nothing of kiln but the plain types of image_codec.h.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/image/image_codec.h"

namespace kiln {

namespace {

std::string OIIOError(const std::string& error, const std::string& fallback) {
    return error.empty() ? fallback : error;
}

OIIO::TypeDesc ToOIIO(SampleType t) {
    switch (t) {
        case SampleType::U8:
            return OIIO::TypeDesc::UINT8;
        case SampleType::U16:
            return OIIO::TypeDesc::UINT16;
        case SampleType::Half:
            return OIIO::TypeDesc::HALF;
        case SampleType::Float:
            return OIIO::TypeDesc::FLOAT;
    }
    return OIIO::TypeDesc::FLOAT;
}

class OIIOReader final : public ImageFileReader {
  public:
    explicit OIIOReader(std::unique_ptr<OIIO::ImageInput> in) : in(std::move(in)) {
        const OIIO::ImageSpec& s = this->in->spec();
        spec.width = s.width;
        spec.height = s.height;
        for (int c = 0; c < s.nchannels; ++c) {
            std::string n = c < int(s.channelnames.size()) ? s.channelnames[c] : "";
            if (n.empty()) {
                n = 'C';
                n += std::to_string(c);
            }
            spec.channelNames.push_back(n);
        }
        switch (OIIO::TypeDesc::BASETYPE(s.format.basetype)) {
            case OIIO::TypeDesc::UINT8:
                spec.type = SampleType::U8;
                break;
            case OIIO::TypeDesc::HALF:
                spec.type = SampleType::Half;
                break;
            case OIIO::TypeDesc::UINT16:
            case OIIO::TypeDesc::INT8:
            case OIIO::TypeDesc::INT16:
                spec.type = SampleType::U16;
                break;
            default:
                spec.type = SampleType::Float;
        }
        spec.fullWidth = s.full_width;
        spec.fullHeight = s.full_height;
        spec.x = s.x - s.full_x;
        spec.y = s.y - s.full_y;
        spec.colorSpace = s.get_string_attribute("oiio:ColorSpace");
        if (float t; s.getattribute("renderTimeSeconds", OIIO::TypeFloat, &t))
            spec.renderTimeSeconds = t;
        if (int spp; s.getattribute("samplesPerPixel", OIIO::TypeInt, &spp))
            spec.samplesPerPixel = spp;
        if (std::array<float, 8> c;
            s.getattribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), c.data()))
            spec.chromaticities = c;
        if (std::array<float, 16> m; s.getattribute("worldToCamera", OIIO::TypeMatrix44, m.data()))
            spec.worldToCamera = m;
        if (std::array<float, 16> m; s.getattribute("worldToNDC", OIIO::TypeMatrix44, m.data()))
            spec.worldToNDC = m;
        for (const OIIO::ParamValue& p : s.extra_attribs)
            if (p.type() == OIIO::TypeString) spec.strings[p.name().string()] = p.get_string();
    }

    const ImageFileSpec& Spec() const override { return spec; }

    void Read(SampleType type, void* data) override {
        // Integer data other than 8 bit are normalised by OpenImageIO to [0, 1] as floats
        if (!in->read_image(0, 0, 0, int(spec.channelNames.size()), ToOIIO(type), data))
            throw std::runtime_error(OIIOError(in->geterror(), "read failed"));
    }

  private:
    std::unique_ptr<OIIO::ImageInput> in;
    ImageFileSpec spec;
};

class OIIOImageCodec final : public ImageCodec {
  public:
    std::unique_ptr<ImageFileReader> Open(const std::string& filename) const override {
        // Colours as stored, not multiplied by alpha (OpenImageIO's default for formats with
        // unassociated alpha such as PNG and TGA): pbrt-v4 reads them unpremultiplied
        OIIO::ImageSpec config;
        config.attribute("oiio:UnassociatedAlpha", 1);
        auto in = OIIO::ImageInput::open(filename, &config);
        if (!in) throw std::runtime_error(OIIOError(OIIO::geterror(), "cannot open"));
        return std::make_unique<OIIOReader>(std::move(in));
    }

    bool CanEncode(const std::string& format) const override {
        // OpenImageIO finds its writer by the file name's extension
        return format.find_first_of("/.") == std::string::npos &&
               OIIO::ImageOutput::create("kiln-format-check." + format) != nullptr;
    }

    std::string Encode(const std::string& format, const ImageFileSpec& spec,
                       const void* data) const override {
        const int nc = int(spec.channelNames.size());
        OIIO::ImageSpec s(spec.width, spec.height, nc, ToOIIO(spec.type));
        s.channelnames = spec.channelNames;
        for (int c = 0; c < nc; ++c) {
            if (spec.channelNames[c] == "A") s.alpha_channel = c;  // colours not premultiplied
            if (spec.channelNames[c] == "Z") s.z_channel = c;
        }
        s.attribute("oiio:UnassociatedAlpha", 1);  // as Read takes them
        if (!spec.colorSpace.empty()) s.attribute("oiio:ColorSpace", spec.colorSpace);
        if (spec.renderTimeSeconds) s.attribute("renderTimeSeconds", *spec.renderTimeSeconds);
        if (spec.samplesPerPixel) s.attribute("samplesPerPixel", *spec.samplesPerPixel);
        if (spec.chromaticities)
            s.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8),
                        spec.chromaticities->data());
        if (spec.worldToCamera)
            s.attribute("worldToCamera", OIIO::TypeMatrix44, spec.worldToCamera->data());
        if (spec.worldToNDC) s.attribute("worldToNDC", OIIO::TypeMatrix44, spec.worldToNDC->data());
        for (const auto& [k, v] : spec.strings) s.attribute(k, v);

        auto out = OIIO::ImageOutput::create(format);
        if (!out)
            throw std::runtime_error(
                OIIOError(OIIO::geterror(), "no writer for ." + format + " files"));
        // Into memory through an I/O proxy. OpenImageIO 2.4's TIFF writer makes broken files
        // that way (small images lack "ImageLength"), and some writers take no proxy: those
        // write a private temporary file, read back. Either way the bytes must decode.
        std::string bytes;
        if (out->supports("ioproxy")) {
            MemoryOutput proxy;
            out->set_ioproxy(&proxy);
            WriteImage(*out, "memory." + format, s, spec, data);
            bytes = std::move(proxy.bytes);
        }
        if (!Decodes(format, bytes, spec)) {
            bytes = EncodeThroughFile(format, s, spec, data);
            if (!Decodes(format, bytes, spec))
                throw std::runtime_error("OpenImageIO's ." + format +
                                         " writer made a file that does not read back");
        }
        return bytes;
    }

  private:
    // An OpenImageIO output (and read-back) proxy into memory
    class MemoryOutput final : public OIIO::Filesystem::IOProxy {
      public:
        MemoryOutput() : IOProxy("memory", Write) {}
        const char* proxytype() const override { return "kiln-memory"; }
        size_t read(void* buf, size_t size) override {
            size_t n = pread(buf, size, m_pos);
            m_pos += int64_t(n);
            return n;
        }
        size_t write(const void* buf, size_t size) override {
            size_t n = pwrite(buf, size, m_pos);
            m_pos += int64_t(n);
            return n;
        }
        size_t pread(void* buf, size_t size, int64_t offset) override {
            if (offset < 0 || size == 0 || size_t(offset) >= bytes.size()) return 0;
            size_t n = std::min(size, bytes.size() - size_t(offset));
            std::memcpy(buf, bytes.data() + offset, n);
            return n;
        }
        size_t pwrite(const void* buf, size_t size, int64_t offset) override {
            // (OpenImageIO's TGA and BMP writers also write nothing from a null buffer)
            if (offset < 0 || size == 0) return 0;
            if (size_t(offset) + size > bytes.size()) bytes.resize(size_t(offset) + size);
            std::memcpy(bytes.data() + offset, buf, size);
            return size;
        }
        size_t size() const override { return bytes.size(); }
        std::string bytes;
    };

    static void WriteImage(OIIO::ImageOutput& out, const std::string& name,
                           const OIIO::ImageSpec& s, const ImageFileSpec& spec, const void* data) {
        if (!out.open(name, s))
            throw std::runtime_error(OIIOError(out.geterror(), "cannot encode"));
        bool ok = out.write_image(ToOIIO(spec.type), data);
        std::string err = ok ? "" : out.geterror();
        if (!out.close() && ok) {
            ok = false;
            err = out.geterror();
        }
        if (!ok) throw std::runtime_error(OIIOError(err, "cannot encode"));
    }

    // Through a file of kiln's own (created exclusively in the temporary folder), read back
    static std::string EncodeThroughFile(const std::string& format, const OIIO::ImageSpec& s,
                                         const ImageFileSpec& spec, const void* data) {
        std::string pattern =
            (std::filesystem::temp_directory_path() / "kiln-encode-XXXXXX.").string() + format;
        std::vector<char> name(pattern.begin(), pattern.end());
        name.push_back('\0');
        int fd = mkstemps(name.data(), int(format.size()) + 1);
        if (fd < 0) throw std::runtime_error("cannot create a temporary file to encode into");
        close(fd);
        std::string file(name.data());
        struct Remove {
            const std::string& file;
            ~Remove() { unlink(file.c_str()); }
        } remove{file};
        auto out = OIIO::ImageOutput::create(format);
        WriteImage(*out, file, s, spec, data);
        std::ifstream in(file, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }

    // Whether bytes are a whole image of spec's size and channels
    static bool Decodes(const std::string& format, const std::string& bytes,
                        const ImageFileSpec& spec) {
        if (bytes.empty()) return false;
        OIIO::Filesystem::IOMemReader reader(bytes.data(), bytes.size());
        OIIO::ImageSpec config;
        OIIO::Filesystem::IOProxy* proxy = &reader;
        config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
        auto in = OIIO::ImageInput::open("memory." + format, &config);
        if (!in) return false;
        const OIIO::ImageSpec& s = in->spec();
        int nc = int(spec.channelNames.size());
        if (s.width != spec.width || s.height != spec.height || s.nchannels != nc) return false;
        std::vector<float> pixels(size_t(s.width) * size_t(s.height) * size_t(nc));
        return in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, pixels.data());
    }
};

}  // namespace

}  // namespace kiln

extern "C" const kiln::ImageCodec* KilnOIIOImageCodec() {
    static const kiln::OIIOImageCodec codec;
    return &codec;
}

extern "C" void KilnOIIOColorMap(const char* name, const float* values, size_t n, float* rgb) {
    if (n == 0) return;
    OIIO::ImageBuf in(OIIO::ImageSpec(int(n), 1, 1, OIIO::TypeDesc::FLOAT));
    in.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, values);
    OIIO::ImageBuf out = OIIO::ImageBufAlgo::color_map(in, 0, name);
    if (out.has_error() || out.nchannels() != 3)
        throw std::runtime_error(std::string("colour map \"") + name + "\": " + out.geterror());
    out.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, rgb);
}
