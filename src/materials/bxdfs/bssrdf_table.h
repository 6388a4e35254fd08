// The photon beam diffusion table of pbrt-v4's TabulatedBSSRDF (pbrt-v4 Sec. 11.4 and 11.5;
// Habel, Christensen & Jarosz 2013, "Photon Beam Diffusion: A Hybrid Monte Carlo Method for
// Subsurface Scattering").
//
// For a semi-infinite homogeneous medium of unit extinction (sigma_t = 1) under a smooth
// boundary of relative index eta, with single-scattering albedo rho and Henyey-Greenstein
// asymmetry g, the table holds the radial exitance profile 2 pi r S(r) at optical radii r:
// single scattering (BeamDiffusionSS) plus multiple scattering (BeamDiffusionMS: the dipole of
// Grosjean's diffusion coefficient integrated along the refracted beam). rhoEff[i], the
// profile's integral over r, is the effective albedo: the fraction of the light entering the
// medium that leaves it again, before the boundary's exit weighting (NormalizedFresnelBxDF).
//
// pbrt-v4's discretisation: 100 albedos rho_i = (1 - e^{-8 i / 99}) / (1 - e^{-8}), 64 radii
// r_0 = 0, r_1 = 2.5e-3, r_j = 1.2 r_{j-1} (up to 203 mean free paths); 100 samples per
// beam integral.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "base/vecmath.h"

namespace kiln {

// The first and second moments of the dielectric Fresnel reflectance, integral_0^1 F(mu) mu^k
// dmu, as the polynomial fits pbrt-v4 uses (d'Eon & Irving 2011, "A Quantized-Diffusion Model
// for Rendering Translucent Materials", Sec. 5; the argument convention is pbrt-v4's).
Float FresnelMoment1(Float eta);
Float FresnelMoment2(Float eta);

// Exitance per unit area (per unit incident power) at optical radius r from single scattering
// along the refracted beam, and from multiple scattering (the diffusion dipole), in a medium of
// coefficients sigma_s, sigma_a (per unit length) under a boundary of relative index eta.
Float BeamDiffusionSS(Float sigma_s, Float sigma_a, Float g, Float eta, Float r);
Float BeamDiffusionMS(Float sigma_s, Float sigma_a, Float g, Float eta, Float r);

class BSSRDFTable {
  public:
    // Computes the table for (g, eta) with pbrt-v4's discretisation (about 20 ms).
    BSSRDFTable(Float g, Float eta);

    Float G() const { return g; }
    Float Eta() const { return eta; }
    std::span<const Float> RhoSamples() const { return rhoSamples; }
    std::span<const Float> RadiusSamples() const { return radiusSamples; }
    // profile[i * radii + j] = 2 pi r_j S(r_j) for albedo rho_i
    std::span<const Float> Profile() const { return profile; }
    std::span<const Float> ProfileCDF() const { return profileCDF; }
    std::span<const Float> RhoEff() const { return rhoEff; }
    Float EvalProfile(int rhoIndex, int radiusIndex) const {
        return profile[size_t(rhoIndex) * radiusSamples.size() + size_t(radiusIndex)];
    }
    // The effective albedo at single-scattering albedo rho (Catmull-Rom over the albedos, as
    // the BSSRDF's Sp integrates to); 0 outside [0, 1].
    Float EffectiveAlbedo(Float rho) const;
    // The single-scattering albedo whose effective albedo is rhoEff (pbrt-v4's
    // InvertCatmullRom of the table; clamped to the table's range).
    Float InvertEffectiveAlbedo(Float rhoEff) const;

  private:
    Float g, eta;
    std::vector<Float> rhoSamples, radiusSamples, profile, rhoEff, profileCDF;
};

// One table per (g, eta), built on first request and kept for the scene's lifetime (materials
// with the same g and eta share it).
class BSSRDFTableCache {
  public:
    const BSSRDFTable& Get(Float g, Float eta);
    int Size() const { return int(tables.size()); }
    double BuildSeconds() const { return buildSeconds; }

  private:
    std::vector<std::unique_ptr<BSSRDFTable>> tables;
    double buildSeconds = 0;
};

}  // namespace kiln
