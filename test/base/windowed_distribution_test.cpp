// WindowedPiecewiseConstant2D: exact window integrals, and samples inside any window drawn with
// exactly the density PDF reports (chi-square against the exact integral over each bin of a
// grid that does not line up with the function's cells).
#include "base/windowed_distribution.h"

#include <gtest/gtest.h>

#include <vector>

#include "base/rng.h"
#include "base/statistics.h"

using namespace kiln;

namespace {

// A 5 x 4 function with a zero cell, a zero column segment and one bright cell.
WindowedPiecewiseConstant2D TestFunction(std::vector<Float>* values = nullptr) {
    std::vector<Float> f(20);
    for (int i = 0; i < 20; ++i) f[size_t(i)] = Float(1 + (i * 7) % 5);
    f[3] = 0, f[8] = 0, f[13] = 12;
    if (values) *values = f;
    return WindowedPiecewiseConstant2D(f, 5, 4);
}

}  // namespace

TEST(WindowedPiecewiseConstant2D, IntegralsAreExact) {
    std::vector<Float> f;
    WindowedPiecewiseConstant2D d = TestFunction(&f);
    double total = 0;
    for (Float v : f) total += v / 20.0;
    EXPECT_NEAR(d.Integral(Bounds2f{Point2f(0, 0), Point2f(1, 1)}), total, 1e-12);
    // A window cutting cells: 0.3 of column 1 (x in [0.2, 0.4)) and half of row 2
    Bounds2f b{Point2f(0.34f, 0.5f), Point2f(0.4f, 0.625f)};
    double expected = f[2 * 5 + 1] * (0.4 - 0.34f) * (0.625 - 0.5);
    EXPECT_NEAR(d.Integral(b), expected, 1e-7);
    EXPECT_EQ(d.Eval(Point2f(0.7f, 0.1f)), f[3]);
}

TEST(WindowedPiecewiseConstant2D, SamplesFollowThePDFInAnyWindow) {
    WindowedPiecewiseConstant2D d = TestFunction();
    const Bounds2f windows[] = {{Point2f(0, 0), Point2f(1, 1)},
                                {Point2f(0.13f, 0.21f), Point2f(0.77f, 0.66f)},
                                {Point2f(0.61f, 0.02f), Point2f(0.69f, 0.9f)}};
    constexpr int kBins = 16, kSamples = 200000;
    for (const Bounds2f& b : windows) {
        std::vector<double> observed(kBins * kBins, 0), expected(kBins * kBins, 0);
        RNG rng(3);
        Vector2f size = b.pMax - b.pMin;
        for (int i = 0; i < kSamples; ++i) {
            Float pdf = 0;
            auto p = d.Sample(Point2f(rng.UniformFloat(), rng.UniformFloat()), b, &pdf);
            ASSERT_TRUE(p);
            ASSERT_GE(p->x, b.pMin.x);
            ASSERT_LE(p->x, b.pMax.x);
            ASSERT_GE(p->y, b.pMin.y);
            ASSERT_LE(p->y, b.pMax.y);
            EXPECT_NEAR(pdf, d.PDF(*p, b), 1e-4f * pdf);
            int bx = std::min(kBins - 1, int((p->x - b.pMin.x) / size.x * kBins));
            int by = std::min(kBins - 1, int((p->y - b.pMin.y) / size.y * kBins));
            observed[size_t(by) * kBins + bx] += 1;
        }
        // Expected counts from the exact integrals over each bin
        double total = d.Integral(b);
        for (int by = 0; by < kBins; ++by)
            for (int bx = 0; bx < kBins; ++bx) {
                Bounds2f bin{
                    Point2f(b.pMin.x + size.x * bx / kBins, b.pMin.y + size.y * by / kBins),
                    Point2f(b.pMin.x + size.x * (bx + 1) / kBins,
                            b.pMin.y + size.y * (by + 1) / kBins)};
                expected[size_t(by) * kBins + bx] = d.Integral(bin) / total * kSamples;
            }
        ChiSquareResult r = ChiSquareTest(observed, expected, 0.01, 3);
        EXPECT_TRUE(r.passed) << r.message;
    }
    // A window where the function is zero: no sample
    Float pdf;
    EXPECT_FALSE(
        d.Sample(Point2f(0.5f, 0.5f), Bounds2f{Point2f(0.61f, 0.01f), Point2f(0.79f, 0.2f)}, &pdf));
}
