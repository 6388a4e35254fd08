#include "core/image/jpeg_codec.h"

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <vector>

#include <jpeglib.h>

namespace kiln {
namespace {

// libjpeg reports errors through error_exit, which must not return: it jumps back to the
// setjmp of the call in progress (no C++ object with a destructor lives between the two)
struct JpegErrors {
    jpeg_error_mgr pub;
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX];
};

void ErrorExit(j_common_ptr cinfo) {
    auto* e = reinterpret_cast<JpegErrors*>(cinfo->err);
    (*cinfo->err->format_message)(cinfo, e->message);
    std::longjmp(e->jump, 1);
}

void NoOutput(j_common_ptr) {}  // warnings are counted, not printed

struct JpegInfo {
    int width = 0, height = 0, channels = 0;
};

// Reads the header and, with pixels non-null, decodes the image into it (rows top to bottom,
// 8-bit samples). Returns an empty message on success, else what went wrong.
std::string Decode(const std::vector<unsigned char>& file, JpegInfo* info, unsigned char* pixels) {
    jpeg_decompress_struct cinfo;
    JpegErrors errors;
    cinfo.err = jpeg_std_error(&errors.pub);
    errors.pub.error_exit = ErrorExit;
    errors.pub.output_message = NoOutput;
    errors.message[0] = '\0';
    if (setjmp(errors.jump)) {
        jpeg_destroy_decompress(&cinfo);
        return errors.message[0] ? errors.message : "damaged JPEG data";
    }
    jpeg_create_decompress(&cinfo);
    jpeg_mem_src(&cinfo, file.data(), static_cast<unsigned long>(file.size()));
    jpeg_read_header(&cinfo, TRUE);
    if (cinfo.jpeg_color_space == JCS_CMYK || cinfo.jpeg_color_space == JCS_YCCK) {
        jpeg_destroy_decompress(&cinfo);
        return "CMYK JPEG files are not supported";
    }
    bool grey = cinfo.jpeg_color_space == JCS_GRAYSCALE;
    cinfo.out_color_space = grey ? JCS_GRAYSCALE : JCS_RGB;
    info->width = int(cinfo.image_width);
    info->height = int(cinfo.image_height);
    info->channels = grey ? 1 : 3;
    if (pixels) {
        jpeg_start_decompress(&cinfo);
        const size_t stride = size_t(info->width) * info->channels;
        while (cinfo.output_scanline < cinfo.output_height) {
            JSAMPROW row = pixels + size_t(cinfo.output_scanline) * stride;
            jpeg_read_scanlines(&cinfo, &row, 1);
        }
        jpeg_finish_decompress(&cinfo);
        if (errors.pub.num_warnings > 0) {
            jpeg_destroy_decompress(&cinfo);
            return "damaged JPEG data (libjpeg would fill in what is missing)";
        }
    }
    jpeg_destroy_decompress(&cinfo);
    return "";
}

class JpegReader final : public ImageFileReader {
  public:
    JpegReader(ImageFileSpec spec, std::vector<unsigned char> file)
        : spec(std::move(spec)), file(std::move(file)) {}
    const ImageFileSpec& Spec() const override { return spec; }
    void Read(SampleType type, void* data) override {
        const size_t n = size_t(spec.width) * spec.height * spec.channelNames.size();
        std::vector<unsigned char> pixels(n);
        JpegInfo info;
        if (std::string error = Decode(file, &info, pixels.data()); !error.empty())
            throw std::runtime_error(error);
        if (type == SampleType::U8) {
            std::memcpy(data, pixels.data(), n);
        } else if (type == SampleType::Float) {
            auto out = static_cast<float*>(data);
            for (size_t i = 0; i < n; ++i) out[i] = pixels[i] / 255.f;
        } else {
            throw std::runtime_error("JPEG files hold 8-bit samples");
        }
    }

  private:
    ImageFileSpec spec;
    std::vector<unsigned char> file;
};

}  // namespace

std::unique_ptr<ImageFileReader> OpenJpeg(const std::string& filename) {
    std::ifstream in(filename, std::ios::binary);
    if (!in) return nullptr;
    unsigned char signature[3] = {};
    in.read(reinterpret_cast<char*>(signature), 3);
    if (in.gcount() != 3 || signature[0] != 0xFF || signature[1] != 0xD8 || signature[2] != 0xFF)
        return nullptr;
    in.seekg(0);
    std::vector<unsigned char> file((std::istreambuf_iterator<char>(in)),
                                    std::istreambuf_iterator<char>());
    JpegInfo info;
    if (std::string error = Decode(file, &info, nullptr); !error.empty())
        throw std::runtime_error(error);
    if (info.width <= 0 || info.height <= 0) throw std::runtime_error("JPEG without pixels");
    ImageFileSpec spec;
    spec.width = spec.fullWidth = info.width;
    spec.height = spec.fullHeight = info.height;
    spec.type = SampleType::U8;
    spec.colorSpace = "sRGB";
    spec.channelNames = info.channels == 1 ? std::vector<std::string>{"Y"}
                                           : std::vector<std::string>{"R", "G", "B"};
    return std::make_unique<JpegReader>(std::move(spec), std::move(file));
}

}  // namespace kiln
