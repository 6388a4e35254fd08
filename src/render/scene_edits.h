// Edits a host makes to a parsed scene between renders (the Python module's
// Scene.set_temperature): they change the SceneDescription, and Scene::Create makes the
// renderable scene from it again without re-parsing any file.
#pragma once

#include <string>
#include <vector>

#include "render/scene_description.h"

namespace kiln {

// What a temperature name refers to: a named material (MakeNamedMaterial), a named float
// texture (Texture "name" "float" ...), an object (ObjectBegin "name": every shape of it), or
// Any: whichever of the three has the name (an error when more than one has it).
enum class TemperatureTarget { Any, Material, Texture, Object };

// Sets the temperature (kelvin; 0: not hot) of what `name` refers to:
//   material  "float temperature" kelvin on it (replacing a "texture temperature")
//   texture   the texture becomes the constant kelvin ("constant" "float value")
//   object    "float temperature" kelvin on each of its shapes (a shape's own temperature wins
//             over its material's)
// Returns the kind it changed ("material", "texture" or "object"). Throws std::invalid_argument
// when kelvin is not finite, negative or above kMaxRenderTemperature, when nothing has the name
// (the message lists what has one) and when `Any` finds it in more than one kind.
std::string SetTemperature(SceneDescription& description, const std::string& name, double kelvin,
                           TemperatureTarget target = TemperatureTarget::Any);

// Sets "float temperature" kelvin on the shape directive `index` (in file order, outside object
// definitions). Throws std::invalid_argument as above, and for an index out of range.
void SetShapeTemperature(SceneDescription& description, int index, double kelvin);

// The names SetTemperature accepts, by kind, in file order.
struct TemperatureNames {
    std::vector<std::string> materials, textures, objects;
    int shapes = 0;  // shape directives outside object definitions
};
TemperatureNames ListTemperatureNames(const SceneDescription& description);

}  // namespace kiln
