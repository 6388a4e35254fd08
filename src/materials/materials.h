// The materials of pbrt-v4 that kiln supports. Each holds the textures and spectra its BxDF is
// built from (reachable through accessors, e.g. to derive emissivity = 1 - reflectance) and
// builds that BxDF at a surface point with GetBxDF.
//
// Roughness parameters are pbrt-v4's: "roughness" (or "uroughness"/"vroughness") in the units
// of the user-facing roughness, turned into Trowbridge-Reitz alpha with RoughnessToAlpha when
// remaproughness is true (the default), used as alpha directly otherwise.
#pragma once

#include <cstdint>
#include <optional>

#include "materials/bxdfs/bxdf.h"
#include "materials/hair_material.h"
#include "materials/material.h"
#include "materials/material_base.h"
#include "materials/measured_material.h"
#include "materials/subsurface_material.h"
#include "spectral/spectrum.h"
#include "textures/texture.h"

namespace kiln {

// Calls f(const FloatTexture&) or f(const SpectrumTexture&) for every texture of the material
// (of a mix: its amount; its components are materials of their own).
template <typename F>
void ForEachTexture(const Material& material, F&& f);

// Trowbridge-Reitz distribution from roughness textures evaluated at ctx.
TrowbridgeReitzDistribution RoughnessDistribution(FloatTexture uRoughness, FloatTexture vRoughness,
                                                  bool remapRoughness,
                                                  const TextureEvalContext& ctx);
// Whether every texture of the material is a constant, so that it scatters alike at every point
// of a uniform temperature (false for mix materials, which choose a component point by point;
// a named metal's constants that follow the temperature count as constant: callers check that
// the temperature is uniform).
bool HasUniformParameters(const Material& material);
// Whether a texture of the material follows the surface's temperature (not through mix).
bool ComputeUsesTemperature(const Material& material);
// Whether any texture of the material, or of a mix's components, uses the footprint.
bool ComputeUsesFootprint(const Material& material);
// A dielectric's relative IOR at the hero wavelength lambda[0]; terminates the secondary
// wavelengths if eta varies with wavelength (is not a ConstantSpectrum). 0 is taken as 1.
Float SampleEta(const Spectrum& eta, SampledWavelengths& lambda);

// DiffuseMaterial Definition
// Lambertian reflection; reflectance (albedo) clamped to [0, 1].
class DiffuseMaterial : public MaterialBase {
  public:
    explicit DiffuseMaterial(SpectrumTexture reflectance) : reflectance(reflectance) {}
    DiffuseBxDF GetBxDF(const MaterialEvalContext& ctx, const SampledWavelengths& lambda) const;
    const SpectrumTexture& Reflectance() const { return reflectance; }

  private:
    SpectrumTexture reflectance;
};

// DiffuseTransmissionMaterial Definition
// Lambertian reflection and transmission (pbrt-v4's "diffusetransmission"): reflectance and
// transmittance times scale, each clamped to [0, 1].
class DiffuseTransmissionMaterial : public MaterialBase {
  public:
    DiffuseTransmissionMaterial(SpectrumTexture reflectance, SpectrumTexture transmittance,
                                Float scale)
        : reflectance(reflectance), transmittance(transmittance), scale(scale) {}
    DiffuseTransmissionBxDF GetBxDF(const MaterialEvalContext& ctx,
                                    const SampledWavelengths& lambda) const;
    const SpectrumTexture& Reflectance() const { return reflectance; }
    const SpectrumTexture& Transmittance() const { return transmittance; }

  private:
    SpectrumTexture reflectance, transmittance;
    Float scale;
};

// ConductorMaterial Definition
// Either eta and k (complex IOR relative to the outside) or, pbrt-v4's alternative, an albedo
// "reflectance" r giving eta = 1, k = 2 sqrt(r) / sqrt(1 - r).
class ConductorMaterial : public MaterialBase {
  public:
    ConductorMaterial(std::optional<SpectrumTexture> eta, std::optional<SpectrumTexture> k,
                      std::optional<SpectrumTexture> reflectance, FloatTexture uRoughness,
                      FloatTexture vRoughness, bool remapRoughness)
        : eta(eta),
          k(k),
          reflectance(reflectance),
          uRoughness(uRoughness),
          vRoughness(vRoughness),
          remapRoughness(remapRoughness) {}
    ConductorBxDF GetBxDF(const MaterialEvalContext& ctx, const SampledWavelengths& lambda) const;

    // eta and k are set exactly when reflectance is not.
    const std::optional<SpectrumTexture>& Eta() const { return eta; }
    const std::optional<SpectrumTexture>& K() const { return k; }
    const std::optional<SpectrumTexture>& Reflectance() const { return reflectance; }
    const FloatTexture& URoughness() const { return uRoughness; }
    const FloatTexture& VRoughness() const { return vRoughness; }
    bool RemapRoughness() const { return remapRoughness; }

  private:
    std::optional<SpectrumTexture> eta, k, reflectance;
    FloatTexture uRoughness, vRoughness;
    bool remapRoughness;
};

// DielectricMaterial Definition
// Smooth or rough glass-like interface; eta is the IOR inside relative to outside. kiln: k,
// the extinction coefficient of the inside (complex index eta + i k; "spectrum k").
class DielectricMaterial : public MaterialBase {
  public:
    DielectricMaterial(Spectrum eta, FloatTexture uRoughness, FloatTexture vRoughness,
                       bool remapRoughness, std::optional<Spectrum> k = std::nullopt)
        : eta(eta),
          k(k),
          uRoughness(uRoughness),
          vRoughness(vRoughness),
          remapRoughness(remapRoughness) {}
    DielectricBxDF GetBxDF(const MaterialEvalContext& ctx, SampledWavelengths& lambda) const;

    const Spectrum& Eta() const { return eta; }
    const std::optional<Spectrum>& K() const { return k; }
    const FloatTexture& URoughness() const { return uRoughness; }
    const FloatTexture& VRoughness() const { return vRoughness; }
    bool RemapRoughness() const { return remapRoughness; }

  private:
    Spectrum eta;
    std::optional<Spectrum> k;
    FloatTexture uRoughness, vRoughness;
    bool remapRoughness;
};

// ThinDielectricMaterial Definition
// A thin smooth slab (window pane): reflection and straight-through transmission.
class ThinDielectricMaterial : public MaterialBase {
  public:
    explicit ThinDielectricMaterial(Spectrum eta) : eta(eta) {}
    ThinDielectricBxDF GetBxDF(const MaterialEvalContext& ctx, SampledWavelengths& lambda) const;
    const Spectrum& Eta() const { return eta; }

  private:
    Spectrum eta;
};

// CoatedDiffuseMaterial Definition
// A dielectric coating over a diffuse base, with an optional scattering medium of the given
// thickness (mean free paths), single-scattering albedo and HG asymmetry g in between.
class CoatedDiffuseMaterial : public MaterialBase {
  public:
    CoatedDiffuseMaterial(SpectrumTexture reflectance, SpectrumTexture albedo,
                          FloatTexture uRoughness, FloatTexture vRoughness, FloatTexture thickness,
                          FloatTexture g, Spectrum eta, int maxDepth, int nSamples,
                          bool remapRoughness, LayeredMIS mis = LayeredMIS::Kiln)
        : reflectance(reflectance),
          albedo(albedo),
          uRoughness(uRoughness),
          vRoughness(vRoughness),
          thickness(thickness),
          g(g),
          eta(eta),
          maxDepth(maxDepth),
          nSamples(nSamples),
          remapRoughness(remapRoughness),
          mis(mis) {}
    CoatedDiffuseBxDF GetBxDF(const MaterialEvalContext& ctx, SampledWavelengths& lambda) const;

    const SpectrumTexture& Reflectance() const { return reflectance; }
    const SpectrumTexture& Albedo() const { return albedo; }
    const FloatTexture& URoughness() const { return uRoughness; }
    const FloatTexture& VRoughness() const { return vRoughness; }
    const FloatTexture& Thickness() const { return thickness; }
    const FloatTexture& G() const { return g; }
    const Spectrum& Eta() const { return eta; }
    int MaxDepth() const { return maxDepth; }
    int NSamples() const { return nSamples; }
    bool RemapRoughness() const { return remapRoughness; }

  private:
    SpectrumTexture reflectance, albedo;
    FloatTexture uRoughness, vRoughness, thickness, g;
    Spectrum eta;
    int maxDepth, nSamples;
    bool remapRoughness;
    LayeredMIS mis;
};

// CoatedConductorMaterial Definition
// A dielectric coating ("interface.*") over a conductor ("conductor.*" or "reflectance"); the
// conductor's eta and k are taken relative to the coating.
class CoatedConductorMaterial : public MaterialBase {
  public:
    struct Params {
        FloatTexture interfaceURoughness, interfaceVRoughness, thickness, g;
        Spectrum interfaceEta;
        std::optional<SpectrumTexture> conductorEta, k, reflectance;
        FloatTexture conductorURoughness, conductorVRoughness;
        SpectrumTexture albedo;
        int maxDepth, nSamples;
        bool remapRoughness;
        LayeredMIS mis = LayeredMIS::Kiln;
    };
    explicit CoatedConductorMaterial(Params p) : p(std::move(p)) {}
    CoatedConductorBxDF GetBxDF(const MaterialEvalContext& ctx, SampledWavelengths& lambda) const;
    const Params& Parameters() const { return p; }

  private:
    Params p;
};

// MixMaterial Definition
// Stochastic selection between two materials: materials[1] with probability amount.
class MixMaterial : public MaterialBase {
  public:
    MixMaterial(Material m0, Material m1, FloatTexture amount)
        : materials{m0, m1}, amount(amount) {}
    // The component used at this point (may itself be a mix), chosen from a hash of ctx.p and
    // ctx.wo (rounded to a relative 1e-4) and the nesting depth of this mix (0 for the
    // outermost).
    const Material* ChooseMaterial(const MaterialEvalContext& ctx, uint64_t depth = 0) const;
    const Material& GetMaterial(int i) const { return materials[i]; }
    const FloatTexture& Amount() const { return amount; }

  private:
    Material materials[2];
    FloatTexture amount;
};

// InterfaceMaterial Definition
// No scattering: marks the boundary of a participating medium.
class InterfaceMaterial : public MaterialBase {};

// PolarizingFilterMaterial Definition
// kiln's "polarizer" and "retarder" sheets (bxdfs/polarizing_filter_bxdf.h); angle and
// retardance in radians. A scene with one renders polarised light (render/radiance.h).
class PolarizingFilterMaterial : public MaterialBase {
  public:
    PolarizingFilterMaterial(PolarizingFilterBxDF::Kind kind, Float angle, Float retardance)
        : bxdf(kind, angle, retardance) {}
    PolarizingFilterBxDF GetBxDF(const MaterialEvalContext&, const SampledWavelengths&) const {
        return bxdf;
    }

  private:
    PolarizingFilterBxDF bxdf;
};

// ForEachTexture
template <typename F>
void ForEachTexture(const Material& material, F&& f) {
    auto opt = [&](const std::optional<SpectrumTexture>& t) {
        if (t) f(*t);
    };
    if (const auto* m = material.GetIf<DiffuseMaterial>()) {
        f(m->Reflectance());
    } else if (const auto* m = material.GetIf<DiffuseTransmissionMaterial>()) {
        f(m->Reflectance()), f(m->Transmittance());
    } else if (const auto* m = material.GetIf<ConductorMaterial>()) {
        opt(m->Eta()), opt(m->K()), opt(m->Reflectance());
        f(m->URoughness()), f(m->VRoughness());
    } else if (const auto* m = material.GetIf<DielectricMaterial>()) {
        f(m->URoughness()), f(m->VRoughness());
    } else if (const auto* m = material.GetIf<CoatedDiffuseMaterial>()) {
        f(m->Reflectance()), f(m->Albedo()), f(m->URoughness()), f(m->VRoughness());
        f(m->Thickness()), f(m->G());
    } else if (const auto* m = material.GetIf<CoatedConductorMaterial>()) {
        const CoatedConductorMaterial::Params& p = m->Parameters();
        f(p.interfaceURoughness), f(p.interfaceVRoughness), f(p.thickness), f(p.g);
        opt(p.conductorEta), opt(p.k), opt(p.reflectance);
        f(p.conductorURoughness), f(p.conductorVRoughness), f(p.albedo);
    } else if (const auto* m = material.GetIf<HairMaterial>()) {
        const HairMaterial::Params& p = m->Parameters();
        opt(p.sigma_a), opt(p.reflectance);
        if (p.eumelanin) f(*p.eumelanin);
        if (p.pheomelanin) f(*p.pheomelanin);
        f(p.eta), f(p.beta_m), f(p.beta_n), f(p.alpha);
    } else if (const auto* m = material.GetIf<SubsurfaceMaterial>()) {
        const SubsurfaceMaterial::Params& p = m->Parameters();
        opt(p.sigma_a), opt(p.sigma_s), opt(p.reflectance), opt(p.mfp);
        f(p.uRoughness), f(p.vRoughness);
    } else if (const auto* m = material.GetIf<MixMaterial>()) {
        f(m->Amount());
    }
}

}  // namespace kiln
