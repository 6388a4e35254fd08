#include "materials/bxdfs/fresnel.h"

namespace kiln {

// Refraction
bool Refract(Vector3f wi, Normal3f n, Float eta, Float* etap, Vector3f* wt) {
    Float cosTheta_i = Dot(n, wi);
    // Incidence from below n: swap the media.
    if (cosTheta_i < 0) {
        eta = 1 / eta;
        cosTheta_i = -cosTheta_i;
        n = -n;
    }
    // Snell's law: sin^2 theta_t = sin^2 theta_i / eta^2.
    Float sin2Theta_i = std::max<Float>(0, 1 - Sqr(cosTheta_i));
    Float sin2Theta_t = sin2Theta_i / Sqr(eta);
    if (sin2Theta_t >= 1) return false;
    Float cosTheta_t = SafeSqrt(1 - sin2Theta_t);
    *wt = -wi / eta + (cosTheta_i / eta - cosTheta_t) * Vector3f(n);
    if (etap) *etap = eta;
    return true;
}

// Dielectric Fresnel equations
namespace {

// Real relative IOR: *Rs, *Rp in double precision; both 1 under total internal reflection.
void DielectricRsRp(double cosTheta_i, double eta, double* Rs, double* Rp) {
    cosTheta_i = std::clamp(cosTheta_i, -1.0, 1.0);
    if (cosTheta_i < 0) {
        eta = 1 / eta;
        cosTheta_i = -cosTheta_i;
    }
    // 1 - cos^2 written as (1 - cos)(1 + cos) keeps precision near normal incidence.
    double sin2Theta_i = (1 - cosTheta_i) * (1 + cosTheta_i);
    double sin2Theta_t = sin2Theta_i / (eta * eta);
    if (sin2Theta_t >= 1) {
        *Rs = *Rp = 1;
        return;
    }
    double cosTheta_t = std::sqrt(1 - sin2Theta_t);
    double r_parl = (eta * cosTheta_i - cosTheta_t) / (eta * cosTheta_i + cosTheta_t);
    double r_perp = (cosTheta_i - eta * cosTheta_t) / (cosTheta_i + eta * cosTheta_t);
    *Rs = r_perp * r_perp;
    *Rp = r_parl * r_parl;
}

}  // namespace

Float FrDielectric(Float cosTheta_i, Float eta) {
    double Rs, Rp;
    DielectricRsRp(cosTheta_i, eta, &Rs, &Rp);
    return Float(std::clamp(0.5 * (Rs + Rp), 0.0, 1.0));
}

FresnelRsRp FrDielectricPolarized(Float cosTheta_i, Float eta) {
    double Rs, Rp;
    DielectricRsRp(cosTheta_i, eta, &Rs, &Rp);
    return {Float(std::clamp(Rs, 0.0, 1.0)), Float(std::clamp(Rp, 0.0, 1.0))};
}

// Complex Fresnel equations
FresnelAmplitudes FrComplexAmplitudes(Float cosTheta_i, std::complex<Float> etaf) {
    using C = std::complex<double>;
    double cosi = std::clamp(double(cosTheta_i), 0.0, 1.0);
    C eta(etaf.real(), etaf.imag());
    // eta = 0 (no medium data): the limit of a perfect reflector.
    if (std::norm(eta) == 0) return {C(-1), C(1)};
    // Grazing incidence: total reflection (the limit of both coefficients is -1).
    if (cosi == 0) return {C(-1), C(-1)};
    double sin2Theta_i = (1 - cosi) * (1 + cosi);
    C sin2Theta_t = sin2Theta_i / (eta * eta);
    // Principal square root: Im(eta cos_t) >= 0 for absorbing media (the transmitted wave
    // decays) and cos_t purely imaginary (evanescent) under total internal reflection.
    C cosTheta_t = std::sqrt(1.0 - sin2Theta_t);
    C rp = (eta * cosi - cosTheta_t) / (eta * cosi + cosTheta_t);
    C rs = (cosi - eta * cosTheta_t) / (cosi + eta * cosTheta_t);
    return {rs, rp};
}

FresnelRsRp FrComplexPolarized(Float cosTheta_i, std::complex<Float> eta) {
    FresnelAmplitudes r = FrComplexAmplitudes(cosTheta_i, eta);
    return {Float(std::clamp(std::norm(r.rs), 0.0, 1.0)),
            Float(std::clamp(std::norm(r.rp), 0.0, 1.0))};
}

// Unpolarised reflectance: the same equations as FrComplexAmplitudes with |a / b|^2 written as
// |a|^2 / |b|^2 and the principal square root spelled out, so no library complex division
// (__divdc3) or csqrt runs per call; this is on the path of every conductor sample.
Float FrComplex(Float cosTheta_i, std::complex<Float> etaf) {
    double cosi = std::clamp(double(cosTheta_i), 0.0, 1.0);
    double er = etaf.real(), ei = etaf.imag();
    double etaNorm = er * er + ei * ei;
    if (etaNorm == 0 || cosi == 0) return 1;  // perfect reflector / grazing limits
    // sin^2 theta_t = sin^2 theta_i / eta^2, eta^2 = (er^2 - ei^2) + 2 i er ei
    double sin2Theta_i = (1 - cosi) * (1 + cosi);
    double e2r = er * er - ei * ei, e2i = 2 * er * ei;
    double inv = sin2Theta_i / (e2r * e2r + e2i * e2i);
    double zr = 1 - e2r * inv, zi = e2i * inv;  // 1 - sin^2 theta_t
    // Principal square root of z (Im >= 0 for Im z >= 0). |z| without hypot's scaling: for
    // float eta and k, |zr| and |zi| stay below 1e90, so their squares cannot overflow
    double mag = std::sqrt(zr * zr + zi * zi);
    double t = std::sqrt(0.5 * (mag + std::abs(zr)));
    double ctr, cti;
    if (t == 0) {
        ctr = cti = 0;
    } else if (zr >= 0) {
        ctr = t;
        cti = zi / (2 * t);
    } else {
        ctr = std::abs(zi) / (2 * t);
        cti = std::copysign(t, zi);
    }
    // rp = (eta cos_i - cos_t) / (eta cos_i + cos_t)
    double ar = er * cosi, ai = ei * cosi;
    double rp = (Sqr(ar - ctr) + Sqr(ai - cti)) / (Sqr(ar + ctr) + Sqr(ai + cti));
    // rs = (cos_i - eta cos_t) / (cos_i + eta cos_t)
    double br = er * ctr - ei * cti, bi = er * cti + ei * ctr;
    double rs = (Sqr(cosi - br) + Sqr(bi)) / (Sqr(cosi + br) + Sqr(bi));
    return Float(std::clamp(0.5 * (rs + rp), 0.0, 1.0));
}

// The same arithmetic as FrComplex above, lane by lane, with its branches turned into selects
// between values computed in every lane (so the loop compiles to SIMD instructions, two doubles
// per instruction with SSE2: the cases a lane does not take may divide by zero, and their
// results are discarded). Each lane's value equals FrComplex(cosTheta_i, {eta[i], k[i]}).
SampledSpectrum FrComplex(Float cosTheta_i, SampledSpectrum eta, SampledSpectrum k) {
    double cosi = std::clamp(double(cosTheta_i), 0.0, 1.0);
    if (cosi == 0) return SampledSpectrum(1);  // grazing limit
    double sin2Theta_i = (1 - cosi) * (1 + cosi);
    double R[NSpectrumSamples];
    for (int i = 0; i < NSpectrumSamples; ++i) {
        double er = eta[i], ei = k[i];
        double e2r = er * er - ei * ei, e2i = 2 * er * ei;
        double inv = sin2Theta_i / (e2r * e2r + e2i * e2i);
        double zr = 1 - e2r * inv, zi = e2i * inv;
        double mag = std::sqrt(zr * zr + zi * zi);
        double t = std::sqrt(0.5 * (mag + std::abs(zr)));
        double zrNonNegative = zi / (2 * t), zrNegative = std::abs(zi) / (2 * t);
        double ctr = t == 0 ? 0 : (zr >= 0 ? t : zrNegative);
        double cti = t == 0 ? 0 : (zr >= 0 ? zrNonNegative : std::copysign(t, zi));
        double ar = er * cosi, ai = ei * cosi;
        double rp = (Sqr(ar - ctr) + Sqr(ai - cti)) / (Sqr(ar + ctr) + Sqr(ai + cti));
        double br = er * ctr - ei * cti, bi = er * cti + ei * ctr;
        double rs = (Sqr(cosi - br) + Sqr(bi)) / (Sqr(cosi + br) + Sqr(bi));
        double r = std::min(std::max(0.5 * (rs + rp), 0.0), 1.0);
        R[i] = er * er + ei * ei == 0 ? 1 : r;  // perfect reflector limit
    }
    SampledSpectrum out;
    for (int i = 0; i < NSpectrumSamples; ++i) out[i] = Float(R[i]);
    return out;
}

// Absorbing dielectrics
Float AbsorbingDielectricOutsideCosine(Float cosTheta_i, Float eta) {
    double c = std::clamp(double(cosTheta_i), -1.0, 1.0);
    if (c >= 0) return Float(c);
    // sin theta_outside = eta sin theta_inside
    double sin2Outside = (1 - c) * (1 + c) * double(eta) * eta;
    return sin2Outside >= 1 ? 0 : Float(std::sqrt(1 - sin2Outside));
}

FresnelRsRp FrAbsorbingDielectricPolarized(Float cosTheta_i, Float eta, Float k) {
    if (k == 0) return FrDielectricPolarized(cosTheta_i, eta);
    Float c = AbsorbingDielectricOutsideCosine(cosTheta_i, eta);
    if (c == 0) return {1, 1};  // grazing from outside, or total internal reflection
    return FrComplexPolarized(c, std::complex<Float>(eta, k));
}

Float FrAbsorbingDielectric(Float cosTheta_i, Float eta, Float k) {
    if (k == 0) return FrDielectric(cosTheta_i, eta);
    Float c = AbsorbingDielectricOutsideCosine(cosTheta_i, eta);
    return c == 0 ? 1 : FrComplex(c, std::complex<Float>(eta, k));
}

}  // namespace kiln
