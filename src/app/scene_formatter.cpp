#include "app/scene_formatter.h"

#include <charconv>
#include <cstdio>
#include <filesystem>

#include "base/atomic_file.h"
#include "core/geometry/ply_writer.h"
#include "core/parser/diagnostics.h"

namespace kiln {

namespace {

// The shortest text that reads back as the same float
std::string Number(Float v) {
    char buf[32];
    auto r = std::to_chars(buf, buf + sizeof(buf), v);
    return std::string(buf, r.ptr);
}

std::string Quoted(const std::string& s) {
    std::string q = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') q += '\\';
        q += c;
    }
    return q + "\"";
}

std::string Numbers(std::initializer_list<Float> values) {
    std::string s;
    for (Float v : values) {
        if (!s.empty()) s += ' ';
        s += Number(v);
    }
    return s;
}

const ParsedParameter* Find(const ParsedParameterVector& params, const std::string& type,
                            const std::string& name) {
    const ParsedParameter* found = nullptr;  // the last one wins, as in lookups
    for (const ParsedParameter& p : params)
        if (p.type == type && p.name == name) found = &p;
    return found;
}

}  // namespace

void SceneFormatter::Line(const std::string& text) {
    out << std::string(size_t(2 * indent), ' ') << text << '\n';
}

void SceneFormatter::Directive(const std::string& head, const ParsedParameterVector& params) {
    Line(head);
    ++indent;
    ++indent;
    for (const ParsedParameter& p : params) Line(p.ToString());
    indent -= 2;
}

void SceneFormatter::Translate(Float dx, Float dy, Float dz, const FileLoc&) {
    Line("Translate " + Numbers({dx, dy, dz}));
}
void SceneFormatter::Scale(Float sx, Float sy, Float sz, const FileLoc&) {
    Line("Scale " + Numbers({sx, sy, sz}));
}
void SceneFormatter::Rotate(Float angle, Float ax, Float ay, Float az, const FileLoc&) {
    Line("Rotate " + Numbers({angle, ax, ay, az}));
}
void SceneFormatter::LookAt(Float ex, Float ey, Float ez, Float lx, Float ly, Float lz, Float ux,
                            Float uy, Float uz, const FileLoc&) {
    Line("LookAt " + Numbers({ex, ey, ez}) + "  " + Numbers({lx, ly, lz}) + "  " +
         Numbers({ux, uy, uz}));
}
void SceneFormatter::ConcatTransform(const std::array<Float, 16>& m, const FileLoc&) {
    std::string s;
    for (Float v : m) {
        s += ' ';
        s += Number(v);
    }
    Line("ConcatTransform [" + s + " ]");
}
void SceneFormatter::Transform(const std::array<Float, 16>& m, const FileLoc&) {
    std::string s;
    for (Float v : m) {
        s += ' ';
        s += Number(v);
    }
    Line("Transform [" + s + " ]");
}
void SceneFormatter::CoordinateSystem(const std::string& name, const FileLoc&) {
    Line("CoordinateSystem " + Quoted(name));
}
void SceneFormatter::CoordSysTransform(const std::string& name, const FileLoc&) {
    Line("CoordSysTransform " + Quoted(name));
}
void SceneFormatter::TransformTimes(Float start, Float end, const FileLoc&) {
    Line("TransformTimes " + Numbers({start, end}));
}
void SceneFormatter::Option(const std::string& name, const std::string& value, const FileLoc&) {
    Line("Option " + Quoted(name) + " " + value);  // the value as written (quotes kept)
}
void SceneFormatter::ColorSpace(const std::string& name, const FileLoc&) {
    Line("ColorSpace " + Quoted(name));
}
void SceneFormatter::PixelFilter(const std::string& name, ParsedParameterVector params,
                                 const FileLoc&) {
    Directive("PixelFilter " + Quoted(name), params);
}
void SceneFormatter::Film(const std::string& type, ParsedParameterVector params, const FileLoc&) {
    Directive("Film " + Quoted(type), params);
}
void SceneFormatter::Accelerator(const std::string& name, ParsedParameterVector params,
                                 const FileLoc&) {
    Directive("Accelerator " + Quoted(name), params);
}
void SceneFormatter::Integrator(const std::string& name, ParsedParameterVector params,
                                const FileLoc&) {
    Directive("Integrator " + Quoted(name), params);
}
void SceneFormatter::Camera(const std::string& name, ParsedParameterVector params, const FileLoc&) {
    Directive("Camera " + Quoted(name), params);
}
void SceneFormatter::Sampler(const std::string& name, ParsedParameterVector params,
                             const FileLoc&) {
    Directive("Sampler " + Quoted(name), params);
}
void SceneFormatter::MakeNamedMedium(const std::string& name, ParsedParameterVector params,
                                     const FileLoc&) {
    Directive("MakeNamedMedium " + Quoted(name), params);
}
void SceneFormatter::MediumInterface(const std::string& insideName, const std::string& outsideName,
                                     const FileLoc&) {
    Line("MediumInterface " + Quoted(insideName) + " " + Quoted(outsideName));
}
void SceneFormatter::AttributeBegin(const FileLoc&) {
    Line("AttributeBegin");
    ++indent;
}
void SceneFormatter::AttributeEnd(const FileLoc&) {
    indent = std::max(0, indent - 1);
    Line("AttributeEnd");
}
void SceneFormatter::Attribute(const std::string& target, ParsedParameterVector params,
                               const FileLoc&) {
    Directive("Attribute " + Quoted(target), params);
}
void SceneFormatter::Texture(const std::string& name, const std::string& type,
                             const std::string& texName, ParsedParameterVector params,
                             const FileLoc&) {
    Directive("Texture " + Quoted(name) + " " + Quoted(type) + " " + Quoted(texName), params);
}
void SceneFormatter::Material(const std::string& name, ParsedParameterVector params,
                              const FileLoc&) {
    Directive("Material " + Quoted(name), params);
}
void SceneFormatter::MakeNamedMaterial(const std::string& name, ParsedParameterVector params,
                                       const FileLoc&) {
    Directive("MakeNamedMaterial " + Quoted(name), params);
}
void SceneFormatter::NamedMaterial(const std::string& name, const FileLoc&) {
    Line("NamedMaterial " + Quoted(name));
}
void SceneFormatter::LightSource(const std::string& name, ParsedParameterVector params,
                                 const FileLoc&) {
    Directive("LightSource " + Quoted(name), params);
}
void SceneFormatter::AreaLightSource(const std::string& name, ParsedParameterVector params,
                                     const FileLoc&) {
    Directive("AreaLightSource " + Quoted(name), params);
}
void SceneFormatter::ObjectBegin(const std::string& name, const FileLoc&) {
    Line("ObjectBegin " + Quoted(name));
    ++indent;
}
void SceneFormatter::ObjectEnd(const FileLoc&) {
    indent = std::max(0, indent - 1);
    Line("ObjectEnd");
}
void SceneFormatter::ObjectInstance(const std::string& name, const FileLoc&) {
    Line("ObjectInstance " + Quoted(name));
}

void SceneFormatter::Shape(const std::string& name, ParsedParameterVector params,
                           const FileLoc& loc) {
    if (toPly && name == "trianglemesh" && WritePlyMesh(params, loc)) {
        Directive("Shape \"plymesh\"", params);
        return;
    }
    Directive("Shape " + Quoted(name), params);
}

bool SceneFormatter::WritePlyMesh(ParsedParameterVector& params, const FileLoc& loc) {
    const ParsedParameter* P = Find(params, "point3", "P");
    if (!P || P->floats.size() < 9 || P->floats.size() % 3 != 0 || Find(params, "vector3", "S"))
        return false;
    size_t nv = P->floats.size() / 3;
    PlyTriangles mesh;
    for (size_t i = 0; i < nv; ++i)
        mesh.p.push_back(Point3f(P->floats[3 * i], P->floats[3 * i + 1], P->floats[3 * i + 2]));
    const ParsedParameter* indices = Find(params, "integer", "indices");
    if (indices)
        mesh.indices = indices->ints;
    else if (nv == 3)
        mesh.indices = {0, 1, 2};
    else
        return false;
    if (const ParsedParameter* N = Find(params, "normal", "N"); N && N->floats.size() == 3 * nv)
        for (size_t i = 0; i < nv; ++i)
            mesh.n.push_back(
                Normal3f(N->floats[3 * i], N->floats[3 * i + 1], N->floats[3 * i + 2]));
    if (const ParsedParameter* uv = Find(params, "point2", "uv"); uv && uv->floats.size() == 2 * nv)
        for (size_t i = 0; i < nv; ++i)
            mesh.uv.push_back(Point2f(uv->floats[2 * i], uv->floats[2 * i + 1]));
    if (const ParsedParameter* f = Find(params, "integer", "faceIndices"))
        mesh.faceIndices = f->ints;
    // Per-vertex float attributes (kiln's "float temperature" with one value per vertex)
    for (const ParsedParameter& p : params)
        if (p.type == "float" && p.floats.size() == nv && nv > 1)
            mesh.vertexAttributes[p.name] = p.floats;
    std::string bytes;
    try {
        bytes = EncodePly(mesh);
    } catch (const std::invalid_argument&) {
        return false;  // inconsistent sizes: print it as it is, for the renderer to report
    }
    char name[32];
    std::snprintf(name, sizeof(name), "mesh_%05d.ply", ++plyCount);
    std::string file = (std::filesystem::path(plyFolder) / name).string();
    try {
        WriteFileAtomically(file, bytes);
    } catch (const std::exception& e) {
        throw SceneError(loc, std::string("cannot write the mesh as PLY: ") + e.what(), file);
    }
    // What the PLY holds leaves the parameter list; the file name takes its place
    ParsedParameterVector rest;
    ParsedParameter filename;
    filename.type = "string";
    filename.name = "filename";
    filename.strings = {file};
    rest.push_back(filename);
    for (ParsedParameter& p : params) {
        bool inPly =
            (p.type == "point3" && p.name == "P") ||
            (p.type == "integer" && (p.name == "indices" || p.name == "faceIndices")) ||
            (p.type == "normal" && p.name == "N" && !mesh.n.empty()) ||
            (p.type == "point2" && p.name == "uv" && !mesh.uv.empty()) ||
            (p.type == "float" && mesh.vertexAttributes.count(p.name) && p.floats.size() == nv);
        if (!inPly) rest.push_back(std::move(p));
    }
    params = std::move(rest);
    return true;
}

}  // namespace kiln
