#include <gtest/gtest.h>

#include "base/rng.h"
#include "base/transform.h"

using namespace kiln;

TEST(Transform, InverseRoundTrip) {
    Transform t = Translate(Vector3f(1, -2, 3)) * Rotate(33, Vector3f(1, 1, 0)) * Scale(2, 3, 0.5f);
    Point3f p(0.3f, -4, 9);
    Point3f q = Inverse(t)(t(p));
    EXPECT_NEAR(q.x, p.x, 1e-5f);
    EXPECT_NEAR(q.y, p.y, 1e-5f);
    EXPECT_NEAR(q.z, p.z, 1e-5f);
    EXPECT_FALSE(t.SwapsHandedness());
    EXPECT_TRUE(Scale(-1, 1, 1).SwapsHandedness());
}

TEST(Transform, NormalsStayPerpendicular) {
    Transform t = Scale(1, 5, 0.2f) * Rotate(70, Vector3f(0, 0, 1));
    Vector3f a(1, 0, 0), b(0, 1, 1);
    Normal3f n(Cross(a, b));
    EXPECT_NEAR(Dot(t(n), t(a)), 0, 1e-5f);
    EXPECT_NEAR(Dot(t(n), t(b)), 0, 1e-5f);
}

TEST(Transform, LookAtMapsEyeToOriginAndLookToPlusZ) {
    auto t = LookAt(Point3f(1, 2, 3), Point3f(1, 2, 10), Vector3f(0, 1, 0));
    ASSERT_TRUE(t.has_value());
    Point3f e = (*t)(Point3f(1, 2, 3));
    EXPECT_NEAR(Length(Vector3f(e)), 0, 1e-6f);
    Point3f l = (*t)(Point3f(1, 2, 10));
    EXPECT_NEAR(l.z, 7, 1e-5f);
    EXPECT_FALSE(LookAt(Point3f(0, 0, 0), Point3f(0, 1, 0), Vector3f(0, 1, 0)).has_value());
}

TEST(Transform, SingularMatrixHasNoInverse) {
    SquareMatrix4 m;
    m.m[1][1] = 0;
    EXPECT_FALSE(Inverse(m).has_value());
}

TEST(RobustOffset, NoSelfIntersectionFarFromOrigin) {
    // A plane z = c far from the origin: offset points must be strictly on the chosen side.
    RNG rng(1);
    for (Float scale : {1.0f, 1e3f, 1e6f}) {
        for (int i = 0; i < 10000; ++i) {
            Point3f p(scale * (rng.UniformFloat() - 0.5f), scale * (rng.UniformFloat() - 0.5f),
                      scale);
            Point3f o = OffsetRayOrigin(p, Normal3f(0, 0, 1), Vector3f(0.3f, 0.1f, 1));
            EXPECT_GT(o.z, p.z);
            Point3f o2 = OffsetRayOrigin(p, Normal3f(0, 0, 1), Vector3f(0.3f, 0.1f, -1));
            EXPECT_LT(o2.z, p.z);
        }
    }
}
