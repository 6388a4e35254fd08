// Directional albedo of a rough dielectric's BSDF for Kirchhoff emission (material_albedo.h).
//
// pbrt-v4's rough dielectric scatters once off its microfacets: light that the masking and
// shadowing term G / G1 removes (it would meet the surface again), and reflections or
// refractions about a facet that point to the wrong side of the surface, are lost. Its
// directional albedo E(wo), the expectation of f |cos| / pdf of its own Sample_f in importance
// mode (power, without radiance's 1 / eta^2), is then below 1 from either side: at roughness 0.3
// (alpha 0.55) a body of index 1.5 holding a hot melt rendered 7.8 % below B(T) in a closed
// cavity when its surface emitted nothing. In equilibrium the radiance arriving is B outside
// and n^2 B inside a body of index n, so the surface emits B (1 - E) outwards and
// n^2 B (1 - E) inwards (BSDFReflectance::EquilibriumScale), and the cavity renders B.
//
// E is tabulated once per material, by quadrature of Sample_f (reflection and refraction each
// forced, their weights summed, so the choice between them adds no error) over an n x n grid of
// midpoints in (s, u.y), u.x = 1 - s^2 (Quadrature), on the nodes of
//   cos theta_o:  the shared cosine axis (64 nodes), outside and inside;
//   eta:          where k is constant (or absent), the real index over the range it takes in
//                 the scene's wavelengths (one node for a constant eta, else 2-8 nodes at most
//                 0.02 apart where they fit); where k varies with wavelength, the wavelength
//                 instead (the shared 95-node axis), as a varying k or eta makes the hero
//                 wavelength the only one;
//   log alpha:    where the roughness is textured, 24 nodes from 1e-3 to 4; else the
//                 material's alpha;
// n = 64 (within 2e-3 of a 512 x 512 quadrature, test/thermal/dielectric_emissivity_test.cpp)
// where the table is small (up to six eta nodes), fewer where the axes multiply (about 6.5
// million samples in all, at least 8 x 8 points per node: 0.12 s for a constant eta and 0.31 s
// for glass-BAF10's dispersion on two cores). Lookups are linear in each axis. The table is
// approximate (Exact() false) where n falls below 64, or the roughness is textured (interpolated in
// alpha) or anisotropic (the table of the isotropic alpha sqrt(alpha_x alpha_y): 0.04 from the
// BSDF's albedo at alpha 0.32 x 0.55, the test's bound 0.05). The reflection is taken as
// unpolarised: polarised emission of rough dielectrics is not modelled.
#pragma once

#include <vector>

#include "base/table_axis.h"
#include "materials/bxdfs/dielectric_bxdf.h"
#include "spectral/sampled_spectrum.h"
#include "thermal/emissivity_tables.h"

namespace kiln {

class DielectricMaterial;

class DielectricEmissivity {
  public:
    DielectricEmissivity(const DielectricMaterial& material, const EmissivityTables& tables);

    // E(wo) of bxdf (built by the material; local frame, wo.z < 0 inside the body) per
    // wavelength. Smooth BxDFs: 1, but for an absorbing one seen from outside beyond the cone
    // that refracts into it (where eta < 1), R(wo) (material_albedo.h).
    SampledSpectrum Albedo(const DielectricBxDF& bxdf, Vector3f wo,
                           const SampledWavelengths& lambda) const;
    // False where the table is approximate (above).
    bool Exact() const { return exact; }

    // E(wo) of bxdf by the quadrature the table uses, with n x n points (for tests).
    static Float Quadrature(const DielectricBxDF& bxdf, Vector3f wo, int n);

  private:
    const EmissivityTables* tables;
    // The second axis: eta (byWavelength false) or the wavelength; one node where constant
    TableAxis spectral, logAlphas;
    bool byWavelength = false;
    std::vector<float> table;  // [((spectral * nAlpha + alpha) * 2 + side) * nCos + cos]
    bool exact = true;
};

}  // namespace kiln
