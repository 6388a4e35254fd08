#include "materials/bxdfs/tabulated_bssrdf.h"

#include <cmath>

#include "base/catmull_rom.h"

namespace kiln {

bool TabulatedBSSRDF::Interpolate(int i, Float rOptical, Float* sr, Float* rhoEff) const {
    int rhoOffset, radiusOffset;
    Float rhoWeights[4], radiusWeights[4];
    if (!CatmullRomWeights(table->RhoSamples(), rho[i], &rhoOffset, rhoWeights) ||
        !CatmullRomWeights(table->RadiusSamples(), rOptical, &radiusOffset, radiusWeights))
        return false;
    *sr = 0;
    if (rhoEff) *rhoEff = 0;
    for (int j = 0; j < 4; ++j) {
        if (rhoWeights[j] == 0) continue;
        if (rhoEff) *rhoEff += table->RhoEff()[size_t(rhoOffset + j)] * rhoWeights[j];
        for (int k = 0; k < 4; ++k)
            if (radiusWeights[k] != 0)
                *sr += rhoWeights[j] * radiusWeights[k] *
                       table->EvalProfile(rhoOffset + j, radiusOffset + k);
    }
    // The table holds 2 pi r S(r): remove the polar measure's factor
    if (rOptical != 0) *sr /= 2 * Pi * rOptical;
    return true;
}

SampledSpectrum TabulatedBSSRDF::Sr(Float r) const {
    SampledSpectrum result(0.f);
    for (int i = 0; i < NSpectrumSamples; ++i) {
        Float sr;
        // Optical radius; the table is for unit extinction, so per render-space area sigma_t^2
        if (Interpolate(i, r * sigma_t[i], &sr, nullptr)) result[i] = sr * Sqr(sigma_t[i]);
    }
    return ClampZero(result);
}

std::optional<Float> TabulatedBSSRDF::SampleSr(Float u) const {
    if (sigma_t[0] == 0) return std::nullopt;
    return SampleCatmullRom2D(table->RhoSamples(), table->RadiusSamples(), table->Profile(),
                              table->ProfileCDF(), rho[0], u) /
           sigma_t[0];
}

SampledSpectrum TabulatedBSSRDF::PDF_Sr(Float r) const {
    SampledSpectrum pdf(0.f);
    for (int i = 0; i < NSpectrumSamples; ++i) {
        Float sr, rhoEff;
        if (Interpolate(i, r * sigma_t[i], &sr, &rhoEff) && rhoEff > 0)
            pdf[i] = sr * Sqr(sigma_t[i]) / rhoEff;
    }
    return ClampZero(pdf);
}

namespace {

// pbrt-v4's frames with the given vector as x, y or z axis
Frame FrameWithAxis(Vector3f n, int axis) {
    Vector3f a, b;
    CoordinateSystem(n, &a, &b);
    if (axis == 0) return Frame(n, a, b);
    if (axis == 1) return Frame(b, n, a);
    return Frame(a, b, n);
}

}  // namespace

std::optional<BSSRDFProbeSegment> TabulatedBSSRDF::SampleSp(Float u1, Point2f u2) const {
    Vector3f n(ns);
    Frame f = FrameWithAxis(n, u1 < 0.25f ? 0 : u1 < 0.5f ? 1 : 2);
    std::optional<Float> r = SampleSr(u2[0]);
    if (!r) return std::nullopt;
    Float phi = 2 * Pi * u2[1];
    std::optional<Float> rMax = SampleSr(0.999f);
    if (!rMax || *r >= *rMax) return std::nullopt;
    Float l = 2 * std::sqrt(Sqr(*rMax) - Sqr(*r));
    Point3f pStart = po + *r * (f.x * std::cos(phi) + f.y * std::sin(phi)) - l * f.z / 2;
    return BSSRDFProbeSegment{pStart, pStart + l * f.z};
}

SampledSpectrum TabulatedBSSRDF::PDF_Sp(Point3f pi, Normal3f ni) const {
    Frame f = Frame::FromZ(Vector3f(ns));
    Vector3f d = f.ToLocal(pi - po), nLocal = f.ToLocal(Vector3f(ni));
    // The radius of pi in the plane perpendicular to each axis, and the axes' probabilities
    const Float rProj[3] = {std::sqrt(Sqr(d.y) + Sqr(d.z)), std::sqrt(Sqr(d.z) + Sqr(d.x)),
                            std::sqrt(Sqr(d.x) + Sqr(d.y))};
    const Float axisProb[3] = {.25f, .25f, .5f};
    const Float nAxis[3] = {nLocal.x, nLocal.y, nLocal.z};
    SampledSpectrum pdf(0.f);
    for (int axis = 0; axis < 3; ++axis)
        pdf += PDF_Sr(rProj[axis]) * (std::abs(nAxis[axis]) * axisProb[axis]);
    return pdf;
}

void SubsurfaceFromDiffuse(const BSSRDFTable& table, const SampledSpectrum& rhoEff,
                           const SampledSpectrum& mfp, SampledSpectrum* sigma_a,
                           SampledSpectrum* sigma_s) {
    for (int c = 0; c < NSpectrumSamples; ++c) {
        // No mean free path (a spectrum that is 0 at this wavelength): no medium, nothing
        // scatters back (pbrt-v4 would divide by 0)
        if (!(mfp[c] > 0)) {
            (*sigma_s)[c] = (*sigma_a)[c] = 0;
            continue;
        }
        Float rho = table.InvertEffectiveAlbedo(rhoEff[c]);
        (*sigma_s)[c] = rho / mfp[c];
        (*sigma_a)[c] = (1 - rho) / mfp[c];
    }
}

}  // namespace kiln
