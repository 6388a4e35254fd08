// Directional albedo of pbrt-v4's layered BxDFs (coateddiffuse, coatedconductor; layered_bxdf.h)
// without a scattering medium between the interfaces, by deterministic transfer between
// discrete directions: the expected value of the random walk that LayeredBxDF::Sample_f
// performs, truncated at the same maxDepth, computed instead of sampled.
//
// Every interface of these BxDFs is isotropic, so the expected exit weight of a walk that is
// at a given interface going up or down depends on its direction only through mu = |cos theta|.
// With sigma_t = 1 (thickness in mean free paths) and no medium, the walk alternates
//   down (at depth d): transmittance exp(-thickness / mu), then the base reflects upwards;
//   up (at depth d):   transmittance, then the coat transmits out (the walk's result) or
//                      reflects back down;
// and stops at depth maxDepth as Sample_f does. The expected values are functions of mu,
// represented by their values at nodes (cubic interpolation in between, the nodes split at the
// coat's total-internal-reflection cosine where they have a kink); each interface's transfer
// from node mu_i to the continuous mu' it scatters to is integrated by quadrature
// (microfacet_quadrature.h) or exactly for smooth interfaces. Accuracy (against Sample_f with
// 10^6 samples; test/bxdfs/layered_albedo_test.cpp): better than 2e-4 absolute.
#pragma once

#include <functional>
#include <vector>

namespace kiln {

// The dielectric coat: relative IOR (inside over outside), Trowbridge-Reitz alpha (isotropic;
// < 1e-3 is smooth, as TrowbridgeReitzDistribution::EffectivelySmooth), layer thickness in mean
// free paths and the walk's maxDepth.
struct CoatParameters {
    double eta = 1.5, alpha = 0, thickness = 0.01;
    int maxDepth = 10;
};

// coateddiffuse: the albedo is a polynomial in the base reflectance r,
//   A(mu_o, r) = sum_k coefficients[o][k] r^k,  k = 0 .. maxDepth / 2,
// for each of the outside cosines muO[o] in (0, 1].
std::vector<std::vector<double>> CoatedDiffuseAlbedoPolynomials(const CoatParameters& coat,
                                                                const std::vector<double>& muO);

// coatedconductor: A(mu_o) for each muO[o] and each of `fresnels` (one per wavelength, say):
// fresnels[l](mu) is the base conductor's Fresnel reflectance at incidence cosine mu (relative
// to the coat), conductorAlpha its roughness. Result [l][o].
std::vector<std::vector<double>> CoatedConductorAlbedo(
    const CoatParameters& coat, double conductorAlpha,
    const std::vector<std::function<double(double)>>& fresnels, const std::vector<double>& muO);

}  // namespace kiln
