#include "materials/bxdfs/dielectric_bxdf.h"

#include "materials/bxdfs/fresnel.h"
#include "materials/bxdfs/fresnel_mueller.h"

namespace kiln {

namespace {

// Probabilities of choosing reflection or transmission given the allowed hemispheres.
void LobeProbabilities(Float R, Float T, BxDFReflTransFlags sampleFlags, Float* pr, Float* pt) {
    *pr = (sampleFlags & BxDFReflTransFlags::Reflection) ? R : 0;
    *pt = (sampleFlags & BxDFReflTransFlags::Transmission) ? T : 0;
}

}  // namespace

// Sampling
std::optional<BSDFSample> DielectricBxDF::Sample_f(Vector3f wo, Float uc, Point2f u,
                                                   TransportMode mode,
                                                   BxDFReflTransFlags sampleFlags) const {
    if (wo.z == 0) return {};
    if (eta == 1 || mfDistrib.EffectivelySmooth()) {
        // Specular: choose reflection with probability proportional to R.
        Float R = Fr(CosTheta(wo)), T = 1 - R, pr, pt;
        LobeProbabilities(R, T, sampleFlags, &pr, &pt);
        if (pr == 0 && pt == 0) return {};
        if (uc < pr / (pr + pt)) {
            Vector3f wi(-wo.x, -wo.y, wo.z);
            SampledSpectrum fr(R / AbsCosTheta(wi));
            return BSDFSample(fr, wi, pr / (pr + pt), BxDFFlags::SpecularReflection);
        }
        Vector3f wi;
        Float etap;
        if (!Refract(wo, Normal3f(0, 0, 1), eta, &etap, &wi)) return {};
        SampledSpectrum ft(T / AbsCosTheta(wi));
        // Radiance is compressed into the smaller solid angle of the denser medium.
        if (mode == TransportMode::Radiance) ft /= Sqr(etap);
        return BSDFSample(ft, wi, pt / (pr + pt), BxDFFlags::SpecularTransmission, etap);
    }

    // Rough: sample a visible microfacet normal, then reflect or refract about it.
    Vector3f wm = mfDistrib.Sample_wm(wo, u);
    Float R = Fr(Dot(wo, wm)), T = 1 - R, pr, pt;
    LobeProbabilities(R, T, sampleFlags, &pr, &pt);
    if (pr == 0 && pt == 0) return {};
    if (uc < pr / (pr + pt)) {
        Vector3f wi = Reflect(wo, wm);
        if (!SameHemisphere(wo, wi)) return {};
        Float pdf = mfDistrib.PDF(wo, wm) / (4 * AbsDot(wo, wm)) * pr / (pr + pt);
        SampledSpectrum f(mfDistrib.D(wm) * mfDistrib.G(wo, wi) * R /
                          std::abs(4 * CosTheta(wi) * CosTheta(wo)));
        return BSDFSample(f, wi, pdf, BxDFFlags::GlossyReflection);
    }
    Float etap;
    Vector3f wi;
    bool tir = !Refract(wo, Normal3f(wm), eta, &etap, &wi);
    if (tir || SameHemisphere(wo, wi) || wi.z == 0) return {};
    // Jacobian of the generalized half vector for refraction (Walter et al. 2007, eq. 17).
    Float denom = Sqr(Dot(wi, wm) + Dot(wo, wm) / etap);
    Float dwm_dwi = AbsDot(wi, wm) / denom;
    Float pdf = mfDistrib.PDF(wo, wm) * dwm_dwi * pt / (pr + pt);
    SampledSpectrum ft(T * mfDistrib.D(wm) * mfDistrib.G(wo, wi) *
                       std::abs(Dot(wi, wm) * Dot(wo, wm) / (CosTheta(wi) * CosTheta(wo) * denom)));
    if (mode == TransportMode::Radiance) ft /= Sqr(etap);
    return BSDFSample(ft, wi, pdf, BxDFFlags::GlossyTransmission, etap);
}

// Evaluation
namespace {

// Generalized half vector (Walter et al. 2007) facing +z; false if the configuration has no
// valid microfacet normal.
bool HalfVector(Vector3f wo, Vector3f wi, Float eta, Vector3f* wm, Float* etap, bool* reflect) {
    Float cosTheta_o = CosTheta(wo), cosTheta_i = CosTheta(wi);
    *reflect = cosTheta_i * cosTheta_o > 0;
    *etap = 1;
    if (!*reflect) *etap = cosTheta_o > 0 ? eta : (1 / eta);
    Vector3f h = wi * *etap + wo;
    if (cosTheta_i == 0 || cosTheta_o == 0 || LengthSquared(h) == 0) return false;
    h = FaceForward(Normalize(h), Vector3f(0, 0, 1));
    // Discard back-facing microfacets.
    if (Dot(h, wi) * cosTheta_i < 0 || Dot(h, wo) * cosTheta_o < 0) return false;
    *wm = h;
    return true;
}

}  // namespace

std::optional<MicrofacetTerm> DielectricBxDF::Term(Vector3f wo, Vector3f wi,
                                                   TransportMode mode) const {
    if (eta == 1 || mfDistrib.EffectivelySmooth()) return {};
    Vector3f wm;
    Float etap;
    bool reflect;
    if (!HalfVector(wo, wi, eta, &wm, &etap, &reflect)) return {};
    if (reflect)
        return MicrofacetTerm{
            wm, mfDistrib.D(wm) * mfDistrib.G(wo, wi) / std::abs(4 * CosTheta(wi) * CosTheta(wo)),
            true};
    Float denom = Sqr(Dot(wi, wm) + Dot(wo, wm) / etap) * CosTheta(wi) * CosTheta(wo);
    Float scale =
        mfDistrib.D(wm) * mfDistrib.G(wo, wi) * std::abs(Dot(wi, wm) * Dot(wo, wm) / denom);
    if (mode == TransportMode::Radiance) scale /= Sqr(etap);
    return MicrofacetTerm{wm, scale, false};
}

SampledSpectrum DielectricBxDF::f(Vector3f wo, Vector3f wi, TransportMode mode) const {
    std::optional<MicrofacetTerm> t = Term(wo, wi, mode);
    if (!t) return {};
    Float F = Fr(Dot(wo, t->wm));
    return SampledSpectrum((t->reflect ? F : 1 - F) * t->scale);
}

Float DielectricBxDF::PDF(Vector3f wo, Vector3f wi, TransportMode,
                          BxDFReflTransFlags sampleFlags) const {
    if (eta == 1 || mfDistrib.EffectivelySmooth()) return 0;
    Vector3f wm;
    Float etap;
    bool reflect;
    if (!HalfVector(wo, wi, eta, &wm, &etap, &reflect)) return 0;
    Float R = Fr(Dot(wo, wm)), T = 1 - R, pr, pt;
    LobeProbabilities(R, T, sampleFlags, &pr, &pt);
    if (pr == 0 && pt == 0) return 0;
    if (reflect) return mfDistrib.PDF(wo, wm) / (4 * AbsDot(wo, wm)) * pr / (pr + pt);
    Float denom = Sqr(Dot(wi, wm) + Dot(wo, wm) / etap);
    Float dwm_dwi = AbsDot(wi, wm) / denom;
    return mfDistrib.PDF(wo, wm) * dwm_dwi * pt / (pr + pt);
}

// Polarised transport
MuellerMatrix DielectricBxDF::MuellerF(Vector3f wo, Vector3f wi, TransportMode mode) const {
    std::optional<MicrofacetTerm> t = Term(wo, wi, mode);
    if (!t) return {};
    Float cosTheta = Dot(wo, t->wm);
    MuellerMatrix F = t->reflect ? AbsorbingDielectricReflectionMueller(cosTheta, eta, k)
                                 : AbsorbingDielectricTransmissionMueller(cosTheta, eta, k);
    return MicrofacetToSurfaceFrame(F, wo, wi, t->wm) * t->scale;
}

MuellerMatrix DielectricBxDF::MuellerSample(Vector3f wo, const BSDFSample& bs,
                                            TransportMode mode) const {
    if (!bs.IsSpecular()) return MuellerF(wo, bs.wi, mode);
    // Smooth: the plane of incidence contains the normal, so the s axes are the frame's
    if (bs.IsReflection())
        return AbsorbingDielectricReflectionMueller(CosTheta(wo), eta, k) / AbsCosTheta(bs.wi);
    MuellerMatrix T =
        AbsorbingDielectricTransmissionMueller(CosTheta(wo), eta, k) / AbsCosTheta(bs.wi);
    if (mode == TransportMode::Radiance) T = T / Sqr(bs.eta);
    return T;
}

}  // namespace kiln
