// A piecewise-constant 2D function on [0,1]^2 sampled within any axis-aligned window (pbrt-v4's
// WindowedPiecewiseConstant2D, used by portal lights to sample only the directions that pass
// through the portal). A summed-area table gives the integral over any window exactly (the
// table interpolated bilinearly is the exact integral of a piecewise-constant function), and
// each of the two coordinates is found by inverting its piecewise-linear distribution
// function exactly (pbrt-v4 bisects it; the density is the same).
#pragma once

#include <optional>
#include <vector>

#include "base/vecmath.h"

namespace kiln {

class WindowedPiecewiseConstant2D {
  public:
    WindowedPiecewiseConstant2D() = default;
    // f: nx x ny non-negative values, row-major, row 0 at y in [0, 1/ny).
    WindowedPiecewiseConstant2D(const std::vector<Float>& f, int nx, int ny);

    // A point of window b (inside [0,1]^2) with density f(p) / integral of f over b (pdf, per
    // unit area of [0,1]^2); nullopt where f integrates to 0 over b.
    std::optional<Point2f> Sample(Point2f u, const Bounds2f& b, Float* pdf) const;
    // The density Sample has at p for window b (0 outside it).
    Float PDF(Point2f p, const Bounds2f& b) const;
    // Integral of f over b (f's average over [0,1]^2 times its area, for the whole domain).
    double Integral(const Bounds2f& b) const;
    // f at p (the cell containing it, clamped to the domain).
    Float Eval(Point2f p) const;

  private:
    // Integral of f over [0, x] x [0, y]
    double I(double x, double y) const;
    // Finds t in [t0, t1] with F(t) = target for a non-decreasing F, linear between the
    // n + 1 cell boundaries k / n
    template <typename F>
    double Invert(const F& cdf, double target, double t0, double t1, int n) const;

    int nx = 0, ny = 0;
    std::vector<Float> f;
    std::vector<double> sat;  // (nx + 1) x (ny + 1) partial integrals at the cell corners
};

}  // namespace kiln
