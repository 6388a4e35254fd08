#include "materials/bxdfs/bxdf.h"

namespace kiln {

SampledSpectrum BxDF::rho(Vector3f wo, std::span<const Float> uc,
                          std::span<const Point2f> u2) const {
    SampledSpectrum r(0.f);
    if (uc.empty()) return r;
    for (size_t i = 0; i < uc.size(); ++i) {
        std::optional<BSDFSample> bs = Sample_f(wo, uc[i], u2[i]);
        if (bs && bs->pdf > 0) r += bs->f * AbsCosTheta(bs->wi) / bs->pdf;
    }
    return r / Float(uc.size());
}

}  // namespace kiln
