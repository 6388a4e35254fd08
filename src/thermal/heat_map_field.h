// HeatMapField ("heatmap"): a temperature field read from an image, or from one image per frame
// of an animation (temperature_field.h).
#pragma once

#include <memory>
#include <string>

#include "core/image/mipmap.h"
#include "textures/texture_mapping.h"
#include "thermal/temperature_field.h"

namespace kiln {

// HeatMapField Definition
// An image lookup (as "imagemap": 2D mapping, t flipped so v = 0 is the bottom row; the first
// channel of multi-channel images) turned into a temperature. With "float tmin" and "float
// tmax" the value is tmin + v (tmax - tmin), v the linear image value (for 8-bit files the
// code value / 255: "encoding" defaults to linear here, unlike imagemap); without them the
// image values are the result (float EXR heat maps in kelvin). An 8-bit image without tmin /
// tmax warns. "string filename" may contain a run of '#' (e.g. "heat.####.exr"): it is
// replaced by the frame number, zero-padded; a fractional frame blends the two neighbouring
// frames linearly. The frame is "float frame" when given, else the animation's (0 without
// one); a sequence without "float frame" is Animated and reads its frames again when the
// animation changes (only the frames in use are kept). Also "string filter" (bilinear),
// "float maxanisotropy" (8), "string wrap" (clamp) and the mapping parameters.
class HeatMapField final : public TemperatureField {
  public:
    Float Evaluate(const TextureEvalContext& ctx) const override;
    bool UsesFootprint() const override { return true; }  // MIP-map filtering
    bool Animated() const override { return followsAnimation; }
    void SetAnimation(const TemperatureAnimation& animation) override;
    // The frame the field shows (fractional: a blend of two images).
    Float Frame() const { return frame; }

    // The file name of a frame: the last run of '#' in the file name part of `pattern`
    // replaced by the zero-padded frame number; `pattern` itself when it has no '#'.
    static std::string FrameFilename(const std::string& pattern, int frame);

    static HeatMapField* Create(const TextureParameterDictionary& params,
                                const Transform& renderFromTexture, const FileLoc& loc,
                                ObjectArena& arena, Diagnostics& diag,
                                const TemperatureAnimation& animation);

    // (public for ObjectArena::New; use Create)
    struct Source {
        std::string pattern;
        MIPMapFilterOptions options;
        WrapMode wrap;
        ColorEncoding encoding;
        FileLoc loc;  // of "filename"
    };
    HeatMapField(TextureMapping2D mapping, Source source, Float offset, Float scale,
                 bool followsAnimation, MemoryBudget& budget)
        : mapping(mapping),
          source(std::move(source)),
          offset(offset),
          scale(scale),
          followsAnimation(followsAnimation),
          budget(budget) {}
    ~HeatMapField() override;

  private:
    // Reads the images of `frame` (one, or two to blend) into a new arena, then replaces the
    // current ones (which are kept if reading fails).
    void LoadFrame(Float frame);

    TextureMapping2D mapping;
    Source source;
    Float offset, scale;  // value = offset + scale * v
    bool followsAnimation;
    MemoryBudget& budget;
    // The images in use, in their own arena (charged to the scene's budget) so a new frame
    // frees the old ones
    std::unique_ptr<ObjectArena> images;
    double chargedBytes = 0;
    const MIPMap *frame0 = nullptr, *frame1 = nullptr;  // frame1: nullptr when not blending
    Float frame = 0, frameWeight = 0;                   // frameWeight: weight of frame1
};

}  // namespace kiln
