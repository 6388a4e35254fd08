#include "base/windowed_distribution.h"

#include <algorithm>
#include <cmath>

namespace kiln {

WindowedPiecewiseConstant2D::WindowedPiecewiseConstant2D(const std::vector<Float>& values, int nx,
                                                         int ny)
    : nx(nx), ny(ny), f(values), sat(size_t(nx + 1) * size_t(ny + 1), 0.0) {
    // sat[j][i]: integral over [0, i/nx] x [0, j/ny], each cell weighing 1 / (nx ny)
    const double cell = 1.0 / (double(nx) * ny);
    for (int j = 1; j <= ny; ++j) {
        double row = 0;
        for (int i = 1; i <= nx; ++i) {
            row += std::max<double>(0, f[size_t(j - 1) * nx + size_t(i - 1)]) * cell;
            sat[size_t(j) * (nx + 1) + i] = sat[size_t(j - 1) * (nx + 1) + i] + row;
        }
    }
}

double WindowedPiecewiseConstant2D::I(double x, double y) const {
    // Bilinear in the corner values: exact for a function constant over each cell
    double sx = std::clamp(x, 0.0, 1.0) * nx, sy = std::clamp(y, 0.0, 1.0) * ny;
    int i = std::min(int(sx), nx - 1), j = std::min(int(sy), ny - 1);
    double dx = sx - i, dy = sy - j;
    auto at = [&](int ii, int jj) { return sat[size_t(jj) * (nx + 1) + ii]; };
    return (1 - dx) * (1 - dy) * at(i, j) + dx * (1 - dy) * at(i + 1, j) +
           (1 - dx) * dy * at(i, j + 1) + dx * dy * at(i + 1, j + 1);
}

double WindowedPiecewiseConstant2D::Integral(const Bounds2f& b) const {
    if (nx == 0) return 0;
    return std::max(0.0, I(b.pMax.x, b.pMax.y) - I(b.pMin.x, b.pMax.y) - I(b.pMax.x, b.pMin.y) +
                             I(b.pMin.x, b.pMin.y));
}

Float WindowedPiecewiseConstant2D::Eval(Point2f p) const {
    int i = std::clamp(int(p.x * nx), 0, nx - 1), j = std::clamp(int(p.y * ny), 0, ny - 1);
    return std::max<Float>(0, f[size_t(j) * nx + i]);
}

template <typename F>
double WindowedPiecewiseConstant2D::Invert(const F& cdf, double target, double t0, double t1,
                                           int n) const {
    // Breakpoints: t0, the cell boundaries strictly inside (t0, t1), t1
    int kFirst = int(std::floor(t0 * n)) + 1, kLast = int(std::ceil(t1 * n)) - 1;
    int m = std::max(0, kLast - kFirst + 1) + 1;  // index of t1
    auto point = [&](int i) { return i == 0 ? t0 : i == m ? t1 : double(kFirst + i - 1) / n; };
    // The first breakpoint whose distribution function exceeds the target
    int lo = 1, hi = m;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (cdf(point(mid)) > target)
            hi = mid;
        else
            lo = mid + 1;
    }
    double a = point(lo - 1), b = point(lo), ca = cdf(a), cb = cdf(b);
    if (!(cb > ca)) return a;
    return std::clamp(a + (target - ca) / (cb - ca) * (b - a), a, b);
}

std::optional<Point2f> WindowedPiecewiseConstant2D::Sample(Point2f u, const Bounds2f& b,
                                                           Float* pdf) const {
    double total = Integral(b);
    if (!(total > 0)) return std::nullopt;
    // x from the window's marginal distribution
    auto cdfX = [&](double x) {
        return Integral(Bounds2f{b.pMin, Point2f(Float(x), b.pMax.y)}) / total;
    };
    double x = Invert(cdfX, u.x, b.pMin.x, b.pMax.x, nx);
    // y from the column holding x, within the window
    int column = std::clamp(int(x * nx), 0, nx - 1);
    Float c0 = Float(column) / nx, c1 = Float(column + 1) / nx;
    double columnTotal = Integral(Bounds2f{Point2f(c0, b.pMin.y), Point2f(c1, b.pMax.y)});
    if (!(columnTotal > 0)) return std::nullopt;
    auto cdfY = [&](double y) {
        return Integral(Bounds2f{Point2f(c0, b.pMin.y), Point2f(c1, Float(y))}) / columnTotal;
    };
    double y = Invert(cdfY, u.y, b.pMin.y, b.pMax.y, ny);
    Point2f p{Float(x), Float(y)};
    *pdf = Float(Eval(p) / total);
    if (!(*pdf > 0)) return std::nullopt;
    return p;
}

Float WindowedPiecewiseConstant2D::PDF(Point2f p, const Bounds2f& b) const {
    if (p.x < b.pMin.x || p.x > b.pMax.x || p.y < b.pMin.y || p.y > b.pMax.y) return 0;
    double total = Integral(b);
    if (!(total > 0)) return 0;
    return Float(Eval(p) / total);
}

}  // namespace kiln
