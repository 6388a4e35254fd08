#include "materials/bxdfs/conductor_bxdf.h"

#include "materials/bxdfs/fresnel.h"
#include "materials/bxdfs/fresnel_mueller.h"

namespace kiln {

std::optional<MicrofacetTerm> ConductorBxDF::Term(Vector3f wo, Vector3f wi) const {
    if (!SameHemisphere(wo, wi) || mfDistrib.EffectivelySmooth()) return {};
    // Torrance-Sparrow: D F G / (4 cos_o cos_i).
    Float cosTheta_o = AbsCosTheta(wo), cosTheta_i = AbsCosTheta(wi);
    if (cosTheta_i == 0 || cosTheta_o == 0) return {};
    Vector3f wm = wi + wo;
    if (LengthSquared(wm) == 0) return {};
    wm = Normalize(wm);
    return MicrofacetTerm{wm,
                          mfDistrib.D(wm) * mfDistrib.G(wo, wi) / (4 * cosTheta_i * cosTheta_o)};
}

SampledSpectrum ConductorBxDF::f(Vector3f wo, Vector3f wi, TransportMode) const {
    std::optional<MicrofacetTerm> t = Term(wo, wi);
    if (!t) return {};
    return FrComplex(AbsDot(wo, t->wm), eta, k) * t->scale;
}

std::optional<BSDFSample> ConductorBxDF::Sample_f(Vector3f wo, Float, Point2f u, TransportMode,
                                                  BxDFReflTransFlags sampleFlags) const {
    if (!(sampleFlags & BxDFReflTransFlags::Reflection) || wo.z == 0) return {};
    if (mfDistrib.EffectivelySmooth()) {
        // Perfect specular reflection.
        Vector3f wi(-wo.x, -wo.y, wo.z);
        SampledSpectrum f = FrComplex(AbsCosTheta(wi), eta, k) / AbsCosTheta(wi);
        return BSDFSample(f, wi, 1, BxDFFlags::SpecularReflection);
    }
    // Rough: sample a visible normal and reflect about it.
    Vector3f wm = mfDistrib.Sample_wm(wo, u);
    Vector3f wi = Reflect(wo, wm);
    if (!SameHemisphere(wo, wi)) return {};
    Float pdf = mfDistrib.PDF(wo, wm) / (4 * AbsDot(wo, wm));
    Float cosTheta_o = AbsCosTheta(wo), cosTheta_i = AbsCosTheta(wi);
    if (cosTheta_i == 0 || cosTheta_o == 0) return {};
    SampledSpectrum F = FrComplex(AbsDot(wo, wm), eta, k);
    SampledSpectrum f = mfDistrib.D(wm) * F * mfDistrib.G(wo, wi) / (4 * cosTheta_i * cosTheta_o);
    return BSDFSample(f, wi, pdf, BxDFFlags::GlossyReflection);
}

Float ConductorBxDF::PDF(Vector3f wo, Vector3f wi, TransportMode,
                         BxDFReflTransFlags sampleFlags) const {
    if (!(sampleFlags & BxDFReflTransFlags::Reflection)) return 0;
    if (!SameHemisphere(wo, wi)) return 0;
    if (mfDistrib.EffectivelySmooth()) return 0;
    Vector3f wm = wo + wi;
    if (LengthSquared(wm) == 0) return 0;
    wm = FaceForward(Normalize(wm), Vector3f(0, 0, 1));
    return mfDistrib.PDF(wo, wm) / (4 * AbsDot(wo, wm));
}

// Polarised transport
MuellerMatrix ConductorBxDF::MuellerF(Vector3f wo, Vector3f wi, TransportMode) const {
    std::optional<MicrofacetTerm> t = Term(wo, wi);
    if (!t) return {};
    // The Fresnel matrix of the microfacet, in its own plane of incidence
    MuellerMatrix F = FresnelReflectionMueller(AbsDot(wo, t->wm), eta, k);
    return MicrofacetToSurfaceFrame(F, wo, wi, t->wm) * t->scale;
}

MuellerMatrix ConductorBxDF::MuellerSample(Vector3f wo, const BSDFSample& bs,
                                           TransportMode mode) const {
    if (!bs.IsSpecular()) return MuellerF(wo, bs.wi, mode);
    return FresnelReflectionMueller(AbsCosTheta(bs.wi), eta, k) / AbsCosTheta(bs.wi);
}

}  // namespace kiln
