// Directional albedo of the conductor material's BSDF for Kirchhoff emission (emissivity.h):
// Fresnel's equations for smooth conductors, and for rough ones the Fresnel-moment form of
// bxdfs/conductor_albedo.h, A = sum_j W_j F(mu_j), from tables built once per material.
//
// The moment weights W_j(cos theta, .) are tabulated over the cosine and the azimuth (uniform
// anisotropic roughness: 17 azimuths, cubic interpolation; the albedo is even about both axes
// of the distribution) at the material's roughness, or over the cosine and log alpha (the
// scene-wide table, cubic in log alpha) for textured roughness. Where the Fresnel factors are
// factorised (below), the per-material projections of that table are resampled at load to a
// log-alpha axis four times finer and interpolated linearly (two alpha nodes per lookup).
//
// The Fresnel factors F(mu_j, x) vary along one parameter x: the wavelength (constant optical
// constants or reflectance; 1 nm nodes), or the reflectance itself (textured "reflectance":
// eta = 1 and k from r, as pbrt-v4), or the wavelength and the temperature (named metals whose
// constants follow the surface's temperature, spectral/metal_temperature.h: every fourth of its
// table's 25 K nodes, 100 K apart, linear between two of them; at most 5.7e-4 in albedo from
// the Fresnel factors of the constants themselves). Tabulated over x, they are factorised,
// F(mu_j, x) ~ sum_r U_jr V_r(x), to the rank that reproduces them to 1e-5
// (base/low_rank.h; rank 7 for pbrt's named metals, up to 13 over reflectance), so a
// lookup interpolates rank-many values over the cosine and roughness once, and rank-many per
// wavelength over x. Textured eta and k evaluate F(mu_j) per sample.
//
// Textured anisotropic roughness would need a four-dimensional table; it uses the isotropic
// albedo at the root mean square roughness sqrt((alpha_x^2 + alpha_y^2) / 2), an approximation
// (Exact() is false and scene creation warns; test/thermal/material_albedo_test.cpp prints its
// error, 0.08 in albedo at alpha 0.22 x 0.55, and bounds it by 0.1 there).
#pragma once

#include <vector>

#include "base/table_axis.h"
#include "materials/bxdfs/conductor_albedo.h"
#include "materials/bxdfs/conductor_bxdf.h"
#include "spectral/sampled_spectrum.h"
#include "thermal/emissivity_tables.h"
#include "thermal/surface_emission.h"

namespace kiln {

class ConductorMaterial;

class ConductorEmissivity {
  public:
    ConductorEmissivity(const ConductorMaterial& material, EmissivityTables& tables);

    // Albedo of bxdf (built by the material) seen from wo (local shading frame). temperature:
    // the one the bxdf's constants were taken at (K; 0: none), for NeedsTemperature(); < 0:
    // unknown (the Fresnel factors are then evaluated from the bxdf's constants).
    SampledSpectrum Albedo(const ConductorBxDF& bxdf, Vector3f wo, const SampledWavelengths& lambda,
                           Float temperature = -1) const;
    // Whether the tables are over temperature too (the material's constants follow it).
    bool NeedsTemperature() const { return fresnelAxis == FresnelAxis::WavelengthTemperature; }

    // The polarisation of what bxdf reflects towards wo (local frame). Smooth conductors:
    // S1 = (Rs - Rp) / 2, S2 = 0. Rough ones: sums over the Fresnel nodes of weights
    // (ConductorAlbedoMoments::ComputeLinearPolarization) times (Rs - Rp)(mu_j) / 2, the
    // Fresnel factors per sample; the weights come from a table over the cosine (and azimuth,
    // for anisotropic roughness) built for the material, or for textured roughness from the
    // shared cosine x log-alpha table of isotropic weights (S2 = 0; anisotropic textures use
    // the root-mean-square alpha). Zero for rough conductors unless the tables were built for
    // polarised rendering (EmissivityTables::polarized).
    ReflectedPolarization LinearPolarization(const ConductorBxDF& bxdf, Vector3f wo) const;

    // False for textured anisotropic roughness (approximated).
    bool Exact() const { return exact; }

    // The azimuth axis of uniform anisotropic roughness: wo's azimuth from the axis of smaller
    // roughness, folded into [0, pi/2], mapped by u = atan(k tan phi) with
    // k = (alpha_large / alpha_small)^(1/4), which moves nodes (uniform in u) towards the
    // albedo's steeper change near that axis (the exponent minimised the largest table error
    // over anisotropy ratios 6 to 500 in test/thermal/material_albedo_test.cpp). One node when
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

    static constexpr int kMaxRank = ConductorAlbedoMoments::kNodes;

  private:
    // What the Fresnel factors vary with across the material's surface points and wavelengths
    enum class FresnelAxis { Wavelength, WavelengthTemperature, Reflectance, PerSample };
    // Table cells (cosine x azimuth or cosine x alpha) and weights around wo; returns the count.
    // projections: of the projected rows (which textured roughness resamples to a finer alpha
    // axis), else of the moment weights.
    int Cells(const TrowbridgeReitzDistribution& d, Vector3f wo, int cell[8], float weight[8],
              bool projections) const;

    const EmissivityTables* tables;
    FresnelAxis fresnelAxis = FresnelAxis::PerSample;
    bool uniformAlpha = false, exact = true;
    float alphaX = 0, alphaY = 0;  // when uniformAlpha
    Azimuths azimuths;             // when uniformAlpha
    // Moment weights W_j: [cos][azimuth][j] at the material's roughness (uniformAlpha), or the
    // scene-wide [cos][log alpha][j] table
    std::vector<float> weights;
    const std::vector<float>* moments = nullptr;
    // Polarised rendering: the weights of S1 and of S2 / sin(2 phi) per cell of `weights`,
    // [cell][S1, S2 / sin(2 phi)][j] (uniform roughness), or the shared S1 weights
    // [cos][log alpha][j] (textured roughness)
    std::vector<float> polarizationWeights;
    const std::vector<float>* polarizationMoments = nullptr;
    // Fresnel factorisation (Wavelength, Reflectance): nodes of x, V_r(x) as [x][r], and the
    // moment weights projected on U, G_r = sum_j W_j U_jr, per table cell as [cell][r]; rows
    // of `stride` floats (the rank rounded up to a multiple of four, zero-padded)
    int stride = 0;
    TableAxis fresnelNodes;
    TableAxis fresnelTemperatures;  // WavelengthTemperature: basis is [T][x][r]
    std::vector<float> basis, projected;
    // Textured roughness with factorised Fresnel factors: projected is [cos][fine alpha][r]
    // over this log-alpha axis (four times finer than the shared table's)
    TableAxis fineLogAlphas;
};

}  // namespace kiln
