// Shape::Create: shapes from "Shape" directives, with pbrt-v4 parameter names and defaults.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/geometry/ply_reader.h"
#include "core/geometry/shape.h"

#include "base/system_memory.h"
#include "core/geometry/loop_subdivision.h"
#include "core/geometry/mesh_displacement.h"
#include "core/parser/diagnostics.h"
#include "core/parser/parameter_dictionary.h"
#include "core/parser/suggestions.h"
#include "spectral/planck.h"

namespace kiln {

namespace {

// Charges the memory of what a directive is about to create (memory_budget.h); a
// MemoryLimitError becomes a SceneError at the directive.
void Charge(ObjectArena& arena, double bytes, const std::string& what, const FileLoc& loc,
            const std::string& token) {
    try {
        arena.Budget().Charge(bytes, what);
    } catch (const MemoryLimitError& e) {
        throw SceneError(loc, e.what(), token);
    }
}

double MeshBytes(double triangles, double vertices) {
    return triangles * MemoryBudget::kBytesPerTriangle + vertices * MemoryBudget::kBytesPerVertex;
}

// The most triangles a displaced PLY mesh may refine into (as loopsubdiv's limit)
constexpr size_t kMaxDisplacedTriangles = size_t(1) << 25;

void CheckIndices(const std::vector<int>& indices, size_t nVertices,
                  const ParameterDictionary& params, const FileLoc& loc) {
    for (int i : indices)
        if (i < 0 || size_t(i) >= nVertices)
            throw SceneError(params.Loc("indices", loc),
                             "vertex index " + std::to_string(i) + " out of range [0, " +
                                 std::to_string(nVertices) + ")",
                             "indices");
}

// Triangle shapes of a mesh, stored in one arena-owned array.
void AddTriangles(const TriangleMesh* mesh, ObjectArena& arena, std::vector<Shape>* shapes,
                  const FileLoc& loc, Diagnostics& diag) {
    if (mesh->nDegenerate > 0)
        diag.Warn(
            loc, std::to_string(mesh->nDegenerate) + " degenerate (zero-area) triangle(s) skipped");
    auto* tris = arena.New<std::vector<Triangle>>(Triangle::FromMesh(mesh));
    shapes->reserve(shapes->size() + tris->size());
    for (const Triangle& t : *tris) shapes->push_back(Shape(&t));
}

void AddPatches(const BilinearPatchMesh* mesh, ObjectArena& arena, std::vector<Shape>* shapes) {
    auto* patches = arena.New<std::vector<BilinearPatch>>(BilinearPatch::FromMesh(mesh));
    shapes->reserve(shapes->size() + patches->size());
    for (const BilinearPatch& b : *patches) shapes->push_back(Shape(&b));
}

template <typename T>
void CheckPerVertex(const std::vector<T>& v, size_t nP, const char* name,
                    const ParameterDictionary& params, const FileLoc& loc) {
    if (!v.empty() && v.size() != nP)
        throw SceneError(params.Loc(name, loc),
                         std::string("number of \"") + name + "\" values (" +
                             std::to_string(v.size()) + ") must match the number of \"P\" (" +
                             std::to_string(nP) + ")",
                         name);
}

// Per-vertex temperatures are kelvin, from 0 to kMaxRenderTemperature
void CheckTemperatures(const std::vector<Float>& t, const FileLoc& at, const std::string& what) {
    for (size_t i = 0; i < t.size(); ++i)
        if (!(t[i] >= 0 && t[i] <= kMaxRenderTemperature))
            throw SceneError(at,
                             what + ": vertex " + std::to_string(i) + " has temperature " +
                                 FormatKelvin(t[i]) +
                                 "; temperatures must be kelvin from 0 to 1e27",
                             "temperature");
}

// Whole triangles (a multiple of 3 indices), each index a vertex.
void CheckTriangleIndices(const std::vector<int>& indices, size_t nVertices,
                          const ParameterDictionary& params, const FileLoc& loc) {
    if (indices.size() % 3 != 0)
        throw SceneError(params.Loc("indices", loc),
                         "number of vertex indices (" + std::to_string(indices.size()) +
                             ") is not a multiple of 3",
                         "indices");
    CheckIndices(indices, nVertices, params, loc);
}

std::vector<Shape> CreateTriangleMesh(const Transform* renderFromObject, bool reverseOrientation,
                                      const ParameterDictionary& params, const FileLoc& loc,
                                      ObjectArena& arena, Diagnostics& diag) {
    std::vector<int> indices = params.GetIntArray("indices");
    std::vector<Point3f> P = params.GetPoint3fArray("P");
    std::vector<Point2f> uv = params.GetPoint2fArray("uv");
    std::vector<Normal3f> N = params.GetNormal3fArray("N");
    std::vector<Vector3f> S = params.GetVector3fArray("S");
    std::vector<int> faceIndices = params.GetIntArray("faceIndices");
    // Per-vertex temperatures: one value per vertex (a single value is a uniform temperature,
    // which scene creation reads; kiln's thermal_properties.h)
    std::vector<Float> temperature = params.GetFloatArray("temperature");
    if (temperature.size() == 1) temperature.clear();
    if (P.empty()) throw SceneError(loc, "vertex positions \"P\" must be provided", "trianglemesh");
    if (indices.empty()) {
        if (P.size() != 3)
            throw SceneError(loc,
                             "vertex indices \"indices\" must be provided with a triangle "
                             "mesh of more than one triangle",
                             "trianglemesh");
        indices = {0, 1, 2};
    }
    CheckTriangleIndices(indices, P.size(), params, loc);
    CheckPerVertex(uv, P.size(), "uv", params, loc);
    CheckPerVertex(N, P.size(), "N", params, loc);
    CheckPerVertex(S, P.size(), "S", params, loc);
    CheckPerVertex(temperature, P.size(), "temperature", params, loc);
    CheckTemperatures(temperature, params.Loc("temperature", loc), "trianglemesh");
    if (!faceIndices.empty() && faceIndices.size() != indices.size() / 3)
        throw SceneError(params.Loc("faceIndices", loc),
                         "number of \"faceIndices\" must match the number of triangles",
                         "faceIndices");
    std::map<std::string, std::vector<Float>> attributes;
    if (!temperature.empty()) attributes["temperature"] = std::move(temperature);
    Charge(arena, MeshBytes(double(indices.size() / 3), double(P.size())),
           "a trianglemesh of " + std::to_string(indices.size() / 3) + " triangles", loc,
           "trianglemesh");
    auto* mesh = arena.New<TriangleMesh>(*renderFromObject, reverseOrientation, std::move(indices),
                                         std::move(P), std::move(N), std::move(S), std::move(uv),
                                         std::move(faceIndices), std::move(attributes));
    std::vector<Shape> shapes;
    AddTriangles(mesh, arena, &shapes, loc, diag);
    return shapes;
}

// "loopsubdiv" (pbrt-v4): "integer levels" (3), "integer indices", "point3 P"; the refined
// triangles carry the limit surface's normals (loop_subdivision.h).
std::vector<Shape> CreateLoopSubdiv(const Transform* renderFromObject, bool reverseOrientation,
                                    const ParameterDictionary& params, const FileLoc& loc,
                                    ObjectArena& arena, Diagnostics& diag) {
    int levels = params.GetOneInt("levels", 3);
    std::vector<int> indices = params.GetIntArray("indices");
    std::vector<Point3f> P = params.GetPoint3fArray("P");
    if (P.empty()) throw SceneError(loc, "vertex positions \"P\" must be provided", "loopsubdiv");
    if (indices.empty())
        throw SceneError(loc, "vertex indices \"indices\" must be provided", "loopsubdiv");
    CheckTriangleIndices(indices, P.size(), params, loc);
    // Each level makes four triangles of one
    constexpr double kMaxTriangles = double(1 << 25);
    if (levels < 0 || double(indices.size() / 3) * std::pow(4.0, levels) > kMaxTriangles)
        throw SceneError(params.Loc("levels", loc),
                         "loopsubdiv \"levels\" must be >= 0 and make at most 2^25 triangles (" +
                             std::to_string(indices.size() / 3) + " triangles to begin with)",
                         std::to_string(levels));
    double triangles = double(indices.size() / 3) * std::pow(4.0, levels);
    Charge(arena, MeshBytes(triangles, triangles / 2),
           "loopsubdiv of " + std::to_string(int64_t(triangles)) + " triangles at level " +
               std::to_string(levels),
           params.Loc("levels", loc), "levels");
    SubdividedMesh m = LoopSubdivide(indices, P, levels);
    auto* mesh = arena.New<TriangleMesh>(
        *renderFromObject, reverseOrientation, std::move(m.indices), std::move(m.p), std::move(m.n),
        std::vector<Vector3f>(), std::vector<Point2f>(), std::vector<int>(),
        std::map<std::string, std::vector<Float>>());
    std::vector<Shape> shapes;
    AddTriangles(mesh, arena, &shapes, loc, diag);
    return shapes;
}

std::vector<Shape> CreateBilinearMesh(const Transform* renderFromObject, bool reverseOrientation,
                                      const ParameterDictionary& params, const FileLoc& loc,
                                      ObjectArena& arena) {
    std::vector<int> indices = params.GetIntArray("indices");
    std::vector<Point3f> P = params.GetPoint3fArray("P");
    std::vector<Point2f> uv = params.GetPoint2fArray("uv");
    std::vector<Normal3f> N = params.GetNormal3fArray("N");
    std::vector<int> faceIndices = params.GetIntArray("faceIndices");
    if (P.empty()) throw SceneError(loc, "vertex positions \"P\" must be provided", "bilinearmesh");
    if (indices.empty()) {
        if (P.size() != 4)
            throw SceneError(loc,
                             "vertex indices \"indices\" must be provided with a bilinear "
                             "mesh of more than one patch",
                             "bilinearmesh");
        indices = {0, 1, 2, 3};
    }
    if (indices.size() % 4 != 0)
        throw SceneError(params.Loc("indices", loc),
                         "number of vertex indices (" + std::to_string(indices.size()) +
                             ") is not a multiple of 4",
                         "indices");
    CheckIndices(indices, P.size(), params, loc);
    CheckPerVertex(uv, P.size(), "uv", params, loc);
    CheckPerVertex(N, P.size(), "N", params, loc);
    if (!faceIndices.empty() && faceIndices.size() != indices.size() / 4)
        throw SceneError(params.Loc("faceIndices", loc),
                         "number of \"faceIndices\" must match the number of patches",
                         "faceIndices");
    Charge(arena,
           double(indices.size() / 4) * MemoryBudget::kBytesPerPatch +
               double(P.size()) * MemoryBudget::kBytesPerVertex,
           "a bilinearmesh of " + std::to_string(indices.size() / 4) + " patches", loc,
           "bilinearmesh");
    auto* mesh = arena.New<BilinearPatchMesh>(*renderFromObject, reverseOrientation,
                                              std::move(indices), std::move(P), std::move(N),
                                              std::move(uv), std::move(faceIndices));
    std::vector<Shape> shapes;
    AddPatches(mesh, arena, &shapes);
    return shapes;
}

std::vector<Shape> CreatePLYMesh(const Transform* renderFromObject, bool reverseOrientation,
                                 const ParameterDictionary& params, const FileLoc& loc,
                                 ObjectArena& arena, Diagnostics& diag,
                                 const MeshDisplacement* displacement) {
    std::string filename = params.GetOneFilename("filename", "");
    if (filename.empty())
        throw SceneError(loc, "\"filename\" must be provided for a plymesh", "plymesh");
    if (!displacement &&
        (!params.GetTexture("displacement").empty() || params.Has("displacement"))) {
        diag.Warn(params.Loc("displacement", loc),
                  "plymesh displacement without its texture; rendering without it");
        params.GetOneFloat("edgelength", 1);
    }
    TriQuadMesh ply;
    // A header may claim any size: its counts are charged before the data are read, a face as
    // one triangle; quads (two triangles each) are charged once read, which the file's size
    // bounds
    double chargedTriangles = 0;
    auto charge = [&](double vertices, double faces) {
        chargedTriangles = faces;
        arena.Budget().Charge(MeshBytes(faces, vertices),
                              "PLY mesh \"" + filename + "\" (" +
                                  std::to_string(int64_t(vertices)) + " vertices, " +
                                  std::to_string(int64_t(faces)) + " faces)");
    };
    try {
        // Its bytes, held while it is parsed, within what the budget has left
        double room = std::min(double(DefaultMaxInputBytes()), arena.Budget().Remaining());
        ply = TriQuadMesh::ReadPLY(filename, charge, uint64_t(std::max(room, 0.0)));
    } catch (const MemoryLimitError& e) {
        throw SceneError(params.Loc("filename", loc), e.what(), filename);
    } catch (const SceneError& e) {
        // Report at the directive, naming the PLY file and the problem.
        throw SceneError(params.Loc("filename", loc), e.Loc().ToString() + ": " + e.Message(),
                         filename);
    }
    double readTriangles = double(ply.triIndices.size() / 3 + ply.quadIndices.size() / 2);
    if (readTriangles > chargedTriangles)
        Charge(arena, MeshBytes(readTriangles - chargedTriangles, 0),
               "PLY mesh \"" + filename + "\" (" + std::to_string(int64_t(readTriangles)) +
                   " triangles)",
               params.Loc("filename", loc), filename);
    if (auto t = ply.vertexAttributes.find("temperature"); t != ply.vertexAttributes.end())
        CheckTemperatures(t->second, params.Loc("filename", loc), filename);
    if (displacement) {
        // As many triangles as the memory left holds, and at most kMaxDisplacedTriangles
        // (the original ones are charged already)
        double before = double(ply.triIndices.size() / 3 + ply.quadIndices.size() / 2);
        size_t fit = size_t(std::min(double(kMaxDisplacedTriangles),
                                     before + arena.Budget().Remaining() / MeshBytes(1, 0.5)));
        try {
            DisplaceMesh(ply, *displacement, *renderFromObject, fit);
        } catch (const std::length_error&) {
            throw SceneError(params.Loc("edgelength", loc),
                             "displacing \"" + filename + "\" at this edge length would make " +
                                 "more than " + std::to_string(fit) + " triangles" +
                                 (fit < kMaxDisplacedTriangles
                                      ? ", more than the memory left (" +
                                            FormatBytes(arena.Budget().Remaining()) + ") holds"
                                      : ""),
                             "edgelength");
        } catch (const std::invalid_argument& e) {
            throw SceneError(params.Loc("displacement", loc),
                             "plymesh \"" + filename + "\": " + e.what(), "displacement");
        }
        Charge(arena, MeshBytes(double(ply.triIndices.size() / 3) - before, 0),
               "displaced PLY mesh \"" + filename + "\"", params.Loc("edgelength", loc),
               "edgelength");
    }
    std::vector<Shape> shapes;
    if (!ply.triIndices.empty()) {
        auto* mesh = arena.New<TriangleMesh>(
            *renderFromObject, reverseOrientation, std::move(ply.triIndices), ply.p, ply.n,
            std::vector<Vector3f>(), ply.uv, std::move(ply.triFaceIndices), ply.vertexAttributes);
        AddTriangles(mesh, arena, &shapes, loc, diag);
    }
    if (!ply.quadIndices.empty()) {
        auto* mesh = arena.New<BilinearPatchMesh>(
            *renderFromObject, reverseOrientation, std::move(ply.quadIndices), std::move(ply.p),
            std::move(ply.n), std::move(ply.uv), std::move(ply.quadFaceIndices));
        AddPatches(mesh, arena, &shapes);
    }
    return shapes;
}

// The shapes of one directive, before the check for finite extents
std::vector<Shape> CreateShapes(const std::string& name, const Transform* renderFromObject,
                                const Transform* objectFromRender, bool reverseOrientation,
                                const ParameterDictionary& params, const FileLoc& loc,
                                ObjectArena& arena, Diagnostics& diag,
                                const MeshDisplacement* displacement) {
    // Quadrics intersect in object space, through the inverse transform; under a singular one
    // (e.g. Scale 0, as pbrt-v4 scenes use to hide objects) they have no area to hit
    if ((name == "sphere" || name == "disk" || name == "cylinder") &&
        renderFromObject->IsSingular()) {
        diag.Warn(loc, "\"" + name + "\" under a singular transform has no area; skipped");
        params.MarkAllUsed();
        return {};
    }
    if (name == "sphere" || name == "disk" || name == "cylinder")
        Charge(arena, MemoryBudget::kBytesPerQuadric, "a " + name, loc, name);
    if (name == "sphere") {
        Float radius = params.GetOneFloat("radius", 1);
        Float zMin = params.GetOneFloat("zmin", -radius);
        Float zMax = params.GetOneFloat("zmax", radius);
        Float phiMax = params.GetOneFloat("phimax", 360);
        if (radius < 0)
            throw SceneError(params.Loc("radius", loc), "sphere radius must not be negative",
                             "radius");
        if (radius == 0) {  // pbrt-v4 accepts it and renders nothing
            diag.Warn(loc, "sphere of radius 0 has no surface; skipped");
            return {};
        }
        return {Shape(arena.New<Sphere>(renderFromObject, objectFromRender, reverseOrientation,
                                        radius, zMin, zMax, phiMax))};
    }
    if (name == "disk") {
        Float height = params.GetOneFloat("height", 0);
        Float radius = params.GetOneFloat("radius", 1);
        Float innerRadius = params.GetOneFloat("innerradius", 0);
        Float phiMax = params.GetOneFloat("phimax", 360);
        if (radius < 0 || innerRadius < 0)
            throw SceneError(loc, "disk radii must not be negative", "disk");
        if (innerRadius >= radius) {  // pbrt-v4 accepts it and renders nothing
            diag.Warn(loc, "disk with innerradius >= radius has no surface; skipped");
            return {};
        }
        return {Shape(arena.New<Disk>(renderFromObject, objectFromRender, reverseOrientation,
                                      height, radius, innerRadius, phiMax))};
    }
    if (name == "cylinder") {
        Float radius = params.GetOneFloat("radius", 1);
        Float zMin = params.GetOneFloat("zmin", -1);
        Float zMax = params.GetOneFloat("zmax", 1);
        Float phiMax = params.GetOneFloat("phimax", 360);
        if (radius < 0) throw SceneError(loc, "cylinder radius must not be negative", "cylinder");
        if (radius == 0 || zMin == zMax) {  // pbrt-v4 accepts it and renders nothing
            diag.Warn(loc, "cylinder of radius 0 or zmin == zmax has no surface; skipped");
            return {};
        }
        return {Shape(arena.New<Cylinder>(renderFromObject, objectFromRender, reverseOrientation,
                                          radius, zMin, zMax, phiMax))};
    }
    if (name == "trianglemesh")
        return CreateTriangleMesh(renderFromObject, reverseOrientation, params, loc, arena, diag);
    if (name == "bilinearmesh")
        return CreateBilinearMesh(renderFromObject, reverseOrientation, params, loc, arena);
    if (name == "plymesh")
        return CreatePLYMesh(renderFromObject, reverseOrientation, params, loc, arena, diag,
                             displacement);
    if (name == "loopsubdiv")
        return CreateLoopSubdiv(renderFromObject, reverseOrientation, params, loc, arena, diag);
    if (name == "curve") {  // scene creation makes curves (curve.h); they are no Shape
        diag.Warn(loc, "shape \"curve\" is created by scene creation, not Shape::Create; skipped");
        return {};
    }
    // pbrt-v4 stops at a shape it does not know; so does kiln, naming the nearest one
    static constexpr std::string_view kShapes[] = {"sphere",       "disk",         "cylinder",
                                                   "trianglemesh", "bilinearmesh", "plymesh",
                                                   "loopsubdiv",   "curve"};
    throw SceneError(loc, "unknown shape \"" + name + "\"" + DidYouMean(name, kShapes), name);
}

}  // namespace

// Shape creation
std::vector<Shape> Shape::Create(const std::string& name, const Transform* renderFromObject,
                                 const Transform* objectFromRender, bool reverseOrientation,
                                 const ParameterDictionary& params, const FileLoc& loc,
                                 ObjectArena& arena, Diagnostics& diag,
                                 const MeshDisplacement* displacement) {
    std::vector<Shape> shapes =
        CreateShapes(name, renderFromObject, objectFromRender, reverseOrientation, params, loc,
                     arena, diag, displacement);
    // Nothing beyond the range kiln traces rays in reaches the accelerator (vertices or radii
    // that overflow float, e.g. 1e30 under a Scale of 1e30, or merely pass 1e17)
    size_t kept = 0;
    for (const Shape& shape : shapes) {
        if (InRenderRange(shape.Bounds())) shapes[kept++] = shape;
    }
    if (kept < shapes.size()) {
        char limit[32];
        std::snprintf(limit, sizeof(limit), "%g", double(kMaxRenderCoordinate));
        diag.Warn(loc, std::to_string(shapes.size() - kept) + " of " +
                           std::to_string(shapes.size()) + " \"" + name +
                           "\" primitives extend beyond float range or +-" + limit +
                           " (render space), the range kiln traces rays in; skipped");
    }
    shapes.resize(kept);
    return shapes;
}

}  // namespace kiln
