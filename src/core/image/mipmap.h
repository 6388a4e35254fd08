// MIP maps: image pyramids for filtered texture lookups (pbrt-v4's MIPMap).
//
// Level 0 is the image itself (resolution rounded up to powers of two by resampling is NOT
// done; like pbrt-v4 each level halves the previous one with a box filter, odd sizes rounded
// up). Lookups take st in [0,1]^2 (image.h conventions: st = (0, 0) is the top-left corner of
// the image) and the screen-space differentials of st, dst0 and dst1, that bound the filter
// footprint. Values are linear and unitless (whatever the image stores).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/object_arena.h"
#include "base/vecmath.h"
#include "core/image/image.h"
#include "spectral/color.h"

namespace kiln {

// FilterFunction Definition
enum class FilterFunction { Point, Bilinear, Trilinear, EWA };
// pbrt-v4 names: "point", "bilinear", "trilinear", "ewa" (also "EWA").
std::optional<FilterFunction> ParseFilter(std::string_view s);
std::string ToString(FilterFunction f);

// MIPMapFilterOptions Definition
struct MIPMapFilterOptions {
    FilterFunction filter = FilterFunction::Bilinear;
    Float maxAnisotropy = 8;  // EWA: longest / shortest ellipse axis is clamped to this
};

// MIPMap Definition
class MIPMap {
  public:
    // Channels kept: "R", "G", "B" if present, else "Y", else the first three (or the first
    // one). Float lookups read the first kept channel (R of an RGB image, as pbrt-v4); RGB
    // lookups of a one-channel image replicate it. `colorSpace` is the colour space of the RGB data
    // (nullptr: sRGB).
    MIPMap(Image image, const RGBColorSpace* colorSpace, WrapMode wrapMode,
           MIPMapFilterOptions options);
    // Reads the file with Image::Read (8-bit data decoded with `encoding`); the colour space
    // comes from the file's metadata when known, else sRGB. Throws std::runtime_error.
    static MIPMap* CreateFromFile(const std::string& filename, MIPMapFilterOptions options,
                                  WrapMode wrap, ColorEncoding encoding, ObjectArena& arena);

    // Filtered lookup, T = Float or RGB, with pbrt-v4 semantics: Point/Bilinear use the level
    // whose texel spacing matches the larger differential, Trilinear blends two levels, EWA
    // filters an elliptical Gaussian footprint.
    template <typename T>
    T Filter(Point2f st, Vector2f dst0, Vector2f dst1) const;

    // Bilinear lookup in level 0.
    RGB Bilerp(Point2f st) const;
    Float BilerpFloat(Point2f st) const;
    // Texel of a level (wrap mode applies).
    template <typename T>
    T Texel(int level, Point2i st) const;
    template <typename T>
    T Bilerp(int level, Point2f st) const;

    int Levels() const { return int(pyramid.size()); }
    Point2i LevelResolution(int level) const { return pyramid[level].Resolution(); }
    const Image& GetLevel(int level) const { return pyramid[level]; }
    // Bytes the levels' samples take.
    size_t MemoryBytes() const {
        size_t bytes = 0;
        for (const Image& level : pyramid) {
            Point2i r = level.Resolution();
            bytes += size_t(r.x) * size_t(r.y) * level.NChannels() * level.BytesPerSample();
        }
        return bytes;
    }
    const RGBColorSpace* GetRGBColorSpace() const { return colorSpace; }
    WrapMode GetWrapMode() const { return wrapMode; }
    const MIPMapFilterOptions& Options() const { return options; }

  private:
    // MIPMap Private Methods
    template <typename T>
    T EWA(int level, Point2f st, Vector2f dst0, Vector2f dst1) const;

    // MIPMap Private Members
    std::vector<Image> pyramid;
    const RGBColorSpace* colorSpace;
    WrapMode wrapMode;
    MIPMapFilterOptions options;
    int rgbChannels[3] = {0, 0, 0};  // channels used for RGB lookups
};

// Lookups are defined for T = Float (first channel) and T = RGB (one channel replicated).
template <>
Float MIPMap::Texel<Float>(int level, Point2i st) const;
template <>
RGB MIPMap::Texel<RGB>(int level, Point2i st) const;
template <>
Float MIPMap::Bilerp<Float>(int level, Point2f st) const;
template <>
RGB MIPMap::Bilerp<RGB>(int level, Point2f st) const;
extern template Float MIPMap::Filter<Float>(Point2f, Vector2f, Vector2f) const;
extern template RGB MIPMap::Filter<RGB>(Point2f, Vector2f, Vector2f) const;

}  // namespace kiln
