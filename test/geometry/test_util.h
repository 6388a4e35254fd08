// Shared helpers for the geometry tests.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <vector>

#include "base/rng.h"
#include "base/sampling.h"
#include "base/statistics.h"
#include "core/geometry/shape.h"

namespace kiln::test {

inline void ExpectNear(Point3f a, Point3f b, Float tol = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}
template <typename A, typename B>
inline void ExpectNearV(A a, B b, Float tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

// Monte Carlo estimate of the integral of shape.PDF(ctx, w) over all directions; returns
// (mean, standard error).
inline std::pair<double, double> IntegrateSolidAnglePDF(const Shape& shape,
                                                        const ShapeSampleContext& ctx, int n,
                                                        uint64_t seed) {
    // Directions uniform over the sphere, or over a cone bounding the shape when ctx is
    // outside the shape's bounding sphere.
    Point3f c;
    Float r;
    shape.Bounds().BoundingSphere(&c, &r);
    r *= 1.01f;
    Float d = Distance(ctx.p, c);
    bool cone = d > 1.5f * r;
    Float cosMax = cone ? std::sqrt(1 - Sqr(r / d)) : -1;
    Frame f = cone ? Frame::FromZ(Normalize(c - ctx.p)) : Frame();
    RNG rng(seed);
    RunningStats stats;
    for (int i = 0; i < n; ++i) {
        Point2f u(rng.UniformFloat(), rng.UniformFloat());
        Vector3f w = cone ? f.FromLocal(SampleUniformCone(u, cosMax)) : SampleUniformSphere(u);
        Float pdfW = cone ? UniformConePDF(cosMax) : UniformSpherePDF();
        stats.Add(shape.PDF(ctx, w) / pdfW);
    }
    return {stats.Mean(), stats.StandardError()};
}

// Checks that Sample(ctx, u) reports the pdf that PDF(ctx, wi) gives for the same direction.
inline void CheckSampledPDFMatches(const Shape& shape, const ShapeSampleContext& ctx, int n,
                                   Float relTol) {
    RNG rng(7);
    int nChecked = 0;
    for (int i = 0; i < n; ++i) {
        auto ss = shape.Sample(ctx, Point2f(rng.UniformFloat(), rng.UniformFloat()));
        if (!ss) continue;
        Vector3f wi = Normalize(ss->intr.p - ctx.p);
        Float pdf = shape.PDF(ctx, wi);
        if (pdf == 0) continue;  // grazing: the spawned ray missed the boundary
        EXPECT_NEAR(ss->pdf, pdf, relTol * pdf) << "sample " << i;
        ++nChecked;
    }
    EXPECT_GT(nChecked, n * 9 / 10);
}

}  // namespace kiln::test
