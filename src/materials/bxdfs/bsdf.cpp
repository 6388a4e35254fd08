#include "materials/bxdfs/bsdf.h"

namespace kiln {

BSDF::BSDF(Normal3f ns, Vector3f dpdus, const BxDF& bxdf, Normal3f ngeom)
    : bxdf(bxdf), valid(true) {
    Vector3f z = Normalize(Vector3f(ns));
    // Fold when the BxDF only reflects and the shading normal is not the geometric one
    BxDFFlags flags = bxdf.Flags();
    if (ngeom != Normal3f(0, 0, 0) && IsReflective(flags) && !IsTransmissive(flags)) {
        Vector3f g = Normalize(Vector3f(ngeom));
        if (AbsDot(g, z) < 1 - 1e-6f) {
            fold = true;
            ng = g;
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

SampledSpectrum BSDF::f(Vector3f woRender, Vector3f wiRender, TransportMode mode) const {
    Vector3f wi = RenderToLocal(wiRender), wo = RenderToLocal(woRender);
    if (wo.z == 0) return {};
    if (!fold) return bxdf.f(wo, wi, mode);
    if (!SameSide(woRender, wiRender) || wi.z == 0) return {};
    SampledSpectrum f = bxdf.f(wo, wi, mode);
    Vector3f mi = RenderToLocal(Mirror(wiRender));
    if (SameHemisphere(wo, mi)) f += bxdf.f(wo, mi, mode) * (AbsCosTheta(mi) / AbsCosTheta(wi));
    return f;
}

std::optional<BSDFSample> BSDF::Sample_f(Vector3f woRender, Float u, Point2f u2, TransportMode mode,
                                         BxDFReflTransFlags sampleFlags) const {
    Vector3f wo = RenderToLocal(woRender);
    // BxDFFlags::Reflection/Transmission share their bits with BxDFReflTransFlags.
    if (wo.z == 0 || !(unsigned(bxdf.Flags()) & unsigned(sampleFlags))) return {};
    std::optional<BSDFSample> bs = bxdf.Sample_f(wo, u, u2, mode, sampleFlags);
    if (!bs || !bs->f || bs->pdf == 0 || bs->wi.z == 0) return {};
    bs->wi = LocalToRender(bs->wi);
    if (!fold) return bs;
    if (!SameSide(woRender, bs->wi)) {
        // Redirect to the mirror image, keeping the sample's weight f |cos| / pdf
        Vector3f w = Mirror(bs->wi);
        Float cosW = AbsCosTheta(RenderToLocal(w));
        if (cosW == 0 || !SameSide(woRender, w)) return {};
        bs->f *= AbsCosTheta(RenderToLocal(bs->wi)) / cosW;
        bs->wi = w;
    }
    // A direction can come from either of its two pre-images: the density that MIS needs is
    // PDF()'s sum, not this sample's own
    if (!bs->IsSpecular()) bs->pdfIsProportional = true;
    return bs;
}

Float BSDF::PDF(Vector3f woRender, Vector3f wiRender, TransportMode mode,
                BxDFReflTransFlags sampleFlags) const {
    Vector3f wo = RenderToLocal(woRender), wi = RenderToLocal(wiRender);
    if (wo.z == 0) return 0;
    if (!fold) return bxdf.PDF(wo, wi, mode, sampleFlags);
    if (!SameSide(woRender, wiRender)) return 0;
    return bxdf.PDF(wo, wi, mode, sampleFlags) +
           bxdf.PDF(wo, RenderToLocal(Mirror(wiRender)), mode, sampleFlags);
}

}  // namespace kiln
