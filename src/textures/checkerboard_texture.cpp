#include "textures/checkerboard_texture.h"

#include <cmath>

#include "textures/texture_parameter_dictionary.h"

namespace kiln {

// Checkerboard Function Definition
Float Checkerboard(const TextureEvalContext& ctx, const TextureMapping2D* map2D,
                   const TextureMapping3D* map3D) {
    // Integral of the 1D checkerboard (+1 on even cells, -1 on odd) against a triangle filter
    // of radius r centred at x, via its antiderivative d
    auto d = [](Float x) {
        Float y = x / 2 - std::floor(x / 2) - Float(0.5);
        return x / 2 + y * (1 - 2 * std::abs(y));
    };
    auto bf = [&](Float x, Float r) -> Float {
        if (std::floor(x - r) == std::floor(x + r)) return 1 - 2 * (int64_t(std::floor(x)) & 1);
        return (d(x + r) - 2 * d(x) + d(x - r)) / Sqr(r);
    };
    // The 2D or 3D checkerboard is the product of 1D ones; filter widths from the footprint
    if (map2D) {
        TexCoord2D c = map2D->Map(ctx);
        Float ds = 1.5f * std::max(std::abs(c.dsdx), std::abs(c.dsdy));
        Float dt = 1.5f * std::max(std::abs(c.dtdx), std::abs(c.dtdy));
        return Float(0.5) - bf(c.st.x, ds) * bf(c.st.y, dt) / 2;
    }
    TexCoord3D c = map3D->Map(ctx);
    Float dx = 1.5f * std::max(std::abs(c.dpdx.x), std::abs(c.dpdy.x));
    Float dy = 1.5f * std::max(std::abs(c.dpdx.y), std::abs(c.dpdy.y));
    Float dz = 1.5f * std::max(std::abs(c.dpdx.z), std::abs(c.dpdy.z));
    return Float(0.5) - bf(c.p.x, dx) * bf(c.p.y, dy) * bf(c.p.z, dz) / 2;
}

// Checkerboard creation
namespace {

struct CheckerMappings {
    std::optional<TextureMapping2D> map2D;
    std::optional<TextureMapping3D> map3D;
};

CheckerMappings GetCheckerMappings(const TextureParameterDictionary& params,
                                   const Transform& renderFromTexture, const FileLoc& loc) {
    int dim = params.GetOneInt("dimension", 2);
    if (dim == 2) return {TextureMapping2D::Create(params, renderFromTexture, loc), std::nullopt};
    if (dim == 3) return {std::nullopt, TextureMapping3D::Create(renderFromTexture)};
    throw SceneError(params.Loc("dimension", loc),
                     std::to_string(dim) + " dimensional checkerboard texture not supported",
                     std::to_string(dim));
}

}  // namespace

FloatCheckerboardTexture* FloatCheckerboardTexture::Create(const TextureParameterDictionary& params,
                                                           const Transform& renderFromTexture,
                                                           const FileLoc& loc, ObjectArena& arena) {
    CheckerMappings m = GetCheckerMappings(params, renderFromTexture, loc);
    return arena.New<FloatCheckerboardTexture>(m.map2D, m.map3D,
                                               params.GetFloatTexture("tex1", 1, arena),
                                               params.GetFloatTexture("tex2", 0, arena));
}

SpectrumCheckerboardTexture* SpectrumCheckerboardTexture::Create(
    const TextureParameterDictionary& params, const Transform& renderFromTexture, SpectrumType type,
    const FileLoc& loc, ObjectArena& arena) {
    CheckerMappings m = GetCheckerMappings(params, renderFromTexture, loc);
    return arena.New<SpectrumCheckerboardTexture>(
        m.map2D, m.map3D,
        params.GetSpectrumTexture("tex1", Spectrum(ConstantSpectrum(1)), type, arena),
        params.GetSpectrumTexture("tex2", Spectrum(ConstantSpectrum(0)), type, arena));
}

}  // namespace kiln
