#include "core/geometry/loop_subdivision.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace kiln {

namespace {

// Connectivity of one level: every edge with the vertices opposite it, and per vertex its
// neighbours in winding order around it.
struct Connectivity {
    struct Edge {
        int a, b;  // a < b
        int opposite[2] = {-1, -1};
        int faces = 0;  // triangles sharing the edge
        bool Boundary() const { return faces != 2; }
    };
    std::vector<Edge> edges;
    std::unordered_map<uint64_t, int> edgeIndex;
    std::vector<std::vector<int>> ring;  // ordered one-ring (see Ring)
    std::vector<bool> boundary;          // vertex on a boundary edge
    std::vector<Vector3f> faceNormalSum;

    static uint64_t Key(int a, int b) {
        if (a > b) std::swap(a, b);
        return (uint64_t(uint32_t(a)) << 32) | uint32_t(b);
    }
    int EdgeOf(int a, int b) const { return edgeIndex.at(Key(a, b)); }

    Connectivity(std::span<const int> indices, std::span<const Point3f> p) {
        size_t nv = p.size();
        boundary.assign(nv, false);
        faceNormalSum.assign(nv, Vector3f(0, 0, 0));
        // For each vertex, the (next, following) pairs of its triangles in winding order
        std::vector<std::vector<std::pair<int, int>>> wedges(nv);
        for (size_t f = 0; f + 2 < indices.size(); f += 3) {
            int v[3] = {indices[f], indices[f + 1], indices[f + 2]};
            Vector3f normal =
                Cross(p[size_t(v[0])] - p[size_t(v[2])], p[size_t(v[1])] - p[size_t(v[2])]);
            for (int k = 0; k < 3; ++k) {
                int a = v[k], b = v[(k + 1) % 3], c = v[(k + 2) % 3];
                auto [it, added] = edgeIndex.try_emplace(Key(a, b), int(edges.size()));
                if (added) edges.push_back({std::min(a, b), std::max(a, b)});
                Edge& e = edges[size_t(it->second)];
                if (e.faces < 2) e.opposite[e.faces] = c;
                ++e.faces;
                wedges[size_t(a)].push_back({b, c});
                faceNormalSum[size_t(a)] += normal;
            }
        }
        for (const Edge& e : edges)
            if (e.Boundary()) boundary[size_t(e.a)] = boundary[size_t(e.b)] = true;
        ring.resize(nv);
        for (size_t v = 0; v < nv; ++v) ring[v] = Ring(wedges[v]);
    }

    // The neighbours around a vertex in winding order: a cycle for an interior vertex, for a
    // boundary vertex the chain from one boundary neighbour to the other. Where the faces do not
    // form one fan (non-manifold), the neighbours in the order met.
    static std::vector<int> Ring(const std::vector<std::pair<int, int>>& wedges) {
        std::vector<int> ring;
        if (wedges.empty()) return ring;
        std::unordered_map<int, int> next;
        std::unordered_map<int, int> predecessors;
        for (auto [a, b] : wedges) {
            next.emplace(a, b);
            ++predecessors[b];
        }
        int start = wedges[0].first;
        for (auto [a, b] : wedges)
            if (!predecessors.count(a)) start = a;  // the chain's first neighbour
        int v = start;
        for (size_t k = 0; k <= wedges.size(); ++k) {
            ring.push_back(v);
            auto it = next.find(v);
            if (it == next.end() || it->second == start) break;
            v = it->second;
        }
        if (ring.size() != wedges.size() + 1 && ring.size() != wedges.size()) {
            // Not a single fan: every neighbour once, in the order met
            ring.clear();
            for (auto [a, b] : wedges)
                for (int w : {a, b})
                    if (std::find(ring.begin(), ring.end(), w) == ring.end()) ring.push_back(w);
        }
        return ring;
    }

    // The two boundary neighbours of a boundary vertex, if exactly two.
    bool BoundaryNeighbours(int v, int* b0, int* b1) const {
        int found = 0;
        for (int w : ring[size_t(v)])
            if (edges[size_t(EdgeOf(v, w))].Boundary()) {
                if (found == 2) return false;
                (found == 0 ? *b0 : *b1) = w;
                ++found;
            }
        return found == 2;
    }
};

Float Beta(int valence) { return valence == 3 ? 3.f / 16 : 3.f / (8 * valence); }

Vector3f Sum(std::span<const Point3f> p, const std::vector<int>& vs) {
    Vector3f s(0, 0, 0);
    for (int v : vs) s += Vector3f(p[size_t(v)]);
    return s;
}

// One level of refinement.
void Refine(std::vector<Point3f>& p, std::vector<int>& indices) {
    Connectivity c(indices, p);
    size_t nv = p.size();
    std::vector<Point3f> q(nv + c.edges.size());
    // Old (even) vertices
    for (size_t v = 0; v < nv; ++v) {
        const std::vector<int>& ring = c.ring[v];
        int b0, b1;
        if (ring.empty()) {
            q[v] = p[v];
        } else if (!c.boundary[v]) {
            int n = int(ring.size());
            Float beta = Beta(n);
            q[v] = Point3f((1 - n * beta) * Vector3f(p[v]) + beta * Sum(p, ring));
        } else if (c.BoundaryNeighbours(int(v), &b0, &b1)) {
            q[v] = Point3f(0.75f * Vector3f(p[v]) +
                           0.125f * (Vector3f(p[size_t(b0)]) + Vector3f(p[size_t(b1)])));
        } else {
            q[v] = p[v];  // a corner
        }
    }
    // New (odd) vertices, one per edge
    for (size_t e = 0; e < c.edges.size(); ++e) {
        const Connectivity::Edge& edge = c.edges[e];
        Vector3f a(p[size_t(edge.a)]), b(p[size_t(edge.b)]);
        if (edge.Boundary())
            q[nv + e] = Point3f(0.5f * (a + b));
        else
            q[nv + e] =
                Point3f(0.375f * (a + b) + 0.125f * (Vector3f(p[size_t(edge.opposite[0])]) +
                                                     Vector3f(p[size_t(edge.opposite[1])])));
    }
    // Each triangle into four, keeping the winding
    std::vector<int> refined;
    refined.reserve(indices.size() * 4);
    for (size_t f = 0; f + 2 < indices.size(); f += 3) {
        int a = indices[f], b = indices[f + 1], cc = indices[f + 2];
        int ab = int(nv) + c.EdgeOf(a, b), bc = int(nv) + c.EdgeOf(b, cc),
            ca = int(nv) + c.EdgeOf(cc, a);
        for (int v : {a, ab, ca, ab, b, bc, ca, bc, cc, ab, bc, ca}) refined.push_back(v);
    }
    p = std::move(q);
    indices = std::move(refined);
}

}  // namespace

SubdividedMesh LoopSubdivide(std::span<const int> indices, std::span<const Point3f> p0,
                             int levels) {
    std::vector<Point3f> p(p0.begin(), p0.end());
    std::vector<int> idx(indices.begin(), indices.end());
    for (int level = 0; level < levels; ++level) Refine(p, idx);

    // Limit positions and normals
    Connectivity c(idx, p);
    SubdividedMesh m;
    m.p.resize(p.size());
    m.n.assign(p.size(), Normal3f(0, 0, 0));
    for (size_t v = 0; v < p.size(); ++v) {
        const std::vector<int>& ring = c.ring[v];
        int n = int(ring.size()), b0, b1;
        Vector3f pv(p[v]), s, t;
        if (ring.empty()) {
            m.p[v] = p[v];
            continue;
        }
        if (!c.boundary[v]) {
            Float w = 1 / (n + 3 / (8 * Beta(n)));
            m.p[v] = Point3f((1 - n * w) * pv + w * Sum(p, ring));
            for (int k = 0; k < n; ++k) {
                Float phi = 2 * Pi * k / n;
                s += std::cos(phi) * Vector3f(p[size_t(ring[size_t(k)])]);
                t += std::sin(phi) * Vector3f(p[size_t(ring[size_t(k)])]);
            }
        } else if (c.BoundaryNeighbours(int(v), &b0, &b1)) {
            m.p[v] =
                Point3f(0.6f * pv + 0.2f * (Vector3f(p[size_t(b0)]) + Vector3f(p[size_t(b1)])));
            // Along the boundary, from the chain's ends; across it, Hoppe et al.'s masks
            Vector3f first(p[size_t(ring.front())]), last(p[size_t(ring.back())]);
            s = last - first;
            if (n == 2) {
                t = first + last - 2.f * pv;
            } else if (n == 3) {
                t = Vector3f(p[size_t(ring[1])]) - pv;
            } else if (n == 4) {
                t = -first + 2.f * Vector3f(p[size_t(ring[1])]) +
                    2.f * Vector3f(p[size_t(ring[2])]) - last - 2.f * pv;
            } else {
                Float theta = Pi / (n - 1);
                t = std::sin(theta) * (first + last);
                for (int k = 1; k < n - 1; ++k)
                    t += (2 * std::cos(theta) - 2) * std::sin(k * theta) *
                         Vector3f(p[size_t(ring[size_t(k)])]);
            }
        } else {
            m.p[v] = p[v];  // a corner: no limit tangents; the faces' normal below
        }
        Vector3f normal = Cross(s, t);
        Vector3f faces = c.faceNormalSum[v];
        if (LengthSquared(normal) == 0 || !std::isfinite(LengthSquared(normal))) normal = faces;
        if (Dot(normal, faces) < 0) normal = -normal;
        Float len = Length(normal);
        if (len > 0 && std::isfinite(len)) m.n[v] = Normal3f(normal / len);
    }
    m.indices = std::move(idx);
    return m;
}

}  // namespace kiln
