#include "materials/bxdfs/fresnel_mueller.h"

#include <complex>

#include "materials/bxdfs/fresnel.h"

namespace kiln {

namespace {

// The entries of a reflection matrix at one wavelength from the amplitude coefficients.
void SetReflection(MuellerMatrix& M, int i, std::complex<double> rs, std::complex<double> rp) {
    double Rs = std::norm(rs), Rp = std::norm(rp);
    std::complex<double> x = rs * std::conj(rp);
    M(0, 0)[i] = M(1, 1)[i] = Float(0.5 * (Rs + Rp));
    M(0, 1)[i] = M(1, 0)[i] = Float(0.5 * (Rs - Rp));
    M(2, 2)[i] = M(3, 3)[i] = Float(x.real());
    M(2, 3)[i] = Float(x.imag());
    M(3, 2)[i] = Float(-x.imag());
}

}  // namespace

MuellerMatrix FresnelReflectionMueller(Float cosTheta_i, const SampledSpectrum& eta,
                                       const SampledSpectrum& k) {
    MuellerMatrix M;
    for (int i = 0; i < NSpectrumSamples; ++i) {
        FresnelAmplitudes r = FrComplexAmplitudes(cosTheta_i, std::complex<Float>(eta[i], k[i]));
        SetReflection(M, i, r.rs, r.rp);
    }
    return M;
}

MuellerMatrix FresnelReflectionMueller(Float cosTheta_i, Float eta) {
    if (cosTheta_i < 0) {
        cosTheta_i = -cosTheta_i;
        eta = 1 / eta;
    }
    FresnelAmplitudes r = FrComplexAmplitudes(cosTheta_i, std::complex<Float>(eta, 0));
    MuellerMatrix M;
    for (int i = 0; i < NSpectrumSamples; ++i) SetReflection(M, i, r.rs, r.rp);
    return M;
}

namespace {

MuellerMatrix TransmissionMueller(FresnelRsRp R) {
    Float Ts = 1 - R.Rs, Tp = 1 - R.Rp;
    MuellerMatrix M;
    if (Ts <= 0 && Tp <= 0) return M;
    M(0, 0) = M(1, 1) = SampledSpectrum(0.5f * (Ts + Tp));
    M(0, 1) = M(1, 0) = SampledSpectrum(0.5f * (Ts - Tp));
    M(2, 2) = M(3, 3) = SampledSpectrum(std::sqrt(std::max<Float>(0, Ts * Tp)));
    return M;
}

}  // namespace

MuellerMatrix FresnelTransmissionMueller(Float cosTheta_i, Float eta) {
    return TransmissionMueller(FrDielectricPolarized(cosTheta_i, eta));
}

MuellerMatrix AbsorbingDielectricReflectionMueller(Float cosTheta_i, Float eta, Float k) {
    Float c = AbsorbingDielectricOutsideCosine(cosTheta_i, eta);
    if (k == 0 || (cosTheta_i < 0 && c == 0)) return FresnelReflectionMueller(cosTheta_i, eta);
    return FresnelReflectionMueller(c, SampledSpectrum(eta), SampledSpectrum(k));
}

MuellerMatrix AbsorbingDielectricTransmissionMueller(Float cosTheta_i, Float eta, Float k) {
    return TransmissionMueller(FrAbsorbingDielectricPolarized(cosTheta_i, eta, k));
}

MuellerMatrix MicrofacetToSurfaceFrame(const MuellerMatrix& M, Vector3f wo, Vector3f wi,
                                       Vector3f wm) {
    Vector3f z(0, 0, 1);
    return RotateMuellerBasis(M, -wi, PlaneAxis(wm, wi), PlaneAxis(z, wi), wo, PlaneAxis(wm, wo),
                              PlaneAxis(z, wo));
}

}  // namespace kiln
