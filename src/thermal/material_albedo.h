// kiln's answer to the thermal module's question about a surface (surface_emission.h): the
// directional albedo A of the BSDF a kiln material built at a point, and the polarisation of
// its reflection (Wilkie & Weidlich 2011, "A Physically Plausible Model for Light Emission
// from Glowing Solid Objects").
//
// By Kirchhoff's law an opaque body in thermal equilibrium emits, in each direction and at each
// wavelength, exactly what it absorbs: emissivity(wo, lambda) = 1 - A(wo, lambda), where A is
// the directional albedo of the body's own BSDF: the expected scattering weight f |cos| / pdf
// of the BSDF the integrator scatters with, at the same point, in the same shading frame. A
// closed isothermal cavity then renders B(T) in every direction whatever its materials and
// geometry (test/render/equilibrium_test.cpp).
//
// MaterialAlbedo computes A for the BSDF a material built at a surface point, without Monte
// Carlo at render time:
//   diffuse:                  A = reflectance (closed form)
//   conductor:                Fresnel (smooth), tables of the microfacet albedo (rough;
//                             conductor_emissivity.h)
//   coateddiffuse,
//   coatedconductor:          tables of the layered walk's expectation (coated_emissivity.h)
//   measured:                 tables of the measured BRDF's albedo per file
//                             (measured_emissivity.h)
//   dielectric (smooth),
//   thindielectric, interface: A = 1, their surfaces emit nothing: a hot transparent body glows
//                             from its interior medium (volume_emission.h)
//   absorbing dielectric:     (a smooth "dielectric" with "k") A = 1 too, except from outside
//                             where the real index is below 1 (glass in its infrared absorption
//                             bands) and wo lies beyond the cone sin theta < eta that refracts
//                             into the body: no ray enters there, what is not reflected is
//                             absorbed at the surface, and A = R(wo) (fresnel.h's
//                             FrAbsorbingDielectric)
//   rough dielectric:         (with or without "k") tables of the single-scattering microfacet
//                             model's albedo from either side, which is below 1: the surface
//                             emits what it loses, inwards scaled by eta^2, the equilibrium
//                             radiance inside the body (dielectric_emissivity.h)
//   subsurface:               A = R(wo) + (1 - R(wo)) rhoEff C: the smooth boundary's Fresnel
//                             reflectance R, and of what it transmits the fraction the
//                             BSSRDF returns (the table's effective albedo at the point's
//                             single-scattering albedo, bxdfs/bssrdf_table.h) times what the
//                             exit lets out: C = NormalizedFresnelBxDF::ExitFraction() x 0.999
//                             (the BSSRDF's probe radii stop at the profile's 0.999 quantile).
//                             This is the albedo of kiln's (pbrt-v4's) BSSRDF transport on a
//                             flat surface; the emission 1 - A is that of the hot medium below
//                             the boundary. A rough boundary uses the smooth Fresnel split
//                             (approximate: Exact() is false)
//   hair:                     the sum of the hair model's attenuations, f + (1 - f)^2 T /
//                             (1 - T f) (closed form; its longitudinal and azimuthal lobes
//                             are normalised: HairBxDF::Albedo)
//   mix:                      the component chosen at the point
// Polarisation (surface_emission.h): LinearPolarization gives (a1, a2) of the reflection; for
// conductors see conductor_emissivity.h; zero for depolarising BSDFs (diffuse, coated, hair:
// their reflection is unpolarised).
//
// Rough conductors use pbrt-v4's single-scattering microfacet model, whose albedo misses the
// multiply scattered energy (for a perfect mirror metal 12 % at alpha 0.3, 69 % at alpha 1,
// normal incidence); emissivity 1 - A is consistent with it, so equilibrium holds exactly, but
// the emissivity of very rough metals is higher than a physical one.
#pragma once

#include <memory>
#include <optional>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "base/closed_set.h"
#include "base/object_arena.h"
#include "materials/bxdfs/bsdf.h"
#include "spectral/sampled_spectrum.h"
#include "thermal/coated_emissivity.h"
#include "thermal/conductor_emissivity.h"
#include "thermal/dielectric_emissivity.h"
#include "thermal/emission_model.h"
#include "thermal/emissivity_tables.h"
#include "thermal/measured_emissivity.h"

namespace kiln {

class Material;
class MaterialAlbedo;
struct SurfaceInteraction;

// The BSDF a material built at a point, as the thermal module's SurfaceReflectance
// (surface_emission.h): directions in the BSDF's local shading frame.
class BSDFReflectance {
  public:
    BSDFReflectance(const MaterialAlbedo& albedo, const Material* material, const BSDF& bsdf,
                    const SurfaceInteraction* si = nullptr)
        : albedo(albedo), material(material), bsdf(bsdf), si(si) {}
    // A(wo) in [0, 1] (the tables carry quadrature and interpolation errors of ~1e-5)
    SampledSpectrum DirectionalAlbedo(Vector3f wo, const SampledWavelengths& lambda) const;
    ReflectedPolarization LinearPolarization(Vector3f wo) const;
    // eta^2 of a dielectric seen from inside (BSDF::PointsInside: below the geometric surface
    // where the shading normal differs), else 1 (surface_emission.h)
    SampledSpectrum EquilibriumScale(Vector3f wo, const SampledWavelengths& lambda) const;

  private:
    const MaterialAlbedo& albedo;
    const Material* material;
    const BSDF& bsdf;
    const SurfaceInteraction* si;  // the point, for materials whose albedo reads textures
};
static_assert(SurfaceReflectance<BSDFReflectance>);

// The directional albedo of the BSDFs one material builds.
class MaterialAlbedo {
  public:
    // The reflectance of bsdf, which `material` built at a surface point (for a mix material,
    // the component chosen there: SurfaceInteraction::material after the scene's GetBSDF).
    // si: the point (its textures give a subsurface material's effective albedo; without it,
    // textures are evaluated at a default context, exact for constant ones).
    BSDFReflectance Reflectance(const Material* material, const BSDF& bsdf,
                                const SurfaceInteraction* si = nullptr) const {
        return BSDFReflectance(*this, material, bsdf, si);
    }
    // A of bsdf, which `material` built at a surface point (for a mix material, the component
    // chosen there: SurfaceInteraction::material after the scene's GetBSDF), seen from woRender
    // (render space). Per wavelength, in [0, 1]; 1 for an invalid BSDF.
    SampledSpectrum Evaluate(const Material* material, const BSDF& bsdf, Vector3f woRender,
                             const SampledWavelengths& lambda) const;
    // The polarisation (above) of what bsdf reflects towards woRender, about the plane of the
    // shading normal and woRender; 0 for an invalid BSDF.
    ReflectedPolarization LinearPolarization(const Material* material, const BSDF& bsdf,
                                             Vector3f woRender) const;
    // Cosine-weighted hemispherical average 2 integral A(mu) mu dmu at the point (for power
    // estimates), by 4-point Gauss-Legendre quadrature over mu.
    SampledSpectrum Hemispherical(const Material* material, const BSDF& bsdf,
                                  const SampledWavelengths& lambda) const;
    // False when the material needs the approximate Monte Carlo table (coated_emissivity.h).
    bool Exact() const;
    // Whether the surface absorbs (and so emits) anything in the scene's wavelengths: false for
    // smooth dielectrics (but absorbing ones whose real index falls below 1 there), thin
    // dielectrics and interfaces, whose hot bodies glow from their interior media.
    bool SurfaceAbsorbs() const;

    // The albedo of `material` and, for a mix, of every component (tables built here).
    static const MaterialAlbedo* Create(const Material& material, EmissivityTables& tables,
                                        ObjectArena& arena);

    struct Diffuse {};
    struct Hair {};
    struct NonAbsorbing {};
    struct AbsorbingDielectric {
        bool indexBelowOne;  // somewhere in the scene's wavelengths
    };
    struct Subsurface {
        Float exitFraction;  // C above
        bool smooth;         // a smooth boundary (else the smooth Fresnel split approximates)
    };
    struct Mix {
        std::vector<std::pair<const Material*, const MaterialAlbedo*>> components;
    };
    // How the albedo is computed, by the material's kind
    using Kind = ClosedSet<Diffuse, Hair, NonAbsorbing, AbsorbingDielectric, DielectricEmissivity,
                           ConductorEmissivity, CoatedDiffuseEmissivity, CoatedConductorEmissivity,
                           MeasuredEmissivity, Subsurface, Mix>;
    explicit MaterialAlbedo(Kind kind) : kind(std::move(kind)) {}

  private:
    friend class BSDFReflectance;
    SampledSpectrum EvaluateLocal(const Material* material, const BSDF& bsdf, Vector3f wo,
                                  const SampledWavelengths& lambda,
                                  const SurfaceInteraction* si = nullptr) const;
    ReflectedPolarization LinearPolarizationLocal(const Material* material, const BSDF& bsdf,
                                                  Vector3f wo) const;
    Kind kind;
};

}  // namespace kiln
