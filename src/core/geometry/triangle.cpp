#include "core/geometry/triangle.h"

#include "base/sampling.h"
#include "core/geometry/shape_util.h"
#include "core/geometry/spherical_sampling.h"

namespace kiln {

// TriangleMesh
TriangleMesh::TriangleMesh(const Transform& renderFromObject, bool reverseOrientation,
                           std::vector<int> indices, std::vector<Point3f> P,
                           std::vector<Normal3f> N, std::vector<Vector3f> S,
                           std::vector<Point2f> UV, std::vector<int> faces,
                           std::map<std::string, std::vector<Float>> attrs)
    : nVertices(int(P.size())),
      reverseOrientation(reverseOrientation),
      transformSwapsHandedness(renderFromObject.SwapsHandedness()),
      n(std::move(N)),
      s(std::move(S)),
      uv(std::move(UV)),
      attributes(std::move(attrs)) {
    p.reserve(P.size() + 1);
    for (Point3f q : P) p.push_back(renderFromObject(q));
    if (renderFromObject.IsSingular()) {
        // A flattened mesh: normals have no transform (it needs the inverse); the geometric
        // normals of the flattened triangles shade it
        n.clear();
        s.clear();
    }
    for (Normal3f& nn : n) {
        nn = renderFromObject(nn);
        if (reverseOrientation) nn = -nn;
    }
    for (Vector3f& ss : s) ss = renderFromObject(ss);
    // Drop zero-area triangles.
    int nIn = int(indices.size() / 3);
    vertexIndices.reserve(indices.size());
    for (int t = 0; t < nIn; ++t) {
        const int* v = &indices[3 * t];
        Vector3f c = Cross(p[v[1]] - p[v[0]], p[v[2]] - p[v[0]]);
        if (c == Vector3f(0, 0, 0) || c.HasNaN()) {
            ++nDegenerate;
            continue;
        }
        vertexIndices.insert(vertexIndices.end(), v, v + 3);
        if (!faces.empty()) faceIndices.push_back(faces[t]);
    }
    nTriangles = int(vertexIndices.size() / 3);
}

std::optional<Float> TriangleMesh::InterpolateAttribute(const std::string& name, int triIndex,
                                                        const std::array<Float, 3>& b) const {
    auto it = attributes.find(name);
    if (it == attributes.end()) return std::nullopt;
    auto v = VertexIndices(triIndex);
    const std::vector<Float>& a = it->second;
    return b[0] * a[v[0]] + b[1] * a[v[1]] + b[2] * a[v[2]];
}

// Triangle basics
std::vector<Triangle> Triangle::FromMesh(const TriangleMesh* mesh) {
    std::vector<Triangle> tris;
    tris.reserve(mesh->nTriangles);
    for (int i = 0; i < mesh->nTriangles; ++i) tris.emplace_back(mesh, i);
    return tris;
}

Bounds3f Triangle::Bounds() const {
    auto v = Vertices();
    return Union(Bounds3f(v[0], v[1]), v[2]);
}

Float Triangle::Area() const {
    auto v = Vertices();
    return 0.5f * Length(Cross(v[1] - v[0], v[2] - v[0]));
}

std::array<Float, 3> Triangle::Barycentrics(Point3f q) const {
    auto v = Vertices();
    // Solve in double: q - v0 = b1 e1 + b2 e2 (least squares in the plane).
    double e1[3] = {double(v[1].x) - v[0].x, double(v[1].y) - v[0].y, double(v[1].z) - v[0].z};
    double e2[3] = {double(v[2].x) - v[0].x, double(v[2].y) - v[0].y, double(v[2].z) - v[0].z};
    double d[3] = {double(q.x) - v[0].x, double(q.y) - v[0].y, double(q.z) - v[0].z};
    auto dot = [](const double* a, const double* b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    };
    double d00 = dot(e1, e1), d01 = dot(e1, e2), d11 = dot(e2, e2);
    double d20 = dot(d, e1), d21 = dot(d, e2);
    double denom = d00 * d11 - d01 * d01;
    if (denom == 0) return {1.f / 3, 1.f / 3, 1.f / 3};
    double b1 = (d11 * d20 - d01 * d21) / denom, b2 = (d00 * d21 - d01 * d20) / denom;
    return {Float(1 - b1 - b2), Float(b1), Float(b2)};
}

// Watertight ray-triangle intersection; returns barycentrics and t.
static std::optional<std::pair<std::array<Float, 3>, Float>> IntersectTriangle(
    const Ray& ray, Float tMax, Point3f p0, Point3f p1, Point3f p2) {
    if (LengthSquared(Cross(p2 - p0, p1 - p0)) == 0) return std::nullopt;
    // Translate to the ray origin, permute so that z is the largest direction component, shear
    // so the ray points along +z.
    Point3f p0t = p0 - Vector3f(ray.o), p1t = p1 - Vector3f(ray.o), p2t = p2 - Vector3f(ray.o);
    int kz = MaxComponentIndex(Abs(ray.d));
    int kx = kz + 1 == 3 ? 0 : kz + 1;
    int ky = kx + 1 == 3 ? 0 : kx + 1;
    Vector3f d = Permute(ray.d, kx, ky, kz);
    p0t = Permute(p0t, kx, ky, kz), p1t = Permute(p1t, kx, ky, kz), p2t = Permute(p2t, kx, ky, kz);
    Float Sx = -d.x / d.z, Sy = -d.y / d.z, Sz = 1 / d.z;
    p0t.x += Sx * p0t.z, p0t.y += Sy * p0t.z;
    p1t.x += Sx * p1t.z, p1t.y += Sy * p1t.z;
    p2t.x += Sx * p2t.z, p2t.y += Sy * p2t.z;
    // Edge functions, in double when any is zero (on an edge).
    Float e0 = p1t.x * p2t.y - p1t.y * p2t.x;
    Float e1 = p2t.x * p0t.y - p2t.y * p0t.x;
    Float e2 = p0t.x * p1t.y - p0t.y * p1t.x;
    if (e0 == 0 || e1 == 0 || e2 == 0) {
        e0 = Float(double(p1t.x) * p2t.y - double(p1t.y) * p2t.x);
        e1 = Float(double(p2t.x) * p0t.y - double(p2t.y) * p0t.x);
        e2 = Float(double(p0t.x) * p1t.y - double(p0t.y) * p1t.x);
    }
    if ((e0 < 0 || e1 < 0 || e2 < 0) && (e0 > 0 || e1 > 0 || e2 > 0)) return std::nullopt;
    Float det = e0 + e1 + e2;
    if (det == 0) return std::nullopt;
    p0t.z *= Sz, p1t.z *= Sz, p2t.z *= Sz;
    Float tScaled = e0 * p0t.z + e1 * p1t.z + e2 * p2t.z;
    if (det < 0 && (tScaled >= 0 || tScaled < tMax * det)) return std::nullopt;
    if (det > 0 && (tScaled <= 0 || tScaled > tMax * det)) return std::nullopt;
    Float invDet = 1 / det;
    Float b0 = e0 * invDet, b1 = e1 * invDet, b2 = e2 * invDet, t = tScaled * invDet;
    if (!(t > 0) || !(t < tMax)) return std::nullopt;
    return std::make_pair(std::array<Float, 3>{b0, b1, b2}, t);
}

std::optional<ShapeIntersection> Triangle::Intersect(const Ray& ray, Float tMax) const {
    auto v = Vertices();
    auto hit = IntersectTriangle(ray, tMax, v[0], v[1], v[2]);
    if (!hit) return std::nullopt;
    return ShapeIntersection{InteractionFromBarycentrics(hit->first, ray.time, -ray.d),
                             hit->second};
}

bool Triangle::IntersectP(const Ray& ray, Float tMax) const {
    auto v = Vertices();
    return IntersectTriangle(ray, tMax, v[0], v[1], v[2]).has_value();
}

// Triangle differential geometry
SurfaceInteraction Triangle::InteractionFromBarycentrics(const std::array<Float, 3>& b, Float time,
                                                         Vector3f wo) const {
    auto vi = mesh->VertexIndices(triIndex);
    Point3f p0 = mesh->p[vi[0]], p1 = mesh->p[vi[1]], p2 = mesh->p[vi[2]];
    std::array<Point2f, 3> uv =
        mesh->uv.empty()
            ? std::array<Point2f, 3>{Point2f(0, 0), Point2f(1, 0), Point2f(1, 1)}
            : std::array<Point2f, 3>{mesh->uv[vi[0]], mesh->uv[vi[1]], mesh->uv[vi[2]]};
    // Partial derivatives from the uv parameterisation.
    Vector2f duv02 = uv[0] - uv[2], duv12 = uv[1] - uv[2];
    Vector3f dp02 = p0 - p2, dp12 = p1 - p2;
    double determinant = double(duv02.x) * duv12.y - double(duv02.y) * duv12.x;
    bool degenerateUV = std::abs(determinant) < 1e-9;
    Vector3f dpdu, dpdv;
    if (!degenerateUV) {
        Float invdet = Float(1 / determinant);
        dpdu = (duv12.y * dp02 - duv02.y * dp12) * invdet;
        dpdv = (duv02.x * dp12 - duv12.x * dp02) * invdet;
    }
    Vector3f ng = SafeNormalize(Cross(p2 - p0, p1 - p0));
    if (ng == Vector3f(0, 0, 0)) ng = Vector3f(0, 0, 1);
    if (degenerateUV || LengthSquared(Cross(dpdu, dpdv)) == 0 || Cross(dpdu, dpdv).HasNaN())
        CoordinateSystem(ng, &dpdu, &dpdv);

    // Hit point and uv from barycentrics (never o + t d).
    Point3f pHit(b[0] * Vector3f(p0) + b[1] * Vector3f(p1) + b[2] * Vector3f(p2));
    Point2f uvHit(b[0] * uv[0].x + b[1] * uv[1].x + b[2] * uv[2].x,
                  b[0] * uv[0].y + b[1] * uv[1].y + b[2] * uv[2].y);
    bool flip = mesh->reverseOrientation ^ mesh->transformSwapsHandedness;
    SurfaceInteraction isect(pHit, uvHit, SafeNormalize(wo), dpdu, dpdv, Normal3f(0, 0, 0),
                             Normal3f(0, 0, 0), time, flip);
    // Geometric normal from the vertex winding (pbrt-v4), robust for slivers.
    Normal3f nGeom(SafeNormalize(Cross(dp02, dp12)));
    if (nGeom == Normal3f(0, 0, 0)) nGeom = Normal3f(-ng);
    isect.n = isect.shading.n = flip ? -nGeom : nGeom;
    isect.faceIndex = mesh->faceIndices.empty() ? 0 : mesh->faceIndices[triIndex];
    // For per-vertex attribute textures (TextureEvalContext::mesh).
    isect.mesh = mesh;
    isect.triIndex = triIndex;
    isect.b = b;

    if (!mesh->n.empty() || !mesh->s.empty()) {
        // Shading normal, tangent and normal derivatives from the per-vertex data.
        Normal3f ns = isect.n;
        if (!mesh->n.empty()) {
            Normal3f ni = b[0] * mesh->n[vi[0]] + b[1] * mesh->n[vi[1]] + b[2] * mesh->n[vi[2]];
            Normal3f nn = SafeNormalize(ni);
            if (nn != Normal3f(0, 0, 0)) ns = nn;
        }
        Vector3f ss = isect.dpdu;
        if (!mesh->s.empty()) {
            Vector3f si = b[0] * mesh->s[vi[0]] + b[1] * mesh->s[vi[1]] + b[2] * mesh->s[vi[2]];
            if (LengthSquared(si) > 0) ss = si;
        }
        Vector3f ts = Cross(ns, ss);
        if (LengthSquared(ts) > 0)
            ss = Cross(ts, ns);
        else
            CoordinateSystem(Vector3f(ns), &ss, &ts);
        Normal3f dndu, dndv;
        if (!mesh->n.empty()) {
            Normal3f dn1 = mesh->n[vi[0]] - mesh->n[vi[2]];
            Normal3f dn2 = mesh->n[vi[1]] - mesh->n[vi[2]];
            if (degenerateUV) {
                Vector3f dn = Cross(Vector3f(mesh->n[vi[2]] - mesh->n[vi[0]]),
                                    Vector3f(mesh->n[vi[1]] - mesh->n[vi[0]]));
                if (LengthSquared(dn) != 0) {
                    Vector3f dnu, dnv;
                    CoordinateSystem(SafeNormalize(dn), &dnu, &dnv);
                    dndu = Normal3f(dnu), dndv = Normal3f(dnv);
                }
            } else {
                Float invDet = Float(1 / determinant);
                dndu = (duv12.y * dn1 - duv02.y * dn2) * invDet;
                dndv = (duv02.x * dn2 - duv12.x * dn1) * invDet;
            }
        }
        isect.SetShadingGeometry(ns, ss, ts, dndu, dndv, true);
    }
    return isect;
}

SurfaceInteraction Triangle::BoundaryInteraction(const std::array<Float, 3>& b, Float time,
                                                 Vector3f wo) const {
    auto vi = mesh->VertexIndices(triIndex);
    Point3f p0 = mesh->p[vi[0]], p1 = mesh->p[vi[1]], p2 = mesh->p[vi[2]];
    SurfaceInteraction isect;
    isect.p = Point3f(b[0] * Vector3f(p0) + b[1] * Vector3f(p1) + b[2] * Vector3f(p2));
    isect.wo = SafeNormalize(wo);
    isect.time = time;
    // The geometric normal as InteractionFromBarycentrics computes and orients it
    Normal3f nGeom(SafeNormalize(Cross(p0 - p2, p1 - p2)));
    if (nGeom == Normal3f(0, 0, 0)) {
        Vector3f ng = SafeNormalize(Cross(p2 - p0, p1 - p0));
        nGeom = ng == Vector3f(0, 0, 0) ? Normal3f(0, 0, -1) : Normal3f(-ng);
    }
    bool flip = mesh->reverseOrientation ^ mesh->transformSwapsHandedness;
    isect.n = isect.shading.n = flip ? -nGeom : nGeom;
    if (!mesh->n.empty()) {
        Normal3f ns =
            SafeNormalize(b[0] * mesh->n[vi[0]] + b[1] * mesh->n[vi[1]] + b[2] * mesh->n[vi[2]]);
        if (ns != Normal3f(0, 0, 0)) {
            isect.shading.n = ns;
            isect.n = FaceForward(isect.n, Vector3f(ns));
        }
    }
    isect.faceIndex = mesh->faceIndices.empty() ? 0 : mesh->faceIndices[triIndex];
    isect.mesh = mesh;
    isect.triIndex = triIndex;
    isect.b = b;
    return isect;
}

// Triangle sampling
// The surface point at barycentrics b: position, geometric normal (facing the interpolated
// shading normal when the mesh has normals, else flipped by orientation) and uv.
Interaction Triangle::PointAt(const std::array<Float, 3>& b, Float time) const {
    auto v = Vertices();
    auto vi = mesh->VertexIndices(triIndex);
    Point3f p(b[0] * Vector3f(v[0]) + b[1] * Vector3f(v[1]) + b[2] * Vector3f(v[2]));
    Normal3f n(SafeNormalize(Cross(v[1] - v[0], v[2] - v[0])));
    if (!mesh->n.empty()) {
        Normal3f ns = b[0] * mesh->n[vi[0]] + b[1] * mesh->n[vi[1]] + b[2] * mesh->n[vi[2]];
        n = FaceForward(n, Vector3f(ns));
    } else if (mesh->reverseOrientation ^ mesh->transformSwapsHandedness) {
        n = -n;
    }
    Point2f uvs =
        mesh->uv.empty()
            ? Point2f(b[1] + b[2], b[2])
            : Point2f(
                  b[0] * mesh->uv[vi[0]].x + b[1] * mesh->uv[vi[1]].x + b[2] * mesh->uv[vi[2]].x,
                  b[0] * mesh->uv[vi[0]].y + b[1] * mesh->uv[vi[1]].y + b[2] * mesh->uv[vi[2]].y);
    return Interaction(p, n, uvs, {}, time);
}

std::optional<ShapeSample> Triangle::Sample(Point2f u) const {
    return ShapeSample{PointAt(SampleUniformTriangle(u), 0), 1 / Area()};
}

SurfaceInteraction Triangle::InteractionAt(Point3f p, Float time, Vector3f wo) const {
    std::array<Float, 3> b = Barycentrics(p);
    // Onto the triangle (points from sampling lie on it up to rounding)
    for (Float& bi : b) bi = std::max<Float>(bi, 0);
    Float sum = b[0] + b[1] + b[2];
    if (sum > 0)
        for (Float& bi : b) bi /= sum;
    return InteractionFromBarycentrics(b, time, wo);
}

std::optional<ShapeSample> Triangle::SampleParametric(Point2f u) const {
    Float su0 = std::sqrt(u[0]);
    std::array<Float, 3> b = {1 - su0, u[1] * su0, 0};
    b[2] = std::max<Float>(0, 1 - b[0] - b[1]);
    return ShapeSample{PointAt(b, 0), 1 / Area()};
}

Point2f Triangle::InvertParametric(Point3f p) const {
    std::array<Float, 3> b = Barycentrics(p);
    Float s = Clamp(1 - b[0], 0, 1);
    return Point2f(Sqr(s), s > 0 ? Clamp(b[1] / s, 0, 1) : 0);
}

Float Triangle::SolidAngle(Point3f p) const { return SphericalTriangleArea(Vertices(), p); }

// Cosine-warp weights at the corners of [0,1]^2 for spherical triangle samples (pbrt-v4).
static std::array<Float, 4> CosineWarpWeights(const std::array<Point3f, 3>& v,
                                              const ShapeSampleContext& ctx) {
    Vector3f wi[3] = {Normalize(v[0] - ctx.p), Normalize(v[1] - ctx.p), Normalize(v[2] - ctx.p)};
    return {std::max<Float>(0.01f, AbsDot(ctx.ns, wi[1])),
            std::max<Float>(0.01f, AbsDot(ctx.ns, wi[1])),
            std::max<Float>(0.01f, AbsDot(ctx.ns, wi[0])),
            std::max<Float>(0.01f, AbsDot(ctx.ns, wi[2]))};
}

std::optional<ShapeSample> Triangle::Sample(const ShapeSampleContext& ctx, Point2f u) const {
    Float solidAngle = SolidAngle(ctx.p);
    if (solidAngle < MinSphericalSampleArea || solidAngle > MaxSphericalSampleArea) {
        auto ss = Sample(u);
        if (!ss) return std::nullopt;
        ss->intr.time = ctx.time;
        return AreaSampleToSolidAngle(ctx, *ss);
    }
    auto v = Vertices();
    Float pdf = 1;
    if (ctx.ns != Normal3f(0, 0, 0)) {
        auto w = CosineWarpWeights(v, ctx);
        u = SampleBilinear(u, w);
        pdf = BilinearPDF(u, w);
    }
    Float triPDF;
    std::array<Float, 3> b = SampleSphericalTriangle(v, ctx.p, u, &triPDF);
    if (triPDF == 0) return std::nullopt;
    pdf *= triPDF;
    return ShapeSample{PointAt(b, ctx.time), pdf};
}

Float Triangle::PDF(const ShapeSampleContext& ctx, Vector3f wi) const {
    Float solidAngle = SolidAngle(ctx.p);
    auto isect = Intersect(ctx.SpawnRay(wi));
    if (!isect) return 0;
    if (solidAngle < MinSphericalSampleArea || solidAngle > MaxSphericalSampleArea) {
        Float pdf =
            (1 / Area()) / (AbsDot(isect->intr.n, -wi) / DistanceSquared(ctx.p, isect->intr.p));
        return std::isinf(pdf) ? 0 : pdf;
    }
    Float pdf = 1 / solidAngle;
    if (ctx.ns != Normal3f(0, 0, 0)) {
        auto v = Vertices();
        Point2f u = InvertSphericalTriangleSample(v, ctx.p, Normalize(wi));
        pdf *= BilinearPDF(u, CosineWarpWeights(v, ctx));
    }
    return pdf;
}

}  // namespace kiln
