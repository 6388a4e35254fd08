#include "render/scene_builder.h"

#include "base/system_memory.h"
#include "spectral/color.h"
#include "spectral/planck.h"

namespace kiln {

SceneBuilder::SceneBuilder(Diagnostics& diagnostics) : diag(diagnostics) {
    gs.colorSpace = &RGBColorSpace::sRGB();
    scene.filmColorSpace = gs.colorSpace;
    // pbrt-v4: anonymous material 0 is a default diffuse one.
    scene.materials.emplace_back("diffuse", ParameterDictionary({}, gs.colorSpace), FileLoc());
    gs.currentMaterialIndex = 0;
    for (SceneEntity* e : {&scene.film, &scene.sampler, &scene.integrator, &scene.filter,
                           &scene.accelerator, static_cast<SceneEntity*>(&scene.camera)})
        e->parameters = ParameterDictionary({}, gs.colorSpace);
    scene.camera.name = "perspective";
}

// Transformations
template <typename F>
void SceneBuilder::ApplyTransform(F f) {
    for (int i = 0; i < 2; ++i)
        if (gs.activeTransformBits & (1 << i)) gs.ctm.t[i] = f(gs.ctm.t[i]);
}

void SceneBuilder::Identity(const FileLoc&) {
    ApplyTransform([](const kiln::Transform&) { return kiln::Transform(); });
}

void SceneBuilder::Translate(Float dx, Float dy, Float dz, const FileLoc&) {
    ApplyTransform([&](const kiln::Transform& t) { return t * kiln::Translate({dx, dy, dz}); });
}

void SceneBuilder::Scale(Float sx, Float sy, Float sz, const FileLoc&) {
    ApplyTransform([&](const kiln::Transform& t) { return t * kiln::Scale(sx, sy, sz); });
}

void SceneBuilder::Rotate(Float angle, Float ax, Float ay, Float az, const FileLoc& loc) {
    if (ax == 0 && ay == 0 && az == 0) {
        diag.Warn(loc, "Rotate about a zero-length axis ignored");
        return;
    }
    ApplyTransform(
        [&](const kiln::Transform& t) { return t * kiln::Rotate(angle, Vector3f(ax, ay, az)); });
}

void SceneBuilder::LookAt(Float ex, Float ey, Float ez, Float lx, Float ly, Float lz, Float ux,
                          Float uy, Float uz, const FileLoc& loc) {
    std::optional<kiln::Transform> lookAt =
        kiln::LookAt(Point3f(ex, ey, ez), Point3f(lx, ly, lz), Vector3f(ux, uy, uz));
    if (!lookAt) {
        // pbrt-v4 reports this and goes on without the transform.
        diag.Warn(loc,
                  "LookAt: eye and look-at point coincide or the up vector is parallel to "
                  "the viewing direction; ignored");
        return;
    }
    ApplyTransform([&](const kiln::Transform& t) { return t * *lookAt; });
}

// Singular matrices are accepted, as pbrt-v4 does (its own scenes use them to flatten or hide
// objects); what is built under one decides what it can do without an inverse.
static kiln::Transform TransformFromFileOrder(const std::array<Float, 16>& m) {
    // The file lists the matrix column by column (pbrt-v4 transposes it).
    SquareMatrix4 mat(m.data());
    return kiln::Transform(mat.Transposed());
}

void SceneBuilder::ConcatTransform(const std::array<Float, 16>& m, const FileLoc&) {
    kiln::Transform t = TransformFromFileOrder(m);
    ApplyTransform([&](const kiln::Transform& ctm) { return ctm * t; });
}

void SceneBuilder::Transform(const std::array<Float, 16>& m, const FileLoc&) {
    kiln::Transform t = TransformFromFileOrder(m);
    ApplyTransform([&](const kiln::Transform&) { return t; });
}

void SceneBuilder::CoordinateSystem(const std::string& name, const FileLoc&) {
    namedCoordinateSystems[name] = gs.ctm;
}

void SceneBuilder::CoordSysTransform(const std::string& name, const FileLoc& loc) {
    auto it = namedCoordinateSystems.find(name);
    if (it == namedCoordinateSystems.end()) {
        diag.Warn(loc, "couldn't find named coordinate system '" + name + "'");
        return;
    }
    gs.ctm = it->second;
}

void SceneBuilder::ActiveTransformAll(const FileLoc&) {
    gs.activeTransformBits = AllTransformsBits;
}
void SceneBuilder::ActiveTransformEndTime(const FileLoc&) {
    gs.activeTransformBits = EndTransformBits;
}
void SceneBuilder::ActiveTransformStartTime(const FileLoc&) {
    gs.activeTransformBits = StartTransformBits;
}
void SceneBuilder::TransformTimes(Float start, Float end, const FileLoc& loc) {
    RequireWorld("TransformTimes", loc, false);
    transformStartTime = start;
    transformEndTime = end;
}

// Rendering options
void SceneBuilder::RequireWorld(const char* directive, const FileLoc& loc, bool world) const {
    if (world && !inWorld)
        throw SceneError(loc, std::string(directive) + " is only allowed after WorldBegin",
                         directive);
    if (!world && inWorld)
        throw SceneError(loc, std::string(directive) + " must come before WorldBegin", directive);
}

ParameterDictionary SceneBuilder::Dict(const FileLoc& loc, ParsedParameterVector params,
                                       const ParsedParameterVector& attributes) {
    // What a directive's entity takes: its parameters (values, names, the search directory
    // each keeps), the entity, and the allocator's per-block overhead; 1e6 spheres measured
    // 1.06 KB per Shape directive in the description (estimated 1.05 KB)
    double bytes = 750;
    for (const ParsedParameter& p : params) {
        bytes += sizeof(ParsedParameter) + 64 + 4.0 * double(p.floats.size() + p.ints.size()) +
                 double(p.bools.size()) + double(p.searchDirectory.size());
        for (const std::string& v : p.strings) bytes += sizeof(std::string) + 16 + double(v.size());
    }
    Account(bytes, loc);
    return ParameterDictionary(std::move(params), attributes, gs.colorSpace);
}

void SceneBuilder::Account(double bytes, const FileLoc& loc) {
    scene.estimatedBytes += bytes;
    if (memoryLimit > 0 && scene.estimatedBytes > memoryLimit)
        throw SceneError(loc, "the scene's directives so far take about " +
                                  FormatBytes(scene.estimatedBytes) +
                                  ", more than --memory-limit (" + FormatBytes(memoryLimit) + ")");
}

void SceneBuilder::Option(const std::string& declaration, const std::string& value,
                          const FileLoc& loc) {
    // The declaration is "type name" (e.g. "bool disablepixeljitter"); the value as written.
    std::string name = declaration;
    if (size_t space = declaration.find_last_of(" \t"); space != std::string::npos)
        name = declaration.substr(space + 1);
    std::string v = value;
    if (v.size() >= 2 && v.front() == '[' && v.back() == ']') v = v.substr(1, v.size() - 2);
    while (!v.empty() && v.front() == ' ') v.erase(v.begin());
    while (!v.empty() && v.back() == ' ') v.pop_back();
    if (v.size() >= 2 && v.front() == '"' && v.back() == '"') v = v.substr(1, v.size() - 2);
    auto asBool = [&]() {
        if (v == "true") return true;
        if (v == "false") return false;
        throw SceneError(loc, "Option \"" + name + "\" expects true or false", value);
    };
    if (name == "disablepixeljitter") {
        scene.disablePixelJitter = asBool();
    } else if (name == "seed") {
        try {
            size_t used = 0;
            int seed = std::stoi(v, &used);
            if (used != v.size()) throw std::invalid_argument(v);
            scene.seedOption = seed;
        } catch (const std::exception&) {
            throw SceneError(loc, "Option \"seed\" expects an integer", value);
        }
    } else if (name == "ambienttemperature") {
        double T = 0;
        try {
            size_t used = 0;
            T = std::stod(v, &used);
            if (used != v.size()) throw std::invalid_argument(v);
        } catch (const std::exception&) {
            throw SceneError(loc, "Option \"ambienttemperature\" expects a number (kelvin)", value);
        }
        if (!(T >= 0) || !(T <= kMaxRenderTemperature))
            throw SceneError(loc, "Option \"ambienttemperature\" must be kelvin from 0 to 1e27",
                             value);
        // 0 K: nothing emits, as without the option
        scene.ambientTemperature = T > 0 ? std::optional<Float>(Float(T)) : std::nullopt;
        scene.ambientTemperatureLoc = loc;
    } else {
        diag.Warn(loc, "Option \"" + name + "\" is not supported by kiln; ignored");
    }
}

void SceneBuilder::ColorSpace(const std::string& name, const FileLoc& loc) {
    const RGBColorSpace* cs = RGBColorSpace::GetNamed(name);
    if (!cs) throw SceneError(loc, "unknown colour space '" + name + "'", name);
    gs.colorSpace = cs;
}

void SceneBuilder::PixelFilter(const std::string& name, ParsedParameterVector params,
                               const FileLoc& loc) {
    RequireWorld("PixelFilter", loc, false);
    scene.filter = SceneEntity(name, Dict(loc, std::move(params)), loc);
}

void SceneBuilder::Film(const std::string& type, ParsedParameterVector params, const FileLoc& loc) {
    RequireWorld("Film", loc, false);
    scene.film = SceneEntity(type, Dict(loc, std::move(params)), loc);
    scene.filmColorSpace = gs.colorSpace;
}

void SceneBuilder::Accelerator(const std::string& name, ParsedParameterVector params,
                               const FileLoc& loc) {
    RequireWorld("Accelerator", loc, false);
    scene.accelerator = SceneEntity(name, Dict(loc, std::move(params)), loc);
}

void SceneBuilder::Integrator(const std::string& name, ParsedParameterVector params,
                              const FileLoc& loc) {
    RequireWorld("Integrator", loc, false);
    scene.integrator = SceneEntity(name, Dict(loc, std::move(params)), loc);
}

void SceneBuilder::Camera(const std::string& name, ParsedParameterVector params,
                          const FileLoc& loc) {
    RequireWorld("Camera", loc, false);
    // The CTM is camera-from-world; the camera's coordinate system is its inverse.
    TransformSet cameraFromWorld = gs.ctm;
    for (const kiln::Transform& t : cameraFromWorld.t)
        if (t.IsSingular())
            throw SceneError(loc, "the camera transform is singular (e.g. a zero Scale)", name);
    TransformSet worldFromCamera;
    for (int i = 0; i < 2; ++i) worldFromCamera.t[i] = Inverse(cameraFromWorld.t[i]);
    namedCoordinateSystems["camera"] = worldFromCamera;
    scene.camera.name = name;
    scene.camera.parameters = Dict(loc, std::move(params));
    scene.camera.loc = loc;
    scene.camera.cameraTransform = CameraTransform(AnimatedTransform(
        worldFromCamera.t[0], transformStartTime, worldFromCamera.t[1], transformEndTime));
    scene.camera.medium = gs.currentOutsideMedium;
    scene.cameraGiven = true;
    renderFromWorld = scene.camera.cameraTransform.RenderFromWorld();
}

void SceneBuilder::Sampler(const std::string& name, ParsedParameterVector params,
                           const FileLoc& loc) {
    RequireWorld("Sampler", loc, false);
    scene.sampler = SceneEntity(name, Dict(loc, std::move(params)), loc);
}

void SceneBuilder::MakeNamedMedium(const std::string& name, ParsedParameterVector params,
                                   const FileLoc& loc) {
    if (!mediumNames.insert(name).second)
        throw SceneError(loc, "redefinition of named medium '" + name + "'", name);
    WarnIfAnimated(loc, "media");
    scene.media.emplace_back(
        name, TransformedSceneEntity("", Dict(loc, std::move(params), gs.mediumAttributes), loc,
                                     RenderFromObject()));
}

void SceneBuilder::MediumInterface(const std::string& insideName, const std::string& outsideName,
                                   const FileLoc&) {
    gs.currentInsideMedium = insideName;
    gs.currentOutsideMedium = outsideName;
}

void SceneBuilder::WorldBegin(const FileLoc& loc) {
    RequireWorld("WorldBegin", loc, false);
    inWorld = true;
    gs.ctm = TransformSet();
    gs.activeTransformBits = AllTransformsBits;
    namedCoordinateSystems["world"] = gs.ctm;
}

// Scene description
void SceneBuilder::AttributeBegin(const FileLoc& loc) {
    pushedStates.push_back(gs);
    pushStack.push_back({'a', loc});
}

void SceneBuilder::AttributeEnd(const FileLoc& loc) {
    if (pushStack.empty())
        throw SceneError(loc, "AttributeEnd without a matching AttributeBegin", "AttributeEnd");
    if (pushStack.back().kind == 'o')
        throw SceneError(
            loc, "AttributeEnd closes the ObjectBegin at " + pushStack.back().loc.ToString(),
            "AttributeEnd");
    gs = std::move(pushedStates.back());
    pushedStates.pop_back();
    pushStack.pop_back();
}

void SceneBuilder::Attribute(const std::string& target, ParsedParameterVector params,
                             const FileLoc& loc) {
    ParsedParameterVector* attributes = nullptr;
    if (target == "shape")
        attributes = &gs.shapeAttributes;
    else if (target == "light")
        attributes = &gs.lightAttributes;
    else if (target == "material")
        attributes = &gs.materialAttributes;
    else if (target == "texture")
        attributes = &gs.textureAttributes;
    else if (target == "medium")
        attributes = &gs.mediumAttributes;
    else
        throw SceneError(loc, "unknown Attribute target '" + target + "'", target);
    for (ParsedParameter& p : params) {
        p.mayBeUnused = true;
        attributes->push_back(std::move(p));
    }
}

bool SceneBuilder::CtmIsAnimated() const { return !(gs.ctm.t[0] == gs.ctm.t[1]); }

kiln::Transform SceneBuilder::RenderFromObject(int which) const {
    return renderFromWorld * gs.ctm.t[which];
}

AnimatedTransform SceneBuilder::RenderFromObjectMotion() const {
    return AnimatedTransform(RenderFromObject(0), transformStartTime, RenderFromObject(1),
                             transformEndTime);
}

void SceneBuilder::WarnIfAnimated(const FileLoc& loc, const char* what) {
    if (!CtmIsAnimated() || !warnedAnimated.insert(what).second) return;
    diag.Warn(loc, std::string("animated transforms of ") + what +
                       " are not supported (as in pbrt-v4); using the start transform");
}

void SceneBuilder::Shape(const std::string& name, ParsedParameterVector params,
                         const FileLoc& loc) {
    RequireWorld("Shape", loc, true);
    ShapeSceneEntity shape;
    shape.name = name;
    shape.parameters = Dict(loc, std::move(params), gs.shapeAttributes);
    shape.loc = loc;
    shape.renderFromObject = RenderFromObject();
    if (CtmIsAnimated()) {
        // A moving shape is made in its object space and placed at each ray's time
        AnimatedTransform motion = RenderFromObjectMotion();
        if (motion.IsAnimated()) {
            if (!gs.areaLightName.empty())
                throw SceneError(loc,
                                 "animated area lights are not supported (as in pbrt-v4): the "
                                 "shape's start and end transforms differ",
                                 name);
            shape.motion = motion;
            shape.renderFromObject = kiln::Transform();
        }
    }
    shape.reverseOrientation = gs.reverseOrientation;
    shape.materialIndex = gs.currentMaterialIndex;
    shape.materialName = gs.currentMaterialName;
    shape.insideMedium = gs.currentInsideMedium;
    shape.outsideMedium = gs.currentOutsideMedium;
    if (!gs.areaLightName.empty()) {
        if (activeInstance) {
            diag.Warn(loc,
                      "area lights are not supported with object instancing (as in pbrt-v4); "
                      "the shape is not emissive");
        } else {
            shape.areaLightIndex = int(scene.areaLights.size());
            scene.areaLights.emplace_back(
                gs.areaLightName, Dict(gs.areaLightLoc, gs.areaLightParams, gs.lightAttributes),
                gs.areaLightLoc, shape.renderFromObject);
        }
    }
    if (activeInstance)
        activeInstance->shapes.push_back(std::move(shape));
    else
        scene.shapes.push_back(std::move(shape));
}

void SceneBuilder::ReverseOrientation(const FileLoc&) {
    gs.reverseOrientation = !gs.reverseOrientation;
}

void SceneBuilder::Texture(const std::string& name, const std::string& type,
                           const std::string& texName, ParsedParameterVector params,
                           const FileLoc& loc) {
    RequireWorld("Texture", loc, true);
    if (type != "float" && type != "spectrum")
        throw SceneError(loc, "texture type must be \"float\" or \"spectrum\"", type);
    std::set<std::string>& names = type == "float" ? floatTextureNames : spectrumTextureNames;
    if (!names.insert(name).second)
        throw SceneError(loc, "redefinition of " + type + " texture '" + name + "'", name);
    TextureSceneEntity tex;
    tex.name = name;
    tex.texName = texName;
    tex.parameters = Dict(loc, std::move(params), gs.textureAttributes);
    tex.loc = loc;
    tex.renderFromObject = RenderFromObject();
    WarnIfAnimated(loc, "textures");
    if (tex.renderFromObject.IsSingular()) {
        // 3D and projective mappings need the inverse
        diag.Warn(loc,
                  "texture '" + name +
                      "' defined under a singular transform; its texture space is world space");
        tex.renderFromObject = renderFromWorld;
    }
    auto& list = type == "float" ? scene.floatTextures : scene.spectrumTextures;
    list.emplace_back(name, std::move(tex));
}

void SceneBuilder::Material(const std::string& name, ParsedParameterVector params,
                            const FileLoc& loc) {
    RequireWorld("Material", loc, true);
    scene.materials.emplace_back(name, Dict(loc, std::move(params), gs.materialAttributes), loc);
    gs.currentMaterialIndex = int(scene.materials.size()) - 1;
    gs.currentMaterialName.clear();
}

void SceneBuilder::MakeNamedMaterial(const std::string& name, ParsedParameterVector params,
                                     const FileLoc& loc) {
    RequireWorld("MakeNamedMaterial", loc, true);
    if (!namedMaterialNames.insert(name).second)
        throw SceneError(loc, "redefinition of named material '" + name + "'", name);
    scene.namedMaterials.emplace_back(
        name, SceneEntity("", Dict(loc, std::move(params), gs.materialAttributes), loc));
}

void SceneBuilder::NamedMaterial(const std::string& name, const FileLoc& loc) {
    RequireWorld("NamedMaterial", loc, true);
    gs.currentMaterialName = name;
    gs.currentMaterialIndex = -1;
}

void SceneBuilder::LightSource(const std::string& name, ParsedParameterVector params,
                               const FileLoc& loc) {
    RequireWorld("LightSource", loc, true);
    WarnIfAnimated(loc, "lights");
    if (RenderFromObject().IsSingular()) {
        // Lights place and orient themselves through the inverse transform
        diag.Warn(loc, "light \"" + name + "\" under a singular transform; skipped");
        return;
    }
    scene.lights.emplace_back(name, Dict(loc, std::move(params), gs.lightAttributes), loc,
                              RenderFromObject());
}

void SceneBuilder::AreaLightSource(const std::string& name, ParsedParameterVector params,
                                   const FileLoc& loc) {
    RequireWorld("AreaLightSource", loc, true);
    gs.areaLightName = name;
    gs.areaLightParams = std::move(params);
    gs.areaLightLoc = loc;
}

void SceneBuilder::ObjectBegin(const std::string& name, const FileLoc& loc) {
    RequireWorld("ObjectBegin", loc, true);
    if (activeInstance)
        throw SceneError(
            loc, "ObjectBegin inside the definition of object '" + activeInstance->name + "'",
            name);
    pushedStates.push_back(gs);
    pushStack.push_back({'o', loc});
    auto [it, inserted] = scene.instanceDefinitions.try_emplace(name);
    if (!inserted) throw SceneError(loc, "redefinition of object '" + name + "'", name);
    it->second.name = name;
    it->second.loc = loc;
    activeInstance = &it->second;
}

void SceneBuilder::ObjectEnd(const FileLoc& loc) {
    RequireWorld("ObjectEnd", loc, true);
    if (!activeInstance || pushStack.empty() || pushStack.back().kind != 'o')
        throw SceneError(loc, "ObjectEnd without a matching ObjectBegin", "ObjectEnd");
    activeInstance = nullptr;
    gs = std::move(pushedStates.back());
    pushedStates.pop_back();
    pushStack.pop_back();
}

void SceneBuilder::ObjectInstance(const std::string& name, const FileLoc& loc) {
    RequireWorld("ObjectInstance", loc, true);
    if (activeInstance) throw SceneError(loc, "ObjectInstance inside an object definition", name);
    kiln::Transform renderFromInstance = RenderFromObject() * Inverse(renderFromWorld);
    if (CtmIsAnimated()) {
        AnimatedTransform motion(RenderFromObject(0) * Inverse(renderFromWorld), transformStartTime,
                                 RenderFromObject(1) * Inverse(renderFromWorld), transformEndTime);
        if (motion.IsAnimated()) {
            Account(sizeof(InstanceSceneEntity) + 512 + double(name.size()), loc);
            scene.instances.push_back({name, loc, motion.Start(), motion});
            return;
        }
    }
    if (renderFromInstance.IsSingular()) {
        // An instance flattened to zero volume (Embree needs the inverse to trace it)
        diag.Warn(loc, "ObjectInstance '" + name + "' under a singular transform; skipped");
        return;
    }
    Account(sizeof(InstanceSceneEntity) + 64 + double(name.size()), loc);
    scene.instances.push_back({name, loc, renderFromInstance});
}

void SceneBuilder::EndOfFiles() {
    if (!pushStack.empty()) {
        const PushRecord& open = pushStack.back();
        throw SceneError(
            open.loc,
            std::string("missing end to ") + (open.kind == 'a' ? "AttributeBegin" : "ObjectBegin"),
            open.kind == 'a' ? "AttributeBegin" : "ObjectBegin");
    }
    for (const InstanceSceneEntity& inst : scene.instances)
        if (!scene.instanceDefinitions.count(inst.name))
            throw SceneError(inst.loc, "unknown object '" + inst.name + "'", inst.name);
    for (const ShapeSceneEntity& shape : scene.shapes)
        if (!shape.materialName.empty() && !namedMaterialNames.count(shape.materialName))
            throw SceneError(shape.loc,
                             "named material '" + shape.materialName + "' is not defined",
                             shape.materialName);
}

}  // namespace kiln
