// Directional albedo of the conductor material's BSDF for Kirchhoff emission (emissivity.h):
// Fresnel's equations for smooth conductors, and for rough ones the Fresnel-moment form of
// bxdfs/conductor_albedo.h evaluated from tables built once per material:
//   uniform optical constants: A(cos theta, lambda) at the material's roughness, or
//     A(cos theta, log alpha, lambda) over the roughness range for textured roughness (one
//     bilinear or trilinear lookup per wavelength);
//   textured optical constants: the moment weights W_j(cos theta, alpha) (at the material's
//     alpha, or from the scene-wide cosine x alpha table) times F(mu_j) evaluated per sample.
// Anisotropic roughness uses the isotropic albedo at the roughness projected on wo's azimuth,
// sqrt(alpha_x^2 cos^2 phi + alpha_y^2 sin^2 phi) (an approximation, measured in
// test/materials/emissivity_test.cpp).
#pragma once

#include <vector>

#include "materials/bxdfs/conductor_bxdf.h"
#include "materials/emissivity_tables.h"
#include "spectral/sampled_spectrum.h"

namespace kiln {

class ConductorMaterial;

class ConductorEmissivity {
  public:
    ConductorEmissivity(const ConductorMaterial& material, EmissivityTables& tables);

    // Albedo of bxdf (built by the material) seen from wo (local shading frame).
    SampledSpectrum Albedo(const ConductorBxDF& bxdf, Vector3f wo,
                           const SampledWavelengths& lambda) const;

  private:
    const EmissivityTables* tables;
    bool uniformSpectra = false, uniformAlpha = false;
    float alpha = 0;                   // when uniformAlpha (isotropic)
    std::vector<float> albedo;         // [cos][lambda]: uniform spectra and alpha
    std::vector<float> albedoByAlpha;  // [cos][alpha][lambda]: uniform spectra, textured alpha
    std::vector<float> fresnel;        // [lambda][j]: F(mu_j), uniform spectra
    std::vector<float> weights;        // [cos][j] at alpha: uniform alpha
    const std::vector<float>* moments = nullptr;  // the scene-wide table: textured alpha
};

}  // namespace kiln
