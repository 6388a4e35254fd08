// PiecewiseLinear2D: Draw and Invert are inverse maps, their pdf is the density Evaluate gives,
// densities integrate to 1 at every parameter point, and values interpolate multilinearly.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "base/piecewise_linear_2d.h"
#include "base/rng.h"

using namespace kiln;

namespace {

// 5 x 4 nodes, parameters of 3 and 2 nodes: 6 slices of random positive data
PiecewiseLinear2D Random(PiecewiseLinear2D::Kind kind, std::vector<float>* out = nullptr) {
    RNG rng(7);
    std::vector<float> data(6 * 20);
    for (float& v : data) v = 0.1f + rng.UniformFloat();
    if (out) *out = data;
    return PiecewiseLinear2D(data, 5, 4, {{0.f, 1.f, 3.f}, {-1.f, 2.f}}, kind);
}

}  // namespace

TEST(PiecewiseLinear2D, DrawAndInvertAreInverse) {
    PiecewiseLinear2D d = Random(PiecewiseLinear2D::Kind::Distribution);
    RNG rng(3);
    for (std::array<Float, 2> params :
         {std::array<Float, 2>{0.5f, 0.3f}, {3.f, -1.f}, {-5.f, 9.f}, {2.2f, 1.9f}})
        for (int i = 0; i < 200; ++i) {
            Point2f u(rng.UniformFloat(), rng.UniformFloat());
            PiecewiseLinear2D::Sample s = d.Draw(u, params);
            EXPECT_NEAR(s.pdf, d.Evaluate(s.p, params), 1e-4f * s.pdf);
            PiecewiseLinear2D::Sample inv = d.Invert(s.p, params);
            EXPECT_NEAR(inv.p.x, u.x, 2e-4f);
            EXPECT_NEAR(inv.p.y, u.y, 2e-4f);
            EXPECT_NEAR(inv.pdf, s.pdf, 1e-4f * s.pdf);
        }
}

TEST(PiecewiseLinear2D, DensityIntegratesToOne) {
    PiecewiseLinear2D d = Random(PiecewiseLinear2D::Kind::Distribution);
    for (std::array<Float, 2> params : {std::array<Float, 2>{0.5f, 0.3f}, {2.9f, 1.5f}}) {
        double sum = 0;
        constexpr int n = 400;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                sum += d.Evaluate(Point2f((i + 0.5f) / n, (j + 0.5f) / n), params);
        EXPECT_NEAR(sum / (n * n), 1, 1e-4);
    }
    // A slice without mass is uniform
    std::vector<float> zero(2 * 2, 0.f);
    PiecewiseLinear2D z(zero, 2, 2, {}, PiecewiseLinear2D::Kind::Distribution);
    EXPECT_FLOAT_EQ(z.Evaluate(Point2f(0.3f, 0.8f), {}), 1);
    EXPECT_NEAR(z.Draw(Point2f(0.3f, 0.8f), {}).p.x, 0.3f, 1e-6f);
}

TEST(PiecewiseLinear2D, ValuesInterpolateMultilinearly) {
    std::vector<float> data;
    PiecewiseLinear2D v = Random(PiecewiseLinear2D::Kind::Values, &data);
    // At a node of the grid and of both parameters: the value itself
    auto at = [&](int slice, int x, int y) { return data[slice * 20 + y * 5 + x]; };
    EXPECT_FLOAT_EQ(v.Evaluate(Point2f(0.5f, 1.f / 3), std::array<Float, 2>{1.f, 2.f}),
                    at(3, 2, 1));
    // Halfway between grid nodes and between parameter nodes 1 and 3 of the first parameter
    Float expected = 0;
    for (int s : {2, 4})
        expected += 0.5f * 0.25f * (at(s, 2, 1) + at(s, 3, 1) + at(s, 2, 2) + at(s, 3, 2));
    EXPECT_NEAR(v.Evaluate(Point2f(0.625f, 0.5f), std::array<Float, 2>{2.f, -1.f}), expected,
                1e-6f);
    // Outside a parameter's range: its end slice; NaN parameters give a finite value
    EXPECT_FLOAT_EQ(v.Evaluate(Point2f(0, 0), std::array<Float, 2>{10.f, 5.f}), at(5, 0, 0));
    EXPECT_TRUE(std::isfinite(v.Evaluate(Point2f(0.2f, 0.2f), std::array<Float, 2>{NAN, 0.f})));
}
