// Accelerator: nearest hits over mixed shapes, instancing, shadow rays, materials, light indices
// and thermal emission, and self-intersection-free re-spawning far from the origin.
#include "core/geometry/accelerator.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <vector>

#include "test_util.h"

namespace kiln {
namespace {

// Opaque tags standing in for materials and emission (only their addresses are used).
const Material* Tag(int i) {
    static const int tags[8] = {};
    return reinterpret_cast<const Material*>(&tags[i]);
}
const ThermalEmission* EmissionTag(int i) {
    static const int tags[8] = {};
    return reinterpret_cast<const ThermalEmission*>(&tags[i]);
}

struct Scene {
    Transform id, sphereXf = Translate(Vector3f(0, 0, 5)), sphereInv = Inverse(sphereXf);
    Transform diskXf = Translate(Vector3f(0, 0, 10)), diskInv = Inverse(diskXf);
    Sphere sphere{&sphereXf, &sphereInv, false, 1, -1, 1, 360};
    Disk disk{&diskXf, &diskInv, false, 0, 3, 0, 360};
    TriangleMesh mesh{Translate(Vector3f(0, 0, 3)),
                      false,
                      {0, 1, 2, 0, 2, 3},
                      {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}},
                      {},
                      {},
                      {},
                      {}};
    std::vector<Triangle> tris = Triangle::FromMesh(&mesh);
};

TEST(Accelerator, NearestHitMaterialsAndLights) {
    Scene s;
    Accelerator accel;
    std::vector<Shape> quadric = {Shape(&s.sphere), Shape(&s.disk)};
    const int lights[2] = {7, 8};
    accel.Add(quadric, Tag(1), lights, EmissionTag(1));
    std::vector<Shape> tris = {Shape(&s.tris[0]), Shape(&s.tris[1])};
    accel.Add(tris, Tag(2), {}, nullptr);
    accel.Commit();

    // Nearest along +z from the origin: the triangles at z = 3.
    auto h = accel.Intersect(Ray(Point3f(0.5f, 0.2f, 0), Vector3f(0, 0, 2)));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->tHit, 1.5f, 1e-6f);
    EXPECT_EQ(h->intr.material, Tag(2));
    EXPECT_EQ(h->intr.lightIndex, -1);
    EXPECT_EQ(h->intr.thermal, nullptr);
    // Outside the quad: the sphere (z = 4), then the disk.
    h = accel.Intersect(Ray(Point3f(0, 0.5f, 3.5f), Vector3f(0, 0, 1)));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->intr.p.z, 5 - std::sqrt(0.75f), 1e-5f);
    EXPECT_EQ(h->intr.material, Tag(1));
    EXPECT_EQ(h->intr.lightIndex, 7);
    EXPECT_EQ(h->intr.thermal, EmissionTag(1));
    h = accel.Intersect(Ray(Point3f(2, 0, 0), Vector3f(0, 0, 1)));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->tHit, 10, 1e-5f);
    EXPECT_EQ(h->intr.lightIndex, 8);
    // tMax and shadow rays.
    EXPECT_FALSE(accel.Intersect(Ray(Point3f(2, 0, 0), Vector3f(0, 0, 1)), 9.9f));
    EXPECT_TRUE(accel.IntersectP(Ray(Point3f(2, 0, 0), Vector3f(0, 0, 1))));
    EXPECT_FALSE(accel.IntersectP(Ray(Point3f(2, 0, 0), Vector3f(0, 0, 1)), 9.9f));
    EXPECT_FALSE(accel.IntersectP(Ray(Point3f(5, 0, 0), Vector3f(0, 0, 1))));
    Bounds3f b = accel.Bounds();
    EXPECT_LE(b.pMin.x, -3);
    EXPECT_GE(b.pMax.z, 10);
}

TEST(Accelerator, InstancesArePlaced) {
    Scene s;
    Accelerator accel;
    int def = accel.NewInstanceDefinition();
    Transform id;
    Sphere unit(&id, &id, false, 1, -1, 1, 360);
    std::vector<Shape> shapes = {Shape(&unit), Shape(&s.tris[0]), Shape(&s.tris[1])};
    accel.AddToInstanceDefinition(def, shapes, Tag(3), EmissionTag(2));
    accel.AddInstance(def, Translate(Vector3f(10, 0, 0)));
    accel.AddInstance(def, Translate(Vector3f(-10, 0, 0)) * Scale(2, 2, 2));
    accel.Commit();
    // Sphere of the first instance, centred at (10, 0, 0).
    auto h = accel.Intersect(Ray(Point3f(10, 0, -5), Vector3f(0, 0, 1)));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->intr.p.z, -1, 1e-5f);
    test::ExpectNearV(h->intr.n, Normal3f(0, 0, -1), 1e-5f);
    EXPECT_EQ(h->intr.material, Tag(3));
    EXPECT_EQ(h->intr.thermal, EmissionTag(2));
    EXPECT_EQ(h->intr.lightIndex, -1);
    // Triangles of the scaled instance: z = 2 * 3 = 6, beyond the sphere of radius 2 -> the
    // sphere is hit first at z = -2.
    h = accel.Intersect(Ray(Point3f(-10, 0, -5), Vector3f(0, 0, 1)));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->intr.p.z, -2, 1e-4f);
    // Off the sphere but on the scaled quad (half-size 2 at z = 6).
    h = accel.Intersect(Ray(Point3f(-8.5f, 1.5f, -5), Vector3f(0, 0, 1)));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->intr.p.z, 6, 1e-4f);
    EXPECT_NEAR(h->tHit, 11, 1e-4f);
    test::ExpectNearV(h->intr.n, Normal3f(0, 0, 1), 1e-5f);
    EXPECT_FALSE(accel.Intersect(Ray(Point3f(0, 0, -5), Vector3f(0, 0, 1))));
    EXPECT_TRUE(accel.IntersectP(Ray(Point3f(-8.5f, 1.5f, -5), Vector3f(0, 0, 1))));
}

// Embree aborts the process on such rays; kiln reports them as a bug instead
TEST(Accelerator, InvalidRaysAreRefusedNotTraced) {
    Scene s;
    Accelerator accel;
    std::vector<Shape> quadric = {Shape(&s.sphere)};
    accel.Add(quadric, Tag(1), {}, nullptr);
    accel.Commit();
    Float nan = std::numeric_limits<Float>::quiet_NaN();
    EXPECT_THROW(accel.Intersect(Ray(Point3f(0, 0, 0), Vector3f(nan, 0, 1))), std::logic_error);
    EXPECT_THROW(accel.IntersectP(Ray(Point3f(1e19f, 0, 0), Vector3f(0, 0, 1))), std::logic_error);
    EXPECT_THROW(accel.Intersect(Ray(Point3f(0, 0, 0), Vector3f(0, 0, 1)), nan), std::logic_error);
    EXPECT_TRUE(accel.Intersect(Ray(Point3f(0, 0, 0), Vector3f(0, 0, 1))));
}

TEST(Accelerator, InstancesThatCannotBeTracedAreLeftOut) {
    Accelerator accel;
    int def = accel.NewInstanceDefinition();
    Transform id;
    Sphere unit(&id, &id, false, 1, -1, 1, 360);
    std::vector<Shape> shapes = {Shape(&unit)};
    accel.AddToInstanceDefinition(def, shapes, Tag(3), nullptr);
    accel.AddInstance(def, Translate(Vector3f(0, 0, 5)));
    accel.AddInstance(def, Scale(1e-30f, 1e-30f, 1e-30f));     // rays 1e30 times too long
    accel.AddInstance(def, Translate(Vector3f(2e17f, 0, 0)));  // beyond the range
    accel.AddInstance(def, Scale(0, 1, 1));                    // singular
    accel.AddInstance(def, Translate(Vector3f(0, 0, -5)) * Scale(1e-3f, 1e-3f, 1e-3f));
    EXPECT_EQ(accel.Commit(), (std::vector<int>{1, 2, 3}));
    EXPECT_TRUE(accel.Intersect(Ray(Point3f(0, 0, 0), Vector3f(0, 0, 1))));
    auto small = accel.Intersect(Ray(Point3f(0, 0, 0), Vector3f(0, 0, -1)));
    ASSERT_TRUE(small);
    EXPECT_NEAR(small->tHit, 5 - 1e-3f, 1e-5f);
    EXPECT_FALSE(accel.Intersect(Ray(Point3f(0, 0, 0), Vector3f(1, 0, 0))));
}

TEST(Accelerator, NoSelfIntersectionFarFromOrigin) {
    const Float far = 1e6f;
    Transform xf = Translate(Vector3f(far, far, far)), inv = Inverse(xf);
    // Feature sizes are large compared to the ray offset there (256 ulps of 1e6 = 16 units).
    Sphere sphere(&xf, &inv, false, 300, -300, 300, 360);
    TriangleMesh mesh(
        Translate(Vector3f(far, far, far)), false, {0, 1, 2, 0, 2, 3},
        {{-4000, -4000, -500}, {4000, -4000, -500}, {4000, 4000, -400}, {-4000, 4000, -500}}, {},
        {}, {}, {});
    auto tris = Triangle::FromMesh(&mesh);
    Accelerator accel;
    std::vector<Shape> shapes = {Shape(&sphere), Shape(&tris[0]), Shape(&tris[1])};
    accel.Add(shapes, nullptr, {}, nullptr);
    accel.Commit();
    RNG rng(17);
    int nHits = 0, nSelf = 0;
    for (int i = 0; i < 2000; ++i) {
        Point3f o(far + 4000 * (rng.UniformFloat() - 0.5f),
                  far + 4000 * (rng.UniformFloat() - 0.5f), far + 3000);
        Point3f target(far + 600 * (rng.UniformFloat() - 0.5f),
                       far + 600 * (rng.UniformFloat() - 0.5f), far);
        auto h = accel.Intersect(Ray(o, target - o));
        if (!h) continue;
        ++nHits;
        // Re-spawn into the hemisphere of the normal (reflection) and below (transmission
        // for the sphere): neither may hit the same surface at the origin.
        Vector3f w = SampleUniformSphere(Point2f(rng.UniformFloat(), rng.UniformFloat()));
        if (Dot(w, h->intr.n) < 0) w = -w;
        auto h2 = accel.Intersect(h->intr.SpawnRay(w));
        if (h2 && h2->tHit < 1) ++nSelf;
        auto h3 = accel.Intersect(h->intr.SpawnRay(-w));
        if (h3 && h3->tHit < 1) ++nSelf;
        // Shadow ray back towards the ray origin: no hit next to its start. (Rays that graze
        // the sphere may legitimately hit it, the origin having moved by up to 16 units.)
        auto hs = accel.Intersect(h->intr.SpawnRayTo(o), 1 - ShadowEpsilon);
        if (hs && Distance(hs->intr.p, h->intr.p) < 1) ++nSelf;
    }
    EXPECT_GT(nHits, 1000);
    EXPECT_EQ(nSelf, 0);
}

TEST(Accelerator, LargeScenesGetTheCompactBVHAndStillHit) {
    // A grid of n x n quads: 2 n^2 triangles, just over the compact threshold
    const int n = 1025;
    std::vector<Point3f> P;
    std::vector<int> indices;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) P.push_back(Point3f(Float(i) / n, Float(j) / n, 1));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            indices.insert(indices.end(), {a, b, d, a, d, c});
        }
    TriangleMesh mesh(Transform(), false, std::move(indices), std::move(P), {}, {}, {}, {});
    std::vector<Triangle> tris = Triangle::FromMesh(&mesh);
    std::vector<Shape> shapes;
    for (const Triangle& t : tris) shapes.push_back(Shape(&t));
    ASSERT_GT(shapes.size(), Accelerator::kCompactPrimitives);

    Accelerator large, small;
    large.Add(shapes, Tag(1), {}, nullptr);
    large.Commit();
    small.Add(std::span(shapes).first(100), Tag(1), {}, nullptr);
    small.Commit();
    EXPECT_TRUE(large.Compact());
    EXPECT_FALSE(small.Compact());
    EXPECT_GT(large.EmbreePeakBytes(), 0);
    // Hits land on the right triangle of the grid
    for (Float x : {0.0003f, 0.5f, 0.9991f}) {
        auto h = large.Intersect(Ray(Point3f(x, 0.25f, 0), Vector3f(0, 0, 1)));
        ASSERT_TRUE(h) << x;
        EXPECT_NEAR(h->tHit, 1, 1e-6f);
        EXPECT_NEAR(h->intr.p.x, x, 1e-6f);
    }
}

}  // namespace
}  // namespace kiln

namespace kiln {
namespace {

// A unit sphere and a quad (triangles) that move: found where they are at each ray's time,
// with their materials, at the top level, inside an object definition placed by a static
// instance, and in a moving instance; shadow rays likewise.
TEST(Accelerator, MovingShapesAreFoundWhereTheyAreAtTheRaysTime) {
    Scene s;
    Accelerator accel;
    Transform id;
    Sphere unit(&id, &id, false, 1, -1, 1, 360);
    std::vector<Shape> sphere = {Shape(&unit)};
    std::vector<Shape> quad = {Shape(&s.tris[0]), Shape(&s.tris[1])};  // z = 3, |x|, |y| <= 1
    // A sphere sliding from x = 0 to x = 10 over times 2 to 4 (top level)
    int slide = accel.NewInstanceDefinition();
    accel.AddToInstanceDefinition(slide, sphere, Tag(4), EmissionTag(3));
    accel.AddAnimatedInstance(slide,
                              AnimatedTransform(Transform(), 2, Translate(Vector3f(10, 0, 0)), 4));
    // A quad turning a quarter turn about z over times 0 to 1, inside a definition placed at
    // y = 20 by a static instance
    int holder = accel.NewInstanceDefinition();
    int turning = accel.NewInstanceDefinition();
    accel.AddToInstanceDefinition(turning, quad, Tag(5), nullptr);
    accel.AddAnimatedInstance(
        turning,
        AnimatedTransform(Scale(4, 0.25f, 1), 0, Rotate(90, Vector3f(0, 0, 1)) * Scale(4, 0.25f, 1),
                          1),
        holder);
    accel.AddInstance(holder, Translate(Vector3f(0, 20, 0)));
    accel.Commit();

    for (Float time : {0.f, 2.f, 2.5f, 3.f, 4.f, 7.f}) {
        Float x = 10 * Clamp((time - 2) / 2, 0, 1);
        auto h = accel.Intersect(Ray(Point3f(x + 0.3f, 0, -5), Vector3f(0, 0, 1), time));
        ASSERT_TRUE(h) << time;
        EXPECT_NEAR(h->intr.p.z, -std::sqrt(1 - 0.09f), 1e-4f) << time;
        EXPECT_NEAR(h->intr.p.x, x + 0.3f, 1e-4f) << time;
        EXPECT_NEAR(h->intr.time, time, 0);
        EXPECT_EQ(h->intr.material, Tag(4));
        EXPECT_EQ(h->intr.thermal, EmissionTag(3));
        EXPECT_EQ(h->intr.lightIndex, -1);
        test::ExpectNearV(h->intr.n, Normal3f(0.3f, 0, -std::sqrt(1 - 0.09f)), 1e-4f);
        // Where it was not
        EXPECT_FALSE(accel.IntersectP(Ray(Point3f(x + 3, 0, -5), Vector3f(0, 0, 1), time)));
        EXPECT_TRUE(accel.IntersectP(Ray(Point3f(x, 0, -5), Vector3f(0, 0, 1), time)));
    }
    // The bar (4 x 0.25 at time 0) lies along x at time 0, along y at 1, along the diagonal at
    // one half (a matrix blend would have shrunk it there)
    auto bar = [&](Point3f p, Float time) {
        return accel.Intersect(Ray(p + Vector3f(0, 20, -5), Vector3f(0, 0, 1), time));
    };
    EXPECT_TRUE(bar(Point3f(3.5f, 0, 0), 0));
    EXPECT_FALSE(bar(Point3f(0, 3.5f, 0), 0));
    EXPECT_TRUE(bar(Point3f(0, 3.5f, 0), 1));
    EXPECT_FALSE(bar(Point3f(3.5f, 0, 0), 1));
    Float d = 3.8f / std::sqrt(2.f);
    auto h = bar(Point3f(d, d, 0), 0.5f);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->intr.p.y, 20 + d, 1e-4f);
    EXPECT_NEAR(h->intr.p.z, 3, 1e-4f);
    EXPECT_NEAR(h->tHit, 8, 1e-4f);
    EXPECT_EQ(h->intr.material, Tag(5));
    // The scene's bounds hold the whole motion
    Bounds3f b = accel.Bounds();
    EXPECT_GE(b.pMax.x, 11);
    EXPECT_GE(b.pMax.y, 24);
}

}  // namespace
}  // namespace kiln
