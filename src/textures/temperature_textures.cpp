#include "textures/temperature_textures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "base/rng.h"
#include "core/image/mipmap.h"
// Only the inline parts of TriangleMesh are used (kiln_textures does not link kiln_geometry).
#include "core/geometry/triangle.h"
#include "spectral/cooling.h"
#include "textures/image_texture.h"
#include "textures/noise.h"
#include "textures/texture_parameter_dictionary.h"

namespace kiln {

namespace {

FileLoc LocOf(const TextureParameterDictionary& params, const char* name, const FileLoc& loc) {
    return params.Has(name) ? params.Loc(name) : loc;
}

}  // namespace

// GradientTexture Method Definitions
GradientTexture::GradientTexture(const Transform& spaceFromRender, Point3f p0, Point3f p1, Float t0,
                                 Float t1, bool clamp)
    : spaceFromRender(spaceFromRender), p0(p0), t0(t0), t1(t1), clamp(clamp) {
    Vector3f d = p1 - p0;
    dirOverLen2 = d / LengthSquared(d);
}

Float GradientTexture::Evaluate(const TextureEvalContext& ctx) const {
    Point3f p = spaceFromRender(ctx.p);
    Float s = Dot(p - p0, dirOverLen2);
    if (clamp) s = Clamp(s, Float(0), Float(1));
    return t0 + (t1 - t0) * s;
}

GradientTexture* GradientTexture::Create(const TextureParameterDictionary& params,
                                         const Transform& renderFromTexture, const FileLoc& loc,
                                         ObjectArena& arena) {
    Point3f p0 = params.GetOnePoint3f("p0", Point3f(0, 0, 0));
    Point3f p1 = params.GetOnePoint3f("p1", Point3f(0, 0, 1));
    if (p0 == p1) throw SceneError(LocOf(params, "p1", loc), "gradient needs p0 != p1", "p1");
    Float t0 = params.GetOneFloat("t0", 0), t1 = params.GetOneFloat("t1", 1);
    std::string space = params.GetOneString("space", "object");
    Transform spaceFromRender;
    if (space == "object")
        spaceFromRender = Inverse(renderFromTexture);
    else if (space == "world")
        spaceFromRender =
            params.Textures() ? Inverse(params.Textures()->renderFromWorld) : Transform();
    else
        throw SceneError(LocOf(params, "space", loc),
                         "unknown gradient space \"" + space + "\" (object or world)", space);
    std::string extrapolate = params.GetOneString("extrapolate", "clamp");
    if (extrapolate != "clamp" && extrapolate != "linear")
        throw SceneError(LocOf(params, "extrapolate", loc),
                         "unknown extrapolation \"" + extrapolate + "\" (clamp or linear)",
                         extrapolate);
    return arena.New<GradientTexture>(spaceFromRender, p0, p1, t0, t1, extrapolate == "clamp");
}

// ThermalNoiseTexture Method Definitions
ThermalNoiseTexture::ThermalNoiseTexture(TextureMapping3D mapping, Float frequency, int octaves,
                                         Float lacunarity, Float gain, int seed, Float minValue,
                                         Float maxValue)
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

Float ThermalNoiseTexture::FBm(Point3f p) const {
    Float sum = 0, o = 1, f = frequency;
    for (int i = 0; i < octaves; ++i) {
        sum += o * Noise(Point3f(f * p.x, f * p.y, f * p.z) + offsets[i]);
        f *= lacunarity;
        o *= gain;
    }
    return sum;
}

Float ThermalNoiseTexture::Evaluate(const TextureEvalContext& ctx) const {
    Float n = bound > 0 ? FBm(mapping.Map(ctx).p) / bound : 0;
    Float u = Clamp(Float(0.5) * (1 + n), Float(0), Float(1));
    return minValue + (maxValue - minValue) * u;
}

ThermalNoiseTexture* ThermalNoiseTexture::Create(const TextureParameterDictionary& params,
                                                 const Transform& renderFromTexture,
                                                 const FileLoc& loc, ObjectArena& arena) {
    int octaves = params.GetOneInt("octaves", 6);
    if (octaves < 1 || octaves > MaxOctaves)
        throw SceneError(LocOf(params, "octaves", loc),
                         "noise \"octaves\" must be in [1, " + std::to_string(MaxOctaves) + "]",
                         "octaves");
    return arena.New<ThermalNoiseTexture>(
        TextureMapping3D::Create(renderFromTexture), params.GetOneFloat("frequency", 1), octaves,
        params.GetOneFloat("lacunarity", 2), params.GetOneFloat("gain", 0.5f),
        params.GetOneInt("seed", 0), params.GetOneFloat("min", 0), params.GetOneFloat("max", 1));
}

// HeatMapTexture Method Definitions
Float HeatMapTexture::Evaluate(const TextureEvalContext& ctx) const {
    TexCoord2D c = mapping.Map(ctx);
    c.st.y = 1 - c.st.y;  // pbrt-v4: t = 0 is the bottom of the image
    Vector2f d0(c.dsdx, -c.dtdx), d1(c.dsdy, -c.dtdy);
    Float v = frame0->Filter<Float>(c.st, d0, d1);
    if (frame1) v = (1 - frameWeight) * v + frameWeight * frame1->Filter<Float>(c.st, d0, d1);
    return offset + scale * v;
}

std::string HeatMapTexture::FrameFilename(const std::string& pattern, int frame) {
    size_t slash = pattern.find_last_of("/\\");
    size_t nameStart = slash == std::string::npos ? 0 : slash + 1;
    size_t last = pattern.find_last_of('#');
    if (last == std::string::npos || last < nameStart) return pattern;
    size_t first = last;
    while (first > nameStart && pattern[first - 1] == '#') --first;
    int width = int(last - first + 1);
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%0*d", width, frame);
    return pattern.substr(0, first) + buf + pattern.substr(last + 1);
}

HeatMapTexture* HeatMapTexture::Create(const TextureParameterDictionary& params,
                                       const Transform& renderFromTexture, const FileLoc& loc,
                                       ObjectArena& arena, Diagnostics& diag, Float frame) {
    std::string pattern = params.GetOneFilename("filename", "");
    if (pattern.empty()) throw SceneError(loc, "\"filename\" must be given for heatmap");
    TextureMapping2D mapping = TextureMapping2D::Create(params, renderFromTexture, loc);

    MIPMapFilterOptions options;
    std::string filterName = params.GetOneString("filter", "bilinear");
    auto filter = ParseFilter(filterName);
    if (!filter)
        throw SceneError(LocOf(params, "filter", loc),
                         "unknown image filter \"" + filterName + "\"", filterName);
    options.filter = *filter;
    options.maxAnisotropy = params.GetOneFloat("maxanisotropy", 8);
    std::string wrapName = params.GetOneString("wrap", "clamp");
    std::optional<WrapMode> wrap = ParseWrapMode(wrapName);
    if (!wrap)
        throw SceneError(LocOf(params, "wrap", loc), "unknown wrap mode \"" + wrapName + "\"",
                         wrapName);
    std::string encodingName = params.GetOneString("encoding", "linear");
    std::optional<ColorEncoding> encoding = ColorEncoding::Parse(encodingName);
    if (!encoding)
        throw SceneError(LocOf(params, "encoding", loc),
                         "unknown color encoding \"" + encodingName + "\"", encodingName);

    ImageTextureCache* cache = params.Textures() ? params.Textures()->imageCache.get() : nullptr;
    auto load = [&](int frame) {
        std::string filename = FrameFilename(pattern, frame);
        std::ostringstream key;
        key << "heatmap\n"
            << filename << '\n'
            << filterName << '\n'
            << options.maxAnisotropy << '\n'
            << ToString(*wrap) << '\n'
            << encoding->ToString();
        if (cache)
            if (const MIPMap* m = cache->Find(key.str())) return m;
        const MIPMap* m = nullptr;
        try {
            m = MIPMap::CreateFromFile(filename, options, *wrap, *encoding, arena);
        } catch (const std::exception& e) {
            throw SceneError(LocOf(params, "filename", loc),
                             std::string("cannot read heat map: ") + e.what(), filename);
        }
        if (!m) throw SceneError(LocOf(params, "filename", loc), "cannot read heat map", filename);
        if (cache) cache->Insert(key.str(), m);
        return m;
    };

    frame = params.GetOneFloat("frame", frame);
    bool sequence = FrameFilename(pattern, 0) != pattern;
    int f0 = sequence ? int(std::floor(frame)) : 0;
    Float w = sequence ? frame - Float(f0) : 0;
    const MIPMap* m0 = load(f0);
    const MIPMap* m1 = w > 0 ? load(f0 + 1) : nullptr;

    Float offset = 0, scale = 1;
    bool hasMin = params.Has("tmin"), hasMax = params.Has("tmax");
    if (hasMin != hasMax)
        throw SceneError(LocOf(params, hasMin ? "tmin" : "tmax", loc),
                         "heatmap needs both \"tmin\" and \"tmax\"", hasMin ? "tmin" : "tmax");
    if (hasMin) {
        offset = params.GetOneFloat("tmin", 0);
        scale = params.GetOneFloat("tmax", 1) - offset;
    } else if (m0->GetLevel(0).Format() == PixelFormat::U256) {
        diag.Warn(loc,
                  "8-bit heat map \"" + pattern +
                      "\" without \"tmin\"/\"tmax\": its values in [0, 1] are used as they are");
    }
    return arena.New<HeatMapTexture>(mapping, m0, m1, w, offset, scale);
}

// VertexAttributeTexture Method Definitions
Float VertexAttributeTexture::Evaluate(const TextureEvalContext& ctx) const {
    if (!ctx.mesh) return defaultValue;
    auto it = ctx.mesh->attributes.find(name);
    if (it == ctx.mesh->attributes.end()) return defaultValue;
    auto v = ctx.mesh->VertexIndices(ctx.triIndex);
    const std::vector<Float>& a = it->second;
    return ctx.b[0] * a[v[0]] + ctx.b[1] * a[v[1]] + ctx.b[2] * a[v[2]];
}

VertexAttributeTexture* VertexAttributeTexture::Create(const TextureParameterDictionary& params,
                                                       ObjectArena& arena) {
    return arena.New<VertexAttributeTexture>(params.GetOneString("name", "temperature"),
                                             params.GetOneFloat("default", 0));
}

// TimeFunctionTexture Method Definitions
TimeFunctionTexture* TimeFunctionTexture::CreateCooling(const TextureParameterDictionary& params,
                                                        const FileLoc& loc, ObjectArena& arena,
                                                        Float time) {
    auto positive = [&](const char* name, Float def) {
        Float v = params.GetOneFloat(name, def);
        if (!(v > 0))
            throw SceneError(LocOf(params, name, loc),
                             std::string("cooling \"") + name + "\" must be positive", name);
        return double(v);
    };
    CoolingParameters p;
    p.T0 = params.GetOneFloat("T0", 1000);
    p.emissivity = params.GetOneFloat("emissivity", 1);
    p.area = positive("area", 1);
    p.specificHeat = positive("specificheat", 500);
    p.h = params.GetOneFloat("h", 0);
    p.Tambient = params.GetOneFloat("Tambient", 0);
    if (p.T0 < 0 || p.Tambient < 0 || p.h < 0 || p.emissivity < 0 || p.emissivity > 1)
        throw SceneError(loc, "cooling needs T0, Tambient, h >= 0 and emissivity in [0, 1]",
                         "cooling");
    if (params.Has("mass"))
        p.mass = positive("mass", 1);
    else if (params.Has("density") && params.Has("thickness"))
        p.mass =
            CoolingParameters::SlabMass(positive("density", 1), positive("thickness", 1), p.area);
    else if (params.Has("density") && params.Has("volume"))
        p.mass = CoolingParameters::BodyMass(positive("density", 1), positive("volume", 1));
    else
        throw SceneError(loc,
                         "cooling needs \"mass\", or \"density\" with \"thickness\" or "
                         "\"volume\"",
                         "cooling");
    time = params.GetOneFloat("time", time);
    return arena.New<TimeFunctionTexture>(Float(CoolingModel(p).Temperature(time)));
}

TimeFunctionTexture* TimeFunctionTexture::CreateKeyframes(const TextureParameterDictionary& params,
                                                          const FileLoc& loc, ObjectArena& arena,
                                                          Float time) {
    std::vector<Float> times = params.GetFloatArray("times");
    std::vector<Float> values = params.GetFloatArray("values");
    if (times.empty() || times.size() != values.size())
        throw SceneError(LocOf(params, "values", loc),
                         "keyframes need \"times\" and \"values\" of the same, non-zero length",
                         "values");
    if (!std::is_sorted(times.begin(), times.end()))
        throw SceneError(LocOf(params, "times", loc), "keyframe \"times\" must not decrease",
                         "times");
    Float t = params.GetOneFloat("time", time);
    Float value;
    if (t <= times.front()) {
        value = values.front();
    } else if (t >= times.back()) {
        value = values.back();
    } else {
        size_t i = size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
        Float w = (t - times[i]) / (times[i + 1] - times[i]);
        value = (1 - w) * values[i] + w * values[i + 1];
    }
    return arena.New<TimeFunctionTexture>(value);
}

}  // namespace kiln
