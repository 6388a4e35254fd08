// SceneDescription: everything a scene file says, as parameter lists attached to transforms,
// before any object is created (pbrt-v4's BasicScene entities). The SceneBuilder fills it
// from parser calls; Scene creates the renderable objects from it.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/animated_transform.h"
#include "base/transform.h"
#include "core/camera/camera_transform.h"
#include "core/parser/file_loc.h"
#include "core/parser/parameter_dictionary.h"

namespace kiln {

// A directive's type name ("sphere", "diffuse", ...), its parameters and where it was written.
struct SceneEntity {
    std::string name;
    ParameterDictionary parameters;
    FileLoc loc;

    SceneEntity() = default;
    SceneEntity(std::string name, ParameterDictionary parameters, FileLoc loc)
        : name(std::move(name)), parameters(std::move(parameters)), loc(std::move(loc)) {}
};

// An entity placed in render space (lights, textures).
struct TransformedSceneEntity : SceneEntity {
    Transform renderFromObject;

    TransformedSceneEntity() = default;
    TransformedSceneEntity(std::string name, ParameterDictionary parameters, FileLoc loc,
                           Transform renderFromObject)
        : SceneEntity(std::move(name), std::move(parameters), std::move(loc)),
          renderFromObject(renderFromObject) {}
};

struct CameraSceneEntity : SceneEntity {
    CameraTransform cameraTransform;
    std::string medium;  // the medium the camera is in ("": none)
};

// A Shape directive with the graphics state it was written in. The material is either an
// anonymous one (materialIndex into SceneDescription::materials) or a named one
// (materialName); areaLightIndex indexes SceneDescription::areaLights (-1: none).
// insideMedium and outsideMedium name the media of the MediumInterface in effect ("": none).
// A moving shape (start and end transforms differ) has `motion` (render from object over
// time) and the identity as renderFromObject: it is made in its object space.
struct ShapeSceneEntity : SceneEntity {
    Transform renderFromObject;
    std::optional<AnimatedTransform> motion;
    bool reverseOrientation = false;
    int materialIndex = -1;
    std::string materialName;
    int areaLightIndex = -1;
    std::string insideMedium, outsideMedium;
};

struct TextureSceneEntity : TransformedSceneEntity {
    std::string texName;  // the texture class: "imagemap", "checkerboard", ...
};

// ObjectBegin/ObjectEnd: shapes in the render space of their definition.
struct InstanceDefinitionSceneEntity {
    std::string name;
    FileLoc loc;
    std::vector<ShapeSceneEntity> shapes;
};

// ObjectInstance: renderFromInstance maps the definition's render space to this instance's;
// a moving instance has `motion` too (renderFromInstance is its start).
struct InstanceSceneEntity {
    std::string name;
    FileLoc loc;
    Transform renderFromInstance;
    std::optional<AnimatedTransform> motion;
};

struct SceneDescription {
    SceneEntity film{"rgb", {}, {}}, sampler{"zsobol", {}, {}}, integrator{"volpath", {}, {}},
        filter{"gaussian", {}, {}}, accelerator{"bvh", {}, {}};
    CameraSceneEntity camera;
    bool cameraGiven = false;
    const RGBColorSpace* filmColorSpace = nullptr;  // in effect at the Film directive

    std::vector<std::pair<std::string, SceneEntity>> namedMaterials;  // in file order
    std::vector<SceneEntity> materials;                               // anonymous
    std::vector<std::pair<std::string, TextureSceneEntity>> floatTextures, spectrumTextures;
    // MakeNamedMedium, in file order: name and the medium (its type in "string type")
    std::vector<std::pair<std::string, TransformedSceneEntity>> media;
    std::vector<TransformedSceneEntity> lights;
    std::vector<TransformedSceneEntity> areaLights;  // one per shape that has one
    std::vector<ShapeSceneEntity> shapes;
    std::map<std::string, InstanceDefinitionSceneEntity> instanceDefinitions;
    std::vector<InstanceSceneEntity> instances;

    // What the description takes in memory, estimated by SceneBuilder; scene creation charges
    // it to the memory budget first.
    double estimatedBytes = 0;

    // Option directives kiln understands (others are reported).
    std::optional<int> seedOption;
    bool disablePixelJitter = false;
    // Option "float ambienttemperature" (kelvin): the temperature of all matter that has none
    // of its own (scene_emitters.h, scene_media.h); where it was given.
    std::optional<Float> ambientTemperature;
    FileLoc ambientTemperatureLoc;
};

}  // namespace kiln
