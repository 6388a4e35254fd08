// Warping functions from [0,1)^n to common distributions, with their densities, and
// tabulated distributions (1D, 2D, alias tables).
//
// Every Sample* routine has a matching *PDF with respect to the measure stated next to it;
// test/base/sampling_test.cpp checks each pair with a chi-square test.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "base/vecmath.h"

namespace kiln {

// Shirley-Chiu concentric map to the unit disk; density 1/pi per unit area.
Point2f SampleUniformDiskConcentric(Point2f u);
// Uniform on the unit sphere; density 1/(4 pi) per steradian.
Vector3f SampleUniformSphere(Point2f u);
inline Float UniformSpherePDF() { return Inv4Pi; }
// Uniform on the upper (z > 0) hemisphere; density 1/(2 pi) per steradian.
Vector3f SampleUniformHemisphere(Point2f u);
inline Float UniformHemispherePDF() { return Inv2Pi; }
// Cosine-weighted upper hemisphere; density cos(theta)/pi per steradian.
Vector3f SampleCosineHemisphere(Point2f u);
inline Float CosineHemispherePDF(Float cosTheta) { return cosTheta * InvPi; }
// Uniform in the cone of directions around +z with cos(theta) >= cosThetaMax; per steradian.
Vector3f SampleUniformCone(Point2f u, Float cosThetaMax);
inline Float UniformConePDF(Float cosThetaMax) { return 1 / (2 * Pi * (1 - cosThetaMax)); }
// Uniform barycentrics (b0, b1, b2) on a triangle (Heitz 2019 low-distortion map).
std::array<Float, 3> SampleUniformTriangle(Point2f u);
// Density proportional to a linear function (a at x=0, b at x=1) on [0,1].
Float SampleLinear(Float u, Float a, Float b);
inline Float LinearPDF(Float x, Float a, Float b) {
    if (x < 0 || x > 1) return 0;
    return 2 * Lerp(x, a, b) / (a + b);
}
// Bilinear density on [0,1]^2 with corner weights w = (w00, w10, w01, w11).
Point2f SampleBilinear(Point2f u, std::span<const Float> w);
Float BilinearPDF(Point2f p, std::span<const Float> w);
// Exponential density a exp(-a x) on [0, inf).
inline Float SampleExponential(Float u, Float a) { return -std::log(1 - u) / a; }

// Multiple importance sampling heuristics.
inline Float PowerHeuristic(int nf, Float fPdf, int ng, Float gPdf) {
    Float f = nf * fPdf, g = ng * gPdf;
    if (std::isinf(Sqr(f))) return 1;
    if (f == 0 && g == 0) return 0;
    return Sqr(f) / (Sqr(f) + Sqr(g));
}
inline Float BalanceHeuristic(int nf, Float fPdf, int ng, Float gPdf) {
    return (nf * fPdf) / (nf * fPdf + ng * gPdf);
}

// Piecewise-constant density on [min, max] from non-negative function values. Sampling
// inverts the CDF from a guide table (the cutpoint method of Chen & Asau 1974): for each of
// Size() equal intervals of u, the bin the CDF search would return at its start, scanned
// forward from there; the same bin as a binary search of the CDF, in a few steps on average.
class PiecewiseConstant1D {
  public:
    PiecewiseConstant1D() = default;
    PiecewiseConstant1D(std::span<const Float> f, Float min = 0, Float max = 1);
    // Returns x in [min, max); *pdf is the density at x, *offset the bucket index.
    Float Sample(Float u, Float* pdf = nullptr, int* offset = nullptr) const;
    Float Integral() const { return funcInt; }
    size_t Size() const { return func.size(); }
    Float Func(size_t i) const { return func[i]; }
    Float Min() const { return min; }
    Float Max() const { return max; }

  private:
    // The bin containing u: the last i < Size() with cdf[i] <= u (0 if none), as FindInterval.
    size_t FindBin(Float u) const;

    std::vector<Float> func, cdf;
    std::vector<uint32_t> guide;  // guide[k]: FindBin(k / Size())
    Float min = 0, max = 1, funcInt = 0;
};

// Piecewise-constant density on a 2D domain (marginal in v, conditional in u).
class PiecewiseConstant2D {
  public:
    PiecewiseConstant2D() = default;
    // f has nv rows of nu values (row-major, v outer), domain [0,1]^2.
    PiecewiseConstant2D(std::span<const Float> f, int nu, int nv);
    Point2f Sample(Point2f u, Float* pdf = nullptr) const;
    Float PDF(Point2f p) const;
    Float Integral() const { return marginal.Integral(); }

  private:
    std::vector<PiecewiseConstant1D> conditional;
    PiecewiseConstant1D marginal;
};

// Walker/Vose alias table: O(1) sampling of a discrete distribution.
class AliasTable {
  public:
    AliasTable() = default;
    explicit AliasTable(std::span<const Float> weights);
    // Returns an index; *pmf its probability, *uRemapped a fresh uniform from the leftover bits.
    int Sample(Float u, Float* pmf = nullptr, Float* uRemapped = nullptr) const;
    Float PMF(int index) const { return bins[index].p; }
    size_t Size() const { return bins.size(); }

  private:
    struct Bin {
        Float q = 0, p = 0;
        int alias = -1;
    };
    std::vector<Bin> bins;
};

}  // namespace kiln
