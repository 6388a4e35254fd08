#include "base/sampling.h"

#include <numeric>

namespace kiln {

// Hemisphere and disk warps
Point2f SampleUniformDiskConcentric(Point2f u) {
    Point2f uOffset(2 * u.x - 1, 2 * u.y - 1);
    if (uOffset.x == 0 && uOffset.y == 0) return {0, 0};
    Float theta, r;
    if (std::abs(uOffset.x) > std::abs(uOffset.y)) {
        r = uOffset.x;
        theta = PiOver4 * (uOffset.y / uOffset.x);
    } else {
        r = uOffset.y;
        theta = PiOver2 - PiOver4 * (uOffset.x / uOffset.y);
    }
    return {r * std::cos(theta), r * std::sin(theta)};
}

Vector3f SampleUniformSphere(Point2f u) {
    Float z = 1 - 2 * u.x;
    Float r = SafeSqrt(1 - z * z);
    Float phi = 2 * Pi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

Vector3f SampleUniformHemisphere(Point2f u) {
    Float z = u.x;
    Float r = SafeSqrt(1 - z * z);
    Float phi = 2 * Pi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

Vector3f SampleCosineHemisphere(Point2f u) {
    Point2f d = SampleUniformDiskConcentric(u);
    Float z = SafeSqrt(1 - d.x * d.x - d.y * d.y);
    return {d.x, d.y, z};
}

Vector3f SampleUniformCone(Point2f u, Float cosThetaMax) {
    Float cosTheta = (1 - u.x) + u.x * cosThetaMax;
    Float sinTheta = SafeSqrt(1 - cosTheta * cosTheta);
    Float phi = u.y * 2 * Pi;
    return SphericalDirection(sinTheta, cosTheta, phi);
}

std::array<Float, 3> SampleUniformTriangle(Point2f u) {
    Float b0, b1;
    if (u.x < u.y) {
        b0 = u.x / 2;
        b1 = u.y - b0;
    } else {
        b1 = u.y / 2;
        b0 = u.x - b1;
    }
    return {b0, b1, 1 - b0 - b1};
}

Float SampleLinear(Float u, Float a, Float b) {
    if (u == 0 && a == 0) return 0;
    Float x = u * (a + b) / (a + std::sqrt(Lerp(u, Sqr(a), Sqr(b))));
    return std::min(x, OneMinusEpsilon);
}

Point2f SampleBilinear(Point2f u, std::span<const Float> w) {
    Point2f p;
    p.y = SampleLinear(u.y, w[0] + w[1], w[2] + w[3]);
    p.x = SampleLinear(u.x, Lerp(p.y, w[0], w[2]), Lerp(p.y, w[1], w[3]));
    return p;
}

Float BilinearPDF(Point2f p, std::span<const Float> w) {
    if (p.x < 0 || p.x > 1 || p.y < 0 || p.y > 1) return 0;
    if (w[0] + w[1] + w[2] + w[3] == 0) return 1;
    return 4 *
           ((1 - p.x) * (1 - p.y) * w[0] + p.x * (1 - p.y) * w[1] + (1 - p.x) * p.y * w[2] +
            p.x * p.y * w[3]) /
           (w[0] + w[1] + w[2] + w[3]);
}

// Tabulated 1D distribution
PiecewiseConstant1D::PiecewiseConstant1D(std::span<const Float> f, Float min, Float max)
    : func(f.begin(), f.end()), cdf(f.size() + 1), min(min), max(max) {
    if (func.empty()) func.push_back(0), cdf.push_back(0);
    for (Float& v : func) v = std::abs(v);
    size_t n = func.size();
    double sum = 0;
    cdf[0] = 0;
    for (size_t i = 1; i <= n; ++i) {
        sum += double(func[i - 1]) * (max - min) / n;
        cdf[i] = Float(sum);
    }
    funcInt = Float(sum);
    if (funcInt == 0) {
        for (size_t i = 1; i <= n; ++i) cdf[i] = Float(i) / Float(n);
    } else {
        for (size_t i = 1; i <= n; ++i) cdf[i] /= funcInt;
    }
    cdf[n] = 1;
    guide.resize(n);
    for (size_t k = 0, o = 0; k < n; ++k) {
        Float u = Float(k) / Float(n);
        while (o + 1 < n && cdf[o + 1] <= u) ++o;
        guide[k] = uint32_t(o);
    }
}

size_t PiecewiseConstant1D::FindBin(Float u) const {
    size_t n = func.size();
    if (!(u >= 0 && u < 1))  // outside the guide's range (or NaN): the binary search
        return FindInterval(cdf.size(), [&](size_t i) { return cdf[i] <= u; });
    size_t o = guide[std::min(size_t(u * Float(n)), n - 1)];
    // u * n may round up into the next interval: step back, then forward to the last bin
    while (o > 0 && cdf[o] > u) --o;
    while (o + 1 < n && cdf[o + 1] <= u) ++o;
    return o;
}

Float PiecewiseConstant1D::Sample(Float u, Float* pdf, int* offset) const {
    size_t o = FindBin(u);
    if (offset) *offset = int(o);
    Float du = u - cdf[o];
    if (cdf[o + 1] - cdf[o] > 0) du /= (cdf[o + 1] - cdf[o]);
    if (pdf) *pdf = (funcInt > 0) ? func[o] / funcInt : 1 / (max - min);
    Float x = Lerp((o + du) / Size(), min, max);
    return x < max ? x : std::nextafter(max, min);  // (nextafter only where rounding reached max)
}

// Tabulated 2D distribution
PiecewiseConstant2D::PiecewiseConstant2D(std::span<const Float> f, int nu, int nv) {
    conditional.reserve(nv);
    for (int v = 0; v < nv; ++v) conditional.emplace_back(f.subspan(size_t(v) * nu, nu), 0, 1);
    std::vector<Float> marg(nv);
    for (int v = 0; v < nv; ++v) marg[v] = conditional[v].Integral();
    marginal = PiecewiseConstant1D(marg, 0, 1);
}

Point2f PiecewiseConstant2D::Sample(Point2f u, Float* pdf) const {
    Float pdfs[2];
    int v;
    Float d1 = marginal.Sample(u.y, &pdfs[1], &v);
    Float d0 = conditional[v].Sample(u.x, &pdfs[0]);
    if (pdf) *pdf = pdfs[0] * pdfs[1];
    return {d0, d1};
}

Float PiecewiseConstant2D::PDF(Point2f p) const {
    int nu = int(conditional[0].Size()), nv = int(marginal.Size());
    int iu = Clamp(int(p.x * nu), 0, nu - 1), iv = Clamp(int(p.y * nv), 0, nv - 1);
    if (marginal.Integral() == 0) return 1;
    return conditional[iv].Func(iu) / marginal.Integral();
}

// Alias table (Vose's construction)
AliasTable::AliasTable(std::span<const Float> weights) : bins(weights.size()) {
    double sum = std::accumulate(weights.begin(), weights.end(), 0.0);
    size_t n = bins.size();
    for (size_t i = 0; i < n; ++i) bins[i].p = sum > 0 ? Float(weights[i] / sum) : Float(1.0 / n);
    struct Outcome {
        double pHat;
        size_t index;
    };
    std::vector<Outcome> under, over;
    for (size_t i = 0; i < n; ++i) {
        double pHat = double(bins[i].p) * n;
        (pHat < 1 ? under : over).push_back({pHat, i});
    }
    while (!under.empty() && !over.empty()) {
        Outcome un = under.back(), ov = over.back();
        under.pop_back(), over.pop_back();
        bins[un.index].q = Float(un.pHat);
        bins[un.index].alias = int(ov.index);
        double pExcess = un.pHat + ov.pHat - 1;
        (pExcess < 1 ? under : over).push_back({pExcess, ov.index});
    }
    while (!over.empty()) {
        bins[over.back().index].q = 1, bins[over.back().index].alias = -1;
        over.pop_back();
    }
    while (!under.empty()) {
        bins[under.back().index].q = 1, bins[under.back().index].alias = -1;
        under.pop_back();
    }
}

int AliasTable::Sample(Float u, Float* pmf, Float* uRemapped) const {
    size_t n = bins.size();
    int offset = std::min<int>(int(u * n), int(n) - 1);
    Float up = std::min<Float>(u * n - offset, OneMinusEpsilon);
    if (up < bins[offset].q) {
        if (pmf) *pmf = bins[offset].p;
        if (uRemapped) *uRemapped = std::min<Float>(up / bins[offset].q, OneMinusEpsilon);
        return offset;
    }
    int alias = bins[offset].alias;
    if (pmf) *pmf = bins[alias].p;
    if (uRemapped)
        *uRemapped = std::min<Float>((up - bins[offset].q) / (1 - bins[offset].q), OneMinusEpsilon);
    return alias;
}

}  // namespace kiln
