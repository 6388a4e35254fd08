#include "materials/materials.h"

#include <cstring>

#include "base/rng.h"
#include "textures/basic_textures.h"
#include "textures/metal_temperature_texture.h"

namespace kiln {

// Shared helpers
TrowbridgeReitzDistribution RoughnessDistribution(FloatTexture uRoughness, FloatTexture vRoughness,
                                                  bool remapRoughness,
                                                  const TextureEvalContext& ctx) {
    Float uRough = uRoughness.Evaluate(ctx), vRough = vRoughness.Evaluate(ctx);
    if (remapRoughness) {
        uRough = TrowbridgeReitzDistribution::RoughnessToAlpha(uRough);
        vRough = TrowbridgeReitzDistribution::RoughnessToAlpha(vRough);
    }
    return TrowbridgeReitzDistribution(uRough, vRough);
}

Float SampleEta(const Spectrum& eta, SampledWavelengths& lambda) {
    Float sampledEta = eta(lambda[0]);
    if (!eta.Is<ConstantSpectrum>()) lambda.TerminateSecondary();
    // Handle a zero eta from a poorly specified spectrum as pbrt-v4 does
    return sampledEta == 0 ? 1 : sampledEta;
}

bool HasUniformParameters(const Material& material) {
    if (material.Is<MixMaterial>()) return false;  // chosen point by point
    bool uniform = true;
    ForEachTexture(material, [&](const auto& t) {
        using T = std::decay_t<decltype(t)>;
        if constexpr (std::is_same_v<T, FloatTexture>)
            uniform &= t.template Is<FloatConstantTexture>();
        else
            uniform &= t.template Is<SpectrumConstantTexture>() ||
                       t.template Is<SpectrumMetalTemperatureTexture>();
    });
    return uniform;
}

bool ComputeUsesTemperature(const Material& material) {
    bool uses = false;
    ForEachTexture(material, [&](const auto& t) {
        using T = std::decay_t<decltype(t)>;
        if constexpr (std::is_same_v<T, SpectrumTexture>)
            if (const auto* m = t.template GetIf<SpectrumMetalTemperatureTexture>())
                uses |= m->FollowsSurface();
    });
    return uses;
}

bool ComputeUsesFootprint(const Material& material) {
    bool uses = false;
    ForEachTexture(material, [&](const auto& t) { uses |= t.UsesFootprint(); });
    uses |= material.Perturbation().UsesFootprint();
    if (const MixMaterial* mix = material.GetIf<MixMaterial>())
        uses |= mix->GetMaterial(0).UsesFootprint() || mix->GetMaterial(1).UsesFootprint();
    return uses;
}

namespace {

// Conductor eta and k from either the complex IOR textures or an albedo reflectance r:
// eta = 1, k = 2 sqrt(r) / sqrt(1 - r) (r clamped below 1).
void ConductorEtaK(const std::optional<SpectrumTexture>& eta,
                   const std::optional<SpectrumTexture>& k,
                   const std::optional<SpectrumTexture>& reflectance, const TextureEvalContext& ctx,
                   const SampledWavelengths& lambda, SampledSpectrum* etas, SampledSpectrum* ks) {
    if (eta && k) {
        // A named metal at temperature: both from one evaluation of its table
        const auto* hot = eta->GetIf<SpectrumMetalTemperatureTexture>();
        if (hot && k->Is<SpectrumMetalTemperatureTexture>()) {
            hot->EvaluateBoth(ctx, lambda, etas, ks);
            return;
        }
        *etas = eta->Evaluate(ctx, lambda);
        *ks = k->Evaluate(ctx, lambda);
        return;
    }
    SampledSpectrum r = Clamp(reflectance->Evaluate(ctx, lambda), Float(0), 0.9999f);
    *etas = SampledSpectrum(1);
    *ks = 2 * Sqrt(r) / Sqrt(ClampZero(SampledSpectrum(1) - r));
}

}  // namespace

// DiffuseMaterial Method Definitions
DiffuseBxDF DiffuseMaterial::GetBxDF(const MaterialEvalContext& ctx,
                                     const SampledWavelengths& lambda) const {
    return DiffuseBxDF(Clamp(reflectance.Evaluate(ctx, lambda), Float(0), Float(1)));
}

// DiffuseTransmissionMaterial Method Definitions
DiffuseTransmissionBxDF DiffuseTransmissionMaterial::GetBxDF(
    const MaterialEvalContext& ctx, const SampledWavelengths& lambda) const {
    return DiffuseTransmissionBxDF(
        Clamp(scale * reflectance.Evaluate(ctx, lambda), Float(0), Float(1)),
        Clamp(scale * transmittance.Evaluate(ctx, lambda), Float(0), Float(1)));
}

// ConductorMaterial Method Definitions
ConductorBxDF ConductorMaterial::GetBxDF(const MaterialEvalContext& ctx,
                                         const SampledWavelengths& lambda) const {
    TrowbridgeReitzDistribution distrib =
        RoughnessDistribution(uRoughness, vRoughness, remapRoughness, ctx);
    SampledSpectrum etas, ks;
    ConductorEtaK(eta, k, reflectance, ctx, lambda, &etas, &ks);
    return ConductorBxDF(distrib, etas, ks);
}

// DielectricMaterial Method Definitions
DielectricBxDF DielectricMaterial::GetBxDF(const MaterialEvalContext& ctx,
                                           SampledWavelengths& lambda) const {
    Float sampledEta = SampleEta(eta, lambda);
    // An absorbing interface follows one wavelength when k varies with it, as for eta
    Float sampledK = 0;
    if (k) {
        sampledK = std::max<Float>(0, (*k)(lambda[0]));
        if (!k->Is<ConstantSpectrum>()) lambda.TerminateSecondary();
    }
    return DielectricBxDF(
        sampledEta, RoughnessDistribution(uRoughness, vRoughness, remapRoughness, ctx), sampledK);
}

// ThinDielectricMaterial Method Definitions
ThinDielectricBxDF ThinDielectricMaterial::GetBxDF(const MaterialEvalContext& ctx,
                                                   SampledWavelengths& lambda) const {
    return ThinDielectricBxDF(SampleEta(eta, lambda), eta.Is<ConstantSpectrum>());
}

// CoatedDiffuseMaterial Method Definitions
CoatedDiffuseBxDF CoatedDiffuseMaterial::GetBxDF(const MaterialEvalContext& ctx,
                                                 SampledWavelengths& lambda) const {
    SampledSpectrum r = Clamp(reflectance.Evaluate(ctx, lambda), Float(0), Float(1));
    TrowbridgeReitzDistribution distrib =
        RoughnessDistribution(uRoughness, vRoughness, remapRoughness, ctx);
    Float thick = thickness.Evaluate(ctx);
    Float sampledEta = SampleEta(eta, lambda);
    SampledSpectrum a = Clamp(albedo.Evaluate(ctx, lambda), Float(0), Float(1));
    Float gg = Clamp(g.Evaluate(ctx), Float(-1), Float(1));
    return CoatedDiffuseBxDF(DielectricBxDF(sampledEta, distrib), DiffuseBxDF(r), thick, a, gg,
                             maxDepth, nSamples, mis);
}

// CoatedConductorMaterial Method Definitions
CoatedConductorBxDF CoatedConductorMaterial::GetBxDF(const MaterialEvalContext& ctx,
                                                     SampledWavelengths& lambda) const {
    TrowbridgeReitzDistribution interfaceDistrib =
        RoughnessDistribution(p.interfaceURoughness, p.interfaceVRoughness, p.remapRoughness, ctx);
    Float ieta = SampleEta(p.interfaceEta, lambda);
    // The conductor's IOR relative to the coating
    SampledSpectrum ce, ck;
    ConductorEtaK(p.conductorEta, p.k, p.reflectance, ctx, lambda, &ce, &ck);
    ce /= ieta;
    ck /= ieta;
    TrowbridgeReitzDistribution conductorDistrib =
        RoughnessDistribution(p.conductorURoughness, p.conductorVRoughness, p.remapRoughness, ctx);
    Float thick = p.thickness.Evaluate(ctx);
    SampledSpectrum a = Clamp(p.albedo.Evaluate(ctx, lambda), Float(0), Float(1));
    Float gg = Clamp(p.g.Evaluate(ctx), Float(-1), Float(1));
    return CoatedConductorBxDF(DielectricBxDF(ieta, interfaceDistrib),
                               ConductorBxDF(conductorDistrib, ce, ck), thick, a, gg, p.maxDepth,
                               p.nSamples, p.mis);
}

// MixMaterial Method Definitions
const Material* MixMaterial::ChooseMaterial(const MaterialEvalContext& ctx, uint64_t depth) const {
    Float amt = amount.Evaluate(ctx);
    if (amt <= 0) return &materials[0];
    if (amt >= 1) return &materials[1];
    // Deterministic uniform value in [0, 1) from the point and direction (and the nesting
    // depth, so that nested mixes choose independently); independent of memory addresses, so
    // renders repeat exactly. The coordinates lose their last 10 mantissa bits first (a
    // relative 1e-4), so that a ray hit and a light sample at the same point, which differ by
    // rounding, choose alike (emission follows the choice: thermal_area_light.h).
    auto coarse = [](Float x) {
        uint32_t bits;
        std::memcpy(&bits, &x, sizeof(bits));
        return bits & ~uint32_t(0x3ff);
    };
    uint64_t h = Hash(coarse(ctx.p.x), coarse(ctx.p.y), coarse(ctx.p.z), coarse(ctx.wo.x),
                      coarse(ctx.wo.y), coarse(ctx.wo.z), depth);
    Float u = std::min<Float>(Float(h >> 40) * 0x1p-24f, 0x1.fffffep-1f);
    return amt < u ? &materials[0] : &materials[1];
}

}  // namespace kiln
