// The simple textures of pbrt-v4: constant, scale, mix, directionmix and bilerp, each in a
// float and a spectrum version. Values are dimensionless for float textures; spectrum
// textures carry the unit of the SpectrumType they were created for.
#pragma once

#include "spectral/spectrum.h"
#include "textures/texture.h"
#include "textures/texture_mapping.h"

namespace kiln {

// FloatConstantTexture Definition
class FloatConstantTexture {
  public:
    bool UsesFootprint() const { return false; }  // the same everywhere
    explicit FloatConstantTexture(Float value) : value(value) {}
    Float Evaluate(const TextureEvalContext&) const { return value; }
    Float Value() const { return value; }

    // "float value" (1).
    static FloatConstantTexture* Create(const TextureParameterDictionary& params,
                                        ObjectArena& arena);

  private:
    Float value;
};

// SpectrumConstantTexture Definition
class SpectrumConstantTexture {
  public:
    bool UsesFootprint() const { return false; }  // the same everywhere
    explicit SpectrumConstantTexture(Spectrum value) : value(std::move(value)) {}
    SampledSpectrum Evaluate(const TextureEvalContext&, const SampledWavelengths& lambda) const {
        return value.Sample(lambda);
    }
    const Spectrum& Value() const { return value; }

    // "spectrum value" (constant 1).
    static SpectrumConstantTexture* Create(const TextureParameterDictionary& params,
                                           SpectrumType type, ObjectArena& arena);

  private:
    Spectrum value;
};

// FloatScaledTexture Definition
// tex * scale.
class FloatScaledTexture {
  public:
    FloatScaledTexture(FloatTexture tex, FloatTexture scale) : tex(tex), scale(scale) {}
    Float Evaluate(const TextureEvalContext& ctx) const {
        Float sc = scale.Evaluate(ctx);
        return sc == 0 ? 0 : tex.Evaluate(ctx) * sc;
    }
    bool UsesFootprint() const { return tex.UsesFootprint() || scale.UsesFootprint(); }

    // "texture|float tex" (1), "texture|float scale" (1); a constant scale of 1 returns tex.
    static FloatTexture Create(const TextureParameterDictionary& params, ObjectArena& arena);

  private:
    FloatTexture tex, scale;
};

// SpectrumScaledTexture Definition
class SpectrumScaledTexture {
  public:
    SpectrumScaledTexture(SpectrumTexture tex, FloatTexture scale) : tex(tex), scale(scale) {}
    SampledSpectrum Evaluate(const TextureEvalContext& ctx,
                             const SampledWavelengths& lambda) const {
        Float sc = scale.Evaluate(ctx);
        return sc == 0 ? SampledSpectrum(0) : tex.Evaluate(ctx, lambda) * sc;
    }
    bool UsesFootprint() const { return tex.UsesFootprint() || scale.UsesFootprint(); }

    // "texture|spectrum tex" (1), "texture|float scale" (1).
    static SpectrumTexture Create(const TextureParameterDictionary& params, SpectrumType type,
                                  ObjectArena& arena);

  private:
    SpectrumTexture tex;
    FloatTexture scale;
};

// FloatMixTexture Definition
// (1 - amount) tex1 + amount tex2.
class FloatMixTexture {
  public:
    FloatMixTexture(FloatTexture tex1, FloatTexture tex2, FloatTexture amount)
        : tex1(tex1), tex2(tex2), amount(amount) {}
    Float Evaluate(const TextureEvalContext& ctx) const {
        Float amt = amount.Evaluate(ctx);
        Float t1 = amt != 1 ? tex1.Evaluate(ctx) : 0;
        Float t2 = amt != 0 ? tex2.Evaluate(ctx) : 0;
        return (1 - amt) * t1 + amt * t2;
    }
    bool UsesFootprint() const {
        return tex1.UsesFootprint() || tex2.UsesFootprint() || amount.UsesFootprint();
    }

    // "tex1" (0), "tex2" (1), "float amount" (0.5).
    static FloatMixTexture* Create(const TextureParameterDictionary& params, ObjectArena& arena);

  private:
    FloatTexture tex1, tex2, amount;
};

// SpectrumMixTexture Definition
class SpectrumMixTexture {
  public:
    SpectrumMixTexture(SpectrumTexture tex1, SpectrumTexture tex2, FloatTexture amount)
        : tex1(tex1), tex2(tex2), amount(amount) {}
    SampledSpectrum Evaluate(const TextureEvalContext& ctx,
                             const SampledWavelengths& lambda) const {
        Float amt = amount.Evaluate(ctx);
        SampledSpectrum t1, t2;
        if (amt != 1) t1 = tex1.Evaluate(ctx, lambda);
        if (amt != 0) t2 = tex2.Evaluate(ctx, lambda);
        return (1 - amt) * t1 + amt * t2;
    }
    bool UsesFootprint() const {
        return tex1.UsesFootprint() || tex2.UsesFootprint() || amount.UsesFootprint();
    }

    static SpectrumMixTexture* Create(const TextureParameterDictionary& params, SpectrumType type,
                                      ObjectArena& arena);

  private:
    SpectrumTexture tex1, tex2;
    FloatTexture amount;
};

// FloatDirectionMixTexture Definition
// a tex1 + (1 - a) tex2 with a = |n . dir|, dir a unit render-space direction.
class FloatDirectionMixTexture {
  public:
    FloatDirectionMixTexture(FloatTexture tex1, FloatTexture tex2, Vector3f dir)
        : tex1(tex1), tex2(tex2), dir(dir) {}
    Float Evaluate(const TextureEvalContext& ctx) const {
        Float amt = AbsDot(ctx.n, dir);
        Float t1 = amt != 0 ? tex1.Evaluate(ctx) : 0;
        Float t2 = amt != 1 ? tex2.Evaluate(ctx) : 0;
        return amt * t1 + (1 - amt) * t2;
    }
    bool UsesFootprint() const { return tex1.UsesFootprint() || tex2.UsesFootprint(); }

    // "tex1" (0), "tex2" (1), "vector3 dir" (0 1 0, in texture space).
    static FloatDirectionMixTexture* Create(const TextureParameterDictionary& params,
                                            const Transform& renderFromTexture, ObjectArena& arena);

  private:
    FloatTexture tex1, tex2;
    Vector3f dir;
};

// SpectrumDirectionMixTexture Definition
class SpectrumDirectionMixTexture {
  public:
    SpectrumDirectionMixTexture(SpectrumTexture tex1, SpectrumTexture tex2, Vector3f dir)
        : tex1(tex1), tex2(tex2), dir(dir) {}
    SampledSpectrum Evaluate(const TextureEvalContext& ctx,
                             const SampledWavelengths& lambda) const {
        Float amt = AbsDot(ctx.n, dir);
        SampledSpectrum t1, t2;
        if (amt != 0) t1 = tex1.Evaluate(ctx, lambda);
        if (amt != 1) t2 = tex2.Evaluate(ctx, lambda);
        return amt * t1 + (1 - amt) * t2;
    }
    bool UsesFootprint() const { return tex1.UsesFootprint() || tex2.UsesFootprint(); }

    static SpectrumDirectionMixTexture* Create(const TextureParameterDictionary& params,
                                               const Transform& renderFromTexture,
                                               SpectrumType type, ObjectArena& arena);

  private:
    SpectrumTexture tex1, tex2;
    Vector3f dir;
};

// FloatBilerpTexture Definition
// Bilinear interpolation of v00, v01, v10, v11 at st = (s, t) of the 2D mapping.
class FloatBilerpTexture {
  public:
    bool UsesFootprint() const { return false; }  // smooth: nothing to filter
    FloatBilerpTexture(TextureMapping2D mapping, Float v00, Float v01, Float v10, Float v11)
        : mapping(mapping), v00(v00), v01(v01), v10(v10), v11(v11) {}
    Float Evaluate(const TextureEvalContext& ctx) const {
        TexCoord2D c = mapping.Map(ctx);
        Float s = c.st.x, t = c.st.y;
        return (1 - s) * (1 - t) * v00 + (1 - s) * t * v01 + s * (1 - t) * v10 + s * t * v11;
    }

    // "float v00, v01, v10, v11" (0, 1, 0, 1) and the mapping parameters.
    static FloatBilerpTexture* Create(const TextureParameterDictionary& params,
                                      const Transform& renderFromTexture, const FileLoc& loc,
                                      ObjectArena& arena);

  private:
    TextureMapping2D mapping;
    Float v00, v01, v10, v11;
};

// SpectrumBilerpTexture Definition
class SpectrumBilerpTexture {
  public:
    bool UsesFootprint() const { return false; }  // smooth: nothing to filter
    SpectrumBilerpTexture(TextureMapping2D mapping, Spectrum v00, Spectrum v01, Spectrum v10,
                          Spectrum v11)
        : mapping(mapping), v00(v00), v01(v01), v10(v10), v11(v11) {}
    SampledSpectrum Evaluate(const TextureEvalContext& ctx,
                             const SampledWavelengths& lambda) const {
        TexCoord2D c = mapping.Map(ctx);
        Float s = c.st.x, t = c.st.y;
        return (1 - s) * (1 - t) * v00.Sample(lambda) + (1 - s) * t * v01.Sample(lambda) +
               s * (1 - t) * v10.Sample(lambda) + s * t * v11.Sample(lambda);
    }

    // "spectrum v00, v01, v10, v11" (constant 0, 1, 0, 1) and the mapping parameters.
    static SpectrumBilerpTexture* Create(const TextureParameterDictionary& params,
                                         const Transform& renderFromTexture, SpectrumType type,
                                         const FileLoc& loc, ObjectArena& arena);

  private:
    TextureMapping2D mapping;
    Spectrum v00, v01, v10, v11;
};

}  // namespace kiln
