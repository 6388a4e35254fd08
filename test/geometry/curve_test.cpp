// Curves (core/geometry/curve.h): basis conversions reproduce the same curve, widths run
// linearly, the interaction at a hit has pbrt-v4's uv and frames, ribbons' normals follow the
// slerp, bad parameters are located errors, and the accelerator finds curves where they are:
// from any ray origin on (Embree's own self-intersection avoidance defeated), while rays
// leaving a curve start off it by its width (pbrt-v4's error bounds) and miss it.
#include <gtest/gtest.h>

#include <cmath>

#include "../textures/param_helpers.h"
#include "core/geometry/accelerator.h"
#include "core/geometry/curve.h"
#include "test_util.h"

namespace kiln {
namespace {

using test::ExpectNear;
using test::Floats;
using test::Int1;
using test::String1;

Point3f Bezier(const std::array<Point3f, 4>& p, Float u) {
    Float b[4] = {(1 - u) * (1 - u) * (1 - u), 3 * (1 - u) * (1 - u) * u, 3 * (1 - u) * u * u,
                  u * u * u};
    Vector3f s(0, 0, 0);
    for (int i = 0; i < 4; ++i) s += b[i] * Vector3f(p[i]);
    return Point3f(s);
}

TEST(Curve, BasisConversionsReproduceTheCurve) {
    // A quadratic Bezier elevated to a cubic is the same curve
    std::array<Point3f, 3> q = {Point3f(0, 0, 0), Point3f(1, 2, 0), Point3f(3, 0, 1)};
    std::array<Point3f, 4> c = ElevateQuadraticBezier(q);
    for (Float u : {0.f, 0.3f, 0.5f, 1.f}) {
        Vector3f quad = (1 - u) * (1 - u) * Vector3f(q[0]) + 2 * (1 - u) * u * Vector3f(q[1]) +
                        u * u * Vector3f(q[2]);
        ExpectNear(Bezier(c, u), Point3f(quad));
    }
    // Uniform cubic b-spline: consecutive segments meet with equal position and tangent, and a
    // segment starts at (P0 + 4 P1 + P2) / 6
    std::array<Point3f, 5> p = {Point3f(0, 0, 0), Point3f(1, 2, 0), Point3f(2, -1, 1),
                                Point3f(4, 1, 0), Point3f(5, 0, 2)};
    auto s0 = CubicBSplineToBezier({p[0], p[1], p[2], p[3]});
    auto s1 = CubicBSplineToBezier({p[1], p[2], p[3], p[4]});
    ExpectNear(s0[0], Point3f((Vector3f(p[0]) + 4.f * Vector3f(p[1]) + Vector3f(p[2])) / 6));
    ExpectNear(s0[3], s1[0]);
    ExpectNear(Point3f(Vector3f(s0[3]) - Vector3f(s0[2])),
               Point3f(Vector3f(s1[1]) - Vector3f(s1[0])));
    // Quadratic b-spline segments meet at their control polygon's midpoints
    auto b0 = QuadraticBSplineToBezier({p[0], p[1], p[2]});
    auto b1 = QuadraticBSplineToBezier({p[1], p[2], p[3]});
    ExpectNear(b0[2], b1[0]);
    ExpectNear(b0[2], Lerp(0.5f, p[1], p[2]));
}

// A curve of the given type from scene parameters.
const CurveSet* Create(ObjectArena& arena, Diagnostics& diag, ParsedParameterVector params,
                       const Transform& t = Transform()) {
    ParameterDictionary d(std::move(params), nullptr);
    return CurveSet::Create(t, false, d, test::TestLoc(), arena, diag);
}

TEST(Curve, SegmentsWidthsAndErrors) {
    ObjectArena arena;
    Diagnostics diag(nullptr);
    // 7 Bezier points of degree 3: 2 segments; widths 0.4 -> 0.1 along the whole curve
    ParsedParameter P =
        Floats("point3", "P", {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0, 4, 0, 0, 5, 0, 0, 6, 0, 0});
    const CurveSet* c =
        Create(arena, diag, {P, test::Float1("width0", 0.4f), test::Float1("width1", 0.1f)});
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->NumSegments(), 2);
    EXPECT_NEAR(c->Width(0, 0), 0.4f, 1e-6f);
    EXPECT_NEAR(c->Width(0, 1), 0.25f, 1e-6f);
    EXPECT_NEAR(c->Width(1, 0.5f), 0.175f, 1e-6f);
    // Embree's radii interpolate linearly too
    const auto& v = c->Vertices();
    EXPECT_NEAR(v[1][3], 0.5f * 0.35f, 1e-6f);
    // Under a scale the widths scale
    const CurveSet* scaled = Create(arena, diag, {P}, Scale(2, 2, 2));
    EXPECT_NEAR(scaled->Width(0, 0.3f), 2, 1e-5f);
    // b-spline: points - 3 segments
    EXPECT_EQ(Create(arena, diag, {P, String1("basis", "bspline")})->NumSegments(), 4);
    EXPECT_EQ(
        Create(arena, diag, {P, String1("basis", "bspline"), Int1("degree", 2)})->NumSegments(), 5);
    EXPECT_EQ(Create(arena, diag, {P, Int1("degree", 2)})->NumSegments(), 3);
    // Errors: point counts, degree, basis, ribbons without (enough) normals, negative widths
    ParsedParameter P6 =
        Floats("point3", "P", {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0, 4, 0, 0, 5, 0, 0});
    EXPECT_THROW(Create(arena, diag, {P6}), SceneError);
    EXPECT_THROW(Create(arena, diag, {P, Int1("degree", 4)}), SceneError);
    EXPECT_THROW(Create(arena, diag, {P, String1("basis", "catmullrom")}), SceneError);
    EXPECT_THROW(Create(arena, diag, {P, String1("type", "ribbon")}), SceneError);
    EXPECT_THROW(Create(arena, diag,
                        {P, String1("type", "ribbon"), Floats("normal", "N", {0, 0, 1, 0, 0, 1})}),
                 SceneError);
    EXPECT_THROW(Create(arena, diag, {P, test::Float1("width", -1)}), SceneError);
    try {
        Create(arena, diag, {P, Int1("degree", 5)});
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("test.pbrt:2"), std::string::npos) << e.what();
    }
    // Normals on a non-ribbon curve and unknown types warn
    int warnings = diag.WarningCount();
    Create(arena, diag, {P, Floats("normal", "N", {0, 0, 1, 0, 0, 1, 0, 0, 1})});
    Create(arena, diag, {P, String1("type", "tube")});
    EXPECT_EQ(diag.WarningCount(), warnings + 2);
}

TEST(Curve, InteractionHasPbrtUVAndFrames) {
    ObjectArena arena;
    Diagnostics diag(nullptr);
    // A straight curve along x of width 0.2, seen by rays along -z
    ParsedParameter P = Floats("point3", "P", {-1, 0, 0, -1.f / 3, 0, 0, 1.f / 3, 0, 0, 1, 0, 0});
    for (const char* type : {"flat", "cylinder"}) {
        SCOPED_TRACE(type);
        const CurveSet* c =
            Create(arena, diag, {P, test::Float1("width", 0.2f), String1("type", type)});
        Vector3f d(0, 0, -1);
        for (Float y : {-0.08f, 0.f, 0.05f}) {
            Point3f o(0.25f, y, 5);
            SurfaceInteraction si = c->InteractionAt(0, 0.625f, o, d, 5, 0);
            EXPECT_NEAR(si.uv.x, 0.625f, 1e-6f);
            // v across the width: 0.5 on the centre line, distance / width either side
            EXPECT_NEAR(std::abs(si.uv.y - 0.5f), std::abs(y) / 0.2f, 1e-5f);
            EXPECT_EQ(si.n, si.shading.n);  // no shading normal of its own
            Float facing = AbsDot(Vector3f(si.n), d);
            if (std::string(type) == "flat")
                EXPECT_NEAR(facing, 1, 1e-5f);
            else  // a tube's normal: cos = sqrt(1 - (2 (v - 0.5))^2)
                EXPECT_NEAR(facing, std::cos(Pi * (si.uv.y - 0.5f)), 1e-4f);
        }
        // The two sides of the centre line get v below and above 0.5
        Float vLow = c->InteractionAt(0, 0.5f, Point3f(0, -0.05f, 5), d, 5, 0).uv.y;
        Float vHigh = c->InteractionAt(0, 0.5f, Point3f(0, 0.05f, 5), d, 5, 0).uv.y;
        EXPECT_LT((vLow - 0.5f) * (vHigh - 0.5f), 0);
    }
}

TEST(Curve, RibbonNormalsFollowTheSlerp) {
    ObjectArena arena;
    Diagnostics diag(nullptr);
    ParsedParameter P = Floats("point3", "P", {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0});
    for (Float twist : {30.f, 90.f, 170.f}) {
        Float t = Radians(twist);
        const CurveSet* c = Create(arena, diag,
                                   {P, String1("type", "ribbon"),
                                    Floats("normal", "N", {0, 0, 1, 0, std::sin(t), std::cos(t)})});
        // The exact slerp
        for (Float u : {0.f, 0.25f, 0.5f, 1.f}) {
            Vector3f n(c->RibbonNormal(0, u));
            EXPECT_NEAR(n.y, std::sin(u * t), 1e-5f);
            EXPECT_NEAR(n.z, std::cos(u * t), 1e-5f);
        }
        // Embree's Bezier of kiln's normal control points: the angle from the slerp
        std::vector<Vector3f> en = c->EmbreeNormals();
        ASSERT_EQ(en.size(), 4u);
        Float worst = 0;
        for (int k = 0; k <= 100; ++k) {
            Float u = k / 100.f;
            Vector3f b = (1 - u) * (1 - u) * (1 - u) * en[0] + 3 * (1 - u) * (1 - u) * u * en[1] +
                         3 * (1 - u) * u * u * en[2] + u * u * u * en[3];
            worst = std::max(worst, AngleBetween(Normalize(b), Vector3f(c->RibbonNormal(0, u))));
        }
        std::printf("ribbon twist %5.1f degrees: Bezier normals within %.4f degrees of slerp\n",
                    twist, Degrees(worst));
        EXPECT_LT(Degrees(worst), twist <= 90 ? 0.1f : 2.f);
    }
}

TEST(Curve, AcceleratorFindsCurves) {
    ObjectArena arena;
    Diagnostics diag(nullptr);
    ParsedParameter P = Floats("point3", "P", {-1, 0, 0, -0.3f, 0.5f, 0, 0.3f, -0.5f, 0, 1, 0, 0});
    for (const char* type : {"flat", "cylinder", "ribbon"}) {
        SCOPED_TRACE(type);
        ParsedParameterVector params = {P, test::Float1("width", 0.1f), String1("type", type)};
        if (std::string(type) == "ribbon")
            params.push_back(Floats("normal", "N", {0, 0, 1, 0, 0.5f, 1}));
        const CurveSet* c = Create(arena, diag, params);
        Accelerator accel;
        accel.AddCurves(*c, nullptr, nullptr);
        accel.Commit();
        // Rays down -z just beside the centre line hit it at z = 0 with the curve's u (exactly
        // on it, at the inflection point u = 0.5, Embree 3.13's flat curves miss)
        for (Float u : {0.1f, 0.5f, 0.8f}) {
            Vector3f side = Normalize(Cross(c->Tangent(0, u), Vector3f(0, 0, 1)));
            Point3f p = c->Position(0, u) + 0.003f * side;
            Ray ray(Point3f(p.x, p.y, 3), Vector3f(0, 0, -1));
            auto si = accel.Intersect(ray);
            ASSERT_TRUE(si.has_value()) << u;
            EXPECT_NEAR(si->tHit, 3, 5e-3f);  // a twisted ribbon leaves z = 0 across its width
            EXPECT_NEAR(si->intr.uv.x, u, 0.02f);
            EXPECT_NEAR(si->intr.uv.y, 0.5f, 0.1f);
            EXPECT_TRUE(accel.IntersectP(ray));
            // Half a width and more beside the curve (across its tangent): a miss
            Point3f q = p + 0.08f * side;
            EXPECT_FALSE(accel.Intersect(Ray(Point3f(q.x, q.y, 3), Vector3f(0, 0, -1))));
        }
    }
}

// A flat curve along x (z = 0) of width 0.2 in its own accelerator.
struct StraightCurve {
    ObjectArena arena;
    Diagnostics diag{nullptr};
    Accelerator accel;
    StraightCurve() {
        ParsedParameter P =
            Floats("point3", "P", {-1, 0, 0, -1.f / 3, 0, 0, 1.f / 3, 0, 0, 1, 0, 0});
        const CurveSet* c = Create(arena, diag, {P, test::Float1("width", 0.2f)});
        accel.AddCurves(*c, nullptr, nullptr);
        accel.Commit();
    }
};

TEST(Curve, RaysLeavingACurveMissIt) {
    // A ray leaving the ray-facing surface of a curve passes within its radius of the centre
    // line; with a ULP offset it met the same curve again wherever it ran within about 30
    // degrees of the tangent towards the centre line (hits beyond twice the radius, which Embree
    // does not skip). From hitWidth * |n|_1 off the surface (pbrt-v4) it passes clear of it.
    StraightCurve scene;
    int rays = 0;
    for (Float y : {0.05f, 0.08f, -0.08f}) {
        auto si = scene.accel.Intersect(Ray(Point3f(0, y, 3), Vector3f(0, 0, -1)));
        ASSERT_TRUE(si.has_value());
        EXPECT_NEAR(si->intr.p.z, 0, 1e-4f);
        for (Float theta : {8.f, 15.f, 25.f})
            for (Float phi : {-60.f, -30.f, 0.f, 30.f, 60.f})
                for (Float sx : {-1.f, 1.f}) {
                    // Towards the centre line across the width, theta from the tangent, phi
                    // out of the ribbon's plane
                    Float st = std::sin(Radians(theta)), ct = std::cos(Radians(theta));
                    Vector3f w(sx * ct, -std::copysign(st * std::cos(Radians(phi)), y),
                               st * std::sin(Radians(phi)));
                    SCOPED_TRACE(testing::Message() << "y " << y << " theta " << theta << " phi "
                                                    << phi << " along " << sx);
                    EXPECT_FALSE(scene.accel.Intersect(si->intr.SpawnRay(w)).has_value());
                    EXPECT_FALSE(scene.accel.IntersectP(si->intr.SpawnRayTo(si->intr.p + 3.f * w),
                                                        1 - ShadowEpsilon));
                    ++rays;
                }
    }
    EXPECT_EQ(rays, 90);
}

TEST(Curve, AcrossCoordinateIsUniformOverTheSurfaceHit) {
    // A thin S-bend needing more straight pieces than Embree's largest tessellation (16): its
    // flat-curve surface runs up to about a width off the curve. v is measured across the
    // surface hit, so hits spread evenly over 0 ... 1; measured from the curve, v came out
    // beyond 0 or 1 for many hits near one edge (clamped: hair at grazing incidence).
    ObjectArena arena;
    Diagnostics diag(nullptr);
    const Float width = 0.01f;
    for (const char* type : {"flat", "cylinder"}) {
        SCOPED_TRACE(type);
        const CurveSet* c =
            Create(arena, diag,
                   {Floats("point3", "P", {-1, 0, 0, -0.3f, 1.5f, 0, 0.3f, -1.5f, 0, 1, 0, 0}),
                    test::Float1("width", width), String1("type", type)});
        EXPECT_EQ(c->TessellationRate(), 16);
        Accelerator accel;
        accel.AddCurves(*c, nullptr, nullptr);
        accel.Commit();
        // Rays down -z at stratified points within a width of the curve, across its tangent
        int hits = 0, atEdge = 0, quarter[4] = {0, 0, 0, 0};
        const int nu = 400, ns = 40;
        for (int i = 0; i < nu; ++i)
            for (int k = 0; k < ns; ++k) {
                Float u = (i + 0.5f) / nu, s = ((k + 0.5f) / ns * 2 - 1) * width;
                Vector3f side = Normalize(Cross(c->Tangent(0, u), Vector3f(0, 0, 1)));
                Point3f p = c->Position(0, u) + s * side;
                auto si = accel.Intersect(Ray(Point3f(p.x, p.y, 1), Vector3f(0, 0, -1)));
                if (!si) continue;
                ++hits;
                Float v = si->intr.uv.y;
                atEdge += v < 0.01f || v > 0.99f;
                ++quarter[std::min(int(v * 4), 3)];
            }
        // About half the points lie on the surface (it is a width wide, the points two)
        EXPECT_GT(hits, nu * ns / 3);
        // Uniform v puts 2 % of hits within 0.01 of an edge, a quarter in each quarter (the
        // bend makes the inner side of each piece denser by less than 1 %)
        EXPECT_LT(atEdge, 0.03 * hits) << atEdge << " of " << hits;
        for (int q = 0; q < 4; ++q) EXPECT_NEAR(quarter[q], 0.25 * hits, 0.03 * hits) << q;
    }
}

TEST(Curve, AcceleratorFindsCurvesNearTheRayOrigin) {
    // Embree (EMBREE_CURVE_SELF_INTERSECTION_AVOIDANCE_FACTOR 2) skips flat-curve hits closer
    // than twice the radius (0.2 here); pbrt-v4 skips none
    StraightCurve scene;
    for (Float z : {0.15f, 0.05f, 0.01f}) {
        SCOPED_TRACE(z);
        Ray down(Point3f(0.3f, 0.02f, z), Vector3f(0, 0, -2));  // t in units of 2
        auto si = scene.accel.Intersect(down);
        ASSERT_TRUE(si.has_value());
        EXPECT_NEAR(si->tHit, z / 2, 1e-5f);
        EXPECT_NEAR(si->intr.p.z, 0, 1e-5f);
        EXPECT_NEAR(si->intr.uv.x, 0.65f, 0.01f);
        EXPECT_NEAR(std::abs(si->intr.uv.y - 0.5f), 0.1f, 0.01f);
        EXPECT_TRUE(scene.accel.IntersectP(down));
        EXPECT_FALSE(scene.accel.IntersectP(down, 0.9f * z / 2));  // stops short of it
        // Nor behind the origin
        Ray up(down.o, Vector3f(0, 0, 1));
        EXPECT_FALSE(scene.accel.Intersect(up).has_value());
        EXPECT_FALSE(scene.accel.IntersectP(up));
    }
}

}  // namespace
}  // namespace kiln
