// Quadric, triangle and bilinear patch shapes: analytic intersections, areas, uniform area
// sampling (chi-square) and solid-angle sampling (pdf consistency, normalisation).
#include <gtest/gtest.h>

#include "core/geometry/spherical_sampling.h"
#include "test_util.h"

namespace kiln {
namespace {

using test::ExpectNear;

struct Xf {
    Transform render, object;
    explicit Xf(const Transform& t) : render(t), object(Inverse(t)) {}
};

// Analytic intersections
TEST(Sphere, AnalyticHit) {
    Xf xf(Translate(Vector3f(1, 2, 3)));
    Sphere s(&xf.render, &xf.object, false, 2, -2, 2, 360);
    Ray r(Point3f(1, 2, -10), Vector3f(0, 0, 2));
    auto si = s.Intersect(r);
    ASSERT_TRUE(si);
    EXPECT_NEAR(si->tHit, 5.5f, 1e-5f);
    ExpectNear(si->intr.p, Point3f(1, 2, 1), 1e-4f);
    test::ExpectNearV(si->intr.n, Normal3f(0, 0, -1), 1e-5f);
    EXPECT_FALSE(s.Intersect(r, 5.0f));
    EXPECT_TRUE(s.IntersectP(r));
    EXPECT_FALSE(s.IntersectP(Ray(Point3f(10, 2, 3), Vector3f(0, 0, 1))));
    // From inside: the far side, normal still points out.
    auto in = s.Intersect(Ray(Point3f(1, 2, 3), Vector3f(1, 0, 0)));
    ASSERT_TRUE(in);
    EXPECT_NEAR(in->tHit, 2, 1e-5f);
    test::ExpectNearV(in->intr.n, Normal3f(1, 0, 0), 1e-5f);
    // ReverseOrientation flips the normal.
    Sphere rs(&xf.render, &xf.object, true, 2, -2, 2, 360);
    test::ExpectNearV(rs.Intersect(r)->intr.n, Normal3f(0, 0, 1), 1e-5f);
    // dpdu x dpdv agrees with the outward normal; dndu is consistent with n = p / r.
    EXPECT_GT(Dot(Cross(si->intr.dpdu, si->intr.dpdv), Vector3f(si->intr.n)), 0);
}

TEST(Sphere, PartialSphereClipsHits) {
    Transform id;
    Sphere s(&id, &id, false, 1, -0.5f, 0.5f, 180);
    EXPECT_FALSE(s.Intersect(Ray(Point3f(0, 0, -5), Vector3f(0, 0, 1))));  // poles cut
    auto si = s.Intersect(Ray(Point3f(0, -5, 0), Vector3f(0, 1, 0)));      // phi > 180: back
    ASSERT_TRUE(si);
    EXPECT_NEAR(si->intr.p.y, 1, 1e-5f);
    EXPECT_NEAR(s.Area(), Pi * 1 * 1, 1e-4f);
}

TEST(Disk, AnalyticHit) {
    Xf xf(Translate(Vector3f(0, 0, 1)));
    Disk d(&xf.render, &xf.object, false, 0.5f, 2, 1, 360);
    auto si = d.Intersect(Ray(Point3f(1.5f, 0, 0), Vector3f(0, 0, 1)));
    ASSERT_TRUE(si);
    EXPECT_NEAR(si->tHit, 1.5f, 1e-6f);
    ExpectNear(si->intr.p, Point3f(1.5f, 0, 1.5f), 1e-6f);
    test::ExpectNearV(si->intr.n, Normal3f(0, 0, 1), 1e-6f);
    EXPECT_NEAR(si->intr.uv.y, 0.5f, 1e-6f);
    EXPECT_FALSE(d.Intersect(Ray(Point3f(0.5f, 0, 0), Vector3f(0, 0, 1))));  // hole
    EXPECT_FALSE(d.Intersect(Ray(Point3f(2.5f, 0, 0), Vector3f(0, 0, 1))));  // outside
    EXPECT_NEAR(d.Area(), Pi * (4 - 1), 1e-4f);
}

TEST(Cylinder, AnalyticHit) {
    Transform id;
    Cylinder c(&id, &id, false, 2, -1, 1, 360);
    auto si = c.Intersect(Ray(Point3f(-5, 0, 0.5f), Vector3f(1, 0, 0)));
    ASSERT_TRUE(si);
    EXPECT_NEAR(si->tHit, 3, 1e-5f);
    ExpectNear(si->intr.p, Point3f(-2, 0, 0.5f), 1e-5f);
    test::ExpectNearV(si->intr.n, Normal3f(-1, 0, 0), 1e-5f);
    EXPECT_FALSE(c.Intersect(Ray(Point3f(-5, 0, 1.5f), Vector3f(1, 0, 0))));
    EXPECT_NEAR(c.Area(), 2 * Pi * 2 * 2, 1e-4f);
}

TriangleMesh MakeQuadMesh(const Transform& t, bool withNormals) {
    std::vector<Point3f> P = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    std::vector<Normal3f> N;
    if (withNormals) N = {{0, 0, 1}, {1, 0, 1}, {1, 0, 1}, {0, 0, 1}};
    std::vector<Point2f> uv = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    return TriangleMesh(t, false, {0, 1, 2, 0, 2, 3}, P, N, {}, uv, {7, 8});
}

TEST(Triangle, AnalyticHitWithNormalsAndUV) {
    TriangleMesh mesh = MakeQuadMesh(Transform(), true);
    Triangle t0(&mesh, 0);
    Ray r(Point3f(0.75f, 0.25f, 2), Vector3f(0, 0, -4));
    auto si = t0.Intersect(r);
    ASSERT_TRUE(si);
    EXPECT_NEAR(si->tHit, 0.5f, 1e-6f);
    ExpectNear(si->intr.p, Point3f(0.75f, 0.25f, 0), 1e-6f);
    EXPECT_NEAR(si->intr.uv.x, 1.5f, 1e-5f);
    EXPECT_NEAR(si->intr.uv.y, 0.5f, 1e-5f);
    test::ExpectNearV(si->intr.n, Normal3f(0, 0, 1), 1e-6f);
    // Shading normal interpolates N: at x = 0.75, n ~ (0.75, 0, 1).
    Normal3f expect(Normalize(Vector3f(0.75f, 0, 1)));
    test::ExpectNearV(si->intr.shading.n, expect, 1e-5f);
    EXPECT_EQ(si->intr.faceIndex, 7);
    // dpdu follows the uv parameterisation: u = 2x.
    test::ExpectNearV(si->intr.dpdu, Vector3f(0.5f, 0, 0), 1e-5f);
    EXPECT_FALSE(t0.Intersect(Ray(Point3f(0.25f, 0.75f, 2), Vector3f(0, 0, -1))));
    EXPECT_NEAR(t0.Area(), 0.5f, 1e-6f);
    auto b = t0.Barycentrics(si->intr.p);
    EXPECT_NEAR(b[0] + b[1] + b[2], 1, 1e-6f);
}

TEST(Triangle, SliverHasFiniteNormal) {
    std::vector<Point3f> P = {{0, 0, 0}, {1, 0, 0}, {2, 1e-30f, 0}};
    TriangleMesh mesh(Transform(), false, {0, 1, 2}, P, {}, {}, {}, {});
    ASSERT_EQ(mesh.NumTriangles(), 1);
    SurfaceInteraction si =
        Triangle(&mesh, 0).InteractionFromBarycentrics({0.3f, 0.3f, 0.4f}, 0, Vector3f(0, 0, 1));
    EXPECT_FALSE(si.n.HasNaN());
    EXPECT_FALSE(si.shading.n.HasNaN());
    EXPECT_NEAR(Length(si.n), 1, 1e-5f);
}

// A medium boundary's hit carries the point and the normal, oriented as the full interaction
// orients it (by winding, orientation, handedness and vertex normals), so that a ray crossing
// it picks the same medium
TEST(Triangle, BoundaryInteractionHasTheFullInteractionsPointAndNormal) {
    RNG rng(3);
    auto random = [&](Float scale) {
        return Vector3f(rng.UniformFloat() - 0.5f, rng.UniformFloat() - 0.5f,
                        rng.UniformFloat() - 0.5f) *
               scale;
    };
    for (int mesh = 0; mesh < 64; ++mesh) {
        bool reverse = mesh & 1, withNormals = mesh & 2;
        Transform t = (mesh & 4) ? Scale(-1, 1, 1) : Transform();
        std::vector<Point3f> P;
        std::vector<Normal3f> N;
        for (int v = 0; v < 3; ++v) P.push_back(Point3f(random(4)));
        if (mesh % 16 == 15) P[2] = P[0] + (P[1] - P[0]) * 2.f + Vector3f(0, 0, 1e-30f);  // sliver
        if (withNormals)
            for (int v = 0; v < 3; ++v) N.push_back(Normal3f(random(2)));
        TriangleMesh m(t, reverse, {0, 1, 2}, P, N, {}, {}, {5});
        if (m.NumTriangles() == 0) continue;
        Triangle tri(&m, 0);
        for (int k = 0; k < 8; ++k) {
            Float b1 = rng.UniformFloat(), b2 = rng.UniformFloat() * (1 - b1);
            std::array<Float, 3> b = {1 - b1 - b2, b1, b2};
            Vector3f wo = random(2);
            SurfaceInteraction full = tri.InteractionFromBarycentrics(b, 0.25f, wo);
            SurfaceInteraction boundary = tri.BoundaryInteraction(b, 0.25f, wo);
            EXPECT_EQ(boundary.p, full.p);
            EXPECT_EQ(boundary.n, full.n) << "mesh " << mesh;
            EXPECT_EQ(boundary.shading.n, full.shading.n) << "mesh " << mesh;
            EXPECT_EQ(boundary.wo, full.wo);
            EXPECT_EQ(boundary.time, full.time);
            EXPECT_EQ(boundary.faceIndex, 5);
        }
    }
}

TEST(Triangle, DegenerateTrianglesAreDropped) {
    std::vector<Point3f> P = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}};
    TriangleMesh mesh(Transform(), false, {0, 1, 2, 0, 1, 3, 1, 1, 3}, P, {}, {}, {}, {});
    EXPECT_EQ(mesh.NumTriangles(), 1);
    EXPECT_EQ(mesh.nDegenerate, 2);
}

TEST(Triangle, InterpolatesAttributes) {
    std::vector<Point3f> P = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    TriangleMesh mesh(Transform(), false, {0, 1, 2}, P, {}, {}, {}, {},
                      {{"temperature", {1000, 2000, 3000}}});
    Triangle t(&mesh, 0);
    auto b = t.Barycentrics(Point3f(0.25f, 0.5f, 0));
    EXPECT_NEAR(*mesh.InterpolateAttribute("temperature", 0, b), 1000 + 250 + 1000, 1e-2f);
    EXPECT_FALSE(mesh.InterpolateAttribute("density", 0, b));
}

BilinearPatchMesh MakePatch(bool planar) {
    std::vector<Point3f> P = {{0, 0, 0}, {2, 0, 0}, {0, 1, 0}, {2, 1, planar ? 0.f : 1.f}};
    return BilinearPatchMesh(Transform(), false, {0, 1, 2, 3}, P, {}, {}, {});
}

TEST(BilinearPatch, HitsLieOnSurface) {
    BilinearPatchMesh planar = MakePatch(true);
    BilinearPatch p(&planar, 0);
    EXPECT_TRUE(p.IsRectangle());
    EXPECT_NEAR(p.Area(), 2, 1e-5f);
    auto si = p.Intersect(Ray(Point3f(1.5f, 0.5f, 3), Vector3f(0, 0, -1)));
    ASSERT_TRUE(si);
    EXPECT_NEAR(si->tHit, 3, 1e-5f);
    EXPECT_NEAR(si->intr.uv.x, 0.75f, 1e-5f);
    EXPECT_NEAR(si->intr.uv.y, 0.5f, 1e-5f);
    test::ExpectNearV(si->intr.n, Normal3f(0, 0, 1), 1e-5f);

    BilinearPatchMesh curved = MakePatch(false);
    BilinearPatch c(&curved, 0);
    EXPECT_FALSE(c.IsRectangle());
    RNG rng(3);
    for (int i = 0; i < 200; ++i) {
        Point3f o(2 * rng.UniformFloat(), rng.UniformFloat(), 5);
        Ray r(o, Vector3f(0.1f * (rng.UniformFloat() - 0.5f), 0, -1));
        auto h = c.Intersect(r);
        if (!h) continue;
        ExpectNear(h->intr.p, r(h->tHit), 1e-4f);
        // z = u v on this patch.
        EXPECT_NEAR(h->intr.p.z, h->intr.uv.x * h->intr.uv.y, 1e-4f);
    }
}

// Area sampling: chi-square over a parameter grid in which uniform area is uniform.
void ChiSquareArea(const Shape& shape, std::function<Point2f(Point3f)> toUnitSquare,
                   std::function<double(int, int, int)> expectedFraction, int n = 16) {
    const int N = 100000;
    std::vector<double> obs(n * n, 0), exp(n * n, 0);
    RNG rng(11);
    for (int i = 0; i < N; ++i) {
        auto ss = shape.Sample(Point2f(rng.UniformFloat(), rng.UniformFloat()));
        ASSERT_TRUE(ss);
        EXPECT_NEAR(ss->pdf, shape.PDF(ss->intr), 1e-3f * ss->pdf);
        Point2f q = toUnitSquare(ss->intr.p);
        int x = Clamp(int(q.x * n), 0, n - 1), y = Clamp(int(q.y * n), 0, n - 1);
        obs[y * n + x] += 1;
    }
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) exp[y * n + x] = N * expectedFraction(x, y, n);
    auto r = ChiSquareTest(obs, exp, 0.01, 5);
    EXPECT_TRUE(r.passed) << r.message;
}

double Uniform(int, int, int n) { return 1.0 / (n * n); }
Float Phi01(Point3f p, Float phiMax) {
    Float phi = std::atan2(p.y, p.x);
    if (phi < 0) phi += 2 * Pi;
    return phi / phiMax;
}

TEST(AreaSampling, Sphere) {
    Transform id;
    Sphere s(&id, &id, false, 2, -1, 1.5f, 270);
    ChiSquareArea(
        Shape(&s), [](Point3f p) { return Point2f((p.z + 1) / 2.5f, Phi01(p, Radians(270))); },
        Uniform);
    EXPECT_NEAR(s.Sample(Point2f(0.3f, 0.6f))->pdf, 1 / s.Area(), 1e-6f);
}

TEST(AreaSampling, Disk) {
    Transform id;
    Disk full(&id, &id, false, 0, 2, 0, 360);
    ChiSquareArea(
        Shape(&full),
        [](Point3f p) { return Point2f((Sqr(p.x) + Sqr(p.y)) / 4, Phi01(p, 2 * Pi)); }, Uniform);
    Disk annulus(&id, &id, false, 0, 2, 1, 90);
    ChiSquareArea(
        Shape(&annulus),
        [](Point3f p) { return Point2f((Sqr(p.x) + Sqr(p.y) - 1) / 3, Phi01(p, PiOver2)); },
        Uniform);
}

TEST(AreaSampling, Cylinder) {
    Transform id;
    Cylinder c(&id, &id, false, 1, -1, 2, 300);
    ChiSquareArea(
        Shape(&c), [](Point3f p) { return Point2f((p.z + 1) / 3, Phi01(p, Radians(300))); },
        Uniform);
}

TEST(AreaSampling, Triangle) {
    std::vector<Point3f> P = {{0, 0, 0}, {3, 0, 1}, {1, 2, 0}};
    TriangleMesh mesh(Transform(), false, {0, 1, 2}, P, {}, {}, {}, {});
    Triangle t(&mesh, 0);
    // Barycentrics (b1, b2): uniform on the half square b1 + b2 <= 1.
    ChiSquareArea(
        Shape(&t),
        [&](Point3f p) {
            auto b = t.Barycentrics(p);
            return Point2f(b[1], b[2]);
        },
        [](int x, int y, int n) {
            if (x + y < n - 1) return 2.0 / (n * n);
            if (x + y == n - 1) return 1.0 / (n * n);
            return 0.0;
        });
}

TEST(AreaSampling, BilinearPatch) {
    BilinearPatchMesh mesh = MakePatch(false);
    BilinearPatch bp(&mesh, 0);
    // Expected fraction per (u, v) cell: integral of |dpdu x dpdv| over the cell.
    auto jac = [&](Float u, Float v) {
        return double(Length(Cross(Vector3f(2, 0, v), Vector3f(0, 1, u))));
    };
    double total = 0;
    const int m = 8;
    std::vector<double> cell(16 * 16, 0);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            for (int j = 0; j < m; ++j)
                for (int i = 0; i < m; ++i) {
                    double f = jac((x + (i + 0.5f) / m) / 16, (y + (j + 0.5f) / m) / 16);
                    cell[y * 16 + x] += f;
                    total += f;
                }
    ChiSquareArea(
        Shape(&bp),
        [&](Point3f p) {
            // p = (2u, v, u v) on this patch.
            return Point2f(p.x / 2, p.y);
        },
        [&](int x, int y, int) { return cell[y * 16 + x] / total; });
    // pbrt-v4 approximates the area of curved patches from a 3x3 grid.
    EXPECT_NEAR(bp.Area(), total / (16 * 16 * m * m), 1e-2 * bp.Area());
}

// Solid-angle sampling
TEST(SolidAngleSampling, SphereOutsideAndInside) {
    Xf xf(Translate(Vector3f(0, 0, 4)));
    Sphere s(&xf.render, &xf.object, false, 1, -1, 1, 360);
    Shape shape(&s);
    ShapeSampleContext outside(Point3f(0.3f, 0.1f, 0), Normal3f(0, 0, 0), Normal3f(0, 0, 0), 0);
    test::CheckSampledPDFMatches(shape, outside, 2000, 1e-3f);
    auto [mean, se] = test::IntegrateSolidAnglePDF(shape, outside, 200000, 1);
    EXPECT_NEAR(mean, 1, 5 * se + 2e-3);
    ShapeSampleContext inside(Point3f(0.2f, 0, 4.3f), Normal3f(0, 0, 0), Normal3f(0, 0, 0), 0);
    test::CheckSampledPDFMatches(shape, inside, 2000, 2e-3f);
    auto [mi, sei] = test::IntegrateSolidAnglePDF(shape, inside, 100000, 2);
    EXPECT_NEAR(mi, 1, 5 * sei + 2e-3);

    // Cone sampling: directions are uniform within the cone (chi-square on cos theta, phi).
    Float cosThetaMax = std::sqrt(1 - Sqr(1 / Distance(outside.p, Point3f(0, 0, 4))));
    Frame f = Frame::FromZ(Normalize(Point3f(0, 0, 4) - outside.p));
    const int n = 8, N = 50000;
    std::vector<double> obs(n * n, 0), exp(n * n, double(N) / (n * n));
    RNG rng(5);
    for (int i = 0; i < N; ++i) {
        auto ss = shape.Sample(outside, Point2f(rng.UniformFloat(), rng.UniformFloat()));
        ASSERT_TRUE(ss);
        Vector3f w = f.ToLocal(Normalize(ss->intr.p - outside.p));
        int x = Clamp(int((1 - w.z) / (1 - cosThetaMax) * n), 0, n - 1);
        int y = Clamp(int(SphericalPhi(w) / (2 * Pi) * n), 0, n - 1);
        obs[y * n + x] += 1;
    }
    auto r = ChiSquareTest(obs, exp);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(SolidAngleSampling, Disk) {
    Xf xf(Translate(Vector3f(0, 0, 2)));
    Disk d(&xf.render, &xf.object, false, 0, 1.5f, 0.2f, 360);
    Shape shape(&d);
    ShapeSampleContext ctx(Point3f(0.5f, 0, 0), Normal3f(0, 0, 1), Normal3f(0, 0, 1), 0);
    test::CheckSampledPDFMatches(shape, ctx, 2000, 1e-3f);
    auto [mean, se] = test::IntegrateSolidAnglePDF(shape, ctx, 200000, 3);
    EXPECT_NEAR(mean, 1, 5 * se + 2e-3);
}

void CheckTriangleSolidAngle(const ShapeSampleContext& ctx, bool expectSpherical) {
    std::vector<Point3f> P = {{-1, -1, 2}, {1.5f, -1, 2.5f}, {0, 1, 1.5f}};
    TriangleMesh mesh(Transform(), false, {0, 1, 2}, P, {}, {}, {}, {});
    Triangle t(&mesh, 0);
    Float sa = t.SolidAngle(ctx.p);
    EXPECT_EQ(sa >= Triangle::MinSphericalSampleArea && sa <= Triangle::MaxSphericalSampleArea,
              expectSpherical);
    Shape shape(&t);
    test::CheckSampledPDFMatches(shape, ctx, 2000, 5e-3f);
    auto [mean, se] = test::IntegrateSolidAnglePDF(shape, ctx, 200000, 4);
    EXPECT_NEAR(mean, 1, 5 * se + 3e-3);

    // Chi-square over barycentric cells (b1, b2); expected counts integrate the claimed
    // solid-angle pdf, converted to area measure, over the part of each cell inside the
    // triangle. Quadrature nodes are centroids of equal sub-triangles (m^2 per half cell), so
    // none lies on an edge, where the ray cast inside PDF() may miss and report 0.
    const int n = 8, m = 12, N = 60000;
    std::vector<double> obs(n * n, 0), exp(n * n, 0);
    Float area = t.Area();
    Normal3f ng(Normalize(Cross(P[1] - P[0], P[2] - P[0])));
    auto pdfArea = [&](double b1, double b2) {
        Vector3f pv = Vector3f(P[0]) * Float(1 - b1 - b2) + Vector3f(P[1]) * Float(b1) +
                      Vector3f(P[2]) * Float(b2);
        Point3f p(pv);
        Vector3f w = p - ctx.p;
        Float d2 = LengthSquared(w);
        w = Normalize(w);
        return double(t.PDF(ctx, w)) * AbsDot(ng, w) / d2;
    };
    // Integral over the half cell {s, t >= 0, s + t <= 1} at (x0, y0) with side h, optionally
    // mirrored to the upper half {s + t >= 1} (in barycentric measure).
    auto halfCell = [&](double x0, double y0, double h, bool upper) {
        double sum = 0;
        for (int j = 0; j < m; ++j)
            for (int i = 0; i + j < m; ++i)
                for (int k = 0; k < 2; ++k) {
                    if (k == 1 && i + j == m - 1) continue;  // no downward triangle here
                    double s = (i + (k ? 2.0 : 1.0) / 3) / m, tt = (j + (k ? 2.0 : 1.0) / 3) / m;
                    if (upper) s = 1 - s, tt = 1 - tt;
                    sum += pdfArea(x0 + h * s, y0 + h * tt);
                }
        return sum * 0.5 * h * h / (m * m);
    };
    double total = 0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x + y < n; ++x) {
            double h = 1.0 / n, e = halfCell(x * h, y * h, h, false);
            if (x + y < n - 1) e += halfCell(x * h, y * h, h, true);
            exp[y * n + x] = e * 2 * area;  // d(area) = 2 area d(b1) d(b2)
            total += exp[y * n + x];
        }
    EXPECT_NEAR(total, 1, 2e-3);
    for (double& e : exp) e *= N / total;
    RNG rng(9);
    for (int i = 0; i < N; ++i) {
        auto ss = shape.Sample(ctx, Point2f(rng.UniformFloat(), rng.UniformFloat()));
        ASSERT_TRUE(ss);
        auto b = t.Barycentrics(ss->intr.p);
        int x = Clamp(int(b[1] * n), 0, n - 1), y = Clamp(int(b[2] * n), 0, n - 1);
        obs[y * n + x] += 1;
    }
    auto r = ChiSquareTest(obs, exp, 0.01, 3);
    EXPECT_TRUE(r.passed) << r.message;
}

// Arvo's mapping: InvertSphericalTriangleSample undoes SampleSphericalTriangle (the cosine
// warp's pdf depends on it); tiny, huge and sliver triangles give finite results.
TEST(SphericalTriangle, InvertsSampleAndStaysFinite) {
    using Tri = std::array<Point3f, 3>;
    const Tri tris[] = {{Point3f(0, 0, 1), Point3f(0.025f, 0, 1), Point3f(0.003f, 0.025f, 1)},
                        {Point3f(-1, -1, 2), Point3f(1.5f, -1, 2.5f), Point3f(0, 1, 1.5f)},
                        {Point3f(-30, -30, 1), Point3f(30, -30, 1), Point3f(0, 30, 1)},
                        {Point3f(0, 0, 1), Point3f(1, 0, 1), Point3f(2, 1e-6f, 1)},
                        {Point3f(0, 0, 1e4f), Point3f(1, 0, 1e4f), Point3f(0, 1, 1e4f)},
                        {Point3f(-1e3f, -1e3f, 1), Point3f(1e3f, -1e3f, 1), Point3f(0, 1e3f, 1)}};
    RNG rng(17);
    for (int k = 0; k < 6; ++k) {
        const Tri& v = tris[k];
        Float sa = SphericalTriangleArea(v, Point3f(0, 0, 0));
        bool checkInverse =
            sa >= Triangle::MinSphericalSampleArea && sa <= Triangle::MaxSphericalSampleArea;
        for (int i = 0; i < 2000; ++i) {
            Point2f u(rng.UniformFloat(), rng.UniformFloat());
            Float pdf;
            auto b = SampleSphericalTriangle(v, Point3f(0, 0, 0), u, &pdf);
            ASSERT_TRUE(std::isfinite(b[0] + b[1] + b[2]) && std::isfinite(pdf)) << k;
            Vector3f w = b[0] * Vector3f(v[0]) + b[1] * Vector3f(v[1]) + b[2] * Vector3f(v[2]);
            Point2f ui = InvertSphericalTriangleSample(v, Point3f(0, 0, 0), Normalize(w));
            ASSERT_TRUE(std::isfinite(ui.x + ui.y)) << k;
            if (!checkInverse) continue;
            EXPECT_NEAR(pdf, 1 / sa, 1e-4f / sa) << k;
            EXPECT_NEAR(ui.x, u.x, 2e-4f) << k << " u = " << u.x << ", " << u.y;
            EXPECT_NEAR(ui.y, u.y, 2e-4f) << k << " u = " << u.x << ", " << u.y;
        }
    }
}

TEST(SolidAngleSampling, TriangleSphericalWithCosineWarp) {
    CheckTriangleSolidAngle(
        ShapeSampleContext(Point3f(0, 0, 0), Normal3f(0, 0.6f, 0.8f), Normal3f(0, 0.6f, 0.8f), 0),
        true);
}

TEST(SolidAngleSampling, TriangleSphericalNoNormal) {
    CheckTriangleSolidAngle(
        ShapeSampleContext(Point3f(0.2f, 0, 0.5f), Normal3f(0, 0, 0), Normal3f(0, 0, 0), 0), true);
}

TEST(SolidAngleSampling, TriangleFarUsesAreaSampling) {
    CheckTriangleSolidAngle(
        ShapeSampleContext(Point3f(0, 0, -200), Normal3f(0, 0, 1), Normal3f(0, 0, 1), 0), false);
}

}  // namespace
}  // namespace kiln
