// Catmull-Rom splines over non-uniform nodes (pbrt-v4's spline interpolation functions, used
// by the BSSRDF table, materials/bxdfs/bssrdf_table.h).
//
// Between nodes x_i and x_{i+1} the spline is the cubic Hermite interpolant of f_i and f_{i+1}
// whose derivatives (scaled to the interval's width w) are finite differences over the
// neighbouring nodes: d_i = w (f_{i+1} - f_{i-1}) / (x_{i+1} - x_{i-1}), one-sided
// (f_{i+1} - f_i) at the ends. Every function here evaluates that same spline.
#pragma once

#include <span>

#include "base/vecmath.h"

namespace kiln {

// The four weights that give the spline at x as sum_k weights[k] f[offset + k] (weights of
// nodes outside the table are 0); false if x is outside [nodes.front(), nodes.back()].
bool CatmullRomWeights(std::span<const Float> nodes, Float x, int* offset, Float weights[4]);

// The spline through (nodes, f) at x; 0 outside the nodes.
Float CatmullRom(std::span<const Float> nodes, std::span<const Float> f, Float x);

// The x at which the spline through (nodes, f), f increasing, equals u (Newton-bisection);
// nodes.front() below f.front(), nodes.back() above f.back().
Float InvertCatmullRom(std::span<const Float> nodes, std::span<const Float> f, Float u);

// The integral of the spline over [nodes.front(), nodes.back()] (exact for the cubic pieces);
// cdf[i] receives the integral up to nodes[i].
Float IntegrateCatmullRom(std::span<const Float> nodes, std::span<const Float> f,
                          std::span<Float> cdf);

// Samples x2 in proportion to the spline in a 2D table values[i1 * n2 + i2] (n2 =
// nodes2.size()) interpolated along the first axis at alpha (cdf: the rows' IntegrateCatmullRom
// cdfs), by inverting the interpolated cdf. *fval and *pdf (if given) receive the spline's value
// and the density at the result. Returns 0 if alpha is outside nodes1.
Float SampleCatmullRom2D(std::span<const Float> nodes1, std::span<const Float> nodes2,
                         std::span<const Float> values, std::span<const Float> cdf, Float alpha,
                         Float u, Float* fval = nullptr, Float* pdf = nullptr);

}  // namespace kiln
