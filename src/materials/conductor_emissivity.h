// Directional albedo of the conductor material's BSDF for Kirchhoff emission (emissivity.h):
// Fresnel's equations for smooth conductors, and for rough ones the Fresnel-moment form of
// bxdfs/conductor_albedo.h evaluated from tables built once per material:
//   uniform optical constants: A(cos theta, lambda) at the material's roughness, or
//     A(cos theta, log alpha, lambda) over the roughness range for textured roughness (one
//     bilinear or trilinear lookup per wavelength);
//   textured optical constants: the moment weights W_j(cos theta, alpha) (at the material's
//     alpha, or from the scene-wide cosine x alpha table) times F(mu_j) evaluated per sample.
// Uniform anisotropic roughness adds an azimuth axis to the material's tables (33 nodes, cubic
// interpolation; the albedo is even about both axes of the distribution). Textured anisotropic
// roughness would need a four-dimensional table; it uses the isotropic albedo at the root mean
// square roughness sqrt((alpha_x^2 + alpha_y^2) / 2), an approximation (Exact() is false and
// scene creation warns; test/materials/emissivity_test.cpp prints its error, 0.08 in albedo
// at alpha 0.22 x 0.55, and bounds it by 0.1 there).
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

    // False for textured anisotropic roughness (approximated).
    bool Exact() const { return exact; }

    // The azimuth axis of uniform anisotropic roughness: wo's azimuth from the axis of smaller
    // roughness, folded into [0, pi/2], mapped by u = atan(k tan phi) with
    // k = (alpha_large / alpha_small)^(1/4), which moves nodes (uniform in u) towards the
    // albedo's steeper change near that axis (the exponent minimised the largest table error
    // over anisotropy ratios 6 to 500 in test/materials/emissivity_test.cpp). One node when
    // isotropic.
    struct Azimuths {
        int n = 1;
        bool smoothAxisY = false;
        double k = 1;
        // Azimuth of node i (radians from the x axis).
        double Phi(int i) const;
        // Up to four nodes and their cubic interpolation weights at wo; returns the count.
        int Weights(Vector3f wo, int node[4], float weight[4]) const;
    };

  private:
    const EmissivityTables* tables;
    bool uniformSpectra = false, uniformAlpha = false, exact = true;
    float alphaX = 0, alphaY = 0;      // when uniformAlpha
    Azimuths azimuths;                 // when uniformAlpha
    std::vector<float> albedo;         // [cos][azimuth][lambda]: uniform spectra and alpha
    std::vector<float> albedoByAlpha;  // [cos][alpha][lambda]: uniform spectra, textured alpha
    std::vector<float> fresnel;        // [lambda][j]: F(mu_j), uniform spectra
    std::vector<float> weights;        // [cos][azimuth][j] at alpha: uniform alpha
    const std::vector<float>* moments = nullptr;  // the scene-wide table: textured alpha
};

}  // namespace kiln
