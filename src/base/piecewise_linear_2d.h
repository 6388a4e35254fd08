// PiecewiseLinear2D: a function on [0,1]^2 given at the nodes of a regular nx x ny grid and
// bilinear between them, optionally one such grid per combination of up to three parameters,
// each tabulated at increasing values (multilinear interpolation between those slices; a
// parameter outside its range takes its end slice). It is the warp of the RGL measured BRDFs
// (Dupuy and Jakob 2018, "An Adaptive Parameterization for Efficient Material Acquisition and
// Rendering"), as pbrt-v4's PiecewiseLinear2D uses it for its `measured` material.
//
// Data layout: slice-major, the last parameter fastest, then y (rows), then x fastest.
//
// Kind::Distribution: each slice is scaled to integrate to 1 over the unit square (an all-zero
// slice becomes uniform) and carries the CDFs of its rows (conditional, in x) and of the row
// totals (marginal, in y). Sample warps a uniform point to one with that density, by inverting
// the marginal then the conditional CDF of the bilinear density; Invert is its exact inverse;
// Evaluate gives the density (per unit area of the square). Between parameter nodes the
// densities and CDFs are both interpolated, so the warp is the exact inverse CDF of the
// interpolated density.
// Kind::Values: the values as given; only Evaluate (bilinear and multilinear interpolation).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "base/vecmath.h"

namespace kiln {

class PiecewiseLinear2D {
  public:
    enum class Kind { Distribution, Values };
    struct Sample {
        Point2f p;
        Float pdf;
    };
    static constexpr int kMaxParameters = 3;

    PiecewiseLinear2D() = default;
    // data: (product of parameter sizes) x ny x nx values, finite and (for a distribution) not
    // negative; nx, ny >= 2; parameterValues: each parameter's nodes, at least one, finite and
    // strictly increasing. The caller checks these (measured_bxdf_data.cpp does).
    PiecewiseLinear2D(std::span<const float> data, int nx, int ny,
                      std::vector<std::vector<float>> parameterValues, Kind kind);

    // Warps u in [0,1)^2 to a point with the density at `params` (one value per parameter).
    Sample Draw(Point2f u, std::span<const Float> params) const;
    // The u that Draw maps to p, and the density at p.
    Sample Invert(Point2f p, std::span<const Float> params) const;
    // The density (Distribution) or the interpolated value (Values) at p.
    Float Evaluate(Point2f p, std::span<const Float> params) const;

    int NX() const { return nx; }
    int NY() const { return ny; }
    size_t BytesUsed() const;

  private:
    // The slices around a parameter point and their multilinear weights
    struct Corners {
        int n = 0;
        uint32_t slice[1 << kMaxParameters];
        Float weight[1 << kMaxParameters];
    };
    Corners Lookup(std::span<const Float> params) const;
    static Float Fetch(const std::vector<float>& a, const Corners& c, size_t sliceSize,
                       size_t index) {
        Float v = 0;
        for (int k = 0; k < c.n; ++k) v += c.weight[k] * a[c.slice[k] * sliceSize + index];
        return v;
    }

    int nx = 0, ny = 0;
    Kind kind = Kind::Values;
    std::vector<std::vector<float>> parameters;
    std::vector<float> values, marginalCDF, conditionalCDF;
};

}  // namespace kiln
