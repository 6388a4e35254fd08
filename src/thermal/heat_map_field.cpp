#include "thermal/heat_map_field.h"

#include <cmath>
#include <cstdio>

#include "textures/texture_parameter_dictionary.h"

namespace kiln {

// HeatMapField Method Definitions
HeatMapField::~HeatMapField() { budget.Release(chargedBytes); }

Float HeatMapField::Evaluate(const TextureEvalContext& ctx) const {
    TexCoord2D c = mapping.Map(ctx);
    c.st.y = 1 - c.st.y;  // pbrt-v4: t = 0 is the bottom of the image
    Vector2f d0(c.dsdx, -c.dtdx), d1(c.dsdy, -c.dtdy);
    Float v = frame0->Filter<Float>(c.st, d0, d1);
    if (frame1) v = (1 - frameWeight) * v + frameWeight * frame1->Filter<Float>(c.st, d0, d1);
    return offset + scale * v;
}

std::string HeatMapField::FrameFilename(const std::string& pattern, int frame) {
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

void HeatMapField::LoadFrame(Float newFrame) {
    if (!std::isfinite(newFrame) || std::abs(newFrame) > 1e9f)
        throw SceneError(source.loc, "heat map frame must be finite and within +-1e9",
                         source.pattern);
    bool sequence = FrameFilename(source.pattern, 0) != source.pattern;
    int f0 = sequence ? int(std::floor(newFrame)) : 0;
    Float w = sequence ? newFrame - Float(f0) : 0;
    auto arena = std::make_unique<ObjectArena>(budget);
    double before = budget.Committed();
    auto load = [&](int f) {
        std::string filename = FrameFilename(source.pattern, f);
        const MIPMap* m = nullptr;
        try {
            m = MIPMap::CreateFromFile(filename, source.options, source.wrap, source.encoding,
                                       *arena);
        } catch (const std::exception& e) {
            throw SceneError(source.loc, std::string("cannot read heat map: ") + e.what(),
                             filename);
        }
        if (!m) throw SceneError(source.loc, "cannot read heat map", filename);
        return m;
    };
    const MIPMap* m0 = nullptr;
    const MIPMap* m1 = nullptr;
    try {
        m0 = load(f0);
        m1 = w > 0 ? load(f0 + 1) : nullptr;
    } catch (...) {
        budget.Release(budget.Committed() - before);
        throw;
    }
    // The new images replace the old ones, whose charge is given back
    double charged = budget.Committed() - before;
    images = std::move(arena);
    budget.Release(chargedBytes);
    chargedBytes = charged;
    frame0 = m0;
    frame1 = m1;
    frame = newFrame;
    frameWeight = w;
}

void HeatMapField::SetAnimation(const TemperatureAnimation& animation) {
    if (!followsAnimation) return;
    Float f = Float(animation.frame.value_or(0));
    if (f != frame || !frame0) LoadFrame(f);
}

HeatMapField* HeatMapField::Create(const TextureParameterDictionary& params,
                                   const Transform& renderFromTexture, const FileLoc& loc,
                                   ObjectArena& arena, Diagnostics& diag,
                                   const TemperatureAnimation& animation) {
    Source source;
    source.pattern = params.GetOneFilename("filename", "");
    if (source.pattern.empty()) throw SceneError(loc, "\"filename\" must be given for heatmap");
    source.loc = params.Loc("filename", loc);
    TextureMapping2D mapping = TextureMapping2D::Create(params, renderFromTexture, loc);

    std::string filterName = params.GetOneString("filter", "bilinear");
    auto filter = ParseFilter(filterName);
    if (!filter)
        throw SceneError(params.Loc("filter", loc), "unknown image filter \"" + filterName + "\"",
                         filterName);
    source.options.filter = *filter;
    source.options.maxAnisotropy = params.GetOneFloat("maxanisotropy", 8);
    std::string wrapName = params.GetOneString("wrap", "clamp");
    std::optional<WrapMode> wrap = ParseWrapMode(wrapName);
    if (!wrap)
        throw SceneError(params.Loc("wrap", loc), "unknown wrap mode \"" + wrapName + "\"",
                         wrapName);
    source.wrap = *wrap;
    std::string encodingName = params.GetOneString("encoding", "linear");
    std::optional<ColorEncoding> encoding = ColorEncoding::Parse(encodingName);
    if (!encoding)
        throw SceneError(params.Loc("encoding", loc),
                         "unknown color encoding \"" + encodingName + "\"", encodingName);
    source.encoding = *encoding;

    Float offset = 0, scale = 1;
    bool hasMin = params.Has("tmin"), hasMax = params.Has("tmax");
    if (hasMin != hasMax)
        throw SceneError(params.Loc(hasMin ? "tmin" : "tmax", loc),
                         "heatmap needs both \"tmin\" and \"tmax\"", hasMin ? "tmin" : "tmax");
    if (hasMin) {
        offset = params.GetOneFloat("tmin", 0);
        scale = params.GetOneFloat("tmax", 1) - offset;
    }
    bool sequence = FrameFilename(source.pattern, 0) != source.pattern;
    bool fixedFrame = params.Has("frame");
    Float frame = params.GetOneFloat("frame", Float(animation.frame.value_or(0)));
    std::string pattern = source.pattern;
    HeatMapField* field = arena.New<HeatMapField>(mapping, std::move(source), offset, scale,
                                                  sequence && !fixedFrame, arena.Budget());
    field->LoadFrame(frame);
    if (!hasMin && field->frame0->GetLevel(0).Format() == PixelFormat::U256)
        diag.Warn(loc,
                  "8-bit heat map \"" + pattern +
                      "\" without \"tmin\"/\"tmax\": its values in [0, 1] are used as they are");
    return field;
}

}  // namespace kiln
