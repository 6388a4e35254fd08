#include "base/piecewise_linear_2d.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace kiln {

namespace {

// The t in [0, 1] where the integral of the linear function a (1 - t) + b t from 0 to t is u
// (u at most (a + b) / 2); almost-constant functions use the linear solution, which avoids the
// cancellation of the quadratic one.
Float SolveLinearCDF(Float u, Float a, Float b) {
    Float t;
    if (std::abs(a - b) < 1e-4f * (a + b))
        t = 2 * u / (a + b);
    else
        t = (a - SafeSqrt(a * a + 2 * u * (b - a))) / (a - b);
    return std::isfinite(t) ? std::clamp<Float>(t, 0, 1) : 0;
}

// Clamps to [0, 1]; NaN gives 0
Float Clamp01(Float w) { return std::min<Float>(1, std::max<Float>(0, w)); }

}  // namespace

PiecewiseLinear2D::PiecewiseLinear2D(std::span<const float> data, int nx, int ny,
                                     std::vector<std::vector<float>> parameterValues, Kind kind)
    : nx(nx), ny(ny), kind(kind), parameters(std::move(parameterValues)) {
    assert(nx >= 2 && ny >= 2 && parameters.size() <= kMaxParameters);
    size_t slices = 1;
    for (const std::vector<float>& p : parameters) slices *= p.size();
    const size_t sliceSize = size_t(nx) * ny;
    assert(data.size() == slices * sliceSize);
    values.assign(data.begin(), data.end());
    if (kind == Kind::Values) return;

    conditionalCDF.resize(values.size());
    marginalCDF.resize(slices * ny);
    for (size_t s = 0; s < slices; ++s) {
        float* d = &values[s * sliceSize];
        float* cc = &conditionalCDF[s * sliceSize];
        float* mc = &marginalCDF[s * ny];
        for (int pass = 0; pass < 2; ++pass) {
            // Integrals of the bilinear function in index units: along each row, then of the
            // row totals along y (trapezoids, exact for linear segments)
            for (int y = 0; y < ny; ++y) {
                double sum = 0;
                cc[y * nx] = 0;
                for (int x = 0; x + 1 < nx; ++x) {
                    sum += 0.5 * (double(d[y * nx + x]) + double(d[y * nx + x + 1]));
                    cc[y * nx + x + 1] = float(sum);
                }
            }
            double sum = 0;
            mc[0] = 0;
            for (int y = 0; y + 1 < ny; ++y) {
                sum += 0.5 * (double(cc[y * nx + nx - 1]) + double(cc[(y + 1) * nx + nx - 1]));
                mc[y + 1] = float(sum);
            }
            if (sum > 0 && std::isfinite(sum)) break;
            // A slice without mass becomes uniform
            std::fill(d, d + sliceSize, 1.f);
        }
        float scale = float(1 / double(mc[ny - 1]));
        for (size_t i = 0; i < sliceSize; ++i) d[i] *= scale, cc[i] *= scale;
        for (int y = 0; y < ny; ++y) mc[y] *= scale;
    }
}

PiecewiseLinear2D::Corners PiecewiseLinear2D::Lookup(std::span<const Float> params) const {
    assert(params.size() == parameters.size());
    Corners c;
    c.n = 1;
    c.slice[0] = 0;
    c.weight[0] = 1;
    for (size_t d = 0; d < parameters.size(); ++d) {
        const std::vector<float>& nodes = parameters[d];
        const uint32_t n = uint32_t(nodes.size());
        for (int k = 0; k < c.n; ++k) c.slice[k] *= n;
        if (n == 1) continue;
        const Float v = params[d];
        const size_t i = FindInterval(n, [&](size_t j) { return nodes[j] <= v; });
        const Float w1 = Clamp01((v - nodes[i]) / (nodes[i + 1] - nodes[i]));
        for (int k = 0; k < c.n; ++k) {
            c.slice[k + c.n] = c.slice[k] + uint32_t(i) + 1;
            c.weight[k + c.n] = c.weight[k] * w1;
            c.slice[k] += uint32_t(i);
            c.weight[k] *= 1 - w1;
        }
        c.n *= 2;
    }
    return c;
}

PiecewiseLinear2D::Sample PiecewiseLinear2D::Draw(Point2f u, std::span<const Float> params) const {
    assert(kind == Kind::Distribution);
    u.x = std::clamp(u.x, 1 - OneMinusEpsilon, OneMinusEpsilon);
    u.y = std::clamp(u.y, 1 - OneMinusEpsilon, OneMinusEpsilon);
    const Corners c = Lookup(params);
    const size_t sliceSize = size_t(nx) * ny;

    // The row: invert the marginal CDF, linear in y within the interval
    auto marginal = [&](size_t y) { return Fetch(marginalCDF, c, ny, y); };
    const size_t row = FindInterval(ny, [&](size_t y) { return marginal(y) < u.y; });
    const size_t r = row * nx;
    const Float r0 = Fetch(conditionalCDF, c, sliceSize, r + nx - 1);
    const Float r1 = Fetch(conditionalCDF, c, sliceSize, r + 2 * nx - 1);
    const Float t = SolveLinearCDF(u.y - marginal(row), r0, r1);

    // The column: invert the conditional CDF of the row at t
    auto conditional = [&](size_t x) {
        return (1 - t) * Fetch(conditionalCDF, c, sliceSize, r + x) +
               t * Fetch(conditionalCDF, c, sliceSize, r + nx + x);
    };
    const Float ux = u.x * ((1 - t) * r0 + t * r1);
    const size_t col = FindInterval(nx, [&](size_t x) { return conditional(x) < ux; });
    const Float c0 = (1 - t) * Fetch(values, c, sliceSize, r + col) +
                     t * Fetch(values, c, sliceSize, r + nx + col);
    const Float c1 = (1 - t) * Fetch(values, c, sliceSize, r + col + 1) +
                     t * Fetch(values, c, sliceSize, r + nx + col + 1);
    const Float s = SolveLinearCDF(ux - conditional(col), c0, c1);

    return {Point2f((col + s) / Float(nx - 1), (row + t) / Float(ny - 1)),
            ((1 - s) * c0 + s * c1) * Float(nx - 1) * Float(ny - 1)};
}

PiecewiseLinear2D::Sample PiecewiseLinear2D::Invert(Point2f p,
                                                    std::span<const Float> params) const {
    assert(kind == Kind::Distribution);
    const Float x = Clamp01(p.x) * (nx - 1), y = Clamp01(p.y) * (ny - 1);
    const size_t col = std::min(size_t(x), size_t(nx - 2));
    const size_t row = std::min(size_t(y), size_t(ny - 2));
    const Float s = x - col, t = y - row;
    const Corners c = Lookup(params);
    const size_t sliceSize = size_t(nx) * ny, r = row * nx;

    const Float c0 = (1 - t) * Fetch(values, c, sliceSize, r + col) +
                     t * Fetch(values, c, sliceSize, r + nx + col);
    const Float c1 = (1 - t) * Fetch(values, c, sliceSize, r + col + 1) +
                     t * Fetch(values, c, sliceSize, r + nx + col + 1);
    const Float pdf = (1 - s) * c0 + s * c1;

    // Conditional CDF in x at row + t, divided by the row total there
    const Float r0 = Fetch(conditionalCDF, c, sliceSize, r + nx - 1);
    const Float r1 = Fetch(conditionalCDF, c, sliceSize, r + 2 * nx - 1);
    const Float rowTotal = (1 - t) * r0 + t * r1;
    Float ux = s * (c0 + 0.5f * s * (c1 - c0)) +
               (1 - t) * Fetch(conditionalCDF, c, sliceSize, r + col) +
               t * Fetch(conditionalCDF, c, sliceSize, r + nx + col);
    ux = rowTotal > 0 ? Clamp01(ux / rowTotal) : 0;
    // Marginal CDF in y
    const Float uy = Clamp01(t * (r0 + 0.5f * t * (r1 - r0)) + Fetch(marginalCDF, c, ny, row));
    return {Point2f(ux, uy), pdf * Float(nx - 1) * Float(ny - 1)};
}

Float PiecewiseLinear2D::Evaluate(Point2f p, std::span<const Float> params) const {
    const Float x = Clamp01(p.x) * (nx - 1), y = Clamp01(p.y) * (ny - 1);
    const size_t col = std::min(size_t(x), size_t(nx - 2));
    const size_t row = std::min(size_t(y), size_t(ny - 2));
    const Float s = x - col, t = y - row;
    const Corners c = Lookup(params);
    const size_t sliceSize = size_t(nx) * ny, i = row * nx + col;
    const Float v = (1 - t) * ((1 - s) * Fetch(values, c, sliceSize, i) +
                               s * Fetch(values, c, sliceSize, i + 1)) +
                    t * ((1 - s) * Fetch(values, c, sliceSize, i + nx) +
                         s * Fetch(values, c, sliceSize, i + nx + 1));
    return kind == Kind::Distribution ? v * Float(nx - 1) * Float(ny - 1) : v;
}

size_t PiecewiseLinear2D::BytesUsed() const {
    size_t n = values.size() + marginalCDF.size() + conditionalCDF.size();
    for (const std::vector<float>& p : parameters) n += p.size();
    return n * sizeof(float);
}

}  // namespace kiln
