#include "materials/bxdfs/directional_albedo.h"

#include <cmath>
#include <optional>

#include "materials/bxdfs/fresnel.h"

namespace kiln {

namespace {

// Closed-form reflectance of the specular BxDFs; nullopt for the others.
std::optional<SampledSpectrum> ExactAlbedo(const BxDF& bxdf, Vector3f wo) {
    Float cosTheta = AbsCosTheta(wo);
    if (const ConductorBxDF* c = bxdf.Cast<ConductorBxDF>();
        c && c->Distribution().EffectivelySmooth())
        return FrComplex(cosTheta, c->Eta(), c->K());
    if (const DielectricBxDF* d = bxdf.Cast<DielectricBxDF>();
        d && (d->Eta() == 1 || d->Distribution().EffectivelySmooth()))
        return SampledSpectrum(FrDielectric(CosTheta(wo), d->Eta()));
    if (const ThinDielectricBxDF* t = bxdf.Cast<ThinDielectricBxDF>()) {
        Float R, T;
        ThinDielectricBxDF::ReflectanceTransmittance(cosTheta, t->Eta(), &R, &T);
        return SampledSpectrum(R);
    }
    return std::nullopt;
}

// Golden-ratio (rank-1) sequence: a fixed, evenly spread set of uc values.
Float GoldenSequence(uint32_t i) {
    double v = (i + 0.5) * 0.6180339887498949;
    return std::min<Float>(Float(v - std::floor(v)), OneMinusEpsilon);
}

}  // namespace

SampledSpectrum DirectionalAlbedo(const BxDF& bxdf, Vector3f wo, int sqrtSamples) {
    if (wo.z == 0) return SampledSpectrum(0.f);
    if (std::optional<SampledSpectrum> exact = ExactAlbedo(bxdf, wo)) return *exact;

    // Estimate: reflection-only importance sampling over the cell centres of an n x n grid;
    // the lobe-selection sample uc follows a golden-ratio sequence over the cells.
    int n = std::max(1, sqrtSamples);
    SampledSpectrum sum(0.f);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            Point2f u((i + 0.5f) / n, (j + 0.5f) / n);
            Float uc = GoldenSequence(uint32_t(j * n + i));
            std::optional<BSDFSample> bs =
                bxdf.Sample_f(wo, uc, u, TransportMode::Radiance, BxDFReflTransFlags::Reflection);
            if (!bs || bs->pdf == 0 || !SameHemisphere(wo, bs->wi)) continue;
            sum += bs->f * AbsCosTheta(bs->wi) / bs->pdf;
        }
    return Clamp(sum / Float(n * n), Float(0), Float(1));
}

}  // namespace kiln
