// Spectral quantities at a few wavelengths, carried along a light path.
//
// A path transports NSpectrumSamples wavelengths at once (hero-wavelength sampling,
// Wilkie et al. 2014): the first is drawn from the visible-range importance density and the
// others are stratified with it. Values are whatever the context says (radiance in
// W m^-2 sr^-1 nm^-1, reflectance, throughput); wavelengths are in nanometres.
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstring>

#include "base/vecmath.h"

namespace kiln {

inline constexpr int NSpectrumSamples = 4;
inline constexpr Float Lambda_min = 360, Lambda_max = 830;

// The values live in one SIMD register (GCC's and Clang's vector extension: SSE on x86-64,
// NEON on ARM): arithmetic is one instruction per operation, and a spectrum is passed to and
// returned from functions in a register rather than through memory, as a struct of four floats
// is under the x86-64 calling convention.
class SampledSpectrum {
    // may_alias: single values are read and written through Float pointers (operator[])
    using Lanes =
        Float __attribute__((vector_size(sizeof(Float) * NSpectrumSamples), __may_alias__));
    using Mask = decltype(Lanes{} != Lanes{});

  public:
    SampledSpectrum() : values{} {}
    explicit SampledSpectrum(Float c) : values(Lanes{} + c) {}
    explicit SampledSpectrum(const std::array<Float, NSpectrumSamples>& v) {
        std::memcpy(&values, v.data(), sizeof values);
    }

    Float operator[](int i) const { return values[i]; }
    Float& operator[](int i) { return reinterpret_cast<Float*>(&values)[i]; }

    explicit operator bool() const { return Any(values != 0); }
    bool IsZero() const { return !bool(*this); }

#define KILN_SS_OP(op)                                            \
    SampledSpectrum& operator op##=(const SampledSpectrum& s) {   \
        values op## = s.values;                                   \
        return *this;                                             \
    }                                                             \
    SampledSpectrum operator op(const SampledSpectrum& s) const { \
        return SampledSpectrum(values op s.values);               \
    }                                                             \
    SampledSpectrum& operator op##=(Float a) {                    \
        values op## = a;                                          \
        return *this;                                             \
    }                                                             \
    SampledSpectrum operator op(Float a) const { return SampledSpectrum(values op a); }
    KILN_SS_OP(+)
    KILN_SS_OP(-)
    KILN_SS_OP(*)
    KILN_SS_OP(/)
#undef KILN_SS_OP

    SampledSpectrum operator-() const { return SampledSpectrum(-values); }
    bool operator==(const SampledSpectrum& s) const { return !Any(values != s.values); }
    bool operator!=(const SampledSpectrum& s) const { return Any(values != s.values); }

    Float MinComponentValue() const {
        Float m = values[0];
        for (int i = 1; i < NSpectrumSamples; ++i) m = std::min<Float>(m, values[i]);
        return m;
    }
    Float MaxComponentValue() const {
        Float m = values[0];
        for (int i = 1; i < NSpectrumSamples; ++i) m = std::max<Float>(m, values[i]);
        return m;
    }
    Float Average() const {
        Float s = 0;
        for (int i = 0; i < NSpectrumSamples; ++i) s += values[i];
        return s / NSpectrumSamples;
    }
    bool HasNaN() const { return Any(values != values); }
    bool IsFinite() const {
        for (int i = 0; i < NSpectrumSamples; ++i)
            if (!std::isfinite(values[i])) return false;
        return true;
    }

    std::array<Float, NSpectrumSamples> Values() const {
        std::array<Float, NSpectrumSamples> v;
        std::memcpy(v.data(), &values, sizeof values);
        return v;
    }

    // a / b, and 0 where b is 0
    friend SampledSpectrum SafeDiv(const SampledSpectrum& a, const SampledSpectrum& b) {
        const Mask nonzero = b.values != 0;
        return SampledSpectrum(
            std::bit_cast<Lanes>(std::bit_cast<Mask>(a.values / b.values) & nonzero));
    }

  private:
    explicit SampledSpectrum(Lanes v) : values(v) {}
    static bool Any(Mask m) {
        bool any = false;
        for (int i = 0; i < NSpectrumSamples; ++i) any |= m[i] != 0;
        return any;
    }

    Lanes values;
};

inline SampledSpectrum operator*(Float a, const SampledSpectrum& s) { return s * a; }
SampledSpectrum SafeDiv(const SampledSpectrum& a, const SampledSpectrum& b);

// Component-wise functions
template <typename F>
inline SampledSpectrum Map(const SampledSpectrum& s, F f) {
    SampledSpectrum r;
    for (int i = 0; i < NSpectrumSamples; ++i) r[i] = f(s[i]);
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
