#include "render/scene_edits.h"

#include <cmath>
#include <stdexcept>

#include "spectral/planck.h"

namespace kiln {

namespace {

void CheckKelvin(double kelvin) {
    if (!std::isfinite(kelvin) || kelvin < 0 || kelvin > kMaxRenderTemperature)
        throw std::invalid_argument("temperature " + FormatKelvin(kelvin) +
                                    " K: must be finite, >= 0 and at most " +
                                    FormatKelvin(kMaxRenderTemperature) + " K");
}

// "float temperature" kelvin, at the directive it is set on (errors point there)
ParsedParameter TemperatureParameter(double kelvin, const FileLoc& loc) {
    ParsedParameter p;
    p.type = "float";
    p.name = "temperature";
    p.loc = loc;
    p.floats = {Float(kelvin)};
    return p;
}

std::string Join(const std::vector<std::string>& names) {
    if (names.empty()) return "none";
    std::string s;
    for (const std::string& n : names) s += (s.empty() ? "\"" : ", \"") + n + "\"";
    return s;
}

}  // namespace

TemperatureNames ListTemperatureNames(const SceneDescription& d) {
    TemperatureNames names;
    for (const auto& [name, entity] : d.namedMaterials) names.materials.push_back(name);
    for (const auto& [name, entity] : d.floatTextures) names.textures.push_back(name);
    for (const auto& [name, definition] : d.instanceDefinitions) names.objects.push_back(name);
    names.shapes = int(d.shapes.size());
    return names;
}

std::string SetTemperature(SceneDescription& d, const std::string& name, double kelvin,
                           TemperatureTarget target) {
    CheckKelvin(kelvin);
    auto wants = [&](TemperatureTarget t) {
        return target == TemperatureTarget::Any || target == t;
    };
    bool material = false, texture = false;
    if (wants(TemperatureTarget::Material))
        for (const auto& [n, entity] : d.namedMaterials) material |= n == name;
    if (wants(TemperatureTarget::Texture))
        for (const auto& [n, entity] : d.floatTextures) texture |= n == name;
    bool object = wants(TemperatureTarget::Object) && d.instanceDefinitions.count(name) > 0;
    if (int(material) + int(texture) + int(object) > 1)
        throw std::invalid_argument("\"" + name +
                                    "\" names more than one of a material, a float texture and "
                                    "an object: say which (kind=\"material\", \"texture\" or "
                                    "\"object\")");
    if (material) {
        // Every definition of the name (a later MakeNamedMaterial replaces an earlier one)
        for (auto& [n, entity] : d.namedMaterials)
            if (n == name) entity.parameters.Set(TemperatureParameter(kelvin, entity.loc));
        return "material";
    }
    if (texture) {
        for (auto& [n, entity] : d.floatTextures)
            if (n == name) {
                ParsedParameter value = TemperatureParameter(kelvin, entity.loc);
                value.name = "value";
                entity.texName = "constant";
                entity.parameters =
                    ParameterDictionary({std::move(value)}, entity.parameters.ColorSpace());
            }
        return "texture";
    }
    if (object) {
        for (ShapeSceneEntity& shape : d.instanceDefinitions.at(name).shapes)
            shape.parameters.Set(TemperatureParameter(kelvin, shape.loc));
        return "object";
    }
    TemperatureNames names = ListTemperatureNames(d);
    std::string message = "no ";
    if (wants(TemperatureTarget::Material)) message += "named material, ";
    if (wants(TemperatureTarget::Texture)) message += "float texture, ";
    if (wants(TemperatureTarget::Object)) message += "object, ";
    message.resize(message.size() - 2);
    message += " is named \"" + name + "\" (";
    if (wants(TemperatureTarget::Material)) message += "materials: " + Join(names.materials) + "; ";
    if (wants(TemperatureTarget::Texture))
        message += "float textures: " + Join(names.textures) + "; ";
    if (wants(TemperatureTarget::Object)) message += "objects: " + Join(names.objects) + "; ";
    message.resize(message.size() - 2);
    throw std::invalid_argument(message + ")");
}

void SetShapeTemperature(SceneDescription& d, int index, double kelvin) {
    CheckKelvin(kelvin);
    if (index < 0 || index >= int(d.shapes.size()))
        throw std::invalid_argument("shape " + std::to_string(index) + ": the scene has " +
                                    std::to_string(d.shapes.size()) +
                                    " shape directives outside object definitions");
    ShapeSceneEntity& shape = d.shapes[size_t(index)];
    shape.parameters.Set(TemperatureParameter(kelvin, shape.loc));
}

}  // namespace kiln
