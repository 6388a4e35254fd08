#include "materials/bxdfs/diffuse_bxdf.h"

#include "base/sampling.h"

namespace kiln {

SampledSpectrum DiffuseBxDF::f(Vector3f wo, Vector3f wi, TransportMode) const {
    if (!SameHemisphere(wo, wi)) return SampledSpectrum(0.f);
    return R * InvPi;
}

std::optional<BSDFSample> DiffuseBxDF::Sample_f(Vector3f wo, Float, Point2f u, TransportMode,
                                                BxDFReflTransFlags sampleFlags) const {
    if (!(sampleFlags & BxDFReflTransFlags::Reflection)) return {};
    // Cosine-weighted hemisphere on the side of wo.
    Vector3f wi = SampleCosineHemisphere(u);
    if (wo.z < 0) wi.z *= -1;
    Float pdf = CosineHemispherePDF(AbsCosTheta(wi));
    return BSDFSample(R * InvPi, wi, pdf, BxDFFlags::DiffuseReflection);
}

Float DiffuseBxDF::PDF(Vector3f wo, Vector3f wi, TransportMode,
                       BxDFReflTransFlags sampleFlags) const {
    if (!(sampleFlags & BxDFReflTransFlags::Reflection) || !SameHemisphere(wo, wi)) return 0;
    return CosineHemispherePDF(AbsCosTheta(wi));
}

}  // namespace kiln
