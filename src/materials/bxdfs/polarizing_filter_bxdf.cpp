#include "materials/bxdfs/polarizing_filter_bxdf.h"

#include <cmath>

#include "materials/bxdfs/fresnel_mueller.h"

namespace kiln {

std::optional<BSDFSample> PolarizingFilterBxDF::Sample_f(Vector3f wo, Float, Point2f, TransportMode,
                                                         BxDFReflTransFlags sampleFlags) const {
    if (wo.z == 0 || !(sampleFlags & BxDFReflTransFlags::Transmission)) return {};
    Vector3f wi = -wo;
    return BSDFSample(SampledSpectrum(UnpolarizedTransmittance() / AbsCosTheta(wi)), wi, 1,
                      BxDFFlags::SpecularTransmission);
}

MuellerMatrix PolarizingFilterBxDF::MuellerSample(Vector3f wo, const BSDFSample& bs,
                                                  TransportMode) const {
    // The element's axis projected across the beam (travelling along wo), and its angle from
    // the reference axis PlaneAxis(z, wo) (the same line as PlaneAxis(z, wi) for wi = -wo)
    Vector3f axis(std::cos(angle), std::sin(angle), 0);
    Vector3f across = axis - Dot(axis, wo) * wo;
    Vector3f x = PlaneAxis(Vector3f(0, 0, 1), wo);
    Float theta = LengthSquared(across) > 1e-12f ? StokesBasisAngle(wo, x, Normalize(across)) : 0;
    MuellerMatrix M =
        kind == Kind::LinearPolarizer ? LinearPolarizer(theta) : LinearRetarder(theta, retardance);
    return M / AbsCosTheta(bs.wi);
}

}  // namespace kiln
