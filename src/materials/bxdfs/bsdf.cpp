#include "materials/bxdfs/bsdf.h"

namespace kiln {

BSDF::BSDF(Normal3f ns, Vector3f dpdus, const BxDF& bxdf) : bxdf(bxdf), valid(true) {
    Vector3f z = Normalize(Vector3f(ns));
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
    return bxdf.f(wo, wi, mode);
}

std::optional<BSDFSample> BSDF::Sample_f(Vector3f woRender, Float u, Point2f u2, TransportMode mode,
                                         BxDFReflTransFlags sampleFlags) const {
    Vector3f wo = RenderToLocal(woRender);
    // BxDFFlags::Reflection/Transmission share their bits with BxDFReflTransFlags.
    if (wo.z == 0 || !(unsigned(bxdf.Flags()) & unsigned(sampleFlags))) return {};
    std::optional<BSDFSample> bs = bxdf.Sample_f(wo, u, u2, mode, sampleFlags);
    if (!bs || !bs->f || bs->pdf == 0 || bs->wi.z == 0) return {};
    bs->wi = LocalToRender(bs->wi);
    return bs;
}

Float BSDF::PDF(Vector3f woRender, Vector3f wiRender, TransportMode mode,
                BxDFReflTransFlags sampleFlags) const {
    Vector3f wo = RenderToLocal(woRender), wi = RenderToLocal(wiRender);
    if (wo.z == 0) return 0;
    return bxdf.PDF(wo, wi, mode, sampleFlags);
}

}  // namespace kiln
