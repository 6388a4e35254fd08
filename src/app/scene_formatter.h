// pbrt-v4's --format and --toply: the scene file (with its Includes and Imports spliced in, an
// Import as an AttributeBegin/AttributeEnd block) printed again in a canonical layout, one
// directive per line and one parameter per line, indented by nesting, numbers written so that
// they read back exactly. With toPly, every "trianglemesh" becomes a "plymesh" whose PLY file
// (binary, in `plyFolder`, named mesh_00001.ply, ...) holds its positions, normals, uv,
// per-vertex float attributes (e.g. "temperature") and face indices; a mesh with tangents
// ("S") stays as it is. Renders of the output are bit-identical to renders of the input.
#pragma once

#include <ostream>
#include <string>

#include "core/parser/parser_target.h"

namespace kiln {

class SceneFormatter final : public ParserTarget {
  public:
    SceneFormatter(std::ostream& out, bool toPly, std::string plyFolder = ".")
        : out(out), toPly(toPly), plyFolder(std::move(plyFolder)) {}

    void Identity(const FileLoc&) override { Line("Identity"); }
    void Translate(Float dx, Float dy, Float dz, const FileLoc&) override;
    void Scale(Float sx, Float sy, Float sz, const FileLoc&) override;
    void Rotate(Float angle, Float ax, Float ay, Float az, const FileLoc&) override;
    void LookAt(Float ex, Float ey, Float ez, Float lx, Float ly, Float lz, Float ux, Float uy,
                Float uz, const FileLoc&) override;
    void ConcatTransform(const std::array<Float, 16>& m, const FileLoc&) override;
    void Transform(const std::array<Float, 16>& m, const FileLoc&) override;
    void CoordinateSystem(const std::string& name, const FileLoc&) override;
    void CoordSysTransform(const std::string& name, const FileLoc&) override;
    void ActiveTransformAll(const FileLoc&) override { Line("ActiveTransform All"); }
    void ActiveTransformEndTime(const FileLoc&) override { Line("ActiveTransform EndTime"); }
    void ActiveTransformStartTime(const FileLoc&) override { Line("ActiveTransform StartTime"); }
    void TransformTimes(Float start, Float end, const FileLoc&) override;
    void Option(const std::string& name, const std::string& value, const FileLoc&) override;
    void ColorSpace(const std::string& name, const FileLoc&) override;
    void PixelFilter(const std::string& name, ParsedParameterVector params,
                     const FileLoc&) override;
    void Film(const std::string& type, ParsedParameterVector params, const FileLoc&) override;
    void Accelerator(const std::string& name, ParsedParameterVector params,
                     const FileLoc&) override;
    void Integrator(const std::string& name, ParsedParameterVector params, const FileLoc&) override;
    void Camera(const std::string& name, ParsedParameterVector params, const FileLoc&) override;
    void Sampler(const std::string& name, ParsedParameterVector params, const FileLoc&) override;
    void MakeNamedMedium(const std::string& name, ParsedParameterVector params,
                         const FileLoc&) override;
    void MediumInterface(const std::string& insideName, const std::string& outsideName,
                         const FileLoc&) override;
    void WorldBegin(const FileLoc&) override { Line("WorldBegin"); }
    void AttributeBegin(const FileLoc&) override;
    void AttributeEnd(const FileLoc&) override;
    void Attribute(const std::string& target, ParsedParameterVector params,
                   const FileLoc&) override;
    void Shape(const std::string& name, ParsedParameterVector params, const FileLoc&) override;
    void ReverseOrientation(const FileLoc&) override { Line("ReverseOrientation"); }
    void Texture(const std::string& name, const std::string& type, const std::string& texName,
                 ParsedParameterVector params, const FileLoc&) override;
    void Material(const std::string& name, ParsedParameterVector params, const FileLoc&) override;
    void MakeNamedMaterial(const std::string& name, ParsedParameterVector params,
                           const FileLoc&) override;
    void NamedMaterial(const std::string& name, const FileLoc&) override;
    void LightSource(const std::string& name, ParsedParameterVector params,
                     const FileLoc&) override;
    void AreaLightSource(const std::string& name, ParsedParameterVector params,
                         const FileLoc&) override;
    void ObjectBegin(const std::string& name, const FileLoc&) override;
    void ObjectEnd(const FileLoc&) override;
    void ObjectInstance(const std::string& name, const FileLoc&) override;
    void EndOfFiles() override { out.flush(); }

    // How many PLY files were written.
    int PlyFiles() const { return plyCount; }

  private:
    void Line(const std::string& text);
    void Directive(const std::string& head, const ParsedParameterVector& params);
    // A trianglemesh as a plymesh (its PLY written); false to print it as it is.
    bool WritePlyMesh(ParsedParameterVector& params, const FileLoc& loc);

    std::ostream& out;
    bool toPly;
    std::string plyFolder;
    int indent = 0, plyCount = 0;
};

}  // namespace kiln
