// Temperature fields that vary over space (temperature_field.h): a linear gradient, fBm noise
// and a mesh's per-vertex attribute. Values in kelvin by convention (the fields themselves are
// unit-agnostic).
#pragma once

#include <array>
#include <string>

#include "base/transform.h"
#include "textures/texture_mapping.h"
#include "thermal/temperature_field.h"

namespace kiln {

// GradientField Definition ("gradient")
// t0 + (t1 - t0) s with s = dot(p - p0, p1 - p0) / |p1 - p0|^2, computed in the space of the
// points ("string space": "object", the texture's space given by the CTM at the Texture
// directive, default; or "world"). "string extrapolate": "clamp" (s clamped to [0, 1],
// default) or "linear". Parameters "point3 p0" (0 0 0), "point3 p1" (0 0 1), "float t0" (0),
// "float t1" (1).
class GradientField final : public TemperatureField {
  public:
    GradientField(const Transform& spaceFromRender, Point3f p0, Point3f p1, Float t0, Float t1,
                  bool clamp);
    Float Evaluate(const TextureEvalContext& ctx) const override;
    bool UsesFootprint() const override { return false; }  // smooth: nothing to filter

    static GradientField* Create(const TextureParameterDictionary& params,
                                 const Transform& renderFromTexture, const FileLoc& loc,
                                 ObjectArena& arena);

  private:
    Transform spaceFromRender;
    Point3f p0;
    Vector3f dirOverLen2;  // (p1 - p0) / |p1 - p0|^2
    Float t0, t1;
    bool clamp;
};

// NoiseField Definition ("noise")
// fBm of improved Perlin noise (textures/noise.h) in texture space: n = sum_{i < octaves}
// gain^i Noise(frequency lacunarity^i p + o_i), o_i a per-octave offset hashed from the seed
// (so a seed gives a different but deterministic field, and octaves do not all vanish at the
// same lattice points). Mapped to [min, max] through the fBm's bound B = sum gain^i
// (|Noise| <= 1): min + (max - min) clamp((1 + n / B) / 2, 0, 1) (max |Noise| measured 0.998
// over 5e6 random points). Values never leave [min, max] and are centred on (min + max) / 2;
// as for any fBm, most lie well inside: with the defaults the standard deviation is ~8% of
// max - min. Parameters "float frequency" (1, per texture-space unit), "integer octaves" (6),
// "float lacunarity" (2), "float gain" (0.5), "integer seed" (0), "float min" (0), "float
// max" (1).
class NoiseField final : public TemperatureField {
  public:
    static constexpr int MaxOctaves = 16;
    NoiseField(TextureMapping3D mapping, Float frequency, int octaves, Float lacunarity, Float gain,
               int seed, Float minValue, Float maxValue);
    Float Evaluate(const TextureEvalContext& ctx) const override;
    bool UsesFootprint() const override { return false; }  // all octaves, unfiltered
    // The fBm sum n at a texture-space point (about [-B, B]).
    Float FBm(Point3f p) const;
    Float Bound() const { return bound; }

    static NoiseField* Create(const TextureParameterDictionary& params,
                              const Transform& renderFromTexture, const FileLoc& loc,
                              ObjectArena& arena);

  private:
    TextureMapping3D mapping;
    Float frequency, lacunarity, gain;
    int octaves;
    Float minValue, maxValue, bound;
    std::array<Vector3f, MaxOctaves> offsets;
};

// VertexAttributeField Definition ("vertexattribute")
// The per-vertex float attribute "string name" ("temperature") of the triangle mesh at the
// point, interpolated with the barycentrics (TextureEvalContext::mesh/triIndex/b); "float
// default" (0) where there is no mesh or the mesh lacks the attribute. (Bilinear-patch
// meshes, i.e. PLY quads, carry no attributes.) Shapes whose mesh has a "temperature"
// attribute and no other temperature get one of these.
class VertexAttributeField final : public TemperatureField {
  public:
    VertexAttributeField(std::string name, Float defaultValue)
        : name(std::move(name)), defaultValue(defaultValue) {}
    Float Evaluate(const TextureEvalContext& ctx) const override;
    bool UsesFootprint() const override { return false; }  // interpolated at the hit

    static VertexAttributeField* Create(const TextureParameterDictionary& params,
                                        ObjectArena& arena);

  private:
    std::string name;
    Float defaultValue;
};

}  // namespace kiln
