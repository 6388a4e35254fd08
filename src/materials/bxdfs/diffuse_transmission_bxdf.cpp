#include "materials/bxdfs/diffuse_transmission_bxdf.h"

#include "base/sampling.h"

namespace kiln {

SampledSpectrum DiffuseTransmissionBxDF::f(Vector3f wo, Vector3f wi, TransportMode) const {
    return SameHemisphere(wo, wi) ? R * InvPi : T * InvPi;
}

void DiffuseTransmissionBxDF::Probabilities(BxDFReflTransFlags sampleFlags, Float* pr,
                                            Float* pt) const {
    *pr = (sampleFlags & BxDFReflTransFlags::Reflection) ? R.MaxComponentValue() : 0;
    *pt = (sampleFlags & BxDFReflTransFlags::Transmission) ? T.MaxComponentValue() : 0;
}

std::optional<BSDFSample> DiffuseTransmissionBxDF::Sample_f(Vector3f wo, Float uc, Point2f u,
                                                            TransportMode mode,
                                                            BxDFReflTransFlags sampleFlags) const {
    Float pr, pt;
    Probabilities(sampleFlags, &pr, &pt);
    if (!(pr > 0) && !(pt > 0)) return {};
    Vector3f wi = SampleCosineHemisphere(u);
    if (uc < pr / (pr + pt)) {
        // Reflection: the side of wo
        if (wo.z < 0) wi.z *= -1;
        Float pdf = CosineHemispherePDF(AbsCosTheta(wi)) * pr / (pr + pt);
        return BSDFSample(f(wo, wi, mode), wi, pdf, BxDFFlags::DiffuseReflection);
    }
    // Transmission: the other side
    if (wo.z > 0) wi.z *= -1;
    Float pdf = CosineHemispherePDF(AbsCosTheta(wi)) * pt / (pr + pt);
    return BSDFSample(f(wo, wi, mode), wi, pdf, BxDFFlags::DiffuseTransmission);
}

Float DiffuseTransmissionBxDF::PDF(Vector3f wo, Vector3f wi, TransportMode,
                                   BxDFReflTransFlags sampleFlags) const {
    Float pr, pt;
    Probabilities(sampleFlags, &pr, &pt);
    if (!(pr > 0) && !(pt > 0)) return 0;
    Float p = SameHemisphere(wo, wi) ? pr : pt;
    return CosineHemispherePDF(AbsCosTheta(wi)) * p / (pr + pt);
}

}  // namespace kiln
