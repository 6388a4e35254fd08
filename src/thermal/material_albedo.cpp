#include "thermal/material_albedo.h"

#include <algorithm>

#include "materials/bxdfs/fresnel.h"
#include "materials/materials.h"
#include "materials/subsurface_material.h"
#include "textures/basic_textures.h"
#include "thermal/thermal_emission.h"

namespace kiln {

namespace {

// Whether eta falls below 1 anywhere in range (at its ends and steps of 0.5 %)
bool IndexBelowOne(const Spectrum& eta, const SpectralRange& range) {
    for (double l = range.min; l < range.max; l *= 1.005)
        if (eta(Float(l)) < 1) return true;
    return eta(range.max) < 1;
}

}  // namespace

// Creation
const MaterialAlbedo* MaterialAlbedo::Create(const Material& material, EmissivityTables& tables,
                                             ObjectArena& arena) {
    if (const MixMaterial* mix = material.GetIf<MixMaterial>()) {
        Mix m;
        for (int i = 0; i < 2; ++i) {
            const Material& component = mix->GetMaterial(i);
            const MaterialAlbedo* a = Create(component, tables, arena);
            // A nested mix contributes its leaves
            if (const Mix* nested = a->kind.GetIf<Mix>())
                m.components.insert(m.components.end(), nested->components.begin(),
                                    nested->components.end());
            else
                m.components.push_back({&component, a});
        }
        return arena.New<MaterialAlbedo>(std::move(m));
    }
    if (material.Is<DiffuseMaterial>() || material.Is<DiffuseTransmissionMaterial>())
        return arena.New<MaterialAlbedo>(Diffuse{});
    if (material.Is<HairMaterial>()) return arena.New<MaterialAlbedo>(Hair{});
    if (const ConductorMaterial* c = material.GetIf<ConductorMaterial>())
        return arena.New<MaterialAlbedo>(ConductorEmissivity(*c, tables));
    if (const CoatedDiffuseMaterial* c = material.GetIf<CoatedDiffuseMaterial>())
        return arena.New<MaterialAlbedo>(CoatedDiffuseEmissivity(*c, material, tables));
    if (const CoatedConductorMaterial* c = material.GetIf<CoatedConductorMaterial>())
        return arena.New<MaterialAlbedo>(CoatedConductorEmissivity(*c, material, tables));
    if (const MeasuredMaterial* m = material.GetIf<MeasuredMaterial>())
        return arena.New<MaterialAlbedo>(MeasuredEmissivity(*m, tables, arena));
    if (const SubsurfaceMaterial* s = material.GetIf<SubsurfaceMaterial>()) {
        const SubsurfaceMaterial::Params& p = s->Parameters();
        auto isZero = [](const FloatTexture& t) {
            const FloatConstantTexture* c = t.GetIf<FloatConstantTexture>();
            return c && c->Value() == 0;
        };
        // The probe radii stop at the profile's 0.999 quantile (TabulatedBSSRDF::SampleSp)
        Float C = NormalizedFresnelBxDF(p.eta).ExitFraction() * 0.999f;
        return arena.New<MaterialAlbedo>(
            Subsurface{C, isZero(p.uRoughness) && isZero(p.vRoughness)});
    }
    if (const DielectricMaterial* d = material.GetIf<DielectricMaterial>()) {
        auto isZero = [](const FloatTexture& t) {
            std::optional<Float> v = t.ConstantValue();
            return v && *v <= 0;
        };
        if (!isZero(d->URoughness()) || !isZero(d->VRoughness()))
            return arena.New<MaterialAlbedo>(DielectricEmissivity(*d, tables));
        if (d->K())
            return arena.New<MaterialAlbedo>(
                AbsorbingDielectric{IndexBelowOne(d->Eta(), tables.Range())});
    }
    return arena.New<MaterialAlbedo>(NonAbsorbing{});
}

namespace {

// An absorbing dielectric seen from wo (local frame): whether wo lies outside, beyond the cone
// of directions that refract into the body (only where its real index is below 1)
bool BeyondRefractionCone(const DielectricBxDF& d, Vector3f wo) {
    if (d.K() == 0 || CosTheta(wo) <= 0 || d.Eta() >= 1) return false;
    return Sin2Theta(wo) >= Sqr(d.Eta());
}

}  // namespace

bool MaterialAlbedo::Exact() const {
    return kind.Dispatch([&](const auto& k) -> bool {
        using K = std::decay_t<decltype(k)>;
        if constexpr (std::is_same_v<K, ConductorEmissivity> ||
                      std::is_same_v<K, DielectricEmissivity> ||
                      std::is_same_v<K, CoatedDiffuseEmissivity> ||
                      std::is_same_v<K, CoatedConductorEmissivity>)
            return k.Exact();
        else if constexpr (std::is_same_v<K, Subsurface>)
            return k.smooth;
        else if constexpr (std::is_same_v<K, Mix>)
            return std::all_of(k.components.begin(), k.components.end(),
                               [](const auto& c) { return c.second->Exact(); });
        else
            return true;
    });
}

bool MaterialAlbedo::SurfaceAbsorbs() const {
    return kind.Dispatch([&](const auto& k) -> bool {
        using K = std::decay_t<decltype(k)>;
        if constexpr (std::is_same_v<K, NonAbsorbing>)
            return false;
        else if constexpr (std::is_same_v<K, AbsorbingDielectric>)
            return k.indexBelowOne;
        else
            return true;
    });
}

// Evaluation
SampledSpectrum MaterialAlbedo::EvaluateLocal(const Material* material, const BSDF& bsdf,
                                              Vector3f wo, const SampledWavelengths& lambda,
                                              const SurfaceInteraction* si) const {
    const BxDF& bxdf = bsdf.GetBxDF();
    return kind.Dispatch([&](const auto& k) -> SampledSpectrum {
        using K = std::decay_t<decltype(k)>;
        if constexpr (std::is_same_v<K, Diffuse>) {
            if (const DiffuseBxDF* d = bxdf.GetIf<DiffuseBxDF>()) return d->Reflectance();
            // A diffusing sheet: what it reflects and what it lets through, from either side
            if (const DiffuseTransmissionBxDF* d = bxdf.GetIf<DiffuseTransmissionBxDF>())
                return d->Reflectance() + d->Transmittance();
            return SampledSpectrum(1.f);
        } else if constexpr (std::is_same_v<K, Hair>) {
            const HairBxDF* h = bxdf.GetIf<HairBxDF>();
            return h ? h->Albedo(wo) : SampledSpectrum(1.f);
        } else if constexpr (std::is_same_v<K, NonAbsorbing>) {
            return SampledSpectrum(1.f);
        } else if constexpr (std::is_same_v<K, AbsorbingDielectric>) {
            const DielectricBxDF* d = bxdf.GetIf<DielectricBxDF>();
            if (!d || !BeyondRefractionCone(*d, wo)) return SampledSpectrum(1.f);
            return SampledSpectrum(FrAbsorbingDielectric(CosTheta(wo), d->Eta(), d->K()));
        } else if constexpr (std::is_same_v<K, DielectricEmissivity>) {
            const DielectricBxDF* d = bxdf.GetIf<DielectricBxDF>();
            return d ? k.Albedo(*d, wo, lambda) : SampledSpectrum(1.f);
        } else if constexpr (std::is_same_v<K, ConductorEmissivity>) {
            const ConductorBxDF* c = bxdf.GetIf<ConductorBxDF>();
            if (!c) return SampledSpectrum(1.f);
            // The temperature the scene's shader built the BSDF at (none without si: then the
            // Fresnel factors come from the BSDF's constants)
            Float T = -1;
            if (k.NeedsTemperature() && si) T = si->thermal ? si->thermal->Temperature(*si) : 0;
            return k.Albedo(*c, wo, lambda, T);
        } else if constexpr (std::is_same_v<K, CoatedDiffuseEmissivity>) {
            const CoatedDiffuseBxDF* c = bxdf.GetIf<CoatedDiffuseBxDF>();
            return c ? k.Albedo(*c, wo, lambda) : SampledSpectrum(1.f);
        } else if constexpr (std::is_same_v<K, CoatedConductorEmissivity>) {
            const CoatedConductorBxDF* c = bxdf.GetIf<CoatedConductorBxDF>();
            if (!c) return SampledSpectrum(1.f);
            // The temperature the scene's shader built the BSDF at (as for conductors)
            Float T = 0;
            if (k.NeedsTemperature() && si && si->thermal) T = si->thermal->Temperature(*si);
            return k.Albedo(*c, wo, lambda, T);
        } else if constexpr (std::is_same_v<K, MeasuredEmissivity>) {
            return bxdf.Is<MeasuredBxDF>() ? k.Albedo(wo, lambda) : SampledSpectrum(1.f);
        } else if constexpr (std::is_same_v<K, Subsurface>) {
            const DielectricBxDF* d = bxdf.GetIf<DielectricBxDF>();
            const SubsurfaceMaterial* s =
                material ? material->GetIf<SubsurfaceMaterial>() : nullptr;
            if (!d || !s) return SampledSpectrum(1.f);
            Float R = FrDielectric(CosTheta(wo), d->Eta());
            MaterialEvalContext ctx = si ? MaterialEvalContext(*si) : MaterialEvalContext();
            return SampledSpectrum(R) + (1 - R) * k.exitFraction * s->EffectiveAlbedo(ctx, lambda);
        } else {
            for (const auto& [component, albedo] : k.components)
                if (component == material)
                    return albedo->EvaluateLocal(material, bsdf, wo, lambda, si);
            return SampledSpectrum(1.f);
        }
    });
}

SampledSpectrum BSDFReflectance::DirectionalAlbedo(Vector3f wo,
                                                   const SampledWavelengths& lambda) const {
    if (!bsdf) return SampledSpectrum(1.f);
    return Clamp(albedo.EvaluateLocal(material, bsdf, wo, lambda, si), Float(0), Float(1));
}

SampledSpectrum BSDFReflectance::EquilibriumScale(Vector3f wo, const SampledWavelengths&) const {
    // Radiance in a body of index n is n^2 times that outside in equilibrium; pbrt-v4's
    // dielectrics face vacuum (their eta is relative)
    if (bsdf && bsdf.PointsInside(wo) && material && material->Is<DielectricMaterial>())
        if (const DielectricBxDF* d = bsdf.GetBxDF().GetIf<DielectricBxDF>())
            return SampledSpectrum(Sqr(d->Eta()));
    return SampledSpectrum(1.f);
}

ReflectedPolarization BSDFReflectance::LinearPolarization(Vector3f wo) const {
    if (!bsdf) return {};
    return albedo.LinearPolarizationLocal(material, bsdf, wo);
}

SampledSpectrum MaterialAlbedo::Evaluate(const Material* material, const BSDF& bsdf,
                                         Vector3f woRender,
                                         const SampledWavelengths& lambda) const {
    return Reflectance(material, bsdf).DirectionalAlbedo(bsdf.RenderToLocal(woRender), lambda);
}

SampledSpectrum MaterialAlbedo::Hemispherical(const Material* material, const BSDF& bsdf,
                                              const SampledWavelengths& lambda) const {
    if (!bsdf) return SampledSpectrum(1.f);
    return HemisphericalAlbedo(Reflectance(material, bsdf), lambda);
}

ReflectedPolarization MaterialAlbedo::LinearPolarization(const Material* material, const BSDF& bsdf,
                                                         Vector3f woRender) const {
    if (!bsdf) return {};
    return LinearPolarizationLocal(material, bsdf, bsdf.RenderToLocal(woRender));
}

ReflectedPolarization MaterialAlbedo::LinearPolarizationLocal(const Material* material,
                                                              const BSDF& bsdf, Vector3f wo) const {
    return kind.Dispatch([&](const auto& k) -> ReflectedPolarization {
        using K = std::decay_t<decltype(k)>;
        if constexpr (std::is_same_v<K, ConductorEmissivity>) {
            const ConductorBxDF* c = bsdf.GetBxDF().GetIf<ConductorBxDF>();
            if (c) return k.LinearPolarization(*c, wo);
        } else if constexpr (std::is_same_v<K, AbsorbingDielectric>) {
            // Within the cone reflection and transmission polarise oppositely and cancel
            const DielectricBxDF* d = bsdf.GetBxDF().GetIf<DielectricBxDF>();
            if (d && BeyondRefractionCone(*d, wo)) {
                FresnelRsRp R = FrAbsorbingDielectricPolarized(CosTheta(wo), d->Eta(), d->K());
                return {SampledSpectrum((R.Rs - R.Rp) / 2), SampledSpectrum(0.f)};
            }
        } else if constexpr (std::is_same_v<K, Mix>) {
            for (const auto& [component, albedo] : k.components)
                if (component == material)
                    return albedo->LinearPolarizationLocal(material, bsdf, wo);
        }
        return {};
    });
}

}  // namespace kiln
