#include "materials/bxdfs/normalized_fresnel_bxdf.h"

#include "base/quadrature.h"
#include "base/sampling.h"
#include "materials/bxdfs/bssrdf_table.h"
#include "materials/bxdfs/fresnel.h"

namespace kiln {

namespace {

// integral_0^1 F(mu, eta) mu dmu for light arriving from outside (composite Gauss-Legendre:
// panels localise the critical angle's kink when eta < 1)
double FresnelMomentQuadrature(Float eta) {
    QuadratureRule rule = CompositeGaussLegendre(64, 8);
    double sum = 0;
    for (size_t i = 0; i < rule.x.size(); ++i)
        sum += rule.weight[i] * FrDielectric(Float(rule.x[i]), eta) * rule.x[i];
    return sum;
}

}  // namespace

NormalizedFresnelBxDF::NormalizedFresnelBxDF(Float eta)
    : eta(eta), c(1 - 2 * FresnelMoment1(1 / eta)) {}

SampledSpectrum NormalizedFresnelBxDF::f(Vector3f wo, Vector3f wi, TransportMode mode) const {
    if (!SameHemisphere(wo, wi)) return SampledSpectrum(0.f);
    Float value = (1 - FrDielectric(CosTheta(wi), eta)) / (c * Pi);
    if (mode == TransportMode::Radiance) value *= Sqr(eta);
    return SampledSpectrum(value);
}

std::optional<BSDFSample> NormalizedFresnelBxDF::Sample_f(Vector3f wo, Float, Point2f u,
                                                          TransportMode mode,
                                                          BxDFReflTransFlags sampleFlags) const {
    if (!(sampleFlags & BxDFReflTransFlags::Reflection)) return std::nullopt;
    Vector3f wi = SampleCosineHemisphere(u);
    if (wo.z < 0) wi.z *= -1;
    return BSDFSample(f(wo, wi, mode), wi, PDF(wo, wi, mode, sampleFlags),
                      BxDFFlags::DiffuseReflection);
}

Float NormalizedFresnelBxDF::PDF(Vector3f wo, Vector3f wi, TransportMode,
                                 BxDFReflTransFlags sampleFlags) const {
    if (!(sampleFlags & BxDFReflTransFlags::Reflection)) return 0;
    return SameHemisphere(wo, wi) ? CosineHemispherePDF(AbsCosTheta(wi)) : 0;
}

Float NormalizedFresnelBxDF::ExitFraction() const {
    return Float((1 - 2 * FresnelMomentQuadrature(eta)) / c);
}

}  // namespace kiln
