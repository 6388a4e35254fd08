#include "thermal/time_temperature_fields.h"

#include <algorithm>

#include "textures/texture_parameter_dictionary.h"

namespace kiln {

// TimeTemperatureField Method Definitions
void TimeTemperatureField::Start(const TextureParameterDictionary& params,
                                 const TemperatureAnimation& animation) {
    followsAnimation = !params.Has("time");
    time = params.GetOneFloat("time", animation.timeSeconds.value_or(0));
    value = At(time);
}

void TimeTemperatureField::SetAnimation(const TemperatureAnimation& animation) {
    if (!followsAnimation) return;
    Float t = animation.timeSeconds.value_or(0);
    if (t != time) value = At(time = t);
}

// CoolingField Method Definitions
CoolingField* CoolingField::Create(const TextureParameterDictionary& params, const FileLoc& loc,
                                   ObjectArena& arena, const TemperatureAnimation& animation) {
    auto positive = [&](const char* name, Float def) {
        Float v = params.GetOneFloat(name, def);
        if (!(v > 0))
            throw SceneError(params.Loc(name, loc),
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
    CoolingField* field = arena.New<CoolingField>(p);
    field->Start(params, animation);
    return field;
}

// KeyframeField Method Definitions
Float KeyframeField::At(Float t) const {
    if (t <= times.front()) return values.front();
    if (t >= times.back()) return values.back();
    size_t i = size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
    Float w = (t - times[i]) / (times[i + 1] - times[i]);
    return (1 - w) * values[i] + w * values[i + 1];
}

KeyframeField* KeyframeField::Create(const TextureParameterDictionary& params, const FileLoc& loc,
                                     ObjectArena& arena, const TemperatureAnimation& animation) {
    std::vector<Float> times = params.GetFloatArray("times");
    std::vector<Float> values = params.GetFloatArray("values");
    if (times.empty() || times.size() != values.size())
        throw SceneError(params.Loc("values", loc),
                         "keyframes need \"times\" and \"values\" of the same, non-zero length",
                         "values");
    if (!std::is_sorted(times.begin(), times.end()))
        throw SceneError(params.Loc("times", loc), "keyframe \"times\" must not decrease", "times");
    KeyframeField* field = arena.New<KeyframeField>(std::move(times), std::move(values));
    field->Start(params, animation);
    return field;
}

}  // namespace kiln
