#include "core/geometry/mesh_displacement.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

namespace kiln {

std::vector<Normal3f> VertexNormals(const std::vector<Point3f>& p, const std::vector<int>& tris) {
    std::vector<Normal3f> n(p.size(), Normal3f(0, 0, 0));
    for (size_t i = 0; i + 2 < tris.size(); i += 3) {
        int v0 = tris[i], v1 = tris[i + 1], v2 = tris[i + 2];
        Vector3f c = Cross(p[size_t(v1)] - p[size_t(v0)], p[size_t(v2)] - p[size_t(v1)]);
        if (!(LengthSquared(c) > 0)) continue;
        Normal3f fn(Normalize(c));
        for (int v : {v0, v1, v2}) n[size_t(v)] = n[size_t(v)] + fn;
    }
    for (Normal3f& v : n)
        if (LengthSquared(v) > 0) v = Normalize(v);
    return n;
}

namespace {

// Longest-edge bisection with shared midpoints
class Refiner {
  public:
    Refiner(TriQuadMesh& mesh, const Transform& renderFromObject, Float maxEdge,
            size_t maxTriangles)
        : m(mesh),
          renderFromObject(renderFromObject),
          maxEdge(maxEdge),
          maxTriangles(maxTriangles) {}

    void Refine(int v0, int v1, int v2, int face) {
        Float d01 = Distance(v0, v1), d12 = Distance(v1, v2), d20 = Distance(v2, v0);
        if (d01 < maxEdge && d12 < maxEdge && d20 < maxEdge) {
            Emit(v0, v1, v2, face);
            return;
        }
        // Rotate so that (a, b) is the longest edge, keeping the winding
        int a, b, c;
        if (d01 > d12)
            d01 > d20 ? (a = v0, b = v1, c = v2) : (a = v2, b = v0, c = v1);
        else
            d12 > d20 ? (a = v1, b = v2, c = v0) : (a = v2, b = v0, c = v1);
        int mid = Midpoint(a, b);
        // A midpoint single precision cannot tell from an end (an edge length far below the
        // mesh's size): the triangle is as refined as float allows (bisecting on would recurse
        // until the stack overflowed)
        if (m.p[size_t(mid)] == m.p[size_t(a)] || m.p[size_t(mid)] == m.p[size_t(b)]) {
            Emit(v0, v1, v2, face);
            return;
        }
        Refine(a, mid, c, face);
        Refine(mid, b, c, face);
    }

    std::vector<int> out, faces;

  private:
    void Emit(int v0, int v1, int v2, int face) {
        if (out.size() / 3 >= maxTriangles)
            throw std::length_error("more than " + std::to_string(maxTriangles) + " triangles");
        out.insert(out.end(), {v0, v1, v2});
        if (face >= 0) faces.push_back(face);
    }
    Float Distance(int i, int j) const {
        return kiln::Distance(renderFromObject(m.p[size_t(i)]), renderFromObject(m.p[size_t(j)]));
    }
    int Midpoint(int i, int j) {
        std::pair<int, int> key = i < j ? std::pair{i, j} : std::pair{j, i};
        auto it = split.find(key);
        if (it != split.end()) return it->second;
        int mid = int(m.p.size());
        split.emplace(key, mid);
        m.p.push_back(Lerp(0.5f, m.p[size_t(i)], m.p[size_t(j)]));
        Normal3f n = m.n[size_t(i)] + m.n[size_t(j)];
        m.n.push_back(LengthSquared(n) > 0 ? Normalize(n) : n);
        m.uv.push_back(Point2f(0.5f * (m.uv[size_t(i)].x + m.uv[size_t(j)].x),
                               0.5f * (m.uv[size_t(i)].y + m.uv[size_t(j)].y)));
        for (auto& [name, values] : m.vertexAttributes)
            values.push_back(0.5f * (values[size_t(i)] + values[size_t(j)]));
        return mid;
    }

    struct PairHash {
        size_t operator()(std::pair<int, int> p) const {
            return std::hash<uint64_t>()(uint64_t(uint32_t(p.first)) << 32 | uint32_t(p.second));
        }
    };
    TriQuadMesh& m;
    const Transform& renderFromObject;
    Float maxEdge;
    size_t maxTriangles;
    std::unordered_map<std::pair<int, int>, int, PairHash> split;
};

}  // namespace

void DisplaceMesh(TriQuadMesh& mesh, const MeshDisplacement& displacement,
                  const Transform& renderFromObject, size_t maxTriangles) {
    if (mesh.uv.size() != mesh.p.size())
        throw std::invalid_argument("displacement needs per-vertex uv");
    // Quads as two triangles each
    for (size_t i = 0; i + 3 < mesh.quadIndices.size(); i += 4) {
        const int* q = &mesh.quadIndices[i];
        mesh.triIndices.insert(mesh.triIndices.end(), {q[0], q[1], q[3], q[0], q[3], q[2]});
        if (!mesh.quadFaceIndices.empty()) {
            int f = mesh.quadFaceIndices[i / 4];
            mesh.triFaceIndices.insert(mesh.triFaceIndices.end(), {f, f});
        }
    }
    mesh.quadIndices.clear();
    mesh.quadFaceIndices.clear();
    if (mesh.n.size() != mesh.p.size()) mesh.n = VertexNormals(mesh.p, mesh.triIndices);

    // At least longest edge / edge length triangles come from each (its pieces are edges of
    // different ones): more than maxTriangles fails at once, before refining
    double atLeast = 0;
    for (size_t t = 0; t + 2 < mesh.triIndices.size(); t += 3) {
        Point3f q[3];
        for (int k = 0; k < 3; ++k) q[k] = renderFromObject(mesh.p[size_t(mesh.triIndices[t + k])]);
        Float longest =
            std::max({Distance(q[0], q[1]), Distance(q[1], q[2]), Distance(q[2], q[0])});
        atLeast += std::ceil(double(longest) / double(displacement.edgeLength));
    }
    if (!(atLeast <= double(maxTriangles)))
        throw std::length_error("more than " + std::to_string(maxTriangles) + " triangles");
    Refiner refiner(mesh, renderFromObject, displacement.edgeLength, maxTriangles);
    std::vector<int> tris = std::move(mesh.triIndices);
    bool faces = !mesh.triFaceIndices.empty();
    for (size_t t = 0; t + 2 < tris.size(); t += 3)
        refiner.Refine(tris[t], tris[t + 1], tris[t + 2], faces ? mesh.triFaceIndices[t / 3] : -1);
    mesh.triIndices = std::move(refiner.out);
    mesh.triFaceIndices = std::move(refiner.faces);

    for (size_t i = 0; i < mesh.p.size(); ++i) {
        Float d = displacement.displace(mesh.p[i], mesh.n[i], mesh.uv[i]);
        if (std::isfinite(d)) mesh.p[i] = mesh.p[i] + d * Vector3f(mesh.n[i]);
    }
    mesh.n = VertexNormals(mesh.p, mesh.triIndices);
}

}  // namespace kiln
