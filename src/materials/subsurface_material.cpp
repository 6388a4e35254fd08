#include "materials/subsurface_material.h"

#include <cmath>

#include "materials/materials.h"
#include "spectral/color.h"
#include "spectral/measured_media.h"
#include "textures/basic_textures.h"
#include "textures/texture_parameter_dictionary.h"

namespace kiln {

DielectricBxDF SubsurfaceMaterial::GetBxDF(const MaterialEvalContext& ctx,
                                           const SampledWavelengths&) const {
    return DielectricBxDF(p.eta,
                          RoughnessDistribution(p.uRoughness, p.vRoughness, p.remapRoughness, ctx));
}

void SubsurfaceMaterial::Coefficients(const MaterialEvalContext& ctx,
                                      const SampledWavelengths& lambda, SampledSpectrum* sigma_a,
                                      SampledSpectrum* sigma_s) const {
    if (p.sigma_a && p.sigma_s) {
        *sigma_a = ClampZero(p.scale * p.sigma_a->Evaluate(ctx, lambda));
        *sigma_s = ClampZero(p.scale * p.sigma_s->Evaluate(ctx, lambda));
        return;
    }
    SampledSpectrum mfree = ClampZero(p.scale * p.mfp->Evaluate(ctx, lambda));
    SampledSpectrum r = Clamp(p.reflectance->Evaluate(ctx, lambda), Float(0), Float(1));
    SubsurfaceFromDiffuse(*table, r, mfree, sigma_a, sigma_s);
}

TabulatedBSSRDF SubsurfaceMaterial::GetBSSRDF(const MaterialEvalContext& ctx,
                                              const SampledWavelengths& lambda) const {
    SampledSpectrum sigma_a, sigma_s;
    Coefficients(ctx, lambda, &sigma_a, &sigma_s);
    return TabulatedBSSRDF(ctx.p, ctx.ns, p.eta, sigma_a, sigma_s, table);
}

SampledSpectrum SubsurfaceMaterial::EffectiveAlbedo(const MaterialEvalContext& ctx,
                                                    const SampledWavelengths& lambda) const {
    SampledSpectrum sigma_a, sigma_s, rhoEff;
    Coefficients(ctx, lambda, &sigma_a, &sigma_s);
    SampledSpectrum rho = SafeDiv(sigma_s, sigma_a + sigma_s);
    for (int i = 0; i < NSpectrumSamples; ++i)
        rhoEff[i] = sigma_a[i] + sigma_s[i] > 0 ? table->EffectiveAlbedo(rho[i]) : 0;
    return rhoEff;
}

SubsurfaceMaterial* SubsurfaceMaterial::Create(const TextureParameterDictionary& params,
                                               BSSRDFTableCache& tables, ObjectArena& arena,
                                               Diagnostics& diag) {
    Params p;
    Float g = params.GetOneFloat("g", 0);
    if (!(g > -1 && g < 1)) throw SceneError(params.Loc("g"), "\"g\" must be in (-1, 1)", "g");
    auto constant = [&](const Spectrum& s) -> SpectrumTexture {
        return arena.New<SpectrumConstantTexture>(s);
    };
    std::string name = params.GetOneString("name", "");
    if (!name.empty()) {
        std::optional<std::pair<Spectrum, Spectrum>> m = MeasuredMediumCoefficients(name);
        if (!m)
            throw SceneError(params.Loc("name"), "named medium \"" + name + "\" not found", name);
        // The measured coefficients are reduced scattering coefficients: g = 0 (pbrt-v4)
        if (g != 0)
            diag.Warn(params.Loc("g"), "non-zero \"g\" ignored with named scattering coefficients");
        g = 0;
        p.sigma_a = constant(m->first);
        p.sigma_s = constant(m->second);
    } else {
        p.sigma_a = params.GetSpectrumTextureOrNull("sigma_a", SpectrumType::Unbounded, arena);
        p.sigma_s = params.GetSpectrumTextureOrNull("sigma_s", SpectrumType::Unbounded, arena);
        if (p.sigma_a && !p.sigma_s)
            throw SceneError(params.Loc("sigma_a"), "\"sigma_a\" given without \"sigma_s\"",
                             "sigma_a");
        if (p.sigma_s && !p.sigma_a)
            throw SceneError(params.Loc("sigma_s"), "\"sigma_s\" given without \"sigma_a\"",
                             "sigma_s");
        if (!p.sigma_a) {
            p.reflectance =
                params.GetSpectrumTextureOrNull("reflectance", SpectrumType::Albedo, arena);
            if (p.reflectance) {
                p.mfp = params.GetSpectrumTexture("mfp", Spectrum(ConstantSpectrum(1)),
                                                  SpectrumType::Unbounded, arena);
            } else {
                // pbrt-v4's default: whole milk (mm^-1)
                const RGBColorSpace& srgb = RGBColorSpace::sRGB();
                p.sigma_a = constant(RGBUnboundedSpectrum(srgb, RGB(.0011f, .0024f, .014f)));
                p.sigma_s = constant(RGBUnboundedSpectrum(srgb, RGB(2.55f, 3.21f, 3.77f)));
            }
        }
    }
    p.scale = params.GetOneFloat("scale", 1);
    if (!std::isfinite(p.scale) || p.scale < 0)
        throw SceneError(params.Loc("scale"), "\"scale\" must be finite and not negative", "scale");
    p.eta = params.GetOneFloat("eta", 1.33f);
    if (!std::isfinite(p.eta) || p.eta <= 0)
        throw SceneError(params.Loc("eta"), "\"eta\" must be positive", "eta");
    p.g = g;
    std::optional<FloatTexture> u = params.GetFloatTextureOrNull("uroughness", arena);
    std::optional<FloatTexture> v = params.GetFloatTextureOrNull("vroughness", arena);
    p.uRoughness = u ? *u : params.GetFloatTexture("roughness", 0, arena);
    p.vRoughness = v ? *v : params.GetFloatTexture("roughness", 0, arena);
    p.remapRoughness = params.GetOneBool("remaproughness", true);
    const BSSRDFTable* table = &tables.Get(g, p.eta);
    return arena.New<SubsurfaceMaterial>(std::move(p), table);
}

}  // namespace kiln
