// pbrt-v4's "subsurface" material: a dielectric boundary (DielectricBxDF) over a homogeneous
// scattering medium whose light transport is pbrt-v4's TabulatedBSSRDF
// (bxdfs/tabulated_bssrdf.h). The BSDF is the boundary's; the integrator (volpath) continues
// a path that the boundary transmits with GetBSSRDF.
#pragma once

#include <optional>

#include "materials/bxdfs/bssrdf_table.h"
#include "materials/bxdfs/dielectric_bxdf.h"
#include "materials/bxdfs/tabulated_bssrdf.h"
#include "materials/material_base.h"
#include "textures/texture.h"

namespace kiln {

class TextureParameterDictionary;

// The medium's coefficients come, as in pbrt-v4, from exactly one of: "name" (a measured medium
// of spectral/measured_media.h, mm^-1; "g" is then 0), "sigma_a" with "sigma_s" (per unit
// length), "reflectance" (the effective albedo rhoEff, inverted through the table) with "mfp"
// (mean free path, default 1), or, with none of them, pbrt-v4's default (whole milk's
// coefficients in mm^-1). "scale" (1) multiplies sigma_a and sigma_s, or mfp. "eta" (1.33),
// "g" (0), "roughness" / "uroughness" / "vroughness" (0) and "remaproughness" (true) as pbrt-v4.
class SubsurfaceMaterial : public MaterialBase {
  public:
    struct Params {
        std::optional<SpectrumTexture> sigma_a, sigma_s, reflectance, mfp;
        Float scale = 1, eta = 1.33f, g = 0;
        FloatTexture uRoughness, vRoughness;
        bool remapRoughness = true;
    };
    SubsurfaceMaterial(Params p, const BSSRDFTable* table) : p(std::move(p)), table(table) {}

    DielectricBxDF GetBxDF(const MaterialEvalContext& ctx, const SampledWavelengths& lambda) const;
    // The BSSRDF at the point (entry ctx.p, shading normal ctx.ns)
    TabulatedBSSRDF GetBSSRDF(const MaterialEvalContext& ctx,
                              const SampledWavelengths& lambda) const;
    // The medium's coefficients at the point, per unit length
    void Coefficients(const MaterialEvalContext& ctx, const SampledWavelengths& lambda,
                      SampledSpectrum* sigma_a, SampledSpectrum* sigma_s) const;
    // The fraction of the light entering the medium at the point that the BSSRDF returns to the
    // boundary: the table's effective albedo at rho = sigma_s / sigma_t (the integral of Sp over
    // a plane).
    SampledSpectrum EffectiveAlbedo(const MaterialEvalContext& ctx,
                                    const SampledWavelengths& lambda) const;

    const Params& Parameters() const { return p; }
    const BSSRDFTable& Table() const { return *table; }

    // Reads the parameters above; the table comes from tables (one per g and eta).
    static SubsurfaceMaterial* Create(const TextureParameterDictionary& params,
                                      BSSRDFTableCache& tables, ObjectArena& arena,
                                      Diagnostics& diag);

  private:
    Params p;
    const BSSRDFTable* table;
};

}  // namespace kiln
