#include "textures/texture.h"

#include <type_traits>

#include "core/parser/suggestions.h"
#include "textures/basic_textures.h"
#include "textures/checkerboard_texture.h"
#include "textures/float_texture_extension.h"
#include "textures/image_texture.h"
#include "textures/metal_temperature_texture.h"
#include "textures/noise_textures.h"
#include "textures/texture_parameter_dictionary.h"

namespace kiln {

// Texture dispatch
Float FloatTexture::Evaluate(const TextureEvalContext& ctx) const {
    return Dispatch([&](const auto* t) { return t->Evaluate(ctx); });
}

SampledSpectrum SpectrumTexture::Evaluate(const TextureEvalContext& ctx,
                                          const SampledWavelengths& lambda) const {
    return Dispatch([&](const auto* t) { return t->Evaluate(ctx, lambda); });
}

// NamedTextures Method Definitions
NamedTextures::NamedTextures() : imageCache(std::make_shared<ImageTextureCache>()) {}

const std::map<std::string, SpectrumTexture>& NamedTextures::SpectrumTextures(
    SpectrumType type) const {
    switch (type) {
        case SpectrumType::Albedo:
            return albedoSpectrumTextures;
        case SpectrumType::Unbounded:
            return unboundedSpectrumTextures;
        default:
            return illuminantSpectrumTextures;
    }
}

std::map<std::string, SpectrumTexture>& NamedTextures::SpectrumTextures(SpectrumType type) {
    const NamedTextures& self = *this;
    return const_cast<std::map<std::string, SpectrumTexture>&>(self.SpectrumTextures(type));
}

// Texture creation
namespace {

// Every texture class kiln or pbrt-v4 knows (the temperature fields: thermal/temperature_field.h)
constexpr std::string_view kTextures[] = {
    "constant", "scale",           "mix",     "directionmix", "checkerboard",
    "bilerp",   "imagemap",        "dots",    "fbm",          "wrinkled",
    "windy",    "marble",          "ptex",    "gradient",     "noise",
    "heatmap",  "vertexattribute", "cooling", "keyframes"};

// pbrt-v4 texture classes that kiln (or this kind of texture) lacks: ptex, and the noise
// textures that exist only as float or only as spectrum textures (and kiln's float-only
// temperature textures).
bool IsUnsupportedTexture(const std::string& name) {
    return name == "fbm" || name == "wrinkled" || name == "windy" || name == "marble" ||
           name == "ptex" || name == "gradient" || name == "noise" || name == "heatmap" ||
           name == "vertexattribute" || name == "cooling" || name == "keyframes";
}

}  // namespace

FloatTexture CreateFloatTexture(const std::string& name, const Transform& renderFromTexture,
                                const TextureParameterDictionary& params, const FileLoc& loc,
                                ObjectArena& arena, Diagnostics& diag) {
    if (name == "constant") return FloatConstantTexture::Create(params, arena);
    if (name == "scale") return FloatScaledTexture::Create(params, arena);
    if (name == "mix") return FloatMixTexture::Create(params, arena);
    if (name == "directionmix")
        return FloatDirectionMixTexture::Create(params, renderFromTexture, arena);
    if (name == "bilerp") return FloatBilerpTexture::Create(params, renderFromTexture, loc, arena);
    if (name == "checkerboard")
        return FloatCheckerboardTexture::Create(params, renderFromTexture, loc, arena);
    if (name == "imagemap") return FloatImageTexture::Create(params, renderFromTexture, loc, arena);
    if (name == "dots") return FloatDotsTexture::Create(params, renderFromTexture, loc, arena);
    if (name == "fbm") return FBmTexture::Create(params, renderFromTexture, arena);
    if (name == "wrinkled") return WrinkledTexture::Create(params, renderFromTexture, arena);
    if (name == "windy")
        return arena.New<WindyTexture>(TextureMapping3D::Create(renderFromTexture));
    if (IsUnsupportedTexture(name)) {
        diag.Warn(loc, "\"" + name + "\" float texture is not supported; using constant 0.5");
        return arena.New<FloatConstantTexture>(0.5f);
    }
    throw SceneError(
        loc, "unknown float texture type \"" + name + "\"" + DidYouMean(name, kTextures), name);
}

SpectrumTexture CreateSpectrumTexture(const std::string& name, const Transform& renderFromTexture,
                                      const TextureParameterDictionary& params, SpectrumType type,
                                      const FileLoc& loc, ObjectArena& arena, Diagnostics& diag) {
    if (name == "constant") return SpectrumConstantTexture::Create(params, type, arena);
    if (name == "scale") return SpectrumScaledTexture::Create(params, type, arena);
    if (name == "mix") return SpectrumMixTexture::Create(params, type, arena);
    if (name == "directionmix")
        return SpectrumDirectionMixTexture::Create(params, renderFromTexture, type, arena);
    if (name == "bilerp")
        return SpectrumBilerpTexture::Create(params, renderFromTexture, type, loc, arena);
    if (name == "checkerboard")
        return SpectrumCheckerboardTexture::Create(params, renderFromTexture, type, loc, arena);
    if (name == "imagemap")
        return SpectrumImageTexture::Create(params, renderFromTexture, type, loc, arena);
    if (name == "dots")
        return SpectrumDotsTexture::Create(params, renderFromTexture, type, loc, arena);
    if (name == "marble") return MarbleTexture::Create(params, renderFromTexture, arena);
    if (IsUnsupportedTexture(name)) {
        diag.Warn(loc, "\"" + name + "\" spectrum texture is not supported; using grey 0.5");
        return arena.New<SpectrumConstantTexture>(Spectrum(ConstantSpectrum(0.5f)));
    }
    throw SceneError(
        loc, "unknown spectrum texture type \"" + name + "\"" + DidYouMean(name, kTextures), name);
}

// Footprint use: every class says (one without UsesFootprint does not compile)
bool FloatTexture::UsesFootprint() const {
    return Dispatch([](auto t) { return t->UsesFootprint(); });
}

std::optional<Float> FloatTexture::ConstantValue() const {
    return Dispatch([](auto t) -> std::optional<Float> {
        if constexpr (std::is_same_v<std::decay_t<decltype(*t)>, FloatConstantTexture>)
            return t->Value();
        else
            return std::nullopt;
    });
}

bool SpectrumTexture::UsesFootprint() const {
    return Dispatch([](auto t) { return t->UsesFootprint(); });
}

}  // namespace kiln
