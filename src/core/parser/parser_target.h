// ParserTarget: the interface the scene parser drives, one method per pbrt-v4 directive.
//
// The parser only checks syntax (argument counts and kinds) and emits these calls in file
// order; it builds nothing. Numbers are passed as written. Transform and ConcatTransform get
// the 16 numbers in file order (pbrt-v4 then transposes them into its matrix).
// Deprecated TransformBegin/TransformEnd arrive as AttributeBegin/AttributeEnd (with a
// warning), as in pbrt-v4. Import arrives as the imported file's directives enclosed in
// AttributeBegin/AttributeEnd (see parser.h). EndOfFiles is called once, after the last file.
#pragma once

#include <array>
#include <cstddef>
#include <string>

#include "base/vecmath.h"
#include "core/parser/file_loc.h"
#include "core/parser/parsed_parameter.h"

namespace kiln {

class ParserTarget {
  public:
    virtual ~ParserTarget() = default;

    // Transformations
    virtual void Identity(const FileLoc& loc) = 0;
    virtual void Translate(Float dx, Float dy, Float dz, const FileLoc& loc) = 0;
    virtual void Scale(Float sx, Float sy, Float sz, const FileLoc& loc) = 0;
    // Angle in degrees.
    virtual void Rotate(Float angle, Float ax, Float ay, Float az, const FileLoc& loc) = 0;
    virtual void LookAt(Float ex, Float ey, Float ez, Float lx, Float ly, Float lz, Float ux,
                        Float uy, Float uz, const FileLoc& loc) = 0;
    virtual void ConcatTransform(const std::array<Float, 16>& m, const FileLoc& loc) = 0;
    virtual void Transform(const std::array<Float, 16>& m, const FileLoc& loc) = 0;
    virtual void CoordinateSystem(const std::string& name, const FileLoc& loc) = 0;
    virtual void CoordSysTransform(const std::string& name, const FileLoc& loc) = 0;
    virtual void ActiveTransformAll(const FileLoc& loc) = 0;
    virtual void ActiveTransformEndTime(const FileLoc& loc) = 0;
    virtual void ActiveTransformStartTime(const FileLoc& loc) = 0;
    virtual void TransformTimes(Float start, Float end, const FileLoc& loc) = 0;

    // Rendering options
    // Option "type name" value (pbrt-v4): `name` is the whole declaration string, e.g.
    // "bool disablepixeljitter"; `value` is the value token as written, quoted strings keeping
    // their quotes (as pbrt-v4). A one-element bracketed list [ v ] is accepted.
    virtual void Option(const std::string& name, const std::string& value, const FileLoc& loc) = 0;
    virtual void ColorSpace(const std::string& name, const FileLoc& loc) = 0;
    virtual void PixelFilter(const std::string& name, ParsedParameterVector params,
                             const FileLoc& loc) = 0;
    virtual void Film(const std::string& type, ParsedParameterVector params,
                      const FileLoc& loc) = 0;
    virtual void Accelerator(const std::string& name, ParsedParameterVector params,
                             const FileLoc& loc) = 0;
    virtual void Integrator(const std::string& name, ParsedParameterVector params,
                            const FileLoc& loc) = 0;
    virtual void Camera(const std::string& name, ParsedParameterVector params,
                        const FileLoc& loc) = 0;
    virtual void Sampler(const std::string& name, ParsedParameterVector params,
                         const FileLoc& loc) = 0;
    virtual void MakeNamedMedium(const std::string& name, ParsedParameterVector params,
                                 const FileLoc& loc) = 0;
    // With one name in the file, inside and outside are both that name.
    virtual void MediumInterface(const std::string& insideName, const std::string& outsideName,
                                 const FileLoc& loc) = 0;
    virtual void WorldBegin(const FileLoc& loc) = 0;

    // Scene description
    virtual void AttributeBegin(const FileLoc& loc) = 0;
    virtual void AttributeEnd(const FileLoc& loc) = 0;
    // target is "shape", "light", "material", "medium" or "texture" (not checked here).
    virtual void Attribute(const std::string& target, ParsedParameterVector params,
                           const FileLoc& loc) = 0;
    virtual void Shape(const std::string& name, ParsedParameterVector params,
                       const FileLoc& loc) = 0;
    virtual void ReverseOrientation(const FileLoc& loc) = 0;
    // Texture "name" "type" "class" params...: type is "float" or "spectrum" (not checked here).
    virtual void Texture(const std::string& name, const std::string& type,
                         const std::string& texName, ParsedParameterVector params,
                         const FileLoc& loc) = 0;
    virtual void Material(const std::string& name, ParsedParameterVector params,
                          const FileLoc& loc) = 0;
    virtual void MakeNamedMaterial(const std::string& name, ParsedParameterVector params,
                                   const FileLoc& loc) = 0;
    virtual void NamedMaterial(const std::string& name, const FileLoc& loc) = 0;
    virtual void LightSource(const std::string& name, ParsedParameterVector params,
                             const FileLoc& loc) = 0;
    virtual void AreaLightSource(const std::string& name, ParsedParameterVector params,
                                 const FileLoc& loc) = 0;
    virtual void ObjectBegin(const std::string& name, const FileLoc& loc) = 0;
    virtual void ObjectEnd(const FileLoc& loc) = 0;
    virtual void ObjectInstance(const std::string& name, const FileLoc& loc) = 0;

    // The parser holds a file's contents (`bytes`, decompressed) while it parses them: the
    // scene file, or the one an Include or Import at loc names.
    virtual void FileContents(size_t bytes, const FileLoc& loc) {
        (void)bytes;
        (void)loc;
    }

    virtual void EndOfFiles() = 0;
};

}  // namespace kiln
