#include "thermal/temperature_field.h"

#include "thermal/heat_map_field.h"
#include "thermal/spatial_temperature_fields.h"
#include "thermal/time_temperature_fields.h"

namespace kiln {

bool IsTemperatureFieldClass(const std::string& name) {
    return name == "gradient" || name == "noise" || name == "heatmap" ||
           name == "vertexattribute" || name == "cooling" || name == "keyframes";
}

FloatTexture CreateTemperatureField(const std::string& name, const Transform& renderFromTexture,
                                    const TextureParameterDictionary& params, const FileLoc& loc,
                                    ObjectArena& arena, Diagnostics& diag,
                                    const TemperatureAnimation& animation,
                                    std::vector<TemperatureField*>* animated) {
    TemperatureField* field = nullptr;
    if (name == "gradient")
        field = GradientField::Create(params, renderFromTexture, loc, arena);
    else if (name == "noise")
        field = NoiseField::Create(params, renderFromTexture, loc, arena);
    else if (name == "heatmap")
        field = HeatMapField::Create(params, renderFromTexture, loc, arena, diag, animation);
    else if (name == "vertexattribute")
        field = VertexAttributeField::Create(params, arena);
    else if (name == "cooling")
        field = CoolingField::Create(params, loc, arena, animation);
    else if (name == "keyframes")
        field = KeyframeField::Create(params, loc, arena, animation);
    else
        throw SceneError(loc, "unknown temperature field \"" + name + "\"", name);
    if (animated && field->Animated()) animated->push_back(field);
    return AsFloatTexture(field);
}

}  // namespace kiln
