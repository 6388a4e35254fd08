#include "core/image/pfm_codec.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace kiln {

namespace {

// PfmReader Definition
class PfmReader final : public ImageFileReader {
  public:
    PfmReader(ImageFileSpec spec, std::vector<float> topDown)
        : spec(std::move(spec)), pixels(std::move(topDown)) {}
    const ImageFileSpec& Spec() const override { return spec; }
    void Read(SampleType type, void* data) override {
        if (type != SampleType::Float)
            throw std::runtime_error("PFM files hold 32-bit float samples");
        std::memcpy(data, pixels.data(), pixels.size() * sizeof(float));
    }

  private:
    ImageFileSpec spec;
    std::vector<float> pixels;
};

uint32_t ByteSwap(uint32_t v) {
    return (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
}

}  // namespace

std::unique_ptr<ImageFileReader> OpenPfm(const std::string& filename) {
    std::ifstream in(filename, std::ios::binary);
    if (!in) return nullptr;
    char magic[3] = {};
    in.read(magic, 3);
    if (in.gcount() != 3 || magic[0] != 'P' || (magic[1] != 'F' && magic[1] != 'f') ||
        !std::isspace(static_cast<unsigned char>(magic[2])))
        return nullptr;
    const int channels = magic[1] == 'F' ? 3 : 1;
    // Width, height and scale as text, each followed by white space (one byte after the scale)
    auto number = [&](const char* what) {
        std::string token;
        int c;
        while ((c = in.get()) != EOF && std::isspace(c)) {
        }
        while (c != EOF && !std::isspace(c) && token.size() < 32) {
            token.push_back(char(c));
            c = in.get();
        }
        if (c == EOF || token.empty() || token.size() >= 32)
            throw std::runtime_error(std::string("damaged PFM header (") + what + ")");
        size_t used = 0;
        double v = 0;
        try {
            v = std::stod(token, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != token.size() || !std::isfinite(v))
            throw std::runtime_error(std::string("damaged PFM header (") + what + " \"" + token +
                                     "\")");
        return v;
    };
    double width = number("width"), height = number("height"), scale = number("scale");
    if (width < 1 || height < 1 || width != std::floor(width) || height != std::floor(height) ||
        width > std::numeric_limits<int>::max() || height > std::numeric_limits<int>::max() ||
        scale == 0)
        throw std::runtime_error("damaged PFM header (width, height or scale)");
    // The samples must be exactly what is left of the file
    std::streamoff start = in.tellg();
    in.seekg(0, std::ios::end);
    std::streamoff size = in.tellg();
    double samples = width * height * channels;
    if (double(size - start) != samples * 4)
        throw std::runtime_error("PFM file of " + std::to_string(size) + " bytes does not hold " +
                                 std::to_string(int64_t(width)) + " x " +
                                 std::to_string(int64_t(height)) + " x " +
                                 std::to_string(channels) + " floats after its header");
    ImageFileSpec spec;
    spec.width = int(width);
    spec.height = int(height);
    spec.channelNames =
        channels == 3 ? std::vector<std::string>{"R", "G", "B"} : std::vector<std::string>{"Y"};
    spec.type = SampleType::Float;
    size_t rowFloats = size_t(spec.width) * channels;
    std::vector<float> file(rowFloats * size_t(spec.height));
    in.seekg(start);
    in.read(reinterpret_cast<char*>(file.data()), std::streamsize(file.size() * sizeof(float)));
    if (!in) throw std::runtime_error("cannot read the PFM samples");
    bool fileLittle = scale < 0;
    if (fileLittle != (std::endian::native == std::endian::little))
        for (float& f : file) f = std::bit_cast<float>(ByteSwap(std::bit_cast<uint32_t>(f)));
    // The scale's magnitude multiplies the samples (as pbrt-v4's ReadPFM applies it)
    if (std::abs(scale) != 1)
        for (float& f : file) f = float(f * std::abs(scale));
    // Rows bottom to top in the file, top to bottom in kiln
    std::vector<float> topDown(file.size());
    for (int y = 0; y < spec.height; ++y)
        std::memcpy(&topDown[size_t(y) * rowFloats], &file[size_t(spec.height - 1 - y) * rowFloats],
                    rowFloats * sizeof(float));
    return std::make_unique<PfmReader>(std::move(spec), std::move(topDown));
}

bool PfmWriterHandles(const ImageFileSpec& spec) {
    const auto& c = spec.channelNames;
    return spec.type == SampleType::Float &&
           (c.size() == 1 || (c.size() == 3 && c[0] == "R" && c[1] == "G" && c[2] == "B"));
}

std::string EncodePfm(const ImageFileSpec& spec, const void* data) {
    if (!PfmWriterHandles(spec))
        throw std::runtime_error("PFM holds one channel or R, G, B as 32-bit floats");
    const int channels = int(spec.channelNames.size());
    std::ostringstream header;
    header << (channels == 3 ? "PF" : "Pf") << '\n'
           << spec.width << ' ' << spec.height << '\n'
           << (std::endian::native == std::endian::little ? "-1" : "1") << '\n';
    std::string out = header.str();
    size_t rowBytes = size_t(spec.width) * channels * sizeof(float);
    const char* bytes = static_cast<const char*>(data);
    out.reserve(out.size() + rowBytes * size_t(spec.height));
    for (int y = spec.height - 1; y >= 0; --y) out.append(bytes + size_t(y) * rowBytes, rowBytes);
    return out;
}

}  // namespace kiln
