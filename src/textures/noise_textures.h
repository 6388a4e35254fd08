// Procedural noise textures of pbrt-v4: fbm, wrinkled, windy and dots (float and spectrum) and
// marble (spectrum). All are dimensionless patterns built on Perlin noise (noise.h).
#pragma once

#include "textures/texture.h"
#include "textures/texture_mapping.h"

namespace kiln {

// FBmTexture Definition
// "integer octaves" (8), "float roughness" (0.5: amplitude ratio between octaves).
class FBmTexture {
  public:
    bool UsesFootprint() const { return true; }  // octaves limited by the footprint
    FBmTexture(TextureMapping3D mapping, int octaves, Float omega)
        : mapping(mapping), octaves(octaves), omega(omega) {}
    Float Evaluate(const TextureEvalContext& ctx) const;
    static FBmTexture* Create(const TextureParameterDictionary& params,
                              const Transform& renderFromTexture, ObjectArena& arena);

  private:
    TextureMapping3D mapping;
    int octaves;
    Float omega;
};

// WrinkledTexture Definition
// Turbulence; same parameters as fbm.
class WrinkledTexture {
  public:
    bool UsesFootprint() const { return true; }  // octaves limited by the footprint
    WrinkledTexture(TextureMapping3D mapping, int octaves, Float omega)
        : mapping(mapping), octaves(octaves), omega(omega) {}
    Float Evaluate(const TextureEvalContext& ctx) const;
    static WrinkledTexture* Create(const TextureParameterDictionary& params,
                                   const Transform& renderFromTexture, ObjectArena& arena);

  private:
    TextureMapping3D mapping;
    int octaves;
    Float omega;
};

// WindyTexture Definition
// Wind-blown waves: |low-frequency fbm| times fbm.
class WindyTexture {
  public:
    bool UsesFootprint() const { return true; }  // octaves limited by the footprint
    explicit WindyTexture(TextureMapping3D mapping) : mapping(mapping) {}
    Float Evaluate(const TextureEvalContext& ctx) const;

  private:
    TextureMapping3D mapping;
};

// Whether a 2D point lies in one of the randomly placed dots of radius 0.35 (one cell in two
// has a dot).
bool InsidePolkaDot(Point2f st);

// FloatDotsTexture Definition
// The texture `inside` in the dots, `outside` elsewhere; 2D mapping parameters. Create gives the
// dots the parameter "outside" (0) and the rest "inside" (1), as pbrt-v4 renders them.
class FloatDotsTexture {
  public:
    // The dots themselves are not antialiased; the textures inside and outside may be
    bool UsesFootprint() const { return inside.UsesFootprint() || outside.UsesFootprint(); }
    FloatDotsTexture(TextureMapping2D mapping, FloatTexture inside, FloatTexture outside)
        : mapping(mapping), inside(inside), outside(outside) {}
    Float Evaluate(const TextureEvalContext& ctx) const {
        return InsidePolkaDot(mapping.Map(ctx).st) ? inside.Evaluate(ctx) : outside.Evaluate(ctx);
    }
    static FloatDotsTexture* Create(const TextureParameterDictionary& params,
                                    const Transform& renderFromTexture, const FileLoc& loc,
                                    ObjectArena& arena);

  private:
    TextureMapping2D mapping;
    FloatTexture inside, outside;
};

// SpectrumDotsTexture Definition
class SpectrumDotsTexture {
  public:
    // The dots themselves are not antialiased; the textures inside and outside may be
    bool UsesFootprint() const { return inside.UsesFootprint() || outside.UsesFootprint(); }
    SpectrumDotsTexture(TextureMapping2D mapping, SpectrumTexture inside, SpectrumTexture outside)
        : mapping(mapping), inside(inside), outside(outside) {}
    SampledSpectrum Evaluate(const TextureEvalContext& ctx,
                             const SampledWavelengths& lambda) const {
        return InsidePolkaDot(mapping.Map(ctx).st) ? inside.Evaluate(ctx, lambda)
                                                   : outside.Evaluate(ctx, lambda);
    }
    static SpectrumDotsTexture* Create(const TextureParameterDictionary& params,
                                       const Transform& renderFromTexture, SpectrumType type,
                                       const FileLoc& loc, ObjectArena& arena);

  private:
    TextureMapping2D mapping;
    SpectrumTexture inside, outside;
};

// MarbleTexture Definition
// Layers of sRGB colours perturbed by fbm: "integer octaves" (8), "float roughness" (0.5),
// "float scale" (1), "float variation" (0.2). Reflectance (albedo) values.
class MarbleTexture {
  public:
    bool UsesFootprint() const { return true; }  // octaves limited by the footprint
    MarbleTexture(TextureMapping3D mapping, int octaves, Float omega, Float scale, Float variation)
        : mapping(mapping), octaves(octaves), omega(omega), scale(scale), variation(variation) {}
    SampledSpectrum Evaluate(const TextureEvalContext& ctx, const SampledWavelengths& lambda) const;
    static MarbleTexture* Create(const TextureParameterDictionary& params,
                                 const Transform& renderFromTexture, ObjectArena& arena);

  private:
    TextureMapping3D mapping;
    int octaves;
    Float omega, scale, variation;
};

}  // namespace kiln
