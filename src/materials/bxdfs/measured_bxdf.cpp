#include "materials/bxdfs/measured_bxdf.h"

#include <array>
#include <cmath>

#include "materials/bxdfs/fresnel.h"

namespace kiln {

namespace {

Float ThetaToU(Float theta) { return SafeSqrt(theta * (2 / Pi)); }
Float PhiToU(Float phi) { return phi * (1 / (2 * Pi)) + 0.5f; }
Float UToTheta(Float u) { return Sqr(u) * (Pi / 2); }
Float UToPhi(Float u) { return (2 * u - 1) * Pi; }

// The unit-square coordinates of a half vector wm seen from wo at azimuth phi_o
Point2f HalfVectorToU(Vector3f wm, Float phi_o, bool isotropic) {
    Float phi_m = std::atan2(wm.y, wm.x);
    Point2f u(ThetaToU(SphericalTheta(wm)), PhiToU(isotropic ? phi_m - phi_o : phi_m));
    u.y -= std::floor(u.y);
    return u;
}

// d(solid angle of wm) / d(unit square), kept above 1e-6 (pbrt-v4)
Float SquareToNormalJacobian(Float u_x, Float sinTheta_m) {
    return std::max<Float>(2 * Sqr(Pi) * u_x * sinTheta_m, 1e-6f);
}

}  // namespace

MeasuredBxDF::MeasuredBxDF(const MeasuredBxDFData* data, const SampledWavelengths& lambdas)
    : data(data) {
    for (int i = 0; i < NSpectrumSamples; ++i) lambda[i] = lambdas[i];
}

SampledSpectrum MeasuredBxDF::Spectra(Point2f p, Float phi_o, Float theta_o) const {
    SampledSpectrum s;
    for (int i = 0; i < NSpectrumSamples; ++i)
        s[i] = std::max<Float>(
            0, data->spectra.Evaluate(p, std::array<Float, 3>{phi_o, theta_o, lambda[i]}));
    return s;
}

std::optional<MeasuredBxDF::Draw> MeasuredBxDF::EvaluateGeometry(const MeasuredBxDFData& data,
                                                                 Vector3f wo, Vector3f wi) {
    Vector3f wm = wi + wo;
    if (LengthSquared(wm) == 0) return {};
    wm = Normalize(wm);
    const Float theta_o = SphericalTheta(wo), phi_o = std::atan2(wo.y, wo.x);
    const Point2f u_wo(ThetaToU(theta_o), PhiToU(phi_o));
    const Point2f u_wm = HalfVectorToU(wm, phi_o, data.isotropic);
    const PiecewiseLinear2D::Sample ui =
        data.vndf.Invert(u_wm, std::array<Float, 2>{phi_o, theta_o});
    const Float denominator = 4 * data.sigma.Evaluate(u_wo, {}) * CosTheta(wi);
    const Float scale = data.ndf.Evaluate(u_wm, {}) / denominator;
    if (!(denominator > 0) || !std::isfinite(scale)) return {};
    return Draw{wi, 0, ui.p, scale, phi_o, theta_o};
}

SampledSpectrum MeasuredBxDF::f(Vector3f wo, Vector3f wi, TransportMode) const {
    if (!data || !SameHemisphere(wo, wi)) return SampledSpectrum(0.f);
    if (wo.z < 0) wo = -wo, wi = -wi;
    std::optional<Draw> d = EvaluateGeometry(*data, wo, wi);
    if (!d) return SampledSpectrum(0.f);
    SampledSpectrum fr = Spectra(d->p, d->phi_o, d->theta_o) * d->scale;
    return fr.IsFinite() ? fr : SampledSpectrum(0.f);
}

std::optional<MeasuredBxDF::Draw> MeasuredBxDF::SampleGeometry(const MeasuredBxDFData& data,
                                                               Vector3f wo, Point2f u) {
    const Float theta_o = SphericalTheta(wo), phi_o = std::atan2(wo.y, wo.x);
    const std::array<Float, 2> params{phi_o, theta_o};
    // A point of the square by luminance, then a normal by the visible-normal warp
    const PiecewiseLinear2D::Sample s = data.luminance.Draw(u, params);
    const PiecewiseLinear2D::Sample v = data.vndf.Draw(s.p, params);
    const Point2f u_wm = v.p;
    Float phi_m = UToPhi(u_wm.y);
    const Float theta_m = UToTheta(u_wm.x);
    if (data.isotropic) phi_m += phi_o;
    const Float sinTheta_m = std::sin(theta_m);
    const Vector3f wm = SphericalDirection(sinTheta_m, std::cos(theta_m), phi_m);
    const Vector3f wi = Reflect(wo, wm);
    const Float woDotWm = Dot(wo, wm);
    if (wi.z <= 0 || woDotWm <= 0) return {};

    const Point2f u_wo(ThetaToU(theta_o), PhiToU(phi_o));
    const Float denominator = 4 * data.sigma.Evaluate(u_wo, {}) * AbsCosTheta(wi);
    const Float pdf = v.pdf * s.pdf / (4 * woDotWm * SquareToNormalJacobian(u_wm.x, sinTheta_m));
    const Float scale = data.ndf.Evaluate(u_wm, {}) / denominator;
    if (!(denominator > 0) || !(pdf > 0) || !std::isfinite(pdf) || !std::isfinite(scale)) return {};
    return Draw{wi, pdf, s.p, scale, phi_o, theta_o};
}

std::optional<BSDFSample> MeasuredBxDF::Sample_f(Vector3f wo, Float, Point2f u, TransportMode,
                                                 BxDFReflTransFlags sampleFlags) const {
    if (!data || !(sampleFlags & BxDFReflTransFlags::Reflection)) return {};
    const bool flip = wo.z <= 0;
    std::optional<Draw> d = SampleGeometry(*data, flip ? -wo : wo, u);
    if (!d) return {};
    SampledSpectrum fr = Spectra(d->p, d->phi_o, d->theta_o) * d->scale;
    if (!fr.IsFinite()) return {};
    return BSDFSample(fr, flip ? -d->wi : d->wi, d->pdf, BxDFFlags::GlossyReflection);
}

Float MeasuredBxDF::PDF(Vector3f wo, Vector3f wi, TransportMode,
                        BxDFReflTransFlags sampleFlags) const {
    if (!data || !(sampleFlags & BxDFReflTransFlags::Reflection) || !SameHemisphere(wo, wi))
        return 0;
    if (wo.z < 0) wo = -wo, wi = -wi;
    Vector3f wm = wi + wo;
    if (LengthSquared(wm) == 0) return 0;
    wm = Normalize(wm);

    const Float theta_o = SphericalTheta(wo), phi_o = std::atan2(wo.y, wo.x);
    const std::array<Float, 2> params{phi_o, theta_o};
    const Point2f u_wm = HalfVectorToU(wm, phi_o, data->isotropic);
    const PiecewiseLinear2D::Sample ui = data->vndf.Invert(u_wm, params);
    const Float luminancePDF = data->luminance.Evaluate(ui.p, params);
    const Float sinTheta_m = std::sqrt(Sqr(wm.x) + Sqr(wm.y));
    const Float jacobian = 4 * Dot(wo, wm) * SquareToNormalJacobian(u_wm.x, sinTheta_m);
    if (!(jacobian > 0)) return 0;
    const Float pdf = ui.pdf * luminancePDF / jacobian;
    return std::isfinite(pdf) ? pdf : 0;
}

}  // namespace kiln
