#include "core/geometry/curve.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/parser/diagnostics.h"
#include "core/parser/parameter_dictionary.h"

namespace kiln {

// Basis conversions (pbrt-v4's)
std::array<Point3f, 4> ElevateQuadraticBezier(const std::array<Point3f, 3>& cp) {
    return {cp[0], Lerp(2.f / 3.f, cp[0], cp[1]), Lerp(1.f / 3.f, cp[1], cp[2]), cp[2]};
}

std::array<Point3f, 4> CubicBSplineToBezier(const std::array<Point3f, 4>& cp) {
    // The b-spline's knot-interval points a third and two thirds of the way along each leg,
    // then the segment's end points halfway between them
    Point3f p012 = cp[0], p123 = cp[1], p234 = cp[2], p345 = cp[3];
    Point3f p122 = Lerp(2.f / 3.f, p012, p123);
    Point3f p223 = Lerp(1.f / 3.f, p123, p234);
    Point3f p233 = Lerp(2.f / 3.f, p123, p234);
    Point3f p334 = Lerp(1.f / 3.f, p234, p345);
    Point3f p222 = Lerp(0.5f, p122, p223);
    Point3f p333 = Lerp(0.5f, p233, p334);
    return {p222, p223, p233, p333};
}

std::array<Point3f, 3> QuadraticBSplineToBezier(const std::array<Point3f, 3>& cp) {
    Point3f p11 = Lerp(0.5f, cp[0], cp[1]);
    Point3f p22 = Lerp(0.5f, cp[1], cp[2]);
    return {p11, cp[1], p22};
}

// Segments
void CurveSet::AddSegment(const std::array<Point3f, 4>& cp, Float width0, Float width1, Normal3f n0,
                          Normal3f n1) {
    for (int i = 0; i < 4; ++i) {
        // Radius linear in u: the Bezier basis reproduces linear control values exactly
        Float w = Lerp(Float(i) / 3, width0, width1);
        vertices.push_back({cp[i].x, cp[i].y, cp[i].z, 0.5f * w});
    }
    // pbrt-v4's refinement depth: the control polygon's largest second difference against 5 %
    // of the segment's widest width
    Float L0 = 0;
    for (int i = 0; i < 2; ++i) {
        Vector3f dd = (cp[i] - cp[i + 1]) - (cp[i + 1] - cp[i + 2]);
        L0 = std::max({L0, std::abs(dd.x), std::abs(dd.y), std::abs(dd.z)});
    }
    Float eps = std::max(width0, width1) * 0.05f;
    int depth = 0;
    if (eps > 0) {
        Float r0 = std::log2(1.41421356f * 6.f * L0 / (8.f * eps)) / 2;
        if (std::isfinite(r0)) depth = std::clamp(int(std::ceil(r0)), 0, kMaxRefinementDepth);
    }
    tessellationDepth = std::max(tessellationDepth, std::min(depth, kMaxTessellationDepth));
    // Beyond Embree's 16 pieces: 2^(depth - 4) primitives of 16 pieces each (ribbons need none)
    int segment = NumSegments() - 1;
    int split = type == CurveType::Ribbon ? 0 : std::max(0, depth - kMaxTessellationDepth);
    if (split > 0 && parts.empty()) {
        // Every earlier segment becomes one primitive
        for (int s = 0; s < segment; ++s) AddPart(s, 0, 1);
    }
    if (split > 0 || !parts.empty()) {
        int n = 1 << split;
        for (int k = 0; k < n; ++k) AddPart(segment, Float(k) / n, Float(k + 1) / n);
    }
    if (type == CurveType::Ribbon) {
        endNormals.push_back(n0);
        endNormals.push_back(n1);
    }
}

void CurveSet::AddPart(int segment, Float u0, Float u1) {
    // The cubic's part u0 ... u1 as a cubic Bezier: its control points are the blossom values
    // B(u0, u0, u0), B(u0, u0, u1), B(u0, u1, u1), B(u1, u1, u1)
    const auto* v = &vertices[4 * size_t(segment)];
    Point3f P[4];
    for (int i = 0; i < 4; ++i) P[i] = Point3f(v[i][0], v[i][1], v[i][2]);
    auto blossom = [&](Float t1, Float t2, Float t3) {
        Point3f a[3] = {Lerp(t1, P[0], P[1]), Lerp(t1, P[1], P[2]), Lerp(t1, P[2], P[3])};
        return Lerp(t3, Lerp(t2, a[0], a[1]), Lerp(t2, a[1], a[2]));
    };
    std::array<Point3f, 4> cp = {blossom(u0, u0, u0), blossom(u0, u0, u1), blossom(u0, u1, u1),
                                 blossom(u1, u1, u1)};
    Float r0 = Lerp(u0, v[0][3], v[3][3]), r1 = Lerp(u1, v[0][3], v[3][3]);
    for (int i = 0; i < 4; ++i)
        partVertices.push_back({cp[i].x, cp[i].y, cp[i].z, Lerp(Float(i) / 3, r0, r1)});
    parts.push_back({segment, float(u0), float(u1)});
}

Point3f CurveSet::Position(int segment, Float u) const {
    const auto* v = &vertices[4 * size_t(segment)];
    Float b[4] = {(1 - u) * (1 - u) * (1 - u), 3 * (1 - u) * (1 - u) * u, 3 * (1 - u) * u * u,
                  u * u * u};
    Point3f p(0, 0, 0);
    for (int i = 0; i < 4; ++i) p = p + b[i] * Vector3f(v[i][0], v[i][1], v[i][2]);
    return p;
}

Vector3f CurveSet::Tangent(int segment, Float u) const {
    const auto* v = &vertices[4 * size_t(segment)];
    auto P = [&](int i) { return Vector3f(v[i][0], v[i][1], v[i][2]); };
    Vector3f d = 3.f * ((1 - u) * (1 - u) * (P(1) - P(0)) + 2 * (1 - u) * u * (P(2) - P(1)) +
                        u * u * (P(3) - P(2)));
    // A segment whose end control points coincide with their neighbours has no derivative
    // at that end: take the chord instead
    if (LengthSquared(d) == 0) d = P(3) - P(0);
    return d;
}

Float CurveSet::Width(int segment, Float u) const {
    const auto* v = &vertices[4 * size_t(segment)];
    return 2 * Lerp(u, v[0][3], v[3][3]);
}

Normal3f CurveSet::RibbonNormal(int segment, Float u) const {
    Normal3f n0 = endNormals[2 * size_t(segment)], n1 = endNormals[2 * size_t(segment) + 1];
    Float angle = AngleBetween(Vector3f(n0), Vector3f(n1));
    if (angle < 1e-6f) return n0;
    Float s = std::sin(angle);
    if (s < 1e-6f) return n0;  // opposite normals: no unique arc
    return Normal3f(
        Normalize(Vector3f(std::sin((1 - u) * angle) / s * n0 + std::sin(u * angle) / s * n1)));
}

std::vector<Vector3f> CurveSet::EmbreeNormals() const {
    std::vector<Vector3f> normals;
    normals.reserve(2 * endNormals.size());
    for (size_t seg = 0; seg < endNormals.size() / 2; ++seg) {
        Vector3f n0(endNormals[2 * seg]), n1(endNormals[2 * seg + 1]);
        // The cubic Bezier through the slerp's values at u = 0, 1/3, 2/3 and 1
        Vector3f s1(RibbonNormal(int(seg), 1.f / 3)), s2(RibbonNormal(int(seg), 2.f / 3));
        Vector3f p1 = 3.f * s1 - 1.5f * s2 - (5.f / 6) * n0 + (1.f / 3) * n1;
        Vector3f p2 = 3.f * s2 - 1.5f * s1 - (5.f / 6) * n1 + (1.f / 3) * n0;
        normals.insert(normals.end(), {n0, p1, p2, n1});
    }
    return normals;
}

Bounds3f CurveSet::Bounds() const {
    Bounds3f b;
    for (const auto& v : vertices) {
        Point3f p(v[0], v[1], v[2]);
        b = Union(b, Bounds3f(p - Vector3f(v[3], v[3], v[3]), p + Vector3f(v[3], v[3], v[3])));
    }
    return b;
}

// Interaction at a hit (pbrt-v4's Curve::InteractionFromIntersection)
SurfaceInteraction CurveSet::InteractionAt(int primitive, Float uPrim, Point3f o, Vector3f d,
                                           Float t, Float time) const {
    uPrim = Clamp(uPrim, 0, 1);
    Part part = parts.empty() ? Part{primitive, 0, 1} : parts[size_t(primitive)];
    int segment = part.segment;
    Float u = Lerp(uPrim, part.u0, part.u1);
    Point3f pHit = o + t * d;
    Vector3f dpdu = Tangent(segment, u);
    Vector3f dn = Normalize(d);
    Float hitWidth = Width(segment, u);
    Normal3f nRibbon;
    if (type == CurveType::Ribbon) {
        nRibbon = RibbonNormal(segment, u);
        hitWidth *= AbsDot(Vector3f(nRibbon), dn);  // foreshortened, as pbrt-v4
    }
    // v from where the ray crosses the width of the surface Embree intersected, on the side
    // pbrt-v4's edge function says (the z component of cross(c - o, dc/du) in a ray space whose
    // z is d: this triple product's sign). Ribbons are intersected on the curve itself (Embree
    // solves for the oriented surface); flat and cylinder curves as TessellationRate() straight
    // pieces between the curve's points at u = j / N, so there the centre line is the piece's,
    // up to a fifth of the width off the curve where thin fibres bend. Measured from the curve
    // instead, hits near one edge came out beyond it: v clamped to 0 or 1, hair met at grazing
    // incidence, which reflects all the light it gets. The offset is measured across the
    // piece's direction (its end tangents interpolated, as Embree turns the piece's ends).
    Point3f c = Position(segment, u);
    Vector3f along = dpdu;
    if (type != CurveType::Ribbon) {
        const int N = TessellationRate();
        Float uN = uPrim * N;
        int j = std::min(int(uN), N - 1);
        Float f = uN - j;
        Float u0 = Lerp(Float(j) / N, part.u0, part.u1),
              u1 = Lerp(Float(j + 1) / N, part.u0, part.u1);
        c = Lerp(f, Position(segment, u0), Position(segment, u1));
        along = (1 - f) * Tangent(segment, u0) + f * Tangent(segment, u1);
    }
    Vector3f toCurve = c - o;
    Vector3f perp = toCurve - Dot(toCurve, dn) * dn;
    Vector3f acrossDir = Cross(along, dn);
    Float v = 0.5f;
    if (hitWidth > 0) {
        // Ribbons: the distance to the curve point (pbrt-v4's); flat curves: its component
        // across the piece (their distance along it is Embree's u's approximation)
        Float dist = type == CurveType::Ribbon || !(LengthSquared(acrossDir) > 0)
                         ? Length(perp)
                         : std::abs(Dot(toCurve, Normalize(acrossDir)));
        v = Dot(toCurve, acrossDir) > 0 ? 0.5f + dist / hitWidth : 0.5f - dist / hitWidth;
    }
    v = Clamp(v, 0, 1);

    Vector3f dpdv;
    if (type == CurveType::Ribbon) {
        dpdv = Normalize(Cross(Vector3f(nRibbon), dpdu)) * hitWidth;
    } else {
        // Across the curve in the plane facing the ray
        dpdv = Normalize(Cross(dn, dpdu)) * hitWidth;
        if (type == CurveType::Cylinder) {
            // Turned about the tangent by theta = -90 ... 90 degrees across the width, so
            // that the normal is a tube's
            dpdv = Rotate(-Lerp(v, -90.f, 90.f), dpdu)(dpdv);
        }
    }
    if (!(LengthSquared(Cross(dpdu, dpdv)) > 0)) {
        // Degenerate frame (a zero tangent or a ray along the curve): any perpendicular pair
        Vector3f a, b;
        CoordinateSystem(-dn, &a, &b);
        dpdu = a, dpdv = b;
    }
    SurfaceInteraction si(pHit, Point2f(u, v), -dn, dpdu, dpdv, Normal3f(0, 0, 0),
                          Normal3f(0, 0, 0), time, flipNormal);
    // pbrt-v4's error bounds for curve hits: the hit width in every axis. The ray-facing
    // surface turns with the ray, so a ray leaving the hit point with a ULP offset passes within
    // the curve's radius of its centre line and meets the same curve again wherever its
    // direction is within about 30 degrees of the tangent (Embree only skips hits closer than
    // the curve's width); from hitWidth * |n|_1 off the surface it passes at least 0.67 widths
    // away.
    si.originError = hitWidth;
    return si;
}

// Creation (pbrt-v4's Curve::Create)
const CurveSet* CurveSet::Create(const Transform& renderFromObject, bool reverseOrientation,
                                 const ParameterDictionary& params, const FileLoc& loc,
                                 ObjectArena& arena, Diagnostics& diag) {
    auto at = [&](const char* name) { return params.Has(name) ? params.Loc(name) : loc; };
    Float width = params.GetOneFloat("width", 1);
    Float width0 = params.GetOneFloat("width0", width);
    Float width1 = params.GetOneFloat("width1", width);
    for (auto [name, w] : {std::pair{"width0", width0}, std::pair{"width1", width1}})
        if (!(w >= 0) || !std::isfinite(w))
            throw SceneError(at(params.Has(name) ? name : "width"),
                             "curve widths must be finite and not negative", name);
    int degree = params.GetOneInt("degree", 3);
    if (degree != 2 && degree != 3)
        throw SceneError(at("degree"),
                         "curve \"degree\" must be 2 or 3, not " + std::to_string(degree),
                         "degree");
    std::string basis = params.GetOneString("basis", "bezier");
    if (basis != "bezier" && basis != "bspline")
        throw SceneError(at("basis"), "curve \"basis\" must be \"bezier\" or \"bspline\"", basis);
    std::vector<Point3f> cp = params.GetPoint3fArray("P");
    size_t nSegments = 0;
    if (basis == "bezier") {
        // The first segment takes degree + 1 points, each further one degree more
        if (cp.size() < size_t(degree) + 1 || (cp.size() - 1 - degree) % degree != 0)
            throw SceneError(at("P"),
                             "a degree " + std::to_string(degree) + " Bezier curve needs " +
                                 std::to_string(degree + 1) + " + n * " + std::to_string(degree) +
                                 " control points, not " + std::to_string(cp.size()),
                             "P");
        nSegments = (cp.size() - 1) / degree;
    } else {
        if (cp.size() < size_t(degree) + 1)
            throw SceneError(at("P"),
                             "a degree " + std::to_string(degree) +
                                 " b-spline curve needs at least " + std::to_string(degree + 1) +
                                 " control points, not " + std::to_string(cp.size()),
                             "P");
        nSegments = cp.size() - degree;
    }
    std::string typeName = params.GetOneString("type", "flat");
    CurveType type;
    if (typeName == "flat") {
        type = CurveType::Flat;
    } else if (typeName == "ribbon") {
        type = CurveType::Ribbon;
    } else if (typeName == "cylinder") {
        type = CurveType::Cylinder;
    } else {
        diag.Warn(at("type"), "unknown curve type \"" + typeName + "\"; using \"cylinder\"");
        type = CurveType::Cylinder;
    }
    std::vector<Normal3f> n = params.GetNormal3fArray("N");
    if (!n.empty() && type != CurveType::Ribbon) {
        diag.Warn(at("N"), "curve normals are only used with ribbon curves; ignored");
        n.clear();
    } else if (type == CurveType::Ribbon) {
        if (n.size() != nSegments + 1)
            throw SceneError(at("N"),
                             "a ribbon curve of " + std::to_string(nSegments) + " segments needs " +
                                 std::to_string(nSegments + 1) + " normals \"N\", not " +
                                 std::to_string(n.size()),
                             "N");
        for (Normal3f& nn : n) {
            nn = renderFromObject(nn);
            if (!(LengthSquared(nn) > 0) || !IsFinite(nn.x + nn.y + nn.z))
                throw SceneError(at("N"), "ribbon curve normals must be finite and non-zero", "N");
            nn = Normalize(nn);
        }
    }
    params.GetOneInt("splitdepth", 3);  // Embree subdivides curves itself

    for (Point3f& p : cp) p = renderFromObject(p);
    // A curve's width scales with the transform (pbrt-v4 intersects in object space)
    Float widthScale = 1;
    {
        Vector3f ax = renderFromObject(Vector3f(1, 0, 0)), ay = renderFromObject(Vector3f(0, 1, 0)),
                 az = renderFromObject(Vector3f(0, 0, 1));
        widthScale = std::cbrt(std::abs(Dot(ax, Cross(ay, az))));
    }
    try {
        arena.Budget().Charge(double(nSegments) * MemoryBudget::kBytesPerCurveSegment,
                              "a curve of " + std::to_string(nSegments) + " segments");
    } catch (const MemoryLimitError& e) {
        throw SceneError(at("P"), e.what(), "P");
    }
    auto* set = arena.New<CurveSet>(type, reverseOrientation ^ renderFromObject.SwapsHandedness());
    size_t cpOffset = 0;
    for (size_t seg = 0; seg < nSegments; ++seg) {
        std::array<Point3f, 4> bez;
        if (basis == "bezier") {
            if (degree == 2)
                bez = ElevateQuadraticBezier({cp[cpOffset], cp[cpOffset + 1], cp[cpOffset + 2]});
            else
                bez = {cp[cpOffset], cp[cpOffset + 1], cp[cpOffset + 2], cp[cpOffset + 3]};
            cpOffset += size_t(degree);
        } else {
            if (degree == 2)
                bez = ElevateQuadraticBezier(
                    QuadraticBSplineToBezier({cp[cpOffset], cp[cpOffset + 1], cp[cpOffset + 2]}));
            else
                bez = CubicBSplineToBezier(
                    {cp[cpOffset], cp[cpOffset + 1], cp[cpOffset + 2], cp[cpOffset + 3]});
            ++cpOffset;
        }
        bool finite = true;
        for (const Point3f& p : bez) finite &= IsFinite(p.x + p.y + p.z);
        if (!finite)
            throw SceneError(at("P"), "curve control points must be finite (in render space)", "P");
        Float w0 = widthScale * Lerp(Float(seg) / nSegments, width0, width1);
        Float w1 = widthScale * Lerp(Float(seg + 1) / nSegments, width0, width1);
        if (type == CurveType::Ribbon)
            set->AddSegment(bez, w0, w1, n[seg], n[seg + 1]);
        else
            set->AddSegment(bez, w0, w1);
    }
    // Split segments: Embree's vertex buffer of the parts (4 vertices of 16 bytes each) and
    // their segment ranges, beyond the segments' own charge
    if (!set->parts.empty()) {
        try {
            arena.Budget().Charge(
                double(set->parts.size()) * (64 + sizeof(Part)),
                "a curve's " + std::to_string(set->parts.size()) + " Embree primitives");
        } catch (const MemoryLimitError& e) {
            throw SceneError(at("P"), e.what(), "P");
        }
    }
    // Width included: Embree traces curves as the tubes or ribbons the widths make
    if (!InRenderRange(set->Bounds()))
        throw SceneError(at("P"),
                         "curve reaches beyond +-1e17 (render space), the range kiln traces "
                         "rays in",
                         "P");
    return set->NumSegments() > 0 ? set : nullptr;
}

}  // namespace kiln
