// Sphere mappings (base/sphere_mappings.h): equal-area and equirectangular round trips, equal
// area (a chi-square test of uniform square points over equal-solid-angle zones), and the
// equal-area square's wrap (continuous across every edge).
#include "base/sphere_mappings.h"

#include <gtest/gtest.h>

#include <vector>

#include "base/rng.h"
#include "base/statistics.h"

namespace kiln {
namespace {

TEST(SphereMappings, EqualAreaRoundTripAndArea) {
    RNG rng(3);
    for (int i = 0; i < 10000; ++i) {
        Point2f p(rng.UniformFloat(), rng.UniformFloat());
        Vector3f w = EqualAreaSquareToSphere(p);
        EXPECT_NEAR(Length(w), 1, 1e-5);
        Point2f q = EqualAreaSphereToSquare(w);
        EXPECT_NEAR(p.x, q.x, 1e-4);
        EXPECT_NEAR(p.y, q.y, 1e-4);
    }
    // Equal area: the inner diamond (half the square) is the upper hemisphere
    int upper = 0;
    for (int i = 0; i < 10000; ++i)
        upper += EqualAreaSquareToSphere(Point2f(rng.UniformFloat(), rng.UniformFloat())).z > 0;
    EXPECT_NEAR(upper, 5000, 4 * 50);
}

TEST(SphereMappings, EquirectRoundTripAndPole) {
    RNG rng(5);
    for (int i = 0; i < 10000; ++i) {
        Point2f p(rng.UniformFloat(), 0.01f + 0.98f * rng.UniformFloat());
        Point2f q = EquirectSphereToSquare(EquirectSquareToSphere(p));
        EXPECT_NEAR(p.x, q.x, 1e-4);
        EXPECT_NEAR(p.y, q.y, 1e-4);
    }
    EXPECT_NEAR(EquirectSquareToSphere(Point2f(0.3f, 0)).z, 1, 1e-6);  // top row: +z
    Vector3f y = EquirectSquareToSphere(Point2f(0.25f, 0.5f));         // phi = pi/2: +y
    EXPECT_NEAR(y.y, 1, 1e-6);
}

// Uniform points on the square give uniform directions: 8 bands of equal z (equal solid angle,
// Archimedes) times 16 equal azimuth sectors.
TEST(SphereMappings, EqualAreaChiSquare) {
    const int nz = 8, nphi = 16, n = 128000;
    std::vector<double> observed(nz * nphi, 0), expected(nz * nphi, double(n) / (nz * nphi));
    RNG rng(9);
    for (int i = 0; i < n; ++i) {
        Vector3f w = EqualAreaSquareToSphere(Point2f(rng.UniformFloat(), rng.UniformFloat()));
        int iz = Clamp(int((w.z + 1) / 2 * nz), 0, nz - 1);
        int ip = Clamp(int(SphericalPhi(w) / (2 * Pi) * nphi), 0, nphi - 1);
        observed[iz * nphi + ip] += 1;
    }
    ChiSquareResult r = ChiSquareTest(observed, expected);
    EXPECT_TRUE(r.passed) << r.message;
}

// A point just outside the square, wrapped, maps to the direction of the point just inside:
// the mapping continues across every edge (the spherical camera relies on it for pixel
// filters reaching past the film's edge).
TEST(SphereMappings, WrapEqualAreaSquareIsContinuousAcrossEdges) {
    RNG rng(4);
    const Float eps = 1e-3f;
    for (int i = 0; i < 2000; ++i) {
        Float t = rng.UniformFloat();
        for (auto [outside, inside] : {std::pair{Point2f(-eps, t), Point2f(eps, t)},
                                       std::pair{Point2f(1 + eps, t), Point2f(1 - eps, t)},
                                       std::pair{Point2f(t, -eps), Point2f(t, eps)},
                                       std::pair{Point2f(t, 1 + eps), Point2f(t, 1 - eps)}}) {
            Point2f w = WrapEqualAreaSquare(outside);
            EXPECT_GE(w.x, 0);
            EXPECT_LE(w.x, 1);
            EXPECT_GE(w.y, 0);
            EXPECT_LE(w.y, 1);
            Vector3f a = EqualAreaSquareToSphere(w), b = EqualAreaSquareToSphere(inside);
            EXPECT_LT(Length(a - b), 0.02f) << outside.x << " " << outside.y;
        }
        // Inside points are unchanged
        Point2f p(rng.UniformFloat(), rng.UniformFloat());
        EXPECT_EQ(WrapEqualAreaSquare(p), p);
    }
    // Beyond a corner: mirrored in both axes
    Point2f c = WrapEqualAreaSquare(Point2f(-0.1f, -0.2f));
    EXPECT_NEAR(c.x, 0.9f, 1e-6);
    EXPECT_NEAR(c.y, 0.8f, 1e-6);
}

}  // namespace
}  // namespace kiln
