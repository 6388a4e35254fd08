#include "materials/bxdfs/hair_bxdf.h"

#include <cmath>

#include "materials/bxdfs/fresnel.h"

namespace kiln {

// Lobe functions
namespace {

// Modified Bessel function of the first kind, order 0 (series, enough terms for x <= 12)
Float I0(Float x) {
    Float val = 0, x2i = 1;
    int64_t ifact = 1, i4 = 1;
    for (int i = 0; i < 10; ++i) {
        if (i > 1) ifact *= i;
        val += x2i / (Float(i4) * Float(ifact) * Float(ifact));
        x2i *= x * x;
        i4 *= 4;
    }
    return val;
}

// log I0(x), asymptotic above 12
Float LogI0(Float x) {
    if (x > 12) return x + 0.5f * (-std::log(2 * Pi) + std::log(1 / x) + 1 / (8 * x));
    return std::log(I0(x));
}

// Longitudinal scattering: the spherical Gaussian of variance v about -theta_o, marginalised
// (d'Eon et al. 2011); the log form for small v avoids overflow
Float Mp(Float cosThetaI, Float cosThetaO, Float sinThetaI, Float sinThetaO, Float v) {
    Float a = cosThetaI * cosThetaO / v, b = sinThetaI * sinThetaO / v;
    if (v <= .1f) return std::exp(LogI0(a) - b - 1 / v + 0.6931f + std::log(1 / (2 * v)));
    return std::exp(-b) * I0(a) / (std::sinh(1 / v) * 2 * v);
}

// The azimuthal angle a path with p internal segments leaves at
Float PhiOf(int p, Float gammaO, Float gammaT) { return 2 * p * gammaT - 2 * gammaO + p * Pi; }

Float Logistic(Float x, Float s) {
    x = std::abs(x);
    Float e = std::exp(-x / s);
    return e / (s * (1 + e) * (1 + e));
}
Float LogisticCDF(Float x, Float s) { return 1 / (1 + std::exp(-x / s)); }
Float TrimmedLogistic(Float x, Float s, Float a, Float b) {
    return Logistic(x, s) / (LogisticCDF(b, s) - LogisticCDF(a, s));
}
Float SampleTrimmedLogistic(Float u, Float s, Float a, Float b) {
    Float k = LogisticCDF(b, s) - LogisticCDF(a, s);
    Float x = -s * std::log(1 / (u * k + LogisticCDF(a, s)) - 1);
    return Clamp(x, a, b);
}

// Azimuthal scattering of lobe p: a trimmed logistic about its exit angle, over [-pi, pi]
Float Np(Float phi, int p, Float s, Float gammaO, Float gammaT) {
    Float dphi = phi - PhiOf(p, gammaO, gammaT);
    dphi = std::remainder(dphi, 2 * Pi);  // to [-pi, pi]
    return TrimmedLogistic(dphi, s, -Pi, Pi);
}

template <int N>
Float Pow(Float x) {
    Float r = 1;
    for (int i = 0; i < N; ++i) r *= x;
    return r;
}

}  // namespace

// HairBxDF
HairBxDF::HairBxDF(Float h, Float eta, const SampledSpectrum& sigma_a, Float beta_m, Float beta_n,
                   Float alpha)
    : h(Clamp(h, -1, 1)), gammaO(SafeASin(h)), eta(eta), sigma_a(sigma_a) {
    beta_m = Clamp(beta_m, 0, 1);
    beta_n = Clamp(beta_n, 0, 1);
    // Longitudinal variances from beta_m (R, TT, TRT and the rest)
    Float sq = 0.726f * beta_m + 0.812f * beta_m * beta_m + 3.7f * Pow<20>(beta_m);
    v[0] = sq * sq;
    v[1] = .25f * v[0];
    v[2] = 4 * v[0];
    for (int p = 3; p <= pMax; ++p) v[p] = v[2];
    // Azimuthal logistic scale from beta_n
    s = std::sqrt(Pi / 8) * (0.265f * beta_n + 1.194f * beta_n * beta_n + 5.372f * Pow<22>(beta_n));
    // sin and cos of 2^k alpha for the scale tilts
    sin2kAlpha[0] = std::sin(Radians(alpha));
    cos2kAlpha[0] = SafeSqrt(1 - sin2kAlpha[0] * sin2kAlpha[0]);
    for (int i = 1; i < pMax; ++i) {
        sin2kAlpha[i] = 2 * cos2kAlpha[i - 1] * sin2kAlpha[i - 1];
        cos2kAlpha[i] =
            cos2kAlpha[i - 1] * cos2kAlpha[i - 1] - sin2kAlpha[i - 1] * sin2kAlpha[i - 1];
    }
}

void HairBxDF::TiltedThetaO(int p, Float sinThetaO, Float cosThetaO, Float* sinThetaOp,
                            Float* cosThetaOp) const {
    // R is tilted by -2 alpha, TT by alpha, TRT by 4 alpha; the rest not at all
    if (p == 0) {
        *sinThetaOp = sinThetaO * cos2kAlpha[1] - cosThetaO * sin2kAlpha[1];
        *cosThetaOp = cosThetaO * cos2kAlpha[1] + sinThetaO * sin2kAlpha[1];
    } else if (p == 1) {
        *sinThetaOp = sinThetaO * cos2kAlpha[0] + cosThetaO * sin2kAlpha[0];
        *cosThetaOp = cosThetaO * cos2kAlpha[0] - sinThetaO * sin2kAlpha[0];
    } else if (p == 2) {
        *sinThetaOp = sinThetaO * cos2kAlpha[2] + cosThetaO * sin2kAlpha[2];
        *cosThetaOp = cosThetaO * cos2kAlpha[2] - sinThetaO * sin2kAlpha[2];
    } else {
        *sinThetaOp = sinThetaO;
        *cosThetaOp = cosThetaO;
    }
    *cosThetaOp = std::abs(*cosThetaOp);
}

Float HairBxDF::GammaT(Float sinThetaO, Float cosThetaO) const {
    Float etap = SafeSqrt(eta * eta - sinThetaO * sinThetaO) / cosThetaO;
    return SafeASin(h / etap);
}

std::array<SampledSpectrum, HairBxDF::pMax + 1> HairBxDF::Attenuation(Float cosThetaO,
                                                                      Float sinThetaO) const {
    // Transmittance of one crossing of the fibre by the refracted ray
    Float sinThetaT = sinThetaO / eta, cosThetaT = SafeSqrt(1 - sinThetaT * sinThetaT);
    Float gammaT = GammaT(sinThetaO, cosThetaO), cosGammaT = std::cos(gammaT);
    SampledSpectrum T = Exp(-sigma_a * (2 * cosGammaT / cosThetaT));
    std::array<SampledSpectrum, pMax + 1> ap;
    // Fresnel reflection at the first interface, then one more crossing per order
    Float cosGammaO = SafeSqrt(1 - h * h);
    Float f = FrDielectric(cosThetaO * cosGammaO, eta);
    ap[0] = SampledSpectrum(f);
    ap[1] = (1 - f) * (1 - f) * T;
    for (int p = 2; p < pMax; ++p) ap[p] = ap[p - 1] * T * f;
    // Every higher order, summed as a geometric series
    SampledSpectrum denom = SampledSpectrum(1.f) - T * f;
    ap[pMax] = denom ? ap[pMax - 1] * f * T / denom : SampledSpectrum(0.f);
    return ap;
}

SampledSpectrum HairBxDF::Albedo(Vector3f wo) const {
    Float sinThetaO = wo.x, cosThetaO = SafeSqrt(1 - sinThetaO * sinThetaO);
    if (cosThetaO == 0) return SampledSpectrum(0.f);  // f is 0 along the fibre (f() above)
    SampledSpectrum sum(0.f);
    for (const SampledSpectrum& a : Attenuation(cosThetaO, sinThetaO)) sum += a;
    return sum;
}

std::array<Float, HairBxDF::pMax + 1> HairBxDF::LobePDF(Float cosThetaO, Float sinThetaO) const {
    std::array<SampledSpectrum, pMax + 1> ap = Attenuation(cosThetaO, sinThetaO);
    std::array<Float, pMax + 1> pdf;
    Float sum = 0;
    for (const SampledSpectrum& a : ap) sum += a.Average();
    for (int i = 0; i <= pMax; ++i) pdf[i] = sum > 0 ? ap[i].Average() / sum : 0;
    return pdf;
}

SampledSpectrum HairBxDF::f(Vector3f wo, Vector3f wi, TransportMode) const {
    Float sinThetaO = wo.x, cosThetaO = SafeSqrt(1 - sinThetaO * sinThetaO);
    Float phiO = std::atan2(wo.z, wo.y);
    Float sinThetaI = wi.x, cosThetaI = SafeSqrt(1 - sinThetaI * sinThetaI);
    Float phiI = std::atan2(wi.z, wi.y);
    if (cosThetaO == 0) return SampledSpectrum(0.f);
    SampledSpectrum fsum = SumLobes(sinThetaO, cosThetaO, sinThetaI, cosThetaI, phiI - phiO,
                                    Attenuation(cosThetaO, sinThetaO));
    // The model's lobes are per unit projected solid angle
    if (std::abs(wi.z) > 0) fsum /= std::abs(wi.z);
    return fsum;
}

template <typename W>
W HairBxDF::SumLobes(Float sinThetaO, Float cosThetaO, Float sinThetaI, Float cosThetaI, Float dphi,
                     const std::array<W, pMax + 1>& weights) const {
    Float gammaT = GammaT(sinThetaO, cosThetaO);
    W sum(0.f);
    for (int p = 0; p < pMax; ++p) {
        Float sinThetaOp, cosThetaOp;
        TiltedThetaO(p, sinThetaO, cosThetaO, &sinThetaOp, &cosThetaOp);
        sum += Mp(cosThetaI, cosThetaOp, sinThetaI, sinThetaOp, v[p]) * weights[p] *
               Np(dphi, p, s, gammaO, gammaT);
    }
    // The remaining orders: untilted, uniform in azimuth
    sum += Mp(cosThetaI, cosThetaO, sinThetaI, sinThetaO, v[pMax]) * weights[pMax] / (2 * Pi);
    return sum;
}

Float HairBxDF::PDF(Vector3f wo, Vector3f wi, TransportMode, BxDFReflTransFlags) const {
    Float sinThetaO = wo.x, cosThetaO = SafeSqrt(1 - sinThetaO * sinThetaO);
    if (cosThetaO == 0) return 0;
    Float sinThetaI = wi.x, cosThetaI = SafeSqrt(1 - sinThetaI * sinThetaI);
    Float dphi = std::atan2(wi.z, wi.y) - std::atan2(wo.z, wo.y);
    return SumLobes(sinThetaO, cosThetaO, sinThetaI, cosThetaI, dphi,
                    LobePDF(cosThetaO, sinThetaO));
}

std::optional<BSDFSample> HairBxDF::Sample_f(Vector3f wo, Float uc, Point2f u, TransportMode mode,
                                             BxDFReflTransFlags sampleFlags) const {
    if (!(uint32_t(sampleFlags) & uint32_t(BxDFReflTransFlags::Reflection))) return {};
    Float sinThetaO = wo.x, cosThetaO = SafeSqrt(1 - sinThetaO * sinThetaO);
    if (cosThetaO == 0) return {};
    Float phiO = std::atan2(wo.z, wo.y);
    // Choose a lobe p by its share of the attenuation; uc is remapped for reuse
    std::array<Float, pMax + 1> apPDF = LobePDF(cosThetaO, sinThetaO);
    int p = 0;
    for (; p < pMax; ++p) {
        if (uc < apPDF[p]) break;
        uc -= apPDF[p];
    }
    uc = apPDF[p] > 0 ? std::min(uc / apPDF[p], OneMinusEpsilon) : 0.5f;
    Float sinThetaOp, cosThetaOp;
    TiltedThetaO(p, sinThetaO, cosThetaO, &sinThetaOp, &cosThetaOp);
    // Mp: a direction on the spherical Gaussian about the tilted -theta_o
    Float cosTheta =
        1 + v[p] * std::log(std::max<Float>(u[0], 1e-5f) + (1 - u[0]) * std::exp(-2 / v[p]));
    Float sinTheta = SafeSqrt(1 - cosTheta * cosTheta);
    Float cosPhi = std::cos(2 * Pi * u[1]);
    Float sinThetaI = Clamp(-cosTheta * sinThetaOp + sinTheta * cosPhi * cosThetaOp, -1, 1);
    Float cosThetaI = SafeSqrt(1 - sinThetaI * sinThetaI);
    // Np: the azimuthal offset about the lobe's exit angle
    Float gammaT = GammaT(sinThetaO, cosThetaO);
    Float dphi =
        p < pMax ? PhiOf(p, gammaO, gammaT) + SampleTrimmedLogistic(uc, s, -Pi, Pi) : 2 * Pi * uc;
    Float phiI = phiO + dphi;
    Vector3f wi(sinThetaI, cosThetaI * std::cos(phiI), cosThetaI * std::sin(phiI));
    Float pdf = SumLobes(sinThetaO, cosThetaO, sinThetaI, cosThetaI, dphi, apPDF);
    if (!(pdf > 0) || !std::isfinite(pdf)) return {};
    return BSDFSample(f(wo, wi, mode), wi, pdf, Flags());
}

// Absorption coefficients
RGB HairBxDF::SigmaAFromConcentration(Float eumelanin, Float pheomelanin) {
    const RGB eu(0.419f, 0.697f, 1.37f), pheo(0.187f, 0.4f, 1.05f);
    return RGB(eumelanin * eu.r + pheomelanin * pheo.r, eumelanin * eu.g + pheomelanin * pheo.g,
               eumelanin * eu.b + pheomelanin * pheo.b);
}

SampledSpectrum HairBxDF::SigmaAFromReflectance(const SampledSpectrum& c, Float beta_n) {
    Float d = 5.969f - 0.215f * beta_n + 2.532f * beta_n * beta_n - 10.73f * Pow<3>(beta_n) +
              5.574f * Pow<4>(beta_n) + 0.245f * Pow<5>(beta_n);
    SampledSpectrum sigma;
    for (int i = 0; i < NSpectrumSamples; ++i) {
        Float l = std::log(std::max<Float>(c[i], 1e-30f)) / d;
        sigma[i] = l * l;
    }
    return sigma;
}

}  // namespace kiln
