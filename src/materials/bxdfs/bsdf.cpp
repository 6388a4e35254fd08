#include "materials/bxdfs/bsdf.h"

#include "materials/bxdfs/fresnel_mueller.h"

namespace kiln {

BSDF::BSDF(Normal3f ns, Vector3f dpdus, const BxDF& bxdf, Normal3f ngeom)
    : bxdf(bxdf), valid(true) {
    Vector3f z = Normalize(Vector3f(ns));
    // Fold when the shading normal is not the geometric one
    if (ngeom != Normal3f(0, 0, 0)) {
        Vector3f g = Normalize(Vector3f(ngeom));
        if (AbsDot(g, z) < 1 - 1e-6f) {
            fold = true;
            ng = Dot(g, z) < 0 ? -g : g;
        }
    }
    Vector3f x = GramSchmidt(dpdus, z);
    Float len2 = LengthSquared(x);
    if (len2 > 1e-12f * std::max<Float>(LengthSquared(dpdus), 1e-30f) && std::isfinite(len2)) {
        x = x / std::sqrt(len2);
        shadingFrame = Frame::FromXZ(x, z);
    } else {
        // dpdus missing or parallel to ns: any tangent will do.
        shadingFrame = Frame::FromZ(z);
    }
}

template <typename Value>
Value BSDF::f(Vector3f woRender, Vector3f wiRender, TransportMode mode) const {
    constexpr bool polarized = std::is_same_v<Value, MuellerMatrix>;
    Vector3f wi = RenderToLocal(wiRender), wo = RenderToLocal(woRender);
    if (wo.z == 0) return {};
    auto value = [&](Vector3f wiR, Vector3f wiLocal) {
        Value v = bxdf.f<Value>(wo, wiLocal, mode);
        if constexpr (polarized)
            if (v) v = ToRenderFrames(v, woRender, wiR, wo, wiLocal);
        return v;
    };
    if (!fold) return value(wiRender, wi);
    if (wi.z == 0) return {};
    // wi gets what the BxDF sends to it and to its mirror image, from the lobe (reflection or
    // transmission in the shading frame) that matches wi's side of the geometric surface
    bool reflect = SameSide(woRender, wiRender);
    Value f{};
    if (SameHemisphere(wo, wi) == reflect) f = value(wiRender, wi);
    Vector3f miRender = Mirror(wiRender), mi = RenderToLocal(miRender);
    if (mi.z != 0 && SameHemisphere(wo, mi) == reflect) {
        Value fm = value(miRender, mi);
        if constexpr (polarized) fm = fm * FoldMueller(wiRender);
        f += fm * (AbsCosTheta(mi) / AbsCosTheta(wi));
    }
    if (!reflect && f) f = f * CrossingScale(wo, woRender, mode);
    return f;
}

Float BSDF::CrossingScale(Vector3f wo, Vector3f woRender, TransportMode mode) const {
    if (!fold || mode != TransportMode::Radiance || (wo.z > 0) == (Dot(woRender, ng) > 0)) return 1;
    Float eta = bxdf.RefractiveRatio();
    if (eta == 1) return 1;
    Float etap = wo.z > 0 ? eta : 1 / eta;
    return Sqr(Sqr(etap));
}

template <typename Value>
std::optional<BSDFSampleOf<Value>> BSDF::Sample_f(Vector3f woRender, Float u, Point2f u2,
                                                  TransportMode mode,
                                                  BxDFReflTransFlags sampleFlags) const {
    constexpr bool polarized = std::is_same_v<Value, MuellerMatrix>;
    Vector3f wo = RenderToLocal(woRender);
    // BxDFFlags::Reflection/Transmission share their bits with BxDFReflTransFlags.
    if (wo.z == 0 || !(unsigned(bxdf.Flags()) & unsigned(sampleFlags))) return {};
    std::optional<BSDFSampleOf<Value>> bs = bxdf.Sample_f<Value>(wo, u, u2, mode, sampleFlags);
    if (!bs || !bs->f || bs->pdf == 0 || bs->wi.z == 0) return {};
    Vector3f wiLocal = bs->wi;
    bs->wi = LocalToRender(bs->wi);
    if constexpr (polarized) bs->f = ToRenderFrames(bs->f, woRender, bs->wi, wo, wiLocal);
    if (!fold) return bs;
    bool reflect = SameHemisphere(wo, wiLocal);
    if (SameSide(woRender, bs->wi) != reflect) {
        // Redirect to the mirror image, keeping the sample's weight f |cos| / pdf
        Vector3f w = Mirror(bs->wi);
        Float cosW = AbsCosTheta(RenderToLocal(w));
        if (cosW == 0 || SameSide(woRender, w) != reflect) return {};
        if constexpr (polarized) bs->f = bs->f * FoldMueller(w);
        bs->f = bs->f * (AbsCosTheta(RenderToLocal(bs->wi)) / cosW);
        bs->wi = w;
    }
    if (!reflect) {
        if (Float scale = CrossingScale(wo, woRender, mode); scale != 1) {
            bs->f = bs->f * scale;
            bs->eta = 1 / bs->eta;  // the crossing the light makes
        }
    }
    // A direction can come from either of its two pre-images: the density that MIS needs is
    // PDF()'s sum, not this sample's own
    if (!bs->IsSpecular()) bs->pdfIsProportional = true;
    return bs;
}

template SampledSpectrum BSDF::f<SampledSpectrum>(Vector3f, Vector3f, TransportMode) const;
template MuellerMatrix BSDF::f<MuellerMatrix>(Vector3f, Vector3f, TransportMode) const;
template std::optional<BSDFSampleOf<SampledSpectrum>> BSDF::Sample_f<SampledSpectrum>(
    Vector3f, Float, Point2f, TransportMode, BxDFReflTransFlags) const;
template std::optional<BSDFSampleOf<MuellerMatrix>> BSDF::Sample_f<MuellerMatrix>(
    Vector3f, Float, Point2f, TransportMode, BxDFReflTransFlags) const;

// Polarisation frames
MuellerMatrix BSDF::ToRenderFrames(const MuellerMatrix& M, Vector3f woRender, Vector3f wiRender,
                                   Vector3f wo, Vector3f wi) const {
    const Vector3f z(0, 0, 1);
    return RotateMuellerBasis(M, -wiRender, LocalToRender(PlaneAxis(z, wi)), StokesBasis(-wiRender),
                              woRender, LocalToRender(PlaneAxis(z, wo)), StokesBasis(woRender));
}

MuellerMatrix BSDF::FoldMueller(Vector3f wiRender) const {
    Vector3f miRender = Mirror(wiRender);
    // A perfect mirror with the s axes: diag(1, 1, -1, -1)
    MuellerMatrix mirror = MuellerMatrix::Identity();
    mirror(2, 2) = mirror(3, 3) = SampledSpectrum(-1.f);
    return RotateMuellerBasis(mirror, -wiRender, PlaneAxis(ng, wiRender), StokesBasis(-wiRender),
                              -miRender, PlaneAxis(ng, miRender), StokesBasis(-miRender));
}

Float BSDF::PDF(Vector3f woRender, Vector3f wiRender, TransportMode mode,
                BxDFReflTransFlags sampleFlags) const {
    Vector3f wo = RenderToLocal(woRender), wi = RenderToLocal(wiRender);
    if (wo.z == 0) return 0;
    if (!fold) return bxdf.PDF(wo, wi, mode, sampleFlags);
    bool reflect = SameSide(woRender, wiRender);
    Vector3f mi = RenderToLocal(Mirror(wiRender));
    Float pdf = 0;
    if (SameHemisphere(wo, wi) == reflect) pdf += bxdf.PDF(wo, wi, mode, sampleFlags);
    if (SameHemisphere(wo, mi) == reflect) pdf += bxdf.PDF(wo, mi, mode, sampleFlags);
    return pdf;
}

}  // namespace kiln
