// pbrt-v4's TabulatedBSSRDF: the separable BSSRDF S = (1 - F(cos_o)) Sp(|po - pi|) Sw(wi) of a
// homogeneous medium under a dielectric boundary, with the radial profile Sp read from a
// BSSRDFTable (bssrdf_table.h) scaled to the point's extinction sigma_t and interpolated at its
// single-scattering albedo rho = sigma_s / sigma_t, per wavelength. The exit's directional
// part Sw is NormalizedFresnelBxDF (normalized_fresnel_bxdf.h).
//
// Sampling the exit point (SampleSp): one of three projection axes of the shading frame at the
// entry point (the normal with probability 1/2, each tangent 1/4), a radius from the hero
// wavelength's profile (rejected beyond its 0.999 quantile r_max) and a uniform angle give a
// probe segment of length 2 sqrt(r_max^2 - r^2) along the axis; the integrator intersects the
// scene along it and picks one hit on the same material. PDF_Sp is the density of such a hit
// per unit area, combining the three axes (one-sample MIS over the projections).
#pragma once

#include <optional>

#include "base/vecmath.h"
#include "materials/bxdfs/bssrdf_table.h"
#include "spectral/sampled_spectrum.h"

namespace kiln {

// A probe segment from p0 to p1 along which exit points are searched
struct BSSRDFProbeSegment {
    Point3f p0, p1;
};

class TabulatedBSSRDF {
  public:
    // po: the entry point; ns its shading normal; sigma_a, sigma_s per unit length of render
    // space (per wavelength).
    TabulatedBSSRDF(Point3f po, Normal3f ns, Float eta, const SampledSpectrum& sigma_a,
                    const SampledSpectrum& sigma_s, const BSSRDFTable* table)
        : po(po),
          ns(ns),
          eta(eta),
          sigma_t(sigma_a + sigma_s),
          rho(SafeDiv(sigma_s, sigma_a + sigma_s)),
          table(table) {}

    // The radial profile Sr at distance r (per unit area; integral over the plane = rhoEff)
    SampledSpectrum Sr(Float r) const;
    SampledSpectrum Sp(Point3f pi) const { return Sr(Distance(po, pi)); }
    // A radius from the hero wavelength's profile (nullopt if its sigma_t is 0)
    std::optional<Float> SampleSr(Float u) const;
    // The density (per unit area of the plane) of radius r under each wavelength's profile
    SampledSpectrum PDF_Sr(Float r) const;
    // A probe segment (above); nullopt when rejected
    std::optional<BSSRDFProbeSegment> SampleSp(Float u1, Point2f u2) const;
    // The density per unit area of finding the exit point pi (geometric normal ni) by SampleSp
    SampledSpectrum PDF_Sp(Point3f pi, Normal3f ni) const;

    Float Eta() const { return eta; }
    const SampledSpectrum& Rho() const { return rho; }
    const SampledSpectrum& SigmaT() const { return sigma_t; }

  private:
    // The profile interpolated at rho[i] and optical radius rOptical (unitless), and the
    // effective albedo at rho[i]; false outside the table.
    bool Interpolate(int i, Float rOptical, Float* sr, Float* rhoEff) const;

    Point3f po;
    Normal3f ns;
    Float eta;
    SampledSpectrum sigma_t, rho;
    const BSSRDFTable* table;
};

// The sigma_a and sigma_s (per unit length) of a medium whose effective albedo is rhoEff and
// whose mean free path 1 / sigma_t is mfp, per wavelength (pbrt-v4's SubsurfaceFromDiffuse);
// 0 and 0 where mfp is not positive.
void SubsurfaceFromDiffuse(const BSSRDFTable& table, const SampledSpectrum& rhoEff,
                           const SampledSpectrum& mfp, SampledSpectrum* sigma_a,
                           SampledSpectrum* sigma_s);

}  // namespace kiln
