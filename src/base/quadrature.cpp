#include "base/quadrature.h"

#include <cmath>

namespace kiln {

QuadratureRule GaussLegendre(int n, double a, double b) {
    QuadratureRule rule;
    rule.x.resize(size_t(n));
    rule.weight.resize(size_t(n));
    double half = 0.5 * (b - a), mid = 0.5 * (a + b);
    if (n == 8) {
        // The rule every table uses, from Abramowitz & Stegun, Table 25.4 (nodes on [-1, 1])
        constexpr double z[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                 0.9602898564975363};
        constexpr double w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                 0.1012285362903763};
        for (int i = 0; i < 4; ++i) {
            rule.x[size_t(3 - i)] = mid - half * z[i];
            rule.x[size_t(4 + i)] = mid + half * z[i];
            rule.weight[size_t(3 - i)] = rule.weight[size_t(4 + i)] = half * w[i];
        }
        return rule;
    }
    const double pi = 3.14159265358979323846;
    for (int i = 0; i < (n + 1) / 2; ++i) {
        // Newton's method on P_n from the Chebyshev-like initial guess (Abramowitz & Stegun)
        double z = std::cos(pi * (i + 0.75) / (n + 0.5)), dp = 0;
        for (int iter = 0; iter < 100; ++iter) {
            double p0 = 1, p1 = 0;
            for (int k = 1; k <= n; ++k) {
                double p2 = p1;
                p1 = p0;
                p0 = ((2 * k - 1) * z * p1 - (k - 1) * p2) / k;
            }
            dp = n * (z * p0 - p1) / (z * z - 1);
            double dz = p0 / dp;
            z -= dz;
            if (std::abs(dz) < 1e-16) break;
        }
        double w = 2 / ((1 - z * z) * dp * dp);
        // Map [-1, 1] to [a, b]
        rule.x[size_t(i)] = mid - half * z;
        rule.x[size_t(n - 1 - i)] = mid + half * z;
        rule.weight[size_t(i)] = rule.weight[size_t(n - 1 - i)] = half * w;
    }
    return rule;
}

QuadratureRule CompositeGaussLegendre(int panels, int n, double a, double b) {
    QuadratureRule rule;
    double h = (b - a) / panels;
    for (int p = 0; p < panels; ++p) {
        QuadratureRule r = GaussLegendre(n, a + p * h, a + (p + 1) * h);
        rule.x.insert(rule.x.end(), r.x.begin(), r.x.end());
        rule.weight.insert(rule.weight.end(), r.weight.begin(), r.weight.end());
    }
    return rule;
}

QuadratureRule SmoothstepGaussLegendre(int panels, int n, double a, double b) {
    QuadratureRule r = CompositeGaussLegendre(panels, n, 0, 1);
    for (size_t k = 0; k < r.x.size(); ++k) {
        double tau = r.x[k];
        r.x[k] = a + (b - a) * tau * tau * (3 - 2 * tau);
        r.weight[k] *= (b - a) * 6 * tau * (1 - tau);
    }
    return r;
}

}  // namespace kiln
