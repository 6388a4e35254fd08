#include "materials/bxdfs/thin_dielectric_bxdf.h"

#include "materials/bxdfs/fresnel.h"
#include "materials/bxdfs/fresnel_mueller.h"

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
    BxDFFlags flags = BxDFFlags::SpecularTransmission;
    return BSDFSample(ft, wi, pt / (pr + pt),
                      straightThrough ? flags | BxDFFlags::StraightThrough : flags);
}

// Polarised transport: the inter-reflection series summed for the s and p waves separately
// (incoherently: rs and rp are real for a dielectric slab seen from outside, and every path's
// matrix has the form of FresnelReflectionMueller without phase). Each wave's reflectance and
// transmittance add to 1, so the slab conserves each polarisation and an isothermal cavity
// stays unpolarised. M00 is therefore the mean of the two waves' series, not the unpolarised
// BxDF's value, which sums the series for the mean reflectance as pbrt-v4 does: the two differ
// at oblique incidence (at 60 degrees and eta 1.5, R = 0.152 against 0.164), the one exception
// to "M00 is the unpolarised value" (bxdf.h). Sampling is the unpolarised BxDF's.
MuellerMatrix ThinDielectricBxDF::MuellerSample(Vector3f wo, const BSDFSample& bs,
                                                TransportMode) const {
    FresnelAmplitudes r = FrComplexAmplitudes(AbsCosTheta(wo), std::complex<Float>(eta, 0));
    double rs = r.rs.real(), rp = r.rp.real(), Rs = rs * rs, Rp = rp * rp;
    double Ts = 1 - Rs, Tp = 1 - Rp;
    double a, b, c;
    if (bs.IsReflection()) {
        // R_x + T_x^2 R_x / (1 - R_x^2) per wave; the lower block: rs rp (1 + Ts Tp / (1 - Rs Rp))
        double RsTot = Rs < 1 ? Rs + Ts * Ts * Rs / (1 - Rs * Rs) : 1;
        double RpTot = Rp < 1 ? Rp + Tp * Tp * Rp / (1 - Rp * Rp) : 1;
        a = 0.5 * (RsTot + RpTot);
        b = 0.5 * (RsTot - RpTot);
        c = Rs * Rp < 1 ? rs * rp * (1 + Ts * Tp / (1 - Rs * Rp)) : rs * rp;
    } else {
        // T_x^2 / (1 - R_x^2) per wave; the lower block: Ts Tp / (1 - Rs Rp)
        double TsTot = Rs < 1 ? Ts * Ts / (1 - Rs * Rs) : 0;
        double TpTot = Rp < 1 ? Tp * Tp / (1 - Rp * Rp) : 0;
        a = 0.5 * (TsTot + TpTot);
        b = 0.5 * (TsTot - TpTot);
        c = Rs * Rp < 1 ? Ts * Tp / (1 - Rs * Rp) : 0;
    }
    MuellerMatrix M;
    if (a <= 0) return M;
    Float scale = 1 / AbsCosTheta(bs.wi);
    M(0, 0) = M(1, 1) = SampledSpectrum(Float(a) * scale);
    M(0, 1) = M(1, 0) = SampledSpectrum(Float(b) * scale);
    M(2, 2) = M(3, 3) = SampledSpectrum(Float(c) * scale);
    return M;
}

}  // namespace kiln
