// Spectral distributions as functions of wavelength: a closed set of kinds behind one value
// type, Spectrum (pbrt-v4's Spectrum, with std::variant in place of its tagged pointer).
//
// Wavelengths are in nm. Values carry whatever unit their use gives them: radiance
// (W m^-2 sr^-1 nm^-1) for emission, dimensionless for reflectance or indices of refraction,
// relative units for normalised illuminants.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "base/closed_set.h"
#include "spectral/rgb_to_spectrum.h"
#include "spectral/sampled_spectrum.h"

namespace kiln {

struct RGB;
struct XYZ;
class RGBColorSpace;
class Spectrum;

// The same value c at every wavelength.
class ConstantSpectrum {
  public:
    explicit ConstantSpectrum(Float c) : c(c) {}
    Float operator()(Float) const { return c; }
    SampledSpectrum Sample(const SampledWavelengths&) const { return SampledSpectrum(c); }
    Float MaxValue() const { return c; }

  private:
    Float c;
};

// Values at every integer wavelength 360-830 nm, interpolated linearly between them (pbrt-v4
// takes the nearest one); 0 outside that range.
class DenselySampledSpectrum {
  public:
    static constexpr int kLambdaMin = 360, kLambdaMax = 830;
    static constexpr int kNumSamples = kLambdaMax - kLambdaMin + 1;

    DenselySampledSpectrum() : values(kNumSamples, Float(0)) {}
    explicit DenselySampledSpectrum(const Spectrum& s);
    template <typename F>
    static DenselySampledSpectrum SampleFunction(F f) {
        DenselySampledSpectrum d;
        for (int i = 0; i < kNumSamples; ++i) d.values[i] = Float(f(Float(kLambdaMin + i)));
        return d;
    }

    Float operator()(Float lambda) const;
    SampledSpectrum Sample(const SampledWavelengths& lambda) const;
    Float MaxValue() const;
    void Scale(Float s);
    std::span<const Float> Values() const { return values; }

  private:
    std::vector<Float> values;
};

// Linear interpolation between tabulated (lambda, value) points; 0 outside them.
class PiecewiseLinearSpectrum {
  public:
    // Wavelengths must increase strictly and match values in count (else
    // std::invalid_argument).
    PiecewiseLinearSpectrum(std::span<const Float> lambdas, std::span<const Float> values);

    // pbrt-v4's FromInterleaved: (lambda, value) pairs; the first and last values are
    // extended to 359 and 831 nm when the table does not reach them; with normalize, scaled so
    // that InnerProduct(s, ybar) = CIE_Y_integral (the luminance Y of a constant 1).
    static PiecewiseLinearSpectrum FromInterleaved(std::span<const Float> interleaved,
                                                   bool normalize);

    // Reads a spectrum file as pbrt-v4 "spectrum" parameters do: pairs of numbers "lambda
    // value" (nm), separated by whitespace or commas, '#' starting a comment to the end of the
    // line, wavelengths strictly increasing. nullopt (and *error set) if unreadable or invalid.
    static std::optional<PiecewiseLinearSpectrum> Read(const std::string& filename,
                                                       std::string* error = nullptr);
    // The same from the file's text (filename only names it in errors).
    static std::optional<PiecewiseLinearSpectrum> Parse(const std::string& contents,
                                                        const std::string& filename,
                                                        std::string* error = nullptr);

    Float operator()(Float lambda) const;
    SampledSpectrum Sample(const SampledWavelengths& lambda) const;
    Float MaxValue() const;
    void Scale(Float s);
    // Outside the visible range (360-830 nm), values beyond the table's ends hold the end values
    // instead of 0: for material properties (optical constants, reflectances), not emission
    // (ParameterDictionary sets it for every spectrum but illuminants, and named spectra of
    // metals and glasses have it).
    void HoldEndsBeyondVisible() { holdEnds = true; }
    std::span<const Float> Lambdas() const { return lambdas; }
    std::span<const Float> Values() const { return values; }

  private:
    std::vector<Float> lambdas, values;
    bool holdEnds = false;
    // First interval for each whole nanometre from floor(lambdas.front()): lookups start there
    // and step at most over the nodes inside that nanometre (empty for very wide ranges)
    std::vector<uint32_t> intervalAtNm;
};

// Blackbody emission at temperature T (K), normalised so that its peak over wavelength is 1
// (pbrt-v4's BlackbodySpectrum, used for "blackbody" parameters); dimensionless. The absolute
// radiance is planck_radiance() in planck.h.
class BlackbodySpectrum {
  public:
    explicit BlackbodySpectrum(Float T_kelvin) : T(T_kelvin) {}
    Float operator()(Float lambda) const;
    // Per path: planck_radiance_normalized's fast path (relative error below 2e-5 at 1-1e6 K)
    SampledSpectrum Sample(const SampledWavelengths& lambda) const;
    Float MaxValue() const { return T > 0 ? 1 : 0; }
    Float Temperature() const { return T; }

  private:
    Float T;
};

// Reflectance of an RGB in [0,1]^3 (pbrt-v4's RGBAlbedoSpectrum); values in [0, 1].
class RGBAlbedoSpectrum {
  public:
    RGBAlbedoSpectrum(const RGBColorSpace& cs, const RGB& rgb);
    Float operator()(Float lambda) const { return rsp(lambda); }
    SampledSpectrum Sample(const SampledWavelengths& lambda) const;
    Float MaxValue() const { return rsp.MaxValue(); }

  private:
    RGBSigmoidPolynomial rsp;
};

// An unbounded non-negative RGB as scale * sigmoid spectrum, scale = 2 max(r, g, b)
// (pbrt-v4's RGBUnboundedSpectrum); same units as the RGB.
class RGBUnboundedSpectrum {
  public:
    RGBUnboundedSpectrum(const RGBColorSpace& cs, const RGB& rgb);
    Float operator()(Float lambda) const { return scale * rsp(lambda); }
    SampledSpectrum Sample(const SampledWavelengths& lambda) const;
    Float MaxValue() const { return scale * rsp.MaxValue(); }

  private:
    Float scale = 1;
    RGBSigmoidPolynomial rsp;
};

// An emitted RGB: RGBUnbounded times the colour space's illuminant (pbrt-v4's
// RGBIlluminantSpectrum), so RGB (1,1,1) is the colour space's white at luminance Y = 1.
class RGBIlluminantSpectrum {
  public:
    RGBIlluminantSpectrum(const RGBColorSpace& cs, const RGB& rgb);
    Float operator()(Float lambda) const { return scale * rsp(lambda) * (*illuminant)(lambda); }
    SampledSpectrum Sample(const SampledWavelengths& lambda) const;
    Float MaxValue() const { return scale * rsp.MaxValue() * illuminant->MaxValue(); }
    const DenselySampledSpectrum& Illuminant() const { return *illuminant; }

  private:
    Float scale = 1;
    RGBSigmoidPolynomial rsp;
    const DenselySampledSpectrum* illuminant;  // the colour space's, which outlives this
};

// Spectrum: one of the kinds above, by value.
class Spectrum : public ClosedSet<ConstantSpectrum, PiecewiseLinearSpectrum, DenselySampledSpectrum,
                                  BlackbodySpectrum, RGBAlbedoSpectrum, RGBUnboundedSpectrum,
                                  RGBIlluminantSpectrum> {
  public:
    using ClosedSet::ClosedSet;
    Float operator()(Float lambda_nm) const {
        return Dispatch([&](const auto& s) { return s(lambda_nm); });
    }
    SampledSpectrum Sample(const SampledWavelengths& lambda) const {
        return Dispatch([&](const auto& s) { return s.Sample(lambda); });
    }
    Float MaxValue() const {
        return Dispatch([](const auto& s) { return s.MaxValue(); });
    }
};

// The CIE 1931 colour-matching functions as spectra (dimensionless, 1 nm table).
namespace spectra {
const Spectrum& X();
const Spectrum& Y();
const Spectrum& Z();
}  // namespace spectra

// Sum of f(lambda) g(lambda) over lambda = 360, 361, ..., 830 nm: the integral at 1 nm steps
// (units of f times g times nm).
Float InnerProduct(const Spectrum& f, const Spectrum& g);

// Integral of s ybar over 360-830 nm, unnormalised (units of s times nm); for an
// RGBIlluminantSpectrum, of its illuminant only (pbrt-v4 semantics).
Float SpectrumToPhotometric(const Spectrum& s);

// CIE XYZ of s: integral(s cmf) / CIE_Y_integral, so a spectrum of constant 1 has Y = 1.
XYZ SpectrumToXYZ(const Spectrum& s);

}  // namespace kiln
