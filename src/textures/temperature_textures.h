// Float textures that give temperatures (kelvin, by convention; the textures themselves are
// unit-agnostic) for thermal emission (`"texture temperature" "name"` on a shape or material):
//   gradient         linear ramp between two points
//   noise            3D gradient-noise fBm mapped into [min, max]
//   heatmap          image lookup (8-bit mapped through [tmin, tmax]; float images as they are),
//                    optionally an image sequence "heat.####.exr" indexed by "frame"
//   vertexattribute  per-vertex mesh attribute ("temperature" from PLY or trianglemesh)
//   cooling          lumped-capacitance cooling T(time) (spectral/cooling.h)
//   keyframes        piecewise-linear T(time) through (times, values)
// They compose with the other float textures ("scale", "mix", ...) like any float texture.
#pragma once

#include <array>
#include <string>

#include "base/transform.h"
#include "textures/texture.h"
#include "textures/texture_mapping.h"

namespace kiln {

class MIPMap;

// GradientTexture Definition
// t0 + (t1 - t0) s with s = dot(p - p0, p1 - p0) / |p1 - p0|^2, computed in the space of the
// points ("string space": "object", the texture's space given by the CTM at the Texture
// directive, default; or "world"). "string extrapolate": "clamp" (s clamped to [0, 1],
// default) or "linear". Parameters "point3 p0" (0 0 0), "point3 p1" (0 0 1), "float t0" (0),
// "float t1" (1).
class GradientTexture {
  public:
    bool UsesFootprint() const { return false; }  // smooth: nothing to filter
    GradientTexture(const Transform& spaceFromRender, Point3f p0, Point3f p1, Float t0, Float t1,
                    bool clamp);
    Float Evaluate(const TextureEvalContext& ctx) const;

    static GradientTexture* Create(const TextureParameterDictionary& params,
                                   const Transform& renderFromTexture, const FileLoc& loc,
                                   ObjectArena& arena);

  private:
    Transform spaceFromRender;
    Point3f p0;
    Vector3f dirOverLen2;  // (p1 - p0) / |p1 - p0|^2
    Float t0, t1;
    bool clamp;
};

// ThermalNoiseTexture Definition ("noise")
// fBm of improved Perlin noise (noise.h) in texture space: n = sum_{i < octaves} gain^i
// Noise(frequency lacunarity^i p + o_i), o_i a per-octave offset hashed from the seed (so a
// seed gives a different but deterministic field, and octaves do not all vanish at the same
// lattice points). Mapped to [min, max] through the fBm's bound B = sum gain^i (|Noise| <= 1):
// min + (max - min) clamp((1 + n / B) / 2, 0, 1) (max |Noise| measured 0.998 over 5e6
// random points). Values never leave [min, max] and are centred on (min + max) / 2; as for any
// fBm, most lie well inside: with the defaults the standard deviation is ~8% of max - min.
// Parameters "float frequency" (1, per texture-space unit), "integer octaves" (6), "float
// lacunarity" (2), "float gain" (0.5), "integer seed" (0), "float min" (0), "float max" (1).
class ThermalNoiseTexture {
  public:
    bool UsesFootprint() const { return false; }  // all octaves, unfiltered
    static constexpr int MaxOctaves = 16;
    ThermalNoiseTexture(TextureMapping3D mapping, Float frequency, int octaves, Float lacunarity,
                        Float gain, int seed, Float minValue, Float maxValue);
    Float Evaluate(const TextureEvalContext& ctx) const;
    // The fBm sum n at a texture-space point (about [-B, B]).
    Float FBm(Point3f p) const;
    Float Bound() const { return bound; }

    static ThermalNoiseTexture* Create(const TextureParameterDictionary& params,
                                       const Transform& renderFromTexture, const FileLoc& loc,
                                       ObjectArena& arena);

  private:
    TextureMapping3D mapping;
    Float frequency, lacunarity, gain;
    int octaves;
    Float minValue, maxValue, bound;
    std::array<Vector3f, MaxOctaves> offsets;
};

// HeatMapTexture Definition ("heatmap")
// An image lookup (as "imagemap": 2D mapping, t flipped so v = 0 is the bottom row; the first
// channel of multi-channel images) turned into a temperature. With "float tmin" and "float
// tmax" the value is tmin + v (tmax - tmin), v the linear image value (for 8-bit files the
// code value / 255: "encoding" defaults to linear here, unlike imagemap); without them the
// image values are the result (float EXR heat maps in kelvin). An 8-bit image without tmin /
// tmax warns. "string filename" may contain a run of '#' (e.g. "heat.####.exr"): it is
// replaced by "float frame" (0) as a zero-padded integer; a fractional frame blends the two
// neighbouring frames linearly. Also "string filter" (bilinear), "float maxanisotropy" (8),
// "string wrap" (clamp) and the mapping parameters.
class HeatMapTexture {
  public:
    bool UsesFootprint() const { return true; }  // MIP-map filtering
    HeatMapTexture(TextureMapping2D mapping, const MIPMap* frame0, const MIPMap* frame1,
                   Float frameWeight, Float offset, Float scale)
        : mapping(mapping),
          frame0(frame0),
          frame1(frame1),
          frameWeight(frameWeight),
          offset(offset),
          scale(scale) {}
    Float Evaluate(const TextureEvalContext& ctx) const;

    // The file name of a frame: the last run of '#' in the file name part of `pattern`
    // replaced by the zero-padded frame number; `pattern` itself when it has no '#'.
    static std::string FrameFilename(const std::string& pattern, int frame);

    // frame: the frame of a sequence unless "float frame" is given
    static HeatMapTexture* Create(const TextureParameterDictionary& params,
                                  const Transform& renderFromTexture, const FileLoc& loc,
                                  ObjectArena& arena, Diagnostics& diag, Float frame = 0);

  private:
    TextureMapping2D mapping;
    const MIPMap *frame0, *frame1;  // frame1 may be nullptr (no blending)
    Float frameWeight;              // weight of frame1
    Float offset, scale;            // value = offset + scale * v
};

// VertexAttributeTexture Definition ("vertexattribute")
// The per-vertex float attribute "string name" ("temperature") of the triangle mesh at the
// point, interpolated with the barycentrics (TextureEvalContext::mesh/triIndex/b); "float
// default" (0) where there is no mesh or the mesh lacks the attribute. (Bilinear-patch
// meshes, i.e. PLY quads, carry no attributes.)
class VertexAttributeTexture {
  public:
    bool UsesFootprint() const { return false; }  // interpolated at the hit
    VertexAttributeTexture(std::string name, Float defaultValue)
        : name(std::move(name)), defaultValue(defaultValue) {}
    Float Evaluate(const TextureEvalContext& ctx) const;

    static VertexAttributeTexture* Create(const TextureParameterDictionary& params,
                                          ObjectArena& arena);

  private:
    std::string name;
    Float defaultValue;
};

// TimeFunctionTexture Definition ("cooling", "keyframes")
// A value that depends only on "float time" (s), computed once when the texture is created:
//   cooling: T(time) of CoolingModel with "float T0" (1000 K), "float emissivity" (1),
//     "float area" (m^2, 1), "float mass" (kg) or "float density" (kg m^-3) with "float
//     thickness" (m; mass = density thickness area) or "float volume" (m^3), "float
//     specificheat" (J kg^-1 K^-1, 500), "float h" (W m^-2 K^-1, 0), "float Tambient" (K, 0).
//   keyframes: "float times" [...] (non-decreasing, s) and "float values" [...], linear
//     interpolation, clamped to the first / last value outside.
class TimeFunctionTexture {
  public:
    bool UsesFootprint() const { return false; }  // a function of time only
    explicit TimeFunctionTexture(Float value) : value(value) {}
    Float Evaluate(const TextureEvalContext&) const { return value; }
    Float Value() const { return value; }

    // time: seconds, unless "float time" is given
    static TimeFunctionTexture* CreateCooling(const TextureParameterDictionary& params,
                                              const FileLoc& loc, ObjectArena& arena,
                                              Float time = 0);
    static TimeFunctionTexture* CreateKeyframes(const TextureParameterDictionary& params,
                                                const FileLoc& loc, ObjectArena& arena,
                                                Float time = 0);

  private:
    Float value;
};

}  // namespace kiln
