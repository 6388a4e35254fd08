// Directional albedo of the coated materials' BSDFs for Kirchhoff emission (emissivity.h),
// from the deterministic walk expectations of bxdfs/layered_albedo.h, tabulated once per
// material:
//   coateddiffuse: A(cos theta, r) = sum_k a_k(cos theta) r^k, exact in the base reflectance
//     r (so reflectance textures cost nothing), with a roughness axis when the coat's
//     roughness is textured and a wavelength axis when its IOR is dispersive;
//   coatedconductor: A(cos theta, lambda) for the conductor's optical constants, with
//     roughness axes when the coat's or the conductor's roughness is textured, and a
//     temperature axis when the constants are a named metal's that follow the surface's
//     temperature (spectral/metal_temperature.h: every eighth of its table's 25 K nodes, 200 K
//     apart, linear between two; test/thermal/material_albedo_test.cpp bounds the error).
// What the walk expectations do not cover (a scattering layer, "albedo" > 0; textured
// thickness, g or conductor optical constants; a dispersive coat over a conductor) uses a
// Monte Carlo table of the BxDF at the material's untextured values, accurate to about 1e-2;
// Exact() is then false and scene creation warns.
#pragma once

#include <optional>
#include <vector>

#include "base/table_axis.h"
#include "materials/bxdfs/layered_bxdf.h"
#include "spectral/sampled_spectrum.h"
#include "thermal/emissivity_tables.h"

namespace kiln {

class CoatedDiffuseMaterial;
class CoatedConductorMaterial;
class Material;

// A(cos theta, lambda) of a material's BSDF at a fixed point, by Monte Carlo over Sample_f
// (the fallback).
class SampledAlbedoTable {
  public:
    SampledAlbedoTable() = default;
    SampledAlbedoTable(const Material& material, const EmissivityTables& tables);
    SampledSpectrum Albedo(Vector3f wo, const SampledWavelengths& lambda) const;

  private:
    TableAxis cosines, lambdas;
    std::vector<float> albedo;  // [cos][lambda]
};

class CoatedDiffuseEmissivity {
  public:
    CoatedDiffuseEmissivity(const CoatedDiffuseMaterial& material, const Material& handle,
                            EmissivityTables& tables);
    SampledSpectrum Albedo(const CoatedDiffuseBxDF& bxdf, Vector3f wo,
                           const SampledWavelengths& lambda) const;
    bool Exact() const { return !fallback; }

  private:
    const EmissivityTables* tables;
    TableAxis alphas, lambdas;  // one node each when uniform
    int nCoefficients = 0;
    std::vector<float> coefficients;  // [lambda][alpha][cos][k]
    std::optional<SampledAlbedoTable> fallback;
};

class CoatedConductorEmissivity {
  public:
    CoatedConductorEmissivity(const CoatedConductorMaterial& material, const Material& handle,
                              EmissivityTables& tables);
    // temperature: the one the bxdf's constants were taken at (K), for NeedsTemperature()
    SampledSpectrum Albedo(const CoatedConductorBxDF& bxdf, Vector3f wo,
                           const SampledWavelengths& lambda, Float temperature = 0) const;
    bool Exact() const { return !fallback; }
    // Whether the tables are over temperature too (the conductor's constants follow it)
    bool NeedsTemperature() const { return temperatures.Size() > 1; }

  private:
    const EmissivityTables* tables;
    TableAxis coatAlphas, baseAlphas;  // one node each when uniform
    TableAxis temperatures;            // K; one node (unused) unless NeedsTemperature()
    std::vector<float> albedo;         // [coat alpha][base alpha][cos][temperature][lambda]
    std::optional<SampledAlbedoTable> fallback;
};

}  // namespace kiln
