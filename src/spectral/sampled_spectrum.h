// Spectral quantities at a few wavelengths, carried along a light path.
//
// A path transports NSpectrumSamples wavelengths at once (hero-wavelength sampling,
// Wilkie et al. 2014): the first is drawn from the visible-range importance density and the
// others are stratified with it. Values are whatever the context says (radiance in
// W m^-2 sr^-1 nm^-1, reflectance, throughput); wavelengths are in nanometres.
#pragma once

#include <array>
#include <cmath>

#include "base/vecmath.h"

namespace kiln {

inline constexpr int NSpectrumSamples = 4;
inline constexpr Float Lambda_min = 360, Lambda_max = 830;

class SampledSpectrum {
  public:
    SampledSpectrum() { values.fill(0); }
    explicit SampledSpectrum(Float c) { values.fill(c); }
    explicit SampledSpectrum(const std::array<Float, NSpectrumSamples>& v) : values(v) {}

    Float operator[](int i) const { return values[i]; }
    Float& operator[](int i) { return values[i]; }

    explicit operator bool() const {
        for (Float v : values)
            if (v != 0) return true;
        return false;
    }
    bool IsZero() const { return !bool(*this); }

#define KILN_SS_OP(op)                                                    \
    SampledSpectrum& operator op##=(const SampledSpectrum& s) {           \
        for (int i = 0; i < NSpectrumSamples; ++i) values[i] op## = s[i]; \
        return *this;                                                     \
    }                                                                     \
    SampledSpectrum operator op(const SampledSpectrum& s) const {         \
        SampledSpectrum r = *this;                                        \
        return r op## = s;                                                \
    }                                                                     \
    SampledSpectrum& operator op##=(Float a) {                            \
        for (int i = 0; i < NSpectrumSamples; ++i) values[i] op## = a;    \
        return *this;                                                     \
    }                                                                     \
    SampledSpectrum operator op(Float a) const {                          \
        SampledSpectrum r = *this;                                        \
        return r op## = a;                                                \
    }
    KILN_SS_OP(+)
    KILN_SS_OP(-)
    KILN_SS_OP(*)
    KILN_SS_OP(/)
#undef KILN_SS_OP

    SampledSpectrum operator-() const {
        SampledSpectrum r;
        for (int i = 0; i < NSpectrumSamples; ++i) r[i] = -values[i];
        return r;
    }
    bool operator==(const SampledSpectrum& s) const { return values == s.values; }
    bool operator!=(const SampledSpectrum& s) const { return values != s.values; }

    Float MinComponentValue() const {
        Float m = values[0];
        for (int i = 1; i < NSpectrumSamples; ++i) m = std::min(m, values[i]);
        return m;
    }
    Float MaxComponentValue() const {
        Float m = values[0];
        for (int i = 1; i < NSpectrumSamples; ++i) m = std::max(m, values[i]);
        return m;
    }
    Float Average() const {
        Float s = 0;
        for (Float v : values) s += v;
        return s / NSpectrumSamples;
    }
    bool HasNaN() const {
        for (Float v : values)
            if (std::isnan(v)) return true;
        return false;
    }
    bool IsFinite() const {
        for (Float v : values)
            if (!std::isfinite(v)) return false;
        return true;
    }

    const std::array<Float, NSpectrumSamples>& Values() const { return values; }

  private:
    std::array<Float, NSpectrumSamples> values;
};

inline SampledSpectrum operator*(Float a, const SampledSpectrum& s) { return s * a; }

// Component-wise functions
template <typename F>
inline SampledSpectrum Map(const SampledSpectrum& s, F f) {
    SampledSpectrum r;
    for (int i = 0; i < NSpectrumSamples; ++i) r[i] = f(s[i]);
    return r;
}
inline SampledSpectrum SafeDiv(const SampledSpectrum& a, const SampledSpectrum& b) {
    SampledSpectrum r;
    for (int i = 0; i < NSpectrumSamples; ++i) r[i] = (b[i] != 0) ? a[i] / b[i] : 0;
    return r;
}
inline SampledSpectrum Sqrt(const SampledSpectrum& s) {
    return Map(s, [](Float v) { return std::sqrt(v); });
}
inline SampledSpectrum SafeSqrt(const SampledSpectrum& s) {
    return Map(s, [](Float v) { return SafeSqrt(v); });
}
inline SampledSpectrum Exp(const SampledSpectrum& s) {
    return Map(s, [](Float v) { return std::exp(v); });
}
inline SampledSpectrum Clamp(const SampledSpectrum& s, Float lo, Float hi) {
    return Map(s, [=](Float v) { return Clamp(v, lo, hi); });
}
inline SampledSpectrum ClampZero(const SampledSpectrum& s) {
    return Map(s, [](Float v) { return std::max<Float>(0, v); });
}
inline SampledSpectrum Lerp(Float t, const SampledSpectrum& a, const SampledSpectrum& b) {
    return (1 - t) * a + t * b;
}

// Wavelengths carried by one path, with the density each was sampled with (per nm).
class SampledWavelengths {
  public:
    // Uniform over [lambdaMin, lambdaMax], stratified: one u gives all samples.
    static SampledWavelengths SampleUniform(Float u, Float lambdaMin = Lambda_min,
                                            Float lambdaMax = Lambda_max) {
        SampledWavelengths swl;
        swl.lambda[0] = Lerp(u, lambdaMin, lambdaMax);
        Float delta = (lambdaMax - lambdaMin) / NSpectrumSamples;
        for (int i = 1; i < NSpectrumSamples; ++i) {
            swl.lambda[i] = swl.lambda[i - 1] + delta;
            if (swl.lambda[i] > lambdaMax) swl.lambda[i] = lambdaMin + (swl.lambda[i] - lambdaMax);
        }
        for (int i = 0; i < NSpectrumSamples; ++i) swl.pdf[i] = 1 / (lambdaMax - lambdaMin);
        return swl;
    }

    // Importance-samples 360-830 nm with the density of Radziszewski et al. (2009), which
    // follows the shape of the CIE Y curve: p(l) = 0.0039398042 / cosh^2(0.0072 (l - 538)).
    static SampledWavelengths SampleVisible(Float u) {
        SampledWavelengths swl;
        for (int i = 0; i < NSpectrumSamples; ++i) {
            Float up = u + Float(i) / NSpectrumSamples;
            if (up > 1) up -= 1;
            swl.lambda[i] = SampleVisibleWavelength(up);
            swl.pdf[i] = VisibleWavelengthPDF(swl.lambda[i]);
        }
        return swl;
    }
    static Float VisibleWavelengthPDF(Float lambda) {
        if (lambda < Lambda_min || lambda > Lambda_max) return 0;
        return 0.0039398042f / Sqr(std::cosh(0.0072f * (lambda - 538)));
    }
    static Float SampleVisibleWavelength(Float u) {
        return 538 - 138.888889f * std::atanh(0.85691062f - 1.82750197f * u);
    }

    // Wavelengths (nm) drawn by some other density, with their densities (per nm).
    static SampledWavelengths FromSamples(const std::array<Float, NSpectrumSamples>& lambda,
                                          const std::array<Float, NSpectrumSamples>& pdf) {
        SampledWavelengths swl;
        swl.lambda = lambda;
        swl.pdf = pdf;
        return swl;
    }

    // All samples at one wavelength (nm) with density 1: for evaluating spectra and BSDFs
    // at chosen wavelengths (tables, tests), not for Monte Carlo estimates.
    static SampledWavelengths FromWavelength(Float lambda_nm) {
        SampledWavelengths swl;
        swl.lambda.fill(lambda_nm);
        swl.pdf.fill(1);
        return swl;
    }

    Float operator[](int i) const { return lambda[i]; }
    Float& operator[](int i) { return lambda[i]; }
    SampledSpectrum PDF() const { return SampledSpectrum(pdf); }

    // Keeps only the hero wavelength (after wavelength-dependent refraction).
    void TerminateSecondary() {
        if (SecondaryTerminated()) return;
        for (int i = 1; i < NSpectrumSamples; ++i) pdf[i] = 0;
        pdf[0] /= NSpectrumSamples;
    }
    bool SecondaryTerminated() const {
        for (int i = 1; i < NSpectrumSamples; ++i)
            if (pdf[i] != 0) return false;
        return true;
    }

  private:
    std::array<Float, NSpectrumSamples> lambda{}, pdf{};
};

}  // namespace kiln
