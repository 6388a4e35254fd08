// The eigen-solver and low-rank factorisation behind kiln's emissivity tables.
#include "base/low_rank.h"

#include <gtest/gtest.h>

#include <cmath>

#include "base/rng.h"

using namespace kiln;

TEST(LowRank, SymmetricEigenDecomposes) {
    const int n = 7;
    RNG rng(3);
    std::vector<double> a(n * n);
    for (int i = 0; i < n; ++i)
        for (int j = i; j < n; ++j) a[i * n + j] = a[j * n + i] = rng.UniformFloat() - 0.5;
    std::vector<double> values, vectors;
    SymmetricEigen(a, n, &values, &vectors);
    for (int c = 0; c < n; ++c) {
        if (c > 0) {
            EXPECT_GE(values[c - 1], values[c]);
        }
        for (int i = 0; i < n; ++i) {
            double av = 0;
            for (int k = 0; k < n; ++k) av += a[i * n + k] * vectors[k * n + c];
            EXPECT_NEAR(av, values[c] * vectors[i * n + c], 1e-12);
        }
        for (int d = 0; d < n; ++d) {
            double dot = 0;
            for (int k = 0; k < n; ++k) dot += vectors[k * n + c] * vectors[k * n + d];
            EXPECT_NEAR(dot, c == d ? 1 : 0, 1e-12);
        }
    }
}

TEST(LowRank, FindsTheRankWithinTolerance) {
    // A smooth rank-3 function of two variables, plus perturbations below and above tolerance
    const int rows = 20, cols = 300;
    auto table = [&](double noise) {
        std::vector<double> m(rows * cols);
        RNG rng(5);
        for (int a = 0; a < rows; ++a)
            for (int b = 0; b < cols; ++b) {
                double x = a / double(rows - 1), y = b / double(cols - 1);
                m[a * cols + b] = 1 + x * std::sin(3 * y) + x * x * x * std::exp(-y) +
                                  noise * (rng.UniformFloat() - 0.5);
            }
        return m;
    };
    std::vector<double> exact = table(0);
    LowRankFactors f = FactorLowRank(exact, rows, cols, 1e-9);
    EXPECT_EQ(f.rank, 3);
    EXPECT_LT(f.maxError, 1e-9);
    // Reconstruction matches the reported error
    double worst = 0;
    for (int a = 0; a < rows; ++a)
        for (int b = 0; b < cols; ++b) {
            double s = 0;
            for (int r = 0; r < f.rank; ++r) s += f.u[a * f.rank + r] * f.v[b * f.rank + r];
            worst = std::max(worst, std::abs(s - exact[a * cols + b]));
        }
    EXPECT_NEAR(worst, f.maxError, 1e-12);
    // Noise of 1e-7 is below a 1e-5 tolerance: still rank 3; a 1e-12 tolerance needs more
    EXPECT_EQ(FactorLowRank(table(1e-7), rows, cols, 1e-5).rank, 3);
    EXPECT_GT(FactorLowRank(table(1e-7), rows, cols, 1e-12).rank, 3);
}
