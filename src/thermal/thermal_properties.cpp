#include "thermal/thermal_properties.h"

#include <cmath>
#include <string>

#include "spectral/planck.h"
#include "textures/basic_textures.h"
#include "textures/texture_parameter_dictionary.h"

namespace kiln {

ThermalProperties ReadThermalProperties(const TextureParameterDictionary& params,
                                        bool perVertexAllowed, ObjectArena& arena) {
    ThermalProperties t;
    std::string type = params.TypeOf("temperature");
    if (type == "float") {
        std::vector<Float> values = params.GetFloatArray("temperature");
        if (values.size() > 1 && perVertexAllowed) {
            // One value per vertex: the mesh keeps them (see geometry/triangle.h).
        } else if (values.size() == 1) {
            if (!(values[0] >= 0 && values[0] <= kMaxRenderTemperature))
                throw SceneError(params.Loc("temperature"),
                                 "temperature must be a number of kelvin from 0 to 1e27",
                                 FormatKelvin(values[0]));
            t.temperature = FloatTexture(arena.New<FloatConstantTexture>(values[0]));
        } else {
            throw SceneError(params.Loc("temperature"),
                             "\"float temperature\" takes one value (kelvin)", "temperature");
        }
    } else if (type == "texture") {
        t.temperature = params.GetFloatTextureOrNull("temperature", arena);
    } else if (!type.empty()) {
        throw SceneError(params.Loc("temperature"),
                         "temperature must be a \"float\" or a \"texture\"", type);
    }
    if (params.Has("emission")) {
        std::string name = params.GetOneString("emission", "kirchhoff");
        t.model = ParseEmissionModel(name);
        if (!t.model)
            throw SceneError(params.Loc("emission"),
                             "unknown emission model (expected kirchhoff, additive, diffuse or "
                             "none)",
                             name);
    }
    return t;
}

}  // namespace kiln
