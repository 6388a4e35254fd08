#include "textures/basic_textures.h"

#include "textures/texture_parameter_dictionary.h"

namespace kiln {

namespace {

Spectrum Constant(Float c) { return Spectrum(ConstantSpectrum(c)); }

}  // namespace

// Constant textures
FloatConstantTexture* FloatConstantTexture::Create(const TextureParameterDictionary& params,
                                                   ObjectArena& arena) {
    return arena.New<FloatConstantTexture>(params.GetOneFloat("value", 1));
}

SpectrumConstantTexture* SpectrumConstantTexture::Create(const TextureParameterDictionary& params,
                                                         SpectrumType type, ObjectArena& arena) {
    std::optional<Spectrum> s = params.GetOneSpectrum("value", Constant(1), type);
    return arena.New<SpectrumConstantTexture>(*s);
}

// Scaled textures
FloatTexture FloatScaledTexture::Create(const TextureParameterDictionary& params,
                                        ObjectArena& arena) {
    FloatTexture tex = params.GetFloatTexture("tex", 1, arena);
    FloatTexture scale = params.GetFloatTexture("scale", 1, arena);
    // A constant factor of 1 leaves the other texture as it is
    if (auto c = scale.GetIf<FloatConstantTexture>(); c && c->Value() == 1) return tex;
    if (auto c = tex.GetIf<FloatConstantTexture>(); c && c->Value() == 1) return scale;
    return arena.New<FloatScaledTexture>(tex, scale);
}

SpectrumTexture SpectrumScaledTexture::Create(const TextureParameterDictionary& params,
                                              SpectrumType type, ObjectArena& arena) {
    SpectrumTexture tex = params.GetSpectrumTexture("tex", Constant(1), type, arena);
    FloatTexture scale = params.GetFloatTexture("scale", 1, arena);
    if (auto c = scale.GetIf<FloatConstantTexture>(); c && c->Value() == 1) return tex;
    return arena.New<SpectrumScaledTexture>(tex, scale);
}

// Mix textures
FloatMixTexture* FloatMixTexture::Create(const TextureParameterDictionary& params,
                                         ObjectArena& arena) {
    return arena.New<FloatMixTexture>(params.GetFloatTexture("tex1", 0, arena),
                                      params.GetFloatTexture("tex2", 1, arena),
                                      params.GetFloatTexture("amount", 0.5f, arena));
}

SpectrumMixTexture* SpectrumMixTexture::Create(const TextureParameterDictionary& params,
                                               SpectrumType type, ObjectArena& arena) {
    return arena.New<SpectrumMixTexture>(
        params.GetSpectrumTexture("tex1", Constant(0), type, arena),
        params.GetSpectrumTexture("tex2", Constant(1), type, arena),
        params.GetFloatTexture("amount", 0.5f, arena));
}

// Direction mix textures
static Vector3f MixDirection(const TextureParameterDictionary& params,
                             const Transform& renderFromTexture) {
    Vector3f dir = renderFromTexture(params.GetOneVector3f("dir", Vector3f(0, 1, 0)));
    return LengthSquared(dir) > 0 ? Normalize(dir) : Vector3f(0, 1, 0);
}

FloatDirectionMixTexture* FloatDirectionMixTexture::Create(const TextureParameterDictionary& params,
                                                           const Transform& renderFromTexture,
                                                           ObjectArena& arena) {
    return arena.New<FloatDirectionMixTexture>(params.GetFloatTexture("tex1", 0, arena),
                                               params.GetFloatTexture("tex2", 1, arena),
                                               MixDirection(params, renderFromTexture));
}

SpectrumDirectionMixTexture* SpectrumDirectionMixTexture::Create(
    const TextureParameterDictionary& params, const Transform& renderFromTexture, SpectrumType type,
    ObjectArena& arena) {
    return arena.New<SpectrumDirectionMixTexture>(
        params.GetSpectrumTexture("tex1", Constant(0), type, arena),
        params.GetSpectrumTexture("tex2", Constant(1), type, arena),
        MixDirection(params, renderFromTexture));
}

// Bilerp textures
FloatBilerpTexture* FloatBilerpTexture::Create(const TextureParameterDictionary& params,
                                               const Transform& renderFromTexture,
                                               const FileLoc& loc, ObjectArena& arena) {
    return arena.New<FloatBilerpTexture>(
        TextureMapping2D::Create(params, renderFromTexture, loc), params.GetOneFloat("v00", 0),
        params.GetOneFloat("v01", 1), params.GetOneFloat("v10", 0), params.GetOneFloat("v11", 1));
}

SpectrumBilerpTexture* SpectrumBilerpTexture::Create(const TextureParameterDictionary& params,
                                                     const Transform& renderFromTexture,
                                                     SpectrumType type, const FileLoc& loc,
                                                     ObjectArena& arena) {
    auto get = [&](const char* name, Float def) {
        return *params.GetOneSpectrum(name, Constant(def), type);
    };
    return arena.New<SpectrumBilerpTexture>(
        TextureMapping2D::Create(params, renderFromTexture, loc), get("v00", 0), get("v01", 1),
        get("v10", 0), get("v11", 1));
}

}  // namespace kiln
