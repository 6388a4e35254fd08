// Image file codecs: what Image::Read and Image::Write (image_io.cpp) exchange with the code
// that reads and writes one file format. OpenEXR files go through kiln's own codec
// (exr_codec.cpp, on the OpenEXR library), PNG without transparency through libpng
// (png_codec.h), PFM through kiln's own reader and writer (pfm_codec.h), TGA through kiln's
// own reader (tga_codec.h) and JPEG through libjpeg (jpeg_codec.h). Every other format
// goes through OpenImageIO, in a plugin (libkiln_oiio.so, oiio_plugin/) that is loaded the first
// time such a file is read or written. A process that reads and writes only those never loads
// OpenImageIO and the ~250 libraries it links (about 117 MB and 0.2-0.3 s of CPU).
//
// The plugin sees only this header: plain data and virtual calls, no kiln function it would
// have to resolve in the executable. Errors are std::runtime_error("reason"); the caller adds
// the file name.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace kiln {

// How samples are stored in a file. U16 stands for every integer type other than 8-bit
// unsigned: those are read as floats normalised to [0, 1].
enum class SampleType { U8, U16, Half, Float };

// ImageFileSpec Definition
struct ImageFileSpec {
    int width = 0, height = 0;  // of the pixels stored (the data window)
    std::vector<std::string> channelNames;
    SampleType type = SampleType::Float;
    // The display window's size and the data window's origin in it (crop and tile renders)
    int fullWidth = 0, fullHeight = 0, x = 0, y = 0;
    // OpenImageIO's "oiio:ColorSpace" of 8-bit data ("sRGB", "Linear", "Gamma2.2", or "")
    std::string colorSpace;
    std::optional<float> renderTimeSeconds;
    std::optional<int> samplesPerPixel;
    std::optional<std::array<float, 8>> chromaticities;  // red, green, blue, white x y
    // Row-major 4x4 matrices (pbrt-v4's "worldToCamera" and "worldToNDC" attributes)
    std::optional<std::array<float, 16>> worldToCamera, worldToNDC;
    std::map<std::string, std::string> strings;  // every other string attribute
};

// ImageFileReader Definition
class ImageFileReader {
  public:
    virtual ~ImageFileReader() = default;
    virtual const ImageFileSpec& Spec() const = 0;
    // Every channel of every pixel, interleaved, rows top to bottom, converted to `type`
    // (Float always works; U8 and Half when the file stores that type).
    virtual void Read(SampleType type, void* data) = 0;
};

// ImageCodec Definition
class ImageCodec {
  public:
    virtual ~ImageCodec() = default;
    virtual std::unique_ptr<ImageFileReader> Open(const std::string& filename) const = 0;
    // The bytes of a file holding `data` (interleaved, spec.type) in the format the extension
    // `format` ("exr", "png", ...) names. Encoded in memory, so that the caller writes the
    // file itself and sees every write error (a full disk); throws std::runtime_error.
    virtual std::string Encode(const std::string& format, const ImageFileSpec& spec,
                               const void* data) const = 0;
    // Whether Encode can write the format the extension `format` names.
    virtual bool CanEncode(const std::string& format) const = 0;
};

// OpenEXR through the OpenEXR library
const ImageCodec& ExrCodec();
// Checks an OpenEXR file's headers before ExrCodec opens it (OpenEXR allocates what they
// state): attribute values and chunk offsets within the file; throws
// std::runtime_error("damaged OpenEXR file: ..."). Returns the largest part's data window and
// channels and the bytes reading it takes (kiln's float samples, OpenEXR's own samples and
// line buffers), to be charged before ExrCodec opens it.
struct ExrHeaderSize {
    int64_t width = 0, height = 0;
    int channels = 0;
    double bytes = 0;
};
ExrHeaderSize CheckExrFile(const std::string& filename);
// Every format OpenImageIO reads or writes. Loads the plugin on first use (next to the
// executable, else in the build directory); throws std::runtime_error if it cannot.
const ImageCodec& OIIOCodec();

// OpenImageIO's named colour map ("inferno", "viridis", ...) at each of `values` (in [0, 1]):
// three display-encoded (sRGB) values per input value. Loads the plugin.
std::vector<float> NamedColorMap(const std::string& name, const std::vector<float>& values);

// The functions the plugin exports (extern "C"): const ImageCodec* KilnOIIOImageCodec(), and
// void KilnOIIOColorMap(const char* name, const float* values, size_t n, float* rgb)
inline constexpr const char* kOIIOCodecSymbol = "KilnOIIOImageCodec";
inline constexpr const char* kOIIOColorMapSymbol = "KilnOIIOColorMap";

}  // namespace kiln
