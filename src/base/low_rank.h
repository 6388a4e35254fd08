// Low-rank factorisation of a tabulated function of two variables, for tables built at load:
// m[a][b] ~ sum_r u[a][r] v[b][r], the truncated singular value decomposition (u: the leading
// eigenvectors of m m^T, orthonormal; v = m^T u), with the rank chosen as the smallest whose
// largest absolute error over the table is at most `tolerance` (full rank reproduces m to
// rounding).
#pragma once

#include <vector>

namespace kiln {

struct LowRankFactors {
    int rank = 0;
    std::vector<double> u;  // [a][r], rows x rank
    std::vector<double> v;  // [b][r], cols x rank
    double maxError = 0;    // largest |m - u v^T| over the table
};

// m: rows x cols, row-major. rows should be small (the eigen-solve is O(rows^3)).
LowRankFactors FactorLowRank(const std::vector<double>& m, int rows, int cols, double tolerance);

// Eigenvalues (descending) and orthonormal eigenvectors (columns of vectors, n x n row-major)
// of the symmetric n x n matrix a, by cyclic Jacobi rotations.
void SymmetricEigen(std::vector<double> a, int n, std::vector<double>* values,
                    std::vector<double>* vectors);

}  // namespace kiln
