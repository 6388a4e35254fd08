// SceneBuilder: the ParserTarget that turns directives into a SceneDescription, keeping the
// graphics state (transforms, materials, area lights, attributes) as pbrt-v4's
// BasicSceneBuilder does. It creates no renderable objects, so it is cheap and testable.
#pragma once

#include <array>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/parser/diagnostics.h"
#include "core/parser/parser_target.h"
#include "render/scene_description.h"

namespace kiln {

class SceneBuilder : public ParserTarget {
  public:
    explicit SceneBuilder(Diagnostics& diagnostics);

    void FileContents(size_t bytes, const FileLoc& loc) override { Account(double(bytes), loc); }

    // Valid after EndOfFiles().
    SceneDescription& Description() { return scene; }
    // The most the description may take (kiln --memory-limit): a directive past it is an
    // error at its location (SceneDescription::estimatedBytes). 0: no limit.
    void SetMemoryLimit(double bytes) { memoryLimit = bytes; }

    // Transformations
    void Identity(const FileLoc& loc) override;
    void Translate(Float dx, Float dy, Float dz, const FileLoc& loc) override;
    void Scale(Float sx, Float sy, Float sz, const FileLoc& loc) override;
    void Rotate(Float angle, Float ax, Float ay, Float az, const FileLoc& loc) override;
    void LookAt(Float ex, Float ey, Float ez, Float lx, Float ly, Float lz, Float ux, Float uy,
                Float uz, const FileLoc& loc) override;
    void ConcatTransform(const std::array<Float, 16>& m, const FileLoc& loc) override;
    void Transform(const std::array<Float, 16>& m, const FileLoc& loc) override;
    void CoordinateSystem(const std::string& name, const FileLoc& loc) override;
    void CoordSysTransform(const std::string& name, const FileLoc& loc) override;
    void ActiveTransformAll(const FileLoc& loc) override;
    void ActiveTransformEndTime(const FileLoc& loc) override;
    void ActiveTransformStartTime(const FileLoc& loc) override;
    void TransformTimes(Float start, Float end, const FileLoc& loc) override;

    // Rendering options
    void Option(const std::string& name, const std::string& value, const FileLoc& loc) override;
    void ColorSpace(const std::string& name, const FileLoc& loc) override;
    void PixelFilter(const std::string& name, ParsedParameterVector params,
                     const FileLoc& loc) override;
    void Film(const std::string& type, ParsedParameterVector params, const FileLoc& loc) override;
    void Accelerator(const std::string& name, ParsedParameterVector params,
                     const FileLoc& loc) override;
    void Integrator(const std::string& name, ParsedParameterVector params,
                    const FileLoc& loc) override;
    void Camera(const std::string& name, ParsedParameterVector params, const FileLoc& loc) override;
    void Sampler(const std::string& name, ParsedParameterVector params,
                 const FileLoc& loc) override;
    void MakeNamedMedium(const std::string& name, ParsedParameterVector params,
                         const FileLoc& loc) override;
    void MediumInterface(const std::string& insideName, const std::string& outsideName,
                         const FileLoc& loc) override;
    void WorldBegin(const FileLoc& loc) override;

    // Scene description
    void AttributeBegin(const FileLoc& loc) override;
    void AttributeEnd(const FileLoc& loc) override;
    void Attribute(const std::string& target, ParsedParameterVector params,
                   const FileLoc& loc) override;
    void Shape(const std::string& name, ParsedParameterVector params, const FileLoc& loc) override;
    void ReverseOrientation(const FileLoc& loc) override;
    void Texture(const std::string& name, const std::string& type, const std::string& texName,
                 ParsedParameterVector params, const FileLoc& loc) override;
    void Material(const std::string& name, ParsedParameterVector params,
                  const FileLoc& loc) override;
    void MakeNamedMaterial(const std::string& name, ParsedParameterVector params,
                           const FileLoc& loc) override;
    void NamedMaterial(const std::string& name, const FileLoc& loc) override;
    void LightSource(const std::string& name, ParsedParameterVector params,
                     const FileLoc& loc) override;
    void AreaLightSource(const std::string& name, ParsedParameterVector params,
                         const FileLoc& loc) override;
    void ObjectBegin(const std::string& name, const FileLoc& loc) override;
    void ObjectEnd(const FileLoc& loc) override;
    void ObjectInstance(const std::string& name, const FileLoc& loc) override;

    void EndOfFiles() override;

  private:
    // The transform pair (shutter open, shutter close) and which of them directives change.
    struct TransformSet {
        kiln::Transform t[2];
    };
    static constexpr int StartTransformBits = 1 << 0, EndTransformBits = 1 << 1,
                         AllTransformsBits = 3;

    struct GraphicsState {
        TransformSet ctm;
        int activeTransformBits = AllTransformsBits;
        bool reverseOrientation = false;
        const RGBColorSpace* colorSpace = nullptr;
        int currentMaterialIndex = 0;  // anonymous material 0 is the default "diffuse"
        std::string currentMaterialName;
        std::string areaLightName;
        ParsedParameterVector areaLightParams;
        FileLoc areaLightLoc;
        ParsedParameterVector shapeAttributes, lightAttributes, materialAttributes,
            textureAttributes, mediumAttributes;
        std::string currentInsideMedium, currentOutsideMedium;  // MediumInterface
    };

    template <typename F>
    void ApplyTransform(F f);
    void RequireWorld(const char* directive, const FileLoc& loc, bool inWorld) const;
    kiln::Transform RenderFromObject(int which = 0) const;  // 0: start, 1: end transform
    bool CtmIsAnimated() const;
    // The CTM's motion in render space, and in render space relative to the world's
    AnimatedTransform RenderFromObjectMotion() const;
    // Directives that cannot move use the start transform, with one warning per kind (as
    // pbrt-v4 warns for lights, textures and media)
    void WarnIfAnimated(const FileLoc& loc, const char* what);
    // A directive's parameters, whose estimated bytes are added to the description's (an
    // error at loc beyond the memory limit)
    ParameterDictionary Dict(const FileLoc& loc, ParsedParameterVector params,
                             const ParsedParameterVector& attributes = {});
    void Account(double bytes, const FileLoc& loc);

    Diagnostics& diag;
    SceneDescription scene;
    GraphicsState gs;
    std::vector<GraphicsState> pushedStates;
    struct PushRecord {
        char kind;  // 'a' AttributeBegin, 'o' ObjectBegin
        FileLoc loc;
    };
    std::vector<PushRecord> pushStack;
    std::map<std::string, TransformSet> namedCoordinateSystems;
    kiln::Transform renderFromWorld;
    bool inWorld = false;
    std::set<std::string> warnedAnimated;
    double memoryLimit = 0;
    Float transformStartTime = 0, transformEndTime = 1;
    InstanceDefinitionSceneEntity* activeInstance = nullptr;
    std::set<std::string> floatTextureNames, spectrumTextureNames, namedMaterialNames, mediumNames;
};

}  // namespace kiln
