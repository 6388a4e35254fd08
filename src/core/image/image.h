// Images: pixel storage (8-bit, half or float) with any number of named channels, wrap modes
// for lookups outside the image, and reading/writing (EXR through OpenEXR, every other format
// through the OpenImageIO plugin: image_codec.h).
//
// Conventions (pbrt-v4's): pixel (0, 0) is the top-left pixel of the file; rows go down.
// Continuous lookups take st in [0,1]^2 with st = (0, 0) at the top-left corner of the image
// and pixel (x, y) centred at st = ((x + 0.5) / width, (y + 0.5) / height). (pbrt-v4's image
// texture flips t, st.t = 1 - uv.v, so that v = 0 is the bottom row; that is the texture's job.)
// Lookups return linear values: U256 pixels are decoded with the image's ColorEncoding; Half
// and Float pixels are linear. Values are relative (the unit of whatever the image stores).
//
// Thread safety: const methods may be called concurrently; writers need exclusive access.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "base/vecmath.h"
#include "core/image/color_encoding.h"

namespace kiln {

class MemoryBudget;

class RGBColorSpace;

// PixelFormat Definition
// U256: 8 bits per channel, encoded with the image's ColorEncoding; Half: IEEE binary16;
// Float: IEEE binary32.
enum class PixelFormat { U256, Half, Float };
std::string ToString(PixelFormat format);

// WrapMode Definition
enum class WrapMode { Repeat, Clamp, Black, OctahedralSphere };
// pbrt-v4 names: "repeat", "clamp", "black", "octahedralsphere".
std::optional<WrapMode> ParseWrapMode(std::string_view s);
std::string ToString(WrapMode mode);

// Maps pixel coordinates outside [0, res) back into the image as the wrap mode says. Returns
// false when the pixel is outside and the mode is Black (its value is then 0). The octahedral
// mode mirrors across the edges of an equal-area octahedral sphere map (pbrt-v4).
bool RemapPixelCoords(Point2i* p, Point2i resolution, WrapMode wrapMode);

// ImageMetadata Definition
// Optional facts stored with an image file (as EXR attributes where the format allows).
struct ImageMetadata {
    std::optional<float> renderTimeSeconds;  // wall-clock rendering time, s
    std::optional<int> samplesPerPixel;
    // The image covers pixelBounds of a fullResolution frame (EXR data vs display window).
    std::optional<Point2i> fullResolution;
    std::optional<Bounds2i> pixelBounds;
    // Colour space of the RGB channels (written as EXR chromaticities; on reading, set when
    // the file's chromaticities match one of RGBColorSpace's named spaces).
    const RGBColorSpace* colorSpace = nullptr;
    // Row-major 4x4 matrices (pbrt-v4's "worldToCamera" and "worldToNDC" EXR attributes).
    std::optional<std::array<float, 16>> cameraFromWorld, NDCFromWorld;
    // Further string attributes, written and read as they are.
    std::map<std::string, std::string> strings;
};

// Image Definition
class Image {
  public:
    // Image Public Methods
    Image() = default;
    // Zero-filled image with the given channels (e.g. {"R", "G", "B"}). `encoding` applies to
    // U256 images only.
    Image(PixelFormat format, Point2i resolution, std::vector<std::string> channelNames,
          ColorEncoding encoding = ColorEncoding::Linear());

    // Reads EXR and any format OpenImageIO reads. 8-bit data are kept as U256 and decoded with
    // `encoding` (default: sRGB for 8-bit files unless the file says it is linear), except the
    // formats IsPbrtV4SrgbOnlyFormat names, whose 8-bit data are always sRGB; 16-bit
    // integer data are decoded with the same encoding into Float; half stays Half, float and
    // everything else become Float (linear). For files whose data window is smaller than the
    // display window (crop renders) the data window is read and *metadata gets pixelBounds and
    // fullResolution. Throws std::runtime_error("file: reason").
    // With a budget, the decoded pixels (in the format they are kept in) are charged to it
    // before they are read (MemoryLimitError if they do not fit); without, they must fit in
    // half the machine's memory.
    static Image Read(const std::string& filename, ImageMetadata* metadata = nullptr,
                      std::optional<ColorEncoding> encoding = std::nullopt,
                      MemoryBudget* budget = nullptr);

    // Writes by extension (.exr, .png, .jpg/.jpeg, .tif/.tiff, .hdr, .pfm, anything else OIIO
    // writes). Raw values are written as they are (no display transform): EXR keeps every
    // channel with its name (layers "albedo.R", "N.X", "Z") as half or float following the
    // image's format (U256 -> half); 8-bit formats (png, jpg, 8-bit tif) get the image's
    // encoding (sRGB for a linear float image) applied after clamping to [0, 1]; tif stores
    // Float/Half images as float. HDR and PFM take the "R", "G", "B" channels (or 1 channel).
    // Atomic: the data go to a temporary file in the same directory that is renamed to
    // `filename` when complete; on failure the temporary file is removed, `filename` is left
    // as it was, and std::runtime_error("file: reason") is thrown.
    void Write(const std::string& filename, const ImageMetadata& metadata = {}) const;

    explicit operator bool() const { return resolution.x > 0 && resolution.y > 0; }
    Point2i Resolution() const { return resolution; }
    int NChannels() const { return int(channelNames.size()); }
    const std::vector<std::string>& ChannelNames() const { return channelNames; }
    PixelFormat Format() const { return format; }
    const ColorEncoding& Encoding() const { return encoding; }
    // Bytes per channel sample: 1 (U256), 2 (Half) or 4 (Float).
    int BytesPerSample() const {
        return format == PixelFormat::U256 ? 1 : format == PixelFormat::Half ? 2 : 4;
    }
    // Index of the named channel, or -1 if absent.
    int ChannelIndex(std::string_view name) const;
    // New image with the named channels, in the given order (same format); throws
    // std::runtime_error if one is missing.
    Image SelectChannels(const std::vector<std::string>& names) const;
    // The part of the image inside bounds (which must lie inside the image).
    Image Crop(const Bounds2i& bounds) const;
    // Same channels converted to another pixel format (U256 uses `encoding`).
    Image ConvertToFormat(PixelFormat to, ColorEncoding encoding = ColorEncoding::SRGB()) const;

    size_t PixelOffset(Point2i p) const {
        return size_t(NChannels()) * (size_t(p.y) * size_t(resolution.x) + size_t(p.x));
    }

    // Channel c of pixel p as a linear value; p outside the image is remapped with wrap
    // (0 for Black).
    Float GetChannel(Point2i p, int c, WrapMode wrap = WrapMode::Clamp) const;
    // Sets channel c of pixel p (inside the image) from a linear value; NaN is stored as 0 as
    // in pbrt-v4; Half values are limited to +-65504; U256 values are clamped to [0, 1],
    // encoded and rounded.
    void SetChannel(Point2i p, int c, Float value);
    // Bilinear interpolation of channel c at st (see the conventions above).
    Float BilerpChannel(Point2f st, int c, WrapMode wrap = WrapMode::Clamp) const;
    // Value of the pixel containing st.
    Float LookupNearestChannel(Point2f st, int c, WrapMode wrap = WrapMode::Clamp) const {
        Point2i p(int(std::floor(st.x * resolution.x)), int(std::floor(st.y * resolution.y)));
        return GetChannel(p, c, wrap);
    }

    // Mean of channel c over all pixels (0 for an empty image).
    Float Average(int c) const;
    // Per-pixel density for importance sampling the image (pbrt-v4's GetSamplingDistribution):
    // the average of the absolute channel values at each pixel times dxdA at the pixel centre
    // mapped into `domain`. Row-major, width x height values (rows top to bottom).
    std::vector<Float> GetSamplingDistribution(
        const std::function<Float(Point2f)>& dxdA = [](Point2f) { return Float(1); },
        const Bounds2f& domain = Bounds2f{Point2f(0, 0), Point2f(1, 1)}) const;
    // Mirrors the rows (top <-> bottom).
    void FlipY();

  private:
    // Image Private Members
    PixelFormat format = PixelFormat::Float;
    Point2i resolution{0, 0};
    std::vector<std::string> channelNames;
    ColorEncoding encoding = ColorEncoding::Linear();
    std::vector<uint8_t> p8;
    std::vector<uint16_t> p16;  // binary16 bit patterns
    std::vector<float> p32;
};

// Lower-case extension of path without the dot ("exr"), or "".
std::string FileExtension(std::string_view path);
// Whether the file's extension is one of the formats pbrt-v4 reads with stb_image (jpg, jpeg,
// tga, bmp, gif, psd, pic, pnm, ppm, pgm): pbrt-v4 takes their 8-bit samples as sRGB whatever
// an "encoding" parameter asks (it applies to PNG only), and so does Image::Read.
bool IsPbrtV4SrgbOnlyFormat(const std::string& filename);
// Whether Image::Write writes files with this extension (as FileExtension gives it): exr, png
// and pfm always; every other format if OpenImageIO has a writer for it (this loads its plugin).
bool CanWriteImageFormat(const std::string& extension);

}  // namespace kiln
