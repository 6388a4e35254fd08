#include "core/image/png_codec.h"

#include <png.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace kiln {

namespace {

// Writing. libpng reports errors through longjmp, so RunPngJob keeps no C++ object alive
// across its setjmp: everything it needs is prepared by the caller in this plain struct, and
// the error message comes back in it.
struct PngJob {
    FILE* file;
    int width, height, channels;
    const unsigned char* data;
    int colorKind;  // 0 sRGB, 1 gamma (gamma below; 1 for linear)
    double gamma;
    png_text* texts;
    int nTexts;
    char error[256];
};

void OnError(png_structp png, png_const_charp message) {
    PngJob* job = static_cast<PngJob*>(png_get_error_ptr(png));
    std::snprintf(job->error, sizeof(job->error), "%s", message);
    png_longjmp(png, 1);
}

void OnWarning(png_structp, png_const_charp) {}

bool RunPngJob(PngJob* job) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, job, OnError, OnWarning);
    if (!png) {
        std::snprintf(job->error, sizeof(job->error), "out of memory");
        return false;
    }
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        if (!job->error[0]) std::snprintf(job->error, sizeof(job->error), "out of memory");
        return false;
    }
    png_init_io(png, job->file);
    png_set_IHDR(png, info, png_uint_32(job->width), png_uint_32(job->height), 8,
                 job->channels == 1 ? PNG_COLOR_TYPE_GRAY : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (job->colorKind == 0)
        png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_ABSOLUTE);
    else
        png_set_gAMA(png, info, job->gamma);
    png_set_oFFs(png, info, 0, 0, PNG_OFFSET_PIXEL);
    if (job->nTexts > 0) png_set_text(png, info, job->texts, job->nTexts);
    png_write_info(png, info);
    const size_t stride = size_t(job->width) * size_t(job->channels);
    for (int y = 0; y < job->height; ++y)
        png_write_row(png, const_cast<png_bytep>(job->data + size_t(y) * stride));
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return true;
}

// Reading

// What the header says, gathered inside ReadPngHeader's setjmp scope
struct PngHeader {
    png_uint_32 width = 0, height = 0;
    int colorType = 0, bitDepth = 0, channels = 0;
    bool transparent = false, srgb = false;
    double gamma = 0;  // the gAMA chunk's value (file gamma), 0 if none
    png_textp text = nullptr;
    int nText = 0;
};

void OnReadError(png_structp png, png_const_charp message) {
    char* error = static_cast<char*>(png_get_error_ptr(png));
    std::snprintf(error, 256, "%s", message);
    png_longjmp(png, 1);
}

// Reads the header and sets up the transforms (palette to RGB, grey to 8 bits, 16-bit samples
// in the machine's byte order, interlacing); false with the message in error on failure
bool ReadPngHeader(png_structp png, png_infop info, PngHeader* h) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_info(png, info);
    int interlace = 0;
    png_get_IHDR(png, info, &h->width, &h->height, &h->bitDepth, &h->colorType, &interlace, nullptr,
                 nullptr);
    h->transparent =
        png_get_valid(png, info, PNG_INFO_tRNS) || (h->colorType & PNG_COLOR_MASK_ALPHA) != 0;
    int intent = 0;
    h->srgb = png_get_sRGB(png, info, &intent) != 0;
    double gamma = 0;
    if (png_get_gAMA(png, info, &gamma)) h->gamma = gamma;
    png_get_text(png, info, &h->text, &h->nText);
    if (h->transparent) return true;  // left to OpenImageIO
    if (h->colorType == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if (h->colorType == PNG_COLOR_TYPE_GRAY && h->bitDepth < 8) png_set_expand_gray_1_2_4_to_8(png);
    if (h->bitDepth == 16) {
        const uint16_t one = 1;
        unsigned char first;
        std::memcpy(&first, &one, 1);
        if (first == 1) png_set_swap(png);  // little-endian machine
    }
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    h->channels = png_get_channels(png, info);
    h->bitDepth = png_get_bit_depth(png, info);
    return true;
}

bool ReadPngRows(png_structp png, png_infop info, png_bytep* rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_image(png, rows);
    png_read_end(png, info);
    return true;
}

class PngReader final : public ImageFileReader {
  public:
    // Takes file (positioned after the signature) and closes it
    explicit PngReader(FILE* file) : file(file) {
        png = png_create_read_struct(PNG_LIBPNG_VER_STRING, error, OnReadError, OnWarning);
        if (png) info = png_create_info_struct(png);
    }

    // Reads the header (throws std::runtime_error for a damaged file)
    void Init() {
        if (!png || !info) throw std::runtime_error("out of memory");
        png_init_io(png, file);
        png_set_sig_bytes(png, 8);
        if (!ReadPngHeader(png, info, &header)) throw std::runtime_error(Error());
        if (header.transparent) return;
        spec.width = int(header.width);
        spec.height = int(header.height);
        spec.fullWidth = spec.width;
        spec.fullHeight = spec.height;
        spec.channelNames = header.channels == 1 ? std::vector<std::string>{"Y"}
                                                 : std::vector<std::string>{"R", "G", "B"};
        spec.type = header.bitDepth == 16 ? SampleType::U16 : SampleType::U8;
        spec.colorSpace = "sRGB";  // also with no colour chunk at all
        if (!header.srgb && header.gamma > 0) {
            // The display gamma, to two decimals (2.2, not 2.19998)
            const double g = std::round(100 / header.gamma) / 100;
            char name[32];
            std::snprintf(name, sizeof(name), "Gamma%g", g);
            spec.colorSpace = g == 1 ? "linear" : name;
        }
        for (int i = 0; i < header.nText; ++i) {
            std::string key = header.text[i].key ? header.text[i].key : "";
            std::string value(header.text[i].text ? header.text[i].text : "",
                              header.text[i].text ? header.text[i].text_length : 0);
            if (key == "oiio:ColorSpace")
                spec.colorSpace = value;
            else if (!key.empty())
                spec.strings[key] = value;
        }
    }
    ~PngReader() override {
        png_destroy_read_struct(&png, &info, nullptr);
        std::fclose(file);
    }
    PngReader(const PngReader&) = delete;
    PngReader& operator=(const PngReader&) = delete;

    bool Transparent() const { return header.transparent; }
    const ImageFileSpec& Spec() const override { return spec; }

    void Read(SampleType type, void* data) override {
        if (read) throw std::runtime_error("PNG pixels read twice");
        read = true;
        const size_t n = size_t(spec.width) * size_t(spec.height) * spec.channelNames.size();
        const size_t bytesPerSample = header.bitDepth == 16 ? 2 : 1;
        const bool direct = type == SampleType::U8 && bytesPerSample == 1;
        if (!direct && type != SampleType::Float)
            throw std::runtime_error("PNG data are read as 8-bit samples or floats");
        std::vector<unsigned char> buffer(direct ? 0 : n * bytesPerSample);
        unsigned char* pixels = direct ? static_cast<unsigned char*>(data) : buffer.data();
        const size_t stride = size_t(spec.width) * spec.channelNames.size() * bytesPerSample;
        std::vector<png_bytep> rows(size_t(spec.height));
        for (size_t y = 0; y < rows.size(); ++y) rows[y] = pixels + y * stride;
        if (!ReadPngRows(png, info, rows.data())) throw std::runtime_error(Error());
        if (direct) return;
        float* out = static_cast<float*>(data);
        if (bytesPerSample == 1) {
            for (size_t i = 0; i < n; ++i) out[i] = pixels[i] * (1.f / 255);  // as OpenImageIO
        } else {
            for (size_t i = 0; i < n; ++i) {
                uint16_t v;
                std::memcpy(&v, pixels + 2 * i, 2);
                out[i] = v * (1.f / 65535);
            }
        }
    }

  private:
    std::string Error() const { return std::string("PNG: ") + (error[0] ? error : "read failed"); }

    FILE* file;
    png_structp png = nullptr;
    png_infop info = nullptr;
    PngHeader header;
    ImageFileSpec spec;
    bool read = false;
    char error[256] = {};
};

}  // namespace

std::unique_ptr<ImageFileReader> OpenPng(const std::string& filename) {
    FILE* file = std::fopen(filename.c_str(), "rb");
    if (!file) return nullptr;
    unsigned char signature[8];
    if (std::fread(signature, 1, 8, file) != 8 || png_sig_cmp(signature, 0, 8) != 0) {
        std::fclose(file);
        return nullptr;
    }
    auto reader = std::make_unique<PngReader>(file);  // owns and closes the file
    reader->Init();
    if (reader->Transparent()) return nullptr;
    return reader;
}

bool PngWriterHandles(const ImageFileSpec& spec) {
    const std::vector<std::string>& n = spec.channelNames;
    return spec.type == SampleType::U8 &&
           (n.size() == 1 || (n.size() == 3 && n[0] == "R" && n[1] == "G" && n[2] == "B"));
}

std::string EncodePng(const ImageFileSpec& spec, const void* data) {
    if (!PngWriterHandles(spec)) throw std::runtime_error("not an 8-bit grey or RGB image");
    // The colour chunks: OpenImageIO's "oiio:ColorSpace" names ("sRGB", "Linear", "GammaG")
    int colorKind = 0;
    double gamma = 1;
    if (spec.colorSpace == "Linear") {
        colorKind = 1;
    } else if (spec.colorSpace.rfind("Gamma", 0) == 0) {
        double g = std::atof(spec.colorSpace.c_str() + 5);
        if (g > 0) colorKind = 1, gamma = 1 / g;
    }
    // tEXt chunks: key and value pointers into strings that outlive the write
    std::vector<std::pair<std::string, std::string>> entries;
    if (!spec.colorSpace.empty()) entries.emplace_back("oiio:ColorSpace", spec.colorSpace);
    for (const auto& [k, v] : spec.strings) entries.emplace_back(k, v);
    std::vector<png_text> texts(entries.size());
    for (size_t i = 0; i < entries.size(); ++i) {
        texts[i] = png_text{};
        texts[i].compression = PNG_TEXT_COMPRESSION_NONE;
        texts[i].key = const_cast<char*>(entries[i].first.c_str());
        texts[i].text = const_cast<char*>(entries[i].second.c_str());
        texts[i].text_length = entries[i].second.size();
    }
    // Into memory: the caller writes the file and sees its errors
    char* buffer = nullptr;
    size_t size = 0;
    FILE* file = open_memstream(&buffer, &size);
    if (!file) throw std::runtime_error("PNG: cannot allocate an output buffer");
    struct Free {
        char** buffer;
        ~Free() { std::free(*buffer); }
    } freeBuffer{&buffer};
    PngJob job{file,
               spec.width,
               spec.height,
               int(spec.channelNames.size()),
               static_cast<const unsigned char*>(data),
               colorKind,
               gamma,
               texts.data(),
               int(texts.size()),
               {}};
    bool ok = RunPngJob(&job);
    if (std::fclose(file) != 0 && ok) {
        ok = false;
        std::snprintf(job.error, sizeof(job.error), "out of memory");
    }
    if (!ok) throw std::runtime_error(std::string("PNG: ") + job.error);
    return std::string(buffer, size);
}

}  // namespace kiln
