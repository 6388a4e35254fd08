// Deterministic numerical integration: Gauss-Legendre rules (used to build tables at load,
// never per sample).
#pragma once

#include <vector>

namespace kiln {

// A rule sum_i weight[i] f(x[i]) ~ integral_a^b f(x) dx.
struct QuadratureRule {
    std::vector<double> x, weight;
};

// n-point Gauss-Legendre rule on [a, b]: exact for polynomials of degree 2n - 1. Nodes and
// weights from Newton iteration on the Legendre polynomial in double precision (Golub-Welsch
// accuracy, ~1e-15).
QuadratureRule GaussLegendre(int n, double a = 0, double b = 1);

// Composite rule: `panels` equal sub-intervals of [a, b], an n-point Gauss-Legendre rule on each
// (for integrands with kinks, whose position the panels localise).
QuadratureRule CompositeGaussLegendre(int panels, int n, double a = 0, double b = 1);

// Composite Gauss-Legendre rule in tau on [0, 1] mapped by t = a + (b - a) (3 tau^2 - 2 tau^3)
// (smoothstep substitution): points cluster at both ends, which absorbs square-root behaviour
// and resolves boundary layers there.
QuadratureRule SmoothstepGaussLegendre(int panels, int n, double a, double b);

// Cubic Lagrange interpolation weights of the four nodes x[0..3] at `at`:
// f(at) ~ sum_a w[a] f(x[a]), exact for cubic f.
inline void CubicLagrangeWeights(const double* x, double at, double w[4]) {
    for (int a = 0; a < 4; ++a) {
        w[a] = 1;
        for (int b = 0; b < 4; ++b)
            if (b != a) w[a] *= (at - x[b]) / (x[a] - x[b]);
    }
}

}  // namespace kiln
