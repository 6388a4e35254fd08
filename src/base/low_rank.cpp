#include "base/low_rank.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace kiln {

void SymmetricEigen(std::vector<double> a, int n, std::vector<double>* values,
                    std::vector<double>* vectors) {
    auto A = [&](int i, int j) -> double& { return a[size_t(i) * n + j]; };
    std::vector<double> q(size_t(n) * n, 0);
    for (int i = 0; i < n; ++i) q[size_t(i) * n + i] = 1;
    double scale = 0;
    for (double x : a) scale = std::max(scale, std::abs(x));
    for (int sweep = 0; sweep < 100; ++sweep) {
        double off = 0;
        for (int i = 0; i < n; ++i)
            for (int j = i + 1; j < n; ++j) off = std::max(off, std::abs(A(i, j)));
        if (off <= 1e-15 * scale) break;
        for (int p = 0; p < n; ++p)
            for (int r = p + 1; r < n; ++r) {
                if (std::abs(A(p, r)) <= 1e-300) continue;
                // The rotation that zeroes A(p, r)
                double theta = (A(r, r) - A(p, p)) / (2 * A(p, r));
                double t = (theta >= 0 ? 1 : -1) / (std::abs(theta) + std::sqrt(theta * theta + 1));
                double c = 1 / std::sqrt(t * t + 1), s = t * c;
                for (int k = 0; k < n; ++k) {
                    double akp = A(k, p), akr = A(k, r);
                    A(k, p) = c * akp - s * akr;
                    A(k, r) = s * akp + c * akr;
                }
                for (int k = 0; k < n; ++k) {
                    double apk = A(p, k), ark = A(r, k);
                    A(p, k) = c * apk - s * ark;
                    A(r, k) = s * apk + c * ark;
                }
                for (int k = 0; k < n; ++k) {
                    double qkp = q[size_t(k) * n + p], qkr = q[size_t(k) * n + r];
                    q[size_t(k) * n + p] = c * qkp - s * qkr;
                    q[size_t(k) * n + r] = s * qkp + c * qkr;
                }
            }
    }
    std::vector<int> order(static_cast<size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int x, int y) { return A(x, x) > A(y, y); });
    values->resize(size_t(n));
    vectors->resize(size_t(n) * n);
    for (int c = 0; c < n; ++c) {
        (*values)[size_t(c)] = A(order[size_t(c)], order[size_t(c)]);
        for (int k = 0; k < n; ++k)
            (*vectors)[size_t(k) * n + c] = q[size_t(k) * n + order[size_t(c)]];
    }
}

LowRankFactors FactorLowRank(const std::vector<double>& m, int rows, int cols, double tolerance) {
    // Gram matrix m m^T and its eigenvectors
    std::vector<double> gram(size_t(rows) * rows, 0);
    for (int i = 0; i < rows; ++i)
        for (int j = i; j < rows; ++j) {
            double s = 0;
            for (int b = 0; b < cols; ++b) s += m[size_t(i) * cols + b] * m[size_t(j) * cols + b];
            gram[size_t(i) * rows + j] = gram[size_t(j) * rows + i] = s;
        }
    std::vector<double> values, vectors;
    SymmetricEigen(gram, rows, &values, &vectors);
    // Projections of the columns on the eigenvectors: v[b][r] = sum_a u[a][r] m[a][b]
    std::vector<double> proj(size_t(cols) * rows, 0);
    for (int b = 0; b < cols; ++b)
        for (int r = 0; r < rows; ++r) {
            double s = 0;
            for (int a = 0; a < rows; ++a)
                s += vectors[size_t(a) * rows + r] * m[size_t(a) * cols + b];
            proj[size_t(b) * rows + r] = s;
        }
    // The smallest rank within tolerance: residual after each added component
    std::vector<double> residual = m;
    LowRankFactors f;
    for (int rank = 1; rank <= rows; ++rank) {
        int r = rank - 1;
        double worst = 0;
        for (int a = 0; a < rows; ++a)
            for (int b = 0; b < cols; ++b) {
                double& e = residual[size_t(a) * cols + b];
                e -= vectors[size_t(a) * rows + r] * proj[size_t(b) * rows + r];
                worst = std::max(worst, std::abs(e));
            }
        f.rank = rank;
        f.maxError = worst;
        if (worst <= tolerance) break;
    }
    f.u.resize(size_t(rows) * f.rank);
    f.v.resize(size_t(cols) * f.rank);
    for (int a = 0; a < rows; ++a)
        for (int r = 0; r < f.rank; ++r)
            f.u[size_t(a) * f.rank + r] = vectors[size_t(a) * rows + r];
    for (int b = 0; b < cols; ++b)
        for (int r = 0; r < f.rank; ++r) f.v[size_t(b) * f.rank + r] = proj[size_t(b) * rows + r];
    return f;
}

}  // namespace kiln
