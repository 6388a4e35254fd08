// Checkerboard textures (pbrt-v4): tex1 on the cells whose integer coordinates sum to an even
// number, tex2 on the others. Both the 2D and the 3D versions are antialiased: the
// checkerboard is integrated in closed form against a triangle filter sized by the
// screen-space footprint.
#pragma once

#include <optional>

#include "textures/texture.h"
#include "textures/texture_mapping.h"

namespace kiln {

// Weight of tex2 in [0, 1] at the point: 0 inside an even cell, 1 inside an odd one, between
// near edges when the footprint is not zero. Exactly one mapping must be given.
Float Checkerboard(const TextureEvalContext& ctx, const TextureMapping2D* map2D,
                   const TextureMapping3D* map3D);

// FloatCheckerboardTexture Definition
class FloatCheckerboardTexture {
  public:
    FloatCheckerboardTexture(std::optional<TextureMapping2D> map2D,
                             std::optional<TextureMapping3D> map3D, FloatTexture tex1,
                             FloatTexture tex2)
        : map2D(map2D), map3D(map3D), tex1(tex1), tex2(tex2) {}
    Float Evaluate(const TextureEvalContext& ctx) const {
        Float wt = Checkerboard(ctx, map2D ? &*map2D : nullptr, map3D ? &*map3D : nullptr);
        Float t1 = wt != 1 ? tex1.Evaluate(ctx) : 0;
        Float t2 = wt != 0 ? tex2.Evaluate(ctx) : 0;
        return (1 - wt) * t1 + wt * t2;
    }
    bool UsesFootprint() const { return true; }  // antialiased

    // "integer dimension" (2 or 3, else SceneError), "tex1" (1), "tex2" (0) and the mapping
    // parameters (2D) or the texture transform (3D).
    static FloatCheckerboardTexture* Create(const TextureParameterDictionary& params,
                                            const Transform& renderFromTexture, const FileLoc& loc,
                                            ObjectArena& arena);

  private:
    std::optional<TextureMapping2D> map2D;
    std::optional<TextureMapping3D> map3D;
    FloatTexture tex1, tex2;
};

// SpectrumCheckerboardTexture Definition
class SpectrumCheckerboardTexture {
  public:
    SpectrumCheckerboardTexture(std::optional<TextureMapping2D> map2D,
                                std::optional<TextureMapping3D> map3D, SpectrumTexture tex1,
                                SpectrumTexture tex2)
        : map2D(map2D), map3D(map3D), tex1(tex1), tex2(tex2) {}
    SampledSpectrum Evaluate(const TextureEvalContext& ctx,
                             const SampledWavelengths& lambda) const {
        Float wt = Checkerboard(ctx, map2D ? &*map2D : nullptr, map3D ? &*map3D : nullptr);
        SampledSpectrum t1, t2;
        if (wt != 1) t1 = tex1.Evaluate(ctx, lambda);
        if (wt != 0) t2 = tex2.Evaluate(ctx, lambda);
        return (1 - wt) * t1 + wt * t2;
    }
    bool UsesFootprint() const { return true; }  // antialiased

    static SpectrumCheckerboardTexture* Create(const TextureParameterDictionary& params,
                                               const Transform& renderFromTexture,
                                               SpectrumType type, const FileLoc& loc,
                                               ObjectArena& arena);

  private:
    std::optional<TextureMapping2D> map2D;
    std::optional<TextureMapping3D> map3D;
    SpectrumTexture tex1, tex2;
};

}  // namespace kiln
