#include "materials/bxdfs/thin_dielectric_bxdf.h"

#include "materials/bxdfs/fresnel.h"

namespace kiln {

void ThinDielectricBxDF::ReflectanceTransmittance(Float cosTheta_o, Float eta, Float* R, Float* T) {
    Float r = FrDielectric(std::abs(cosTheta_o), eta), t = 1 - r;
    // Sum the geometric series of inter-reflections inside the slab: R' = R + T^2 R / (1 - R^2).
    if (r < 1) {
        r += Sqr(t) * r / (1 - Sqr(r));
        t = 1 - r;
    }
    *R = r;
    *T = t;
}

std::optional<BSDFSample> ThinDielectricBxDF::Sample_f(Vector3f wo, Float uc, Point2f,
                                                       TransportMode,
                                                       BxDFReflTransFlags sampleFlags) const {
    if (wo.z == 0) return {};
    Float R, T;
    ReflectanceTransmittance(AbsCosTheta(wo), eta, &R, &T);
    Float pr = R, pt = T;
    if (!(sampleFlags & BxDFReflTransFlags::Reflection)) pr = 0;
    if (!(sampleFlags & BxDFReflTransFlags::Transmission)) pt = 0;
    if (pr == 0 && pt == 0) return {};
    if (uc < pr / (pr + pt)) {
        Vector3f wi(-wo.x, -wo.y, wo.z);
        SampledSpectrum fr(R / AbsCosTheta(wi));
        return BSDFSample(fr, wi, pr / (pr + pt), BxDFFlags::SpecularReflection);
    }
    // Straight through: the two refractions cancel.
    Vector3f wi = -wo;
    SampledSpectrum ft(T / AbsCosTheta(wi));
    return BSDFSample(ft, wi, pt / (pr + pt), BxDFFlags::SpecularTransmission);
}

}  // namespace kiln
