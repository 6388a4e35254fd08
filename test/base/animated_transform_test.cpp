#include <gtest/gtest.h>

#include <cmath>

#include "base/animated_transform.h"
#include "base/rng.h"

using namespace kiln;

namespace {

void ExpectMatrixNear(const SquareMatrix4& a, const SquareMatrix4& b, Float tol) {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_NEAR(a.m[i][j], b.m[i][j], tol) << i << "," << j;
}

}  // namespace

TEST(AnimatedTransform, EndsAndClampedTimesGiveTheKeyTransforms) {
    Transform a = Translate(Vector3f(1, 2, 3)) * Rotate(20, Vector3f(1, 0, 0)) * Scale(2, 1, 1);
    Transform b = Translate(Vector3f(-1, 0, 5)) * Rotate(150, Vector3f(0, 1, 1)) * Scale(1, 3, 1);
    AnimatedTransform at(a, 2, b, 4);
    ASSERT_TRUE(at.IsAnimated());
    EXPECT_EQ(at.Interpolate(1).Matrix(), a.Matrix());
    EXPECT_EQ(at.Interpolate(2).Matrix(), a.Matrix());
    EXPECT_EQ(at.Interpolate(4).Matrix(), b.Matrix());
    EXPECT_EQ(at.Interpolate(9).Matrix(), b.Matrix());
    // Just inside the interval the decomposition recomposes the key transforms
    ExpectMatrixNear(at.Interpolate(2 + 1e-6f).Matrix(), a.Matrix(), 1e-4f);
    ExpectMatrixNear(at.Interpolate(4 - 1e-6f).Matrix(), b.Matrix(), 1e-4f);
}

TEST(AnimatedTransform, RotationIsInterpolatedAlongTheArc) {
    // A quarter turn about z: halfway is an eighth of a turn, a third of the way 30 degrees
    AnimatedTransform at(Transform(), 0, Rotate(90, Vector3f(0, 0, 1)), 1);
    ExpectMatrixNear(at.Interpolate(0.5f).Matrix(), Rotate(45, Vector3f(0, 0, 1)).Matrix(), 1e-6f);
    ExpectMatrixNear(at.Interpolate(1 / 3.f).Matrix(), Rotate(30, Vector3f(0, 0, 1)).Matrix(),
                     1e-6f);
    // Points keep their distance from the axis (a matrix lerp would shrink them by cos 45)
    Point3f p = at(Point3f(1, 0, 0), 0.5f);
    EXPECT_NEAR(std::hypot(p.x, p.y), 1, 1e-6);
    // 270 degrees the other way is the same end rotation: the shorter arc is taken
    AnimatedTransform other(Transform(), 0, Rotate(-270, Vector3f(0, 0, 1)), 1);
    ExpectMatrixNear(other.Interpolate(0.5f).Matrix(), Rotate(45, Vector3f(0, 0, 1)).Matrix(),
                     1e-6f);
}

TEST(AnimatedTransform, TranslationAndScaleAreLinear) {
    AnimatedTransform at(Translate(Vector3f(0, 0, 0)) * Scale(1, 1, 1), 0,
                         Translate(Vector3f(4, -2, 8)) * Scale(3, 5, 0.5f), 2);
    Transform half = at.Interpolate(0.5f);  // a quarter of the way
    ExpectMatrixNear(half.Matrix(),
                     (Translate(Vector3f(1, -0.5f, 2)) * Scale(1.5f, 2, 0.875f)).Matrix(), 1e-6f);
    // The inverse comes with it
    Point3f p(0.3f, -2, 7);
    Point3f q = Inverse(half)(half(p));
    EXPECT_NEAR(q.x, p.x, 1e-5f);
    EXPECT_NEAR(q.y, p.y, 1e-5f);
    EXPECT_NEAR(q.z, p.z, 1e-5f);
}

TEST(AnimatedTransform, MirrorsAndFlatteningScalesStayFinite) {
    for (Transform t : {Scale(-1, 1, 1) * Rotate(30, Vector3f(0, 1, 0)), Scale(0, 2, 1)}) {
        AnimatedTransform at(t, 0, Translate(Vector3f(1, 0, 0)) * t, 1);
        ExpectMatrixNear(at.Interpolate(1e-7f).Matrix(), t.Matrix(), 1e-5f);
        SquareMatrix4 m = at.MatrixAt(0.5f);
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) EXPECT_TRUE(std::isfinite(m.m[i][j]));
        EXPECT_NEAR(m.m[0][3], t.Matrix().m[0][3] + 0.5f, 1e-6f);
    }
}

TEST(AnimatedTransform, MotionBoundsHoldEveryPointAtEveryTime) {
    RNG rng(7);
    for (int trial = 0; trial < 20; ++trial) {
        auto randomTransform = [&] {
            Vector3f axis(rng.UniformFloat() - 0.5f, rng.UniformFloat() - 0.5f,
                          rng.UniformFloat() - 0.5f);
            return Translate(Vector3f(4 * rng.UniformFloat() - 2, 4 * rng.UniformFloat() - 2,
                                      4 * rng.UniformFloat() - 2)) *
                   Rotate(360 * rng.UniformFloat(), axis) *
                   Scale(0.5f + rng.UniformFloat(), 0.5f + rng.UniformFloat(),
                         0.5f + rng.UniformFloat());
        };
        AnimatedTransform at(randomTransform(), 0, randomTransform(), 1);
        Bounds3f box(Point3f(-1, 2, -0.5f), Point3f(1.5f, 3, 0.5f));
        Bounds3f motion = at.MotionBounds(box);
        for (int k = 0; k < 2000; ++k) {
            Float time = rng.UniformFloat();
            Point3f p(Lerp(rng.UniformFloat(), box.pMin.x, box.pMax.x),
                      Lerp(rng.UniformFloat(), box.pMin.y, box.pMax.y),
                      k % 2 ? box.pMin.z : box.pMax.z);
            Point3f q = at(p, time);
            ASSERT_TRUE(q.x >= motion.pMin.x && q.x <= motion.pMax.x && q.y >= motion.pMin.y &&
                        q.y <= motion.pMax.y && q.z >= motion.pMin.z && q.z <= motion.pMax.z)
                << "trial " << trial << " time " << time;
        }
        // Not loose: within a few percent of the sampled extent
        Bounds3f sampled;
        for (int k = 0; k <= 1000; ++k) sampled = Union(sampled, at.Interpolate(k / 1000.f)(box));
        Vector3f extra = (motion.pMax - motion.pMin) - (sampled.pMax - sampled.pMin);
        Vector3f size = sampled.pMax - sampled.pMin;
        EXPECT_LT(extra.x, 0.1f * size.x);
        EXPECT_LT(extra.y, 0.1f * size.y);
        EXPECT_LT(extra.z, 0.1f * size.z);
    }
}
