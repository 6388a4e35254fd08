#include "core/geometry/bilinear_patch.h"

#include "base/sampling.h"
#include "core/geometry/shape_util.h"

namespace kiln {

// BilinearPatchMesh
BilinearPatchMesh::BilinearPatchMesh(const Transform& renderFromObject, bool reverseOrientation,
                                     std::vector<int> indices, std::vector<Point3f> P,
                                     std::vector<Normal3f> N, std::vector<Point2f> UV,
                                     std::vector<int> faces)
    : nPatches(int(indices.size() / 4)),
      nVertices(int(P.size())),
      reverseOrientation(reverseOrientation),
      transformSwapsHandedness(renderFromObject.SwapsHandedness()),
      vertexIndices(std::move(indices)),
      n(std::move(N)),
      uv(std::move(UV)),
      faceIndices(std::move(faces)) {
    p.reserve(P.size());
    for (Point3f q : P) p.push_back(renderFromObject(q));
    if (renderFromObject.IsSingular()) n.clear();  // normals need the inverse; none exists
    for (Normal3f& nn : n) {
        nn = renderFromObject(nn);
        if (reverseOrientation) nn = -nn;
    }
}

// BilinearPatch basics
BilinearPatch::BilinearPatch(const BilinearPatchMesh* mesh, int blpIndex)
    : mesh(mesh), blpIndex(blpIndex) {
    auto [p00, p10, p01, p11] = Corners();
    if (IsRectangle()) {
        area = Distance(p00, p01) * Distance(p00, p10);
    } else {
        // Sum of the areas of a 3x3 grid of quads (pbrt-v4's approximation).
        constexpr int na = 3;
        Point3f pa[na + 1][na + 1];
        for (int i = 0; i <= na; ++i)
            for (int j = 0; j <= na; ++j) {
                Float u = Float(i) / na, v = Float(j) / na;
                pa[i][j] = Lerp(v, Lerp(u, p00, p10), Lerp(u, p01, p11));
            }
        for (int i = 0; i < na; ++i)
            for (int j = 0; j < na; ++j)
                area +=
                    0.5f * Length(Cross(pa[i + 1][j + 1] - pa[i][j], pa[i + 1][j] - pa[i][j + 1]));
    }
}

std::vector<BilinearPatch> BilinearPatch::FromMesh(const BilinearPatchMesh* mesh) {
    std::vector<BilinearPatch> r;
    r.reserve(mesh->nPatches);
    for (int i = 0; i < mesh->nPatches; ++i) r.emplace_back(mesh, i);
    return r;
}

std::array<Point3f, 4> BilinearPatch::Corners() const {
    const int* v = &mesh->vertexIndices[4 * blpIndex];
    return {mesh->p[v[0]], mesh->p[v[1]], mesh->p[v[2]], mesh->p[v[3]]};
}

Bounds3f BilinearPatch::Bounds() const {
    auto [p00, p10, p01, p11] = Corners();
    return Union(Bounds3f(p00, p01), Bounds3f(p10, p11));
}

bool BilinearPatch::IsRectangle() const {
    auto [p00, p10, p01, p11] = Corners();
    if (p00 == p01 || p01 == p11 || p11 == p10 || p10 == p00) return false;
    Normal3f n(SafeNormalize(Cross(p10 - p00, p01 - p00)));
    if (AbsDot(SafeNormalize(p11 - p00), n) > 1e-5f) return false;
    Point3f pCenter(0.25f * (Vector3f(p00) + Vector3f(p01) + Vector3f(p10) + Vector3f(p11)));
    Float d2[4] = {DistanceSquared(p00, pCenter), DistanceSquared(p01, pCenter),
                   DistanceSquared(p10, pCenter), DistanceSquared(p11, pCenter)};
    for (int i = 1; i < 4; ++i)
        if (std::abs(d2[i] - d2[0]) / d2[0] > 1e-4f) return false;
    return true;
}

// Bilinear patch intersection
static std::optional<std::pair<Point2f, Float>> IntersectPatch(const Ray& ray, Float tMax,
                                                               Point3f p00, Point3f p10,
                                                               Point3f p01, Point3f p11) {
    // Quadratic in u (Reshetov 2019).
    Float a = Dot(Cross(p10 - p00, p01 - p11), ray.d);
    Float c = Dot(Cross(p00 - ray.o, ray.d), p01 - p00);
    Float b = Dot(Cross(p10 - ray.o, ray.d), p11 - p10) - (a + c);
    Float det = Sqr(b) - 4 * a * c;
    if (det < 0) return std::nullopt;
    Float sqrtDet = std::sqrt(det);
    Float u1, u2;
    if (a == 0) {
        if (b == 0) return std::nullopt;
        u1 = -c / b;
        u2 = -1;
    } else {
        u1 = (-b - std::copysign(sqrtDet, b)) / 2;
        u2 = c / u1;
        u1 /= a;
    }
    Float t = tMax, u = 0, v = 0;
    auto candidate = [&](Float uc) {
        if (!(0 <= uc && uc <= 1)) return;
        // Line of constant u; closest approach to the ray gives v and t.
        Point3f uo = Lerp(uc, p00, p10);
        Vector3f ud = Lerp(uc, p01, p11) - uo;
        Vector3f deltao = uo - ray.o;
        Vector3f perp = Cross(ray.d, ud);
        Float p2 = LengthSquared(perp);
        if (p2 == 0) return;
        Float vc = Dot(Cross(deltao, ray.d), perp);
        Float tc = Dot(Cross(deltao, ud), perp);
        if (tc > 0 && tc < t * p2 && 0 <= vc && vc <= p2) {
            t = tc / p2;
            u = uc;
            v = vc / p2;
        }
    };
    candidate(u1);
    if (u2 != u1) candidate(u2);
    if (!(t < tMax)) return std::nullopt;
    return std::make_pair(Point2f(u, v), t);
}

std::optional<ShapeIntersection> BilinearPatch::Intersect(const Ray& ray, Float tMax) const {
    auto [p00, p10, p01, p11] = Corners();
    auto hit = IntersectPatch(ray, tMax, p00, p10, p01, p11);
    if (!hit) return std::nullopt;
    return ShapeIntersection{InteractionFromParameters(hit->first, ray.time, -ray.d), hit->second};
}

bool BilinearPatch::IntersectP(const Ray& ray, Float tMax) const {
    auto [p00, p10, p01, p11] = Corners();
    return IntersectPatch(ray, tMax, p00, p10, p01, p11).has_value();
}

// Bilinear patch differential geometry
SurfaceInteraction BilinearPatch::InteractionFromParameters(Point2f uv, Float time,
                                                            Vector3f wo) const {
    auto [p00, p10, p01, p11] = Corners();
    const int* vi = &mesh->vertexIndices[4 * blpIndex];
    Float u = uv.x, v = uv.y;
    Point3f p = Lerp(v, Lerp(u, p00, p10), Lerp(u, p01, p11));
    Vector3f dpdu = Lerp(v, p10, p11) - Lerp(v, p00, p01);
    Vector3f dpdv = Lerp(u, p01, p11) - Lerp(u, p00, p10);
    Point2f st = uv;
    Float duds = 1, dvdt = 1;
    if (!mesh->uv.empty()) {
        // Texture coordinates interpolate bilinearly too; rescale the derivatives.
        Point2f uv00 = mesh->uv[vi[0]], uv10 = mesh->uv[vi[1]], uv01 = mesh->uv[vi[2]],
                uv11 = mesh->uv[vi[3]];
        auto bilerp = [&](int c) {
            return (1 - u) * (1 - v) * uv00[c] + u * (1 - v) * uv10[c] + (1 - u) * v * uv01[c] +
                   u * v * uv11[c];
        };
        st = Point2f(bilerp(0), bilerp(1));
        Float dsdu = -uv00[0] + uv10[0] + v * (uv00[0] - uv01[0] - uv10[0] + uv11[0]);
        Float dtdv = -uv00[1] + uv01[1] + u * (uv00[1] - uv01[1] - uv10[1] + uv11[1]);
        duds = std::abs(dsdu) < 1e-8f ? 0 : 1 / dsdu;
        dvdt = std::abs(dtdv) < 1e-8f ? 0 : 1 / dtdv;
        Vector3f dpds = dpdu * duds, dpdt = dpdv * dvdt;
        Vector3f cst = Cross(dpds, dpdt);
        if (LengthSquared(cst) > 0) {
            if (Dot(Cross(dpdu, dpdv), cst) < 0) dpdt = -dpdt;
            dpdu = dpds, dpdv = dpdt;
        }
    }
    Vector3f d2Pduv = (p00 - p01) + (p11 - p10);
    Normal3f dndu, dndv;
    WeingartenNormalDerivatives(dpdu, dpdv, Vector3f(0, 0, 0), d2Pduv * (duds * dvdt),
                                Vector3f(0, 0, 0), &dndu, &dndv);
    if (LengthSquared(Cross(dpdu, dpdv)) == 0) {
        Vector3f ng = SafeNormalize(Cross(p10 - p00, p01 - p00));
        if (ng == Vector3f(0, 0, 0)) ng = Vector3f(0, 0, 1);
        CoordinateSystem(ng, &dpdu, &dpdv);
    }
    bool flip = mesh->reverseOrientation ^ mesh->transformSwapsHandedness;
    SurfaceInteraction isect(p, st, SafeNormalize(wo), dpdu, dpdv, dndu, dndv, time, flip);
    isect.n = isect.shading.n = SafeNormalize(isect.n);
    isect.faceIndex = mesh->faceIndices.empty() ? 0 : mesh->faceIndices[blpIndex];
    if (!mesh->n.empty()) {
        Normal3f n00 = mesh->n[vi[0]], n10 = mesh->n[vi[1]], n01 = mesh->n[vi[2]],
                 n11 = mesh->n[vi[3]];
        Normal3f ns = (1 - u) * (1 - v) * n00 + u * (1 - v) * n10 + (1 - u) * v * n01 + u * v * n11;
        ns = SafeNormalize(ns);
        if (ns != Normal3f(0, 0, 0)) {
            Normal3f dnsdu = (1 - v) * (n10 - n00) + v * (n11 - n01);
            Normal3f dnsdv = (1 - u) * (n01 - n00) + u * (n11 - n10);
            Vector3f ss = GramSchmidt(isect.dpdu, Vector3f(ns));
            if (LengthSquared(ss) == 0) {
                Vector3f t2;
                CoordinateSystem(Vector3f(ns), &ss, &t2);
            }
            ss = Normalize(ss) * Length(isect.dpdu);
            Vector3f ts = Normalize(Cross(ns, ss)) * Length(isect.dpdv);
            if (Dot(ts, isect.dpdv) < 0) ts = -ts;
            isect.SetShadingGeometry(ns, ss, ts, dnsdu * duds, dnsdv * dvdt, true);
        }
    }
    return isect;
}

// Bilinear patch sampling
std::array<Float, 4> BilinearPatch::SamplingWeights() const {
    auto [p00, p10, p01, p11] = Corners();
    return {Length(Cross(p10 - p00, p01 - p00)), Length(Cross(p10 - p00, p11 - p10)),
            Length(Cross(p11 - p01, p01 - p00)), Length(Cross(p11 - p01, p11 - p10))};
}

std::optional<ShapeSample> BilinearPatch::Sample(Point2f u) const {
    auto w = SamplingWeights();
    Point2f uv = SampleBilinear(u, w);
    Float pdf = BilinearPDF(uv, w);
    auto [p00, p10, p01, p11] = Corners();
    const int* vi = &mesh->vertexIndices[4 * blpIndex];
    Point3f p = Lerp(uv.y, Lerp(uv.x, p00, p10), Lerp(uv.x, p01, p11));
    Vector3f dpdu = Lerp(uv.y, p10, p11) - Lerp(uv.y, p00, p01);
    Vector3f dpdv = Lerp(uv.x, p01, p11) - Lerp(uv.x, p00, p10);
    Float jac = Length(Cross(dpdu, dpdv));
    if (jac == 0) return std::nullopt;
    Normal3f n(SafeNormalize(Cross(dpdu, dpdv)));
    if (!mesh->n.empty()) {
        Float a = uv.x, b = uv.y;
        Normal3f ns = (1 - a) * (1 - b) * mesh->n[vi[0]] + a * (1 - b) * mesh->n[vi[1]] +
                      (1 - a) * b * mesh->n[vi[2]] + a * b * mesh->n[vi[3]];
        n = FaceForward(n, Vector3f(ns));
    } else if (mesh->reverseOrientation ^ mesh->transformSwapsHandedness) {
        n = -n;
    }
    Point2f st = uv;
    if (!mesh->uv.empty()) {
        Float a = uv.x, b = uv.y;
        auto bl = [&](int c) {
            return (1 - a) * (1 - b) * mesh->uv[vi[0]][c] + a * (1 - b) * mesh->uv[vi[1]][c] +
                   (1 - a) * b * mesh->uv[vi[2]][c] + a * b * mesh->uv[vi[3]][c];
        };
        st = Point2f(bl(0), bl(1));
    }
    return ShapeSample{Interaction(p, n, st), pdf / jac};
}

Point2f BilinearPatch::Parameters(Point3f pt) const {
    auto [p00, p10, p01, p11] = Corners();
    Point2f uv(0.5f, 0.5f);
    for (int it = 0; it < 12; ++it) {
        Point3f p = Lerp(uv.y, Lerp(uv.x, p00, p10), Lerp(uv.x, p01, p11));
        Vector3f dpdu = Lerp(uv.y, p10, p11) - Lerp(uv.y, p00, p01);
        Vector3f dpdv = Lerp(uv.x, p01, p11) - Lerp(uv.x, p00, p10);
        Vector3f r = pt - p;
        // Least-squares step: [dpdu dpdv] duv = r.
        Float a = Dot(dpdu, dpdu), b = Dot(dpdu, dpdv), c = Dot(dpdv, dpdv);
        Float ru = Dot(dpdu, r), rv = Dot(dpdv, r);
        Float det = a * c - b * b;
        if (det == 0) break;
        uv = Point2f(Clamp(uv.x + (c * ru - b * rv) / det, 0, 1),
                     Clamp(uv.y + (a * rv - b * ru) / det, 0, 1));
    }
    return uv;
}

Float BilinearPatch::PDF(const Interaction& intr) const {
    auto [p00, p10, p01, p11] = Corners();
    Point2f uv = Parameters(intr.p);
    Vector3f dpdu = Lerp(uv.y, p10, p11) - Lerp(uv.y, p00, p01);
    Vector3f dpdv = Lerp(uv.x, p01, p11) - Lerp(uv.x, p00, p10);
    Float jac = Length(Cross(dpdu, dpdv));
    return jac == 0 ? 0 : BilinearPDF(uv, SamplingWeights()) / jac;
}

SurfaceInteraction BilinearPatch::InteractionAt(Point3f p, Float time, Vector3f wo) const {
    return InteractionFromParameters(Parameters(p), time, wo);
}

std::optional<ShapeSample> BilinearPatch::SampleParametric(Point2f uv) const {
    SurfaceInteraction si = InteractionFromParameters(uv, 0, Vector3f(0, 0, 1));
    auto [p00, p10, p01, p11] = Corners();
    Vector3f dpdu = Lerp(uv.y, p10, p11) - Lerp(uv.y, p00, p01);
    Vector3f dpdv = Lerp(uv.x, p01, p11) - Lerp(uv.x, p00, p10);
    Float jac = Length(Cross(dpdu, dpdv));
    if (jac == 0) return std::nullopt;
    return ShapeSample{Interaction(si.p, si.n, si.uv), 1 / jac};
}

std::optional<ShapeSample> BilinearPatch::Sample(const ShapeSampleContext& ctx, Point2f u) const {
    auto ss = Sample(u);
    if (!ss) return std::nullopt;
    ss->intr.time = ctx.time;
    return AreaSampleToSolidAngle(ctx, *ss);
}

Float BilinearPatch::PDF(const ShapeSampleContext& ctx, Vector3f wi) const {
    auto isect = Intersect(ctx.SpawnRay(wi));
    if (!isect) return 0;
    Float pdf =
        PDF(isect->intr) / (AbsDot(isect->intr.n, -wi) / DistanceSquared(ctx.p, isect->intr.p));
    return std::isinf(pdf) ? 0 : pdf;
}

}  // namespace kiln
