#include "thermal/spatial_temperature_fields.h"

#include <algorithm>
#include <cmath>

#include "base/rng.h"
// Only the inline parts of TriangleMesh are used (the mesh's vertex indices and attributes).
#include "core/geometry/triangle.h"
#include "textures/noise.h"
#include "textures/texture_parameter_dictionary.h"

namespace kiln {

// GradientField Method Definitions
GradientField::GradientField(const Transform& spaceFromRender, Point3f p0, Point3f p1, Float t0,
                             Float t1, bool clamp)
    : spaceFromRender(spaceFromRender), p0(p0), t0(t0), t1(t1), clamp(clamp) {
    Vector3f d = p1 - p0;
    dirOverLen2 = d / LengthSquared(d);
}

Float GradientField::Evaluate(const TextureEvalContext& ctx) const {
    Point3f p = spaceFromRender(ctx.p);
    Float s = Dot(p - p0, dirOverLen2);
    if (clamp) s = Clamp(s, Float(0), Float(1));
    return t0 + (t1 - t0) * s;
}

GradientField* GradientField::Create(const TextureParameterDictionary& params,
                                     const Transform& renderFromTexture, const FileLoc& loc,
                                     ObjectArena& arena) {
    Point3f p0 = params.GetOnePoint3f("p0", Point3f(0, 0, 0));
    Point3f p1 = params.GetOnePoint3f("p1", Point3f(0, 0, 1));
    if (p0 == p1) throw SceneError(params.Loc("p1", loc), "gradient needs p0 != p1", "p1");
    Float t0 = params.GetOneFloat("t0", 0), t1 = params.GetOneFloat("t1", 1);
    std::string space = params.GetOneString("space", "object");
    Transform spaceFromRender;
    if (space == "object")
        spaceFromRender = Inverse(renderFromTexture);
    else if (space == "world")
        spaceFromRender =
            params.Textures() ? Inverse(params.Textures()->renderFromWorld) : Transform();
    else
        throw SceneError(params.Loc("space", loc),
                         "unknown gradient space \"" + space + "\" (object or world)", space);
    std::string extrapolate = params.GetOneString("extrapolate", "clamp");
    if (extrapolate != "clamp" && extrapolate != "linear")
        throw SceneError(params.Loc("extrapolate", loc),
                         "unknown extrapolation \"" + extrapolate + "\" (clamp or linear)",
                         extrapolate);
    return arena.New<GradientField>(spaceFromRender, p0, p1, t0, t1, extrapolate == "clamp");
}

// NoiseField Method Definitions
NoiseField::NoiseField(TextureMapping3D mapping, Float frequency, int octaves, Float lacunarity,
                       Float gain, int seed, Float minValue, Float maxValue)
    : mapping(mapping),
      frequency(frequency),
      lacunarity(lacunarity),
      gain(gain),
      octaves(std::clamp(octaves, 1, MaxOctaves)),
      minValue(minValue),
      maxValue(maxValue) {
    bound = 0;
    Float o = 1;
    for (int i = 0; i < this->octaves; ++i, o *= gain) bound += std::abs(o);
    // Offsets in [0, 64)^3: decorrelate the octaves and select the field for the seed (the
    // noise's lattice repeats every 256 units, so larger offsets would add nothing).
    for (int i = 0; i < MaxOctaves; ++i) {
        uint64_t h = Hash(uint64_t(uint32_t(seed)), uint64_t(i), uint64_t(0x7e3a1d));
        auto unit = [](uint64_t bits) { return Float(bits & 0xffffff) / Float(1 << 24); };
        offsets[i] = Float(64) * Vector3f(unit(h), unit(h >> 21), unit(h >> 42));
    }
}

Float NoiseField::FBm(Point3f p) const {
    Float sum = 0, o = 1, f = frequency;
    for (int i = 0; i < octaves; ++i) {
        sum += o * Noise(Point3f(f * p.x, f * p.y, f * p.z) + offsets[i]);
        f *= lacunarity;
        o *= gain;
    }
    return sum;
}

Float NoiseField::Evaluate(const TextureEvalContext& ctx) const {
    Float n = bound > 0 ? FBm(mapping.Map(ctx).p) / bound : 0;
    Float u = Clamp(Float(0.5) * (1 + n), Float(0), Float(1));
    return minValue + (maxValue - minValue) * u;
}

NoiseField* NoiseField::Create(const TextureParameterDictionary& params,
                               const Transform& renderFromTexture, const FileLoc& loc,
                               ObjectArena& arena) {
    int octaves = params.GetOneInt("octaves", 6);
    if (octaves < 1 || octaves > MaxOctaves)
        throw SceneError(params.Loc("octaves", loc),
                         "noise \"octaves\" must be in [1, " + std::to_string(MaxOctaves) + "]",
                         "octaves");
    return arena.New<NoiseField>(
        TextureMapping3D::Create(renderFromTexture), params.GetOneFloat("frequency", 1), octaves,
        params.GetOneFloat("lacunarity", 2), params.GetOneFloat("gain", 0.5f),
        params.GetOneInt("seed", 0), params.GetOneFloat("min", 0), params.GetOneFloat("max", 1));
}

// VertexAttributeField Method Definitions
Float VertexAttributeField::Evaluate(const TextureEvalContext& ctx) const {
    if (!ctx.mesh) return defaultValue;
    auto it = ctx.mesh->attributes.find(name);
    if (it == ctx.mesh->attributes.end()) return defaultValue;
    auto v = ctx.mesh->VertexIndices(ctx.triIndex);
    const std::vector<Float>& a = it->second;
    return ctx.b[0] * a[v[0]] + ctx.b[1] * a[v[1]] + ctx.b[2] * a[v[2]];
}

VertexAttributeField* VertexAttributeField::Create(const TextureParameterDictionary& params,
                                                   ObjectArena& arena) {
    return arena.New<VertexAttributeField>(params.GetOneString("name", "temperature"),
                                           params.GetOneFloat("default", 0));
}

}  // namespace kiln
