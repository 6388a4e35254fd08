#include "base/catmull_rom.h"

#include <cmath>
#include <utility>

namespace kiln {

namespace {

// The root of f in [t0, t1] where f(t0) and f(t1) differ in sign, by Newton steps that fall
// back to bisection when they leave the bracket. f returns (value, derivative).
template <typename F>
Float NewtonBisection(Float t0, Float t1, F f, Float xEps = 1e-6f, Float fEps = 1e-6f) {
    Float f0 = f(t0).first, f1 = f(t1).first;
    if (std::abs(f0) < fEps) return t0;
    if (std::abs(f1) < fEps) return t1;
    bool startIsNegative = f0 < 0;
    Float t = t0 + (t1 - t0) * -f0 / (f1 - f0);
    for (int iteration = 0; iteration < 100; ++iteration) {
        if (!(t0 < t && t < t1)) t = (t0 + t1) / 2;
        auto [ft, dft] = f(t);
        if (std::abs(ft) < fEps) return t;
        // Keep the root bracketed
        if (startIsNegative == (ft < 0))
            t0 = t;
        else
            t1 = t;
        if (t1 - t0 < xEps) return t;
        t -= ft / dft;
    }
    return t;
}

// Derivatives (scaled by the width of interval i) of the spline at nodes i and i + 1
template <typename Value>
std::pair<Float, Float> Derivatives(std::span<const Float> nodes, int i, Value f) {
    const int n = int(nodes.size());
    Float x0 = nodes[size_t(i)], x1 = nodes[size_t(i) + 1], width = x1 - x0;
    Float f0 = f(i), f1 = f(i + 1);
    Float d0 = i > 0 ? width * (f1 - f(i - 1)) / (x1 - nodes[size_t(i) - 1]) : f1 - f0;
    Float d1 = i + 2 < n ? width * (f(i + 2) - f0) / (nodes[size_t(i) + 2] - x0) : f1 - f0;
    return {d0, d1};
}

// The spline's integral over [0, t] of its interval, in units of the width, and its value
Float SegmentIntegral(Float t, Float f0, Float f1, Float d0, Float d1) {
    return EvaluatePolynomial(t, Float(0), f0, 0.5f * d0, (1.f / 3.f) * (-2 * d0 - d1) + f1 - f0,
                              0.25f * (d0 + d1) + 0.5f * (f0 - f1));
}
Float SegmentValue(Float t, Float f0, Float f1, Float d0, Float d1) {
    return EvaluatePolynomial(t, f0, d0, -2 * d0 - d1 + 3 * (f1 - f0), d0 + d1 + 2 * (f0 - f1));
}

}  // namespace

bool CatmullRomWeights(std::span<const Float> nodes, Float x, int* offset, Float weights[4]) {
    if (!(x >= nodes.front() && x <= nodes.back())) return false;
    const size_t idx = FindInterval(nodes.size(), [&](size_t i) { return nodes[i] <= x; });
    *offset = int(idx) - 1;
    Float x0 = nodes[idx], x1 = nodes[idx + 1];
    Float t = (x - x0) / (x1 - x0), t2 = t * t, t3 = t2 * t;
    // Hermite basis: f0 and f1, then the derivative terms spread over the neighbours
    weights[1] = 2 * t3 - 3 * t2 + 1;
    weights[2] = -2 * t3 + 3 * t2;
    Float h0 = t3 - 2 * t2 + t, h1 = t3 - t2;
    if (idx > 0) {
        Float w0 = h0 * (x1 - x0) / (x1 - nodes[idx - 1]);
        weights[0] = -w0;
        weights[2] += w0;
    } else {
        weights[0] = 0;
        weights[1] -= h0;
        weights[2] += h0;
    }
    if (idx + 2 < nodes.size()) {
        Float w3 = h1 * (x1 - x0) / (nodes[idx + 2] - x0);
        weights[1] -= w3;
        weights[3] = w3;
    } else {
        weights[1] -= h1;
        weights[2] += h1;
        weights[3] = 0;
    }
    return true;
}

Float CatmullRom(std::span<const Float> nodes, std::span<const Float> f, Float x) {
    int offset;
    Float w[4];
    if (!CatmullRomWeights(nodes, x, &offset, w)) return 0;
    Float v = 0;
    for (int k = 0; k < 4; ++k)
        if (w[k] != 0) v += w[k] * f[size_t(offset + k)];
    return v;
}

Float InvertCatmullRom(std::span<const Float> nodes, std::span<const Float> f, Float u) {
    if (!(u > f.front())) return nodes.front();
    if (!(u < f.back())) return nodes.back();
    const int i = int(FindInterval(f.size(), [&](size_t k) { return f[k] <= u; }));
    auto value = [&](int k) { return f[size_t(k)]; };
    // Plain variables, not structured bindings: lambdas capture them (clang 14 cannot capture
    // bindings)
    const std::pair<Float, Float> d = Derivatives(nodes, i, value);
    const Float d0 = d.first, d1 = d.second;
    Float x0 = nodes[size_t(i)], width = nodes[size_t(i) + 1] - x0;
    Float f0 = f[size_t(i)], f1 = f[size_t(i) + 1];
    auto eval = [&](Float t) -> std::pair<Float, Float> {
        Float t2 = t * t, t3 = t2 * t;
        Float F = (2 * t3 - 3 * t2 + 1) * f0 + (-2 * t3 + 3 * t2) * f1 + (t3 - 2 * t2 + t) * d0 +
                  (t3 - t2) * d1;
        Float dF = (6 * t2 - 6 * t) * f0 + (-6 * t2 + 6 * t) * f1 + (3 * t2 - 4 * t + 1) * d0 +
                   (3 * t2 - 2 * t) * d1;
        return {F - u, dF};
    };
    return x0 + NewtonBisection(0, 1, eval) * width;
}

Float IntegrateCatmullRom(std::span<const Float> nodes, std::span<const Float> f,
                          std::span<Float> cdf) {
    auto value = [&](int k) { return f[size_t(k)]; };
    Float sum = 0;
    cdf[0] = 0;
    for (int i = 0; i + 1 < int(nodes.size()); ++i) {
        auto [d0, d1] = Derivatives(nodes, i, value);
        Float width = nodes[size_t(i) + 1] - nodes[size_t(i)];
        sum += width * ((f[size_t(i)] + f[size_t(i) + 1]) / 2 + (d0 - d1) / 12);
        cdf[size_t(i) + 1] = sum;
    }
    return sum;
}

Float SampleCatmullRom2D(std::span<const Float> nodes1, std::span<const Float> nodes2,
                         std::span<const Float> values, std::span<const Float> cdf, Float alpha,
                         Float u, Float* fval, Float* pdf) {
    int offset;
    Float weights[4];
    if (!CatmullRomWeights(nodes1, alpha, &offset, weights)) return 0;
    const size_t n2 = nodes2.size();
    // The table interpolated along the first axis at alpha
    auto interpolate = [&](std::span<const Float> array, int i2) {
        Float v = 0;
        for (int k = 0; k < 4; ++k)
            if (weights[k] != 0) v += array[size_t(offset + k) * n2 + size_t(i2)] * weights[k];
        return v;
    };
    auto F = [&](int i2) { return interpolate(cdf, i2); };
    auto f = [&](int i2) { return interpolate(values, i2); };
    // The interval whose cdf range holds u, then the root of the cubic's integral in it
    Float maximum = F(int(n2) - 1);
    u *= maximum;
    const int i = int(FindInterval(n2, [&](size_t k) { return F(int(k)) <= u; }));
    Float f0 = f(i), f1 = f(i + 1);
    Float x0 = nodes2[size_t(i)], width = nodes2[size_t(i) + 1] - x0;
    const std::pair<Float, Float> d = Derivatives(nodes2, i, f);
    const Float d0 = d.first, d1 = d.second;  // captured below (not bindings: clang 14)
    u = (u - F(i)) / width;
    Float fhat = 0;
    auto eval = [&](Float t) -> std::pair<Float, Float> {
        fhat = SegmentValue(t, f0, f1, d0, d1);
        return {SegmentIntegral(t, f0, f1, d0, d1) - u, fhat};
    };
    Float t = NewtonBisection(0, 1, eval);
    if (fval) *fval = fhat;
    if (pdf) *pdf = fhat / maximum;
    return x0 + width * t;
}

}  // namespace kiln
