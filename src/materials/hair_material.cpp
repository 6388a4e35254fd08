#include "materials/hair_material.h"

#include <algorithm>

#include "spectral/color.h"
#include "spectral/spectrum.h"
#include "textures/basic_textures.h"
#include "textures/texture_parameter_dictionary.h"

namespace kiln {

HairBxDF HairMaterial::GetBxDF(const MaterialEvalContext& ctx,
                               const SampledWavelengths& lambda) const {
    Float bm = std::max<Float>(1e-2f, p.beta_m.Evaluate(ctx));
    Float bn = std::max<Float>(1e-2f, p.beta_n.Evaluate(ctx));
    Float alpha = p.alpha.Evaluate(ctx), eta = p.eta.Evaluate(ctx);
    SampledSpectrum sigma_a;
    if (p.sigma_a) {
        sigma_a = ClampZero(p.sigma_a->Evaluate(ctx, lambda));
    } else if (p.reflectance) {
        SampledSpectrum c = p.reflectance->Evaluate(ctx, lambda);
        for (int i = 0; i < NSpectrumSamples; ++i) c[i] = Clamp(c[i], 0, 1);
        sigma_a = HairBxDF::SigmaAFromReflectance(c, bn);
    } else {
        Float ce = std::max<Float>(0, p.eumelanin ? p.eumelanin->Evaluate(ctx) : 0);
        Float cp = std::max<Float>(0, p.pheomelanin ? p.pheomelanin->Evaluate(ctx) : 0);
        sigma_a =
            RGBUnboundedSpectrum(RGBColorSpace::sRGB(), HairBxDF::SigmaAFromConcentration(ce, cp))
                .Sample(lambda);
    }
    return HairBxDF(-1 + 2 * ctx.uv.y, eta, sigma_a, bm, bn, alpha);
}

HairMaterial* HairMaterial::Create(const TextureParameterDictionary& params, ObjectArena& arena,
                                   Diagnostics& diag) {
    Params p{
        params.GetSpectrumTextureOrNull("sigma_a", SpectrumType::Unbounded, arena),
        // ("color" is pbrt-v4's older name for it, read when "reflectance" is absent)
        params.Has("reflectance")
            ? params.GetSpectrumTextureOrNull("reflectance", SpectrumType::Albedo, arena)
            : params.GetSpectrumTextureOrNull("color", SpectrumType::Albedo, arena),
        params.GetFloatTextureOrNull("eumelanin", arena),
        params.GetFloatTextureOrNull("pheomelanin", arena),
        params.GetFloatTexture("eta", 1.55f, arena), params.GetFloatTexture("beta_m", 0.3f, arena),
        params.GetFloatTexture("beta_n", 0.3f, arena), params.GetFloatTexture("alpha", 2.f, arena)};
    auto melaninLoc = [&] { return params.Loc(p.eumelanin ? "eumelanin" : "pheomelanin"); };
    if (p.sigma_a) {
        if (p.reflectance)
            diag.Warn(params.Loc("reflectance"),
                      "hair: \"reflectance\" is ignored since \"sigma_a\" is given");
        if (p.eumelanin || p.pheomelanin)
            diag.Warn(melaninLoc(),
                      "hair: melanin concentrations are ignored since \"sigma_a\" is given");
    } else if (p.reflectance) {
        if (p.eumelanin || p.pheomelanin)
            diag.Warn(melaninLoc(),
                      "hair: melanin concentrations are ignored since \"reflectance\" is given");
    } else if (!p.eumelanin && !p.pheomelanin) {
        p.eumelanin = FloatTexture(arena.New<FloatConstantTexture>(1.3f));  // brown hair
    }
    return arena.New<HairMaterial>(std::move(p));
}

}  // namespace kiln
