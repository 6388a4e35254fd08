// Quadrics under scaling transforms (quadrics.h): areas and sampling densities are render
// space's. pbrt-v4 takes both from object space, so a light on a scaled sphere, disk or
// cylinder was sampled with the wrong density.
#include <gtest/gtest.h>

#include "base/rng.h"
#include "base/statistics.h"
#include "test_util.h"

namespace kiln {
namespace {

// A transform and its inverse
struct Placement {
    Transform render, object;
    explicit Placement(const Transform& t) : render(t), object(Inverse(t)) {}
};

// A similarity, a non-uniform scale and a non-uniform scale after a rotation (so its axes are
// not the object's)
std::vector<Transform> Transforms() {
    return {Translate(Vector3f(0.3f, -0.2f, 0.5f)) * Scale(2, 2, 2) * Rotate(30, Vector3f(1, 1, 0)),
            Scale(1.5f, 1, 0.8f), Rotate(40, Vector3f(0, 1, 1)) * Scale(1, 0.5f, 2)};
}

// The render-space area by Monte Carlo over the shape's own area sampling: the mean of
// 1 / pdf (pdf per render-space area) is the area whatever the density, if pdf is the density
// with which the points come.
std::pair<double, double> AreaFromSampling(const Shape& shape, int n) {
    RunningStats s;
    RNG rng(17);
    for (int i = 0; i < n; ++i) {
        auto ss = shape.Sample(Point2f(rng.UniformFloat(), rng.UniformFloat()));
        s.Add(ss && ss->pdf > 0 ? 1 / double(ss->pdf) : 0);
        if (ss) {
            EXPECT_NEAR(ss->pdf, shape.PDF(ss->intr), 1e-3f * ss->pdf);
        }
    }
    return {s.Mean(), s.StandardError()};
}

// The area of the render-space image of a unit-parameter surface p(u, v) by a fine midpoint
// rule on |dp/du x dp/dv| (finite differences): independent of the shapes' own area code.
template <typename Surface>
double ParametricArea(Surface p, int n = 400) {
    double sum = 0;
    const double h = 1.0 / n, e = 1e-4;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            double u = (i + 0.5) * h, v = (j + 0.5) * h;
            Vector3f du = (p(u + e, v) - p(u - e, v)) / Float(2 * e);
            Vector3f dv = (p(u, v + e) - p(u, v - e)) / Float(2 * e);
            sum += Length(Cross(du, dv)) * h * h;
        }
    return sum;
}

TEST(TransformedQuadrics, SphereAreaAndDensities) {
    for (const Transform& t : Transforms()) {
        Placement xf(t);
        Sphere s(&xf.render, &xf.object, false, 1.3f, -1.3f, 1.3f, 360);
        Shape shape(&s);
        double exact = ParametricArea([&](double u, double v) {
            double z = 1.3 * (2 * u - 1), phi = 2 * Pi * v, r = std::sqrt(1.69 - z * z);
            return Vector3f(xf.render(Point3f(r * std::cos(phi), r * std::sin(phi), z)));
        });
        EXPECT_NEAR(s.Area(), exact, 2e-4 * exact);
        auto [mcArea, se] = AreaFromSampling(shape, 200000);
        EXPECT_NEAR(mcArea, exact, 5 * se + 1e-4 * exact);
        // From inside, every direction meets the surface once: the pdf integrates to 1
        Point3f centre = xf.render(Point3f(0.1f, -0.2f, 0.3f));
        ShapeSampleContext inside(centre, Normal3f(0, 0, 0), Normal3f(0, 0, 0), 0);
        test::CheckSampledPDFMatches(shape, inside, 2000, 2e-3f);
        auto [mean, seIn] = test::IntegrateSolidAnglePDF(shape, inside, 200000, 2);
        EXPECT_NEAR(mean, 1, 5 * seIn + 2e-3);
        // From outside, a similarity's sphere by its cone
        if (t.SimilarityScale() > 0) {
            ShapeSampleContext outside(xf.render(Point3f(0, 0, 0)) + Vector3f(0, 0, 6),
                                       Normal3f(0, 0, 0), Normal3f(0, 0, 0), 0);
            test::CheckSampledPDFMatches(shape, outside, 2000, 1e-3f);
            auto [mo, seOut] = test::IntegrateSolidAnglePDF(shape, outside, 200000, 3);
            EXPECT_NEAR(mo, 1, 5 * seOut + 2e-3);
        }
    }
}

TEST(TransformedQuadrics, CylinderAndDiskAreasAndDensities) {
    for (const Transform& t : Transforms()) {
        Placement xf(t);
        Cylinder c(&xf.render, &xf.object, false, 0.7f, -1, 1.5f, 360);
        Shape cyl(&c);
        double exact = ParametricArea([&](double u, double v) {
            double z = -1 + 2.5 * u, phi = 2 * Pi * v;
            return Vector3f(xf.render(Point3f(0.7 * std::cos(phi), 0.7 * std::sin(phi), z)));
        });
        EXPECT_NEAR(c.Area(), exact, 2e-4 * exact);
        auto [mcArea, se] = AreaFromSampling(cyl, 200000);
        EXPECT_NEAR(mcArea, exact, 5 * se + 1e-4 * exact);
        // From a point on the axis every direction meets the open tube at most once
        ShapeSampleContext axis(xf.render(Point3f(0, 0, 0.2f)), Normal3f(0, 0, 0),
                                Normal3f(0, 0, 0), 0);
        test::CheckSampledPDFMatches(cyl, axis, 2000, 2e-3f);
        auto [mean, seAxis] = test::IntegrateSolidAnglePDF(cyl, axis, 200000, 4);
        // The tube's ends are open: the pdf integrates to 1 over the directions that meet it
        EXPECT_NEAR(mean, 1, 5 * seAxis + 2e-3);

        Disk d(&xf.render, &xf.object, false, 0.4f, 1.2f, 0.3f, 360);
        Shape disk(&d);
        double exactDisk = ParametricArea([&](double u, double v) {
            double r = 0.3 + 0.9 * u, phi = 2 * Pi * v;
            return Vector3f(xf.render(Point3f(r * std::cos(phi), r * std::sin(phi), 0.4)));
        });
        EXPECT_NEAR(d.Area(), exactDisk, 2e-4 * exactDisk);
        auto [mcDisk, seDisk] = AreaFromSampling(disk, 100000);
        EXPECT_NEAR(mcDisk, exactDisk, 5 * seDisk + 1e-4 * exactDisk);
        ShapeSampleContext above(xf.render(Point3f(0.2f, 0.1f, 2)), Normal3f(0, 0, 0),
                                 Normal3f(0, 0, 0), 0);
        test::CheckSampledPDFMatches(disk, above, 2000, 2e-3f);
        auto [md, seAbove] = test::IntegrateSolidAnglePDF(disk, above, 200000, 5);
        EXPECT_NEAR(md, 1, 5 * seAbove + 2e-3);
    }
}

// A transform that swaps handedness keeps the surface's outside outside: hit and sampled
// normals point away from the sphere's centre and the cylinder's axis, and along the mirrored
// object-space normal for the disk (pbrt-v4 turns mirrored quadrics inside out).
TEST(TransformedQuadrics, MirrorsKeepNormalsOutward) {
    for (const Transform& t : {Scale(-1, 1, 1), Rotate(20, Vector3f(0, 0, 1)) * Scale(1, -2, 1)}) {
        Placement xf(t);
        Sphere s(&xf.render, &xf.object, false, 1, -1, 1, 360);
        Cylinder c(&xf.render, &xf.object, false, 1, -1, 1, 360);
        Disk d(&xf.render, &xf.object, false, 0, 1, 0, 360);
        RNG rng(23);
        for (int i = 0; i < 200; ++i) {
            Point2f u(rng.UniformFloat(), rng.UniformFloat());
            // Rays from far outside towards a sampled point: the hit's normal faces the ray
            // for the sphere and the cylinder's outside
            for (const Shape& shape : {Shape(&s), Shape(&c), Shape(&d)}) {
                auto ss = shape.Sample(u);
                ASSERT_TRUE(ss);
                Point3f pObj = xf.object(ss->intr.p);
                Normal3f outward = shape.Is<Disk>()     ? Normal3f(0, 0, 1)
                                   : shape.Is<Sphere>() ? Normal3f(pObj.x, pObj.y, pObj.z)
                                                        : Normal3f(pObj.x, pObj.y, 0);
                Vector3f expected = Normalize(Vector3f(xf.render(outward)));
                EXPECT_GT(Dot(Vector3f(ss->intr.n), expected), 0.999f);
                Ray r(ss->intr.p + expected * 3.f, -expected);
                auto hit = shape.Intersect(r);
                ASSERT_TRUE(hit);
                EXPECT_GT(Dot(Vector3f(hit->intr.n), expected), 0.999f);
            }
        }
    }
}

TEST(TransformedQuadrics, SimilarityScale) {
    EXPECT_FLOAT_EQ(Transform().SimilarityScale(), 1);
    EXPECT_NEAR((Rotate(33, Vector3f(1, 2, 3)) * Scale(2.5f, 2.5f, 2.5f)).SimilarityScale(), 2.5f,
                1e-5f);
    EXPECT_NEAR(Scale(-3, 3, 3).SimilarityScale(), 3, 1e-6f);  // a reflection
    EXPECT_EQ(Scale(1, 1, 1.01f).SimilarityScale(), 0);
    EXPECT_EQ(Scale(0, 0, 0).SimilarityScale(), 0);
}

}  // namespace
}  // namespace kiln
