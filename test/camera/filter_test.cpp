// Pixel filters: integrals against numerical quadrature, chi-square tests of Sample, weights,
// and creation from parameters.
#include "core/film/filter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "../textures/param_helpers.h"
#include "base/rng.h"
#include "base/statistics.h"
#include "core/parser/parameter_dictionary.h"

namespace kiln {
namespace {

struct FilterCase {
    std::string name;
    std::function<Filter(ObjectArena&)> make;
    bool tabulated;
};

std::vector<FilterCase> Cases() {
    return {
        {"box", [](ObjectArena& a) { return Filter(a.New<BoxFilter>()); }, false},
        {"box_wide", [](ObjectArena& a) { return Filter(a.New<BoxFilter>(Vector2f(1, 0.75f))); },
         false},
        {"gaussian",
         [](ObjectArena& a) { return Filter(a.New<GaussianFilter>(Vector2f(1.5f, 1.5f))); }, true},
        {"mitchell", [](ObjectArena& a) { return Filter(a.New<MitchellFilter>(Vector2f(2, 2))); },
         true},
        {"sinc", [](ObjectArena& a) { return Filter(a.New<LanczosSincFilter>(Vector2f(4, 4))); },
         true},
        {"triangle", [](ObjectArena& a) { return Filter(a.New<TriangleFilter>(Vector2f(2, 2))); },
         false},
        {"triangle_aniso",
         [](ObjectArena& a) { return Filter(a.New<TriangleFilter>(Vector2f(1, 2.5f))); }, false},
    };
}

// Midpoint-rule integral of f over the filter's support.
double NumericIntegral(const Filter& f, bool absolute = false) {
    Vector2f r = f.Radius();
    const int n = 1000;
    double sum = 0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            Point2f p(-r.x + (x + 0.5f) * 2 * r.x / n, -r.y + (y + 0.5f) * 2 * r.y / n);
            double v = f.Evaluate(p);
            sum += absolute ? std::abs(v) : v;
        }
    return sum * (4.0 * r.x * r.y) / (double(n) * n);
}

TEST(Filter, IntegralMatchesQuadrature) {
    for (const FilterCase& c : Cases()) {
        ObjectArena arena;
        Filter f = c.make(arena);
        double numeric = NumericIntegral(f);
        EXPECT_NEAR(f.Integral(), numeric, 2e-3 * std::abs(numeric) + 1e-5) << c.name;
    }
}

TEST(Filter, EvaluateIsZeroOutsideSupport) {
    for (const FilterCase& c : Cases()) {
        ObjectArena arena;
        Filter f = c.make(arena);
        Vector2f r = f.Radius();
        EXPECT_EQ(f.Evaluate(Point2f(r.x * 1.01f, 0)), 0) << c.name;
        EXPECT_EQ(f.Evaluate(Point2f(0, -r.y * 1.01f)), 0) << c.name;
        EXPECT_GT(f.Evaluate(Point2f(0, 0)), 0) << c.name;
    }
}

// The density that Sample claims, integrated over the bins of a grid over the support. For
// tabulated filters, bins are unions of the FilterSampler's 32-per-pixel cells, where the
// density is |f(cell centre)| / sum; otherwise the density is |f| / integral (fine quadrature).
std::vector<double> ExpectedBinProbabilities(const Filter& f, bool tabulated, int nbx, int nby) {
    Vector2f r = f.Radius();
    int sub = 16;
    int ncx = nbx * sub, ncy = nby * sub;
    if (tabulated) {
        ncx = int(32 * r.x), ncy = int(32 * r.y);
        sub = ncx / nbx;
    }
    std::vector<double> p(size_t(nbx) * nby, 0.0);
    double total = 0;
    for (int y = 0; y < ncy; ++y)
        for (int x = 0; x < ncx; ++x) {
            Point2f c(-r.x + (x + 0.5f) * 2 * r.x / ncx, -r.y + (y + 0.5f) * 2 * r.y / ncy);
            double v = std::abs(f.Evaluate(c));
            p[size_t(y / (ncy / nby)) * nbx + x / (ncx / nbx)] += v;
            total += v;
        }
    for (double& v : p) v /= total;
    return p;
}

TEST(Filter, SampleChiSquare) {
    std::vector<FilterCase> cases = Cases();
    for (const FilterCase& c : cases) {
        ObjectArena arena;
        Filter f = c.make(arena);
        Vector2f r = f.Radius();
        // Tabulated: bins of 4x4 table cells. Analytic: 16 x 16 bins.
        int nbx = c.tabulated ? int(32 * r.x) / 4 : 16;
        int nby = c.tabulated ? int(32 * r.y) / 4 : 16;
        std::vector<double> expected = ExpectedBinProbabilities(f, c.tabulated, nbx, nby);
        const int n = 200000;
        std::vector<double> observed(expected.size(), 0.0);
        RNG rng(7);
        for (int i = 0; i < n; ++i) {
            FilterSample fs = f.Sample(Point2f(rng.UniformFloat(), rng.UniformFloat()));
            ASSERT_LE(std::abs(fs.p.x), r.x) << c.name;
            ASSERT_LE(std::abs(fs.p.y), r.y) << c.name;
            int bx = Clamp(int((fs.p.x + r.x) / (2 * r.x) * nbx), 0, nbx - 1);
            int by = Clamp(int((fs.p.y + r.y) / (2 * r.y) * nby), 0, nby - 1);
            observed[size_t(by) * nbx + bx] += 1;
        }
        for (double& e : expected) e *= n;
        ChiSquareResult res = ChiSquareTest(observed, expected, 0.01, int(cases.size()));
        EXPECT_TRUE(res.passed) << c.name << ": " << res.message << " p=" << res.pValue;
    }
}

// weight = f / pdf: one magnitude for all samples, the sign of f; its mean estimates the
// integral of f (tabulated filters) or is 1 (box and triangle, sampled exactly as pbrt-v4).
TEST(Filter, SampleWeights) {
    for (const FilterCase& c : Cases()) {
        ObjectArena arena;
        Filter f = c.make(arena);
        RNG rng(11);
        RunningStats stats;
        Float posWeight = 0;
        for (int i = 0; i < 100000; ++i) {
            FilterSample fs = f.Sample(Point2f(rng.UniformFloat(), rng.UniformFloat()));
            stats.Add(fs.weight);
            Float fv = f.Evaluate(fs.p);
            if (!c.tabulated) {
                ASSERT_EQ(fs.weight, 1) << c.name;
                continue;
            }
            // Away from sign changes the weight has f's sign.
            if (std::abs(fv) > 0.1f * f.Evaluate(Point2f(0, 0))) {
                ASSERT_EQ(fv > 0, fs.weight > 0) << c.name << " at " << fs.p.x << "," << fs.p.y;
            }
            if (fs.weight > 0) {
                if (posWeight == 0) posWeight = fs.weight;
                ASSERT_NEAR(fs.weight, posWeight, 1e-3f * posWeight) << c.name;
            } else {
                ASSERT_NEAR(-fs.weight, posWeight == 0 ? -fs.weight : posWeight, 1e-3f * posWeight)
                    << c.name;
            }
        }
        if (c.tabulated) {
            // The tabulated integral differs from the exact one by O(cell^2).
            double tol = 5 * stats.StandardError() + 2e-3 * std::abs(f.Integral());
            EXPECT_NEAR(stats.Mean(), f.Integral(), tol) << c.name;
            // |weight| = integral of |f|.
            EXPECT_NEAR(posWeight, NumericIntegral(f, true), 2e-3 * posWeight) << c.name;
        }
    }
}

TEST(Filter, TriangleSampleIsSymmetricAndCoversSupport) {
    TriangleFilter t(Vector2f(2, 2));
    EXPECT_FLOAT_EQ(t.Sample(Point2f(0.5f, 0.5f)).p.x, 0);
    EXPECT_NEAR(t.Sample(Point2f(0, 0)).p.x, -2, 1e-6);
    EXPECT_NEAR(t.Sample(Point2f(OneMinusEpsilon, 0)).p.x, 2, 1e-3);
}

TEST(Filter, CreateDefaults) {
    ObjectArena arena;
    Diagnostics diag(nullptr);
    ParameterDictionary empty;
    FileLoc loc;
    auto radius = [&](const char* name) {
        return Filter::Create(name, empty, loc, arena, diag).Radius();
    };
    EXPECT_EQ(radius("box").x, 0.5f);
    EXPECT_EQ(radius("gaussian").x, 1.5f);
    EXPECT_EQ(radius("mitchell").y, 2.f);
    EXPECT_EQ(radius("sinc").x, 4.f);
    EXPECT_EQ(radius("triangle").x, 2.f);
    Filter g = Filter::Create("gaussian", empty, loc, arena, diag);
    EXPECT_TRUE(g.Is<GaussianFilter>());
    EXPECT_THROW(Filter::Create("lanczos", empty, loc, arena, diag), SceneError);
    EXPECT_EQ(diag.WarningCount(), 0);
}

TEST(Filter, CreateWithParameters) {
    ObjectArena arena;
    Diagnostics diag(nullptr);
    ParameterDictionary params(
        {test::Floats("float", "xradius", {3}), test::Floats("float", "yradius", {1}),
         test::Floats("float", "B", {0}), test::Floats("float", "C", {0.5f})},
        nullptr);
    Filter f = Filter::Create("mitchell", params, FileLoc(), arena, diag);
    EXPECT_EQ(f.Radius().x, 3.f);
    EXPECT_EQ(f.Radius().y, 1.f);
    EXPECT_NEAR(f.Integral(), NumericIntegral(f), 2e-3);
    ParameterDictionary bad({test::Floats("float", "xradius", {-1})}, nullptr);
    EXPECT_THROW(Filter::Create("box", bad, FileLoc(), arena, diag), SceneError);
}

}  // namespace
}  // namespace kiln
