// Spectrum kinds: evaluation, sampling, and the integrals over the CIE observer.
#include "spectral/spectrum.h"
#include "base/number_text.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "base/file_reading.h"
#include "spectral/cie.h"
#include "spectral/color.h"
#include "spectral/planck.h"

namespace kiln {

// Helpers
namespace {

template <typename S>
SampledSpectrum SamplePointwise(const S& s, const SampledWavelengths& lambda) {
    SampledSpectrum r;
    for (int i = 0; i < NSpectrumSamples; ++i) r[i] = s(lambda[i]);
    return r;
}

}  // namespace

// DenselySampledSpectrum
DenselySampledSpectrum::DenselySampledSpectrum(const Spectrum& s) : values(kNumSamples) {
    for (int i = 0; i < kNumSamples; ++i) values[i] = s(Float(kLambdaMin + i));
}

Float DenselySampledSpectrum::operator()(Float lambda) const {
    Float x = lambda - Float(kLambdaMin);
    if (!(x >= 0) || x > Float(kNumSamples - 1)) return 0;
    int i = std::min(int(x), kNumSamples - 2);
    return Lerp(x - Float(i), values[i], values[i + 1]);
}

SampledSpectrum DenselySampledSpectrum::Sample(const SampledWavelengths& lambda) const {
    return SamplePointwise(*this, lambda);
}

Float DenselySampledSpectrum::MaxValue() const {
    return *std::max_element(values.begin(), values.end());
}

void DenselySampledSpectrum::Scale(Float s) {
    for (Float& v : values) v *= s;
}

// PiecewiseLinearSpectrum
PiecewiseLinearSpectrum::PiecewiseLinearSpectrum(std::span<const Float> l, std::span<const Float> v)
    : lambdas(l.begin(), l.end()), values(v.begin(), v.end()) {
    if (lambdas.size() != values.size())
        throw std::invalid_argument("PiecewiseLinearSpectrum: lambda and value counts differ");
    for (size_t i = 1; i < lambdas.size(); ++i)
        if (!(lambdas[i] > lambdas[i - 1]))
            throw std::invalid_argument("PiecewiseLinearSpectrum: wavelengths not increasing");
    if (lambdas.size() >= 2 && lambdas.back() - lambdas.front() < 1e5f) {
        const Float start = std::floor(lambdas.front());
        const size_t n = size_t(lambdas.back() - start) + 2;
        intervalAtNm.resize(n);
        size_t o = 0;
        for (size_t k = 0; k < n; ++k) {
            while (o + 2 < lambdas.size() && lambdas[o + 1] <= start + Float(k)) ++o;
            intervalAtNm[k] = uint32_t(o);
        }
    }
}

PiecewiseLinearSpectrum PiecewiseLinearSpectrum::FromInterleaved(std::span<const Float> samples,
                                                                 bool normalize) {
    if (samples.size() % 2 != 0 || samples.empty())
        throw std::invalid_argument("FromInterleaved: need (lambda, value) pairs");
    const size_t n = samples.size() / 2;
    std::vector<Float> lambda, v;
    // Extend samples to cover the visible range if needed (pbrt-v4)
    if (samples[0] > Lambda_min) {
        lambda.push_back(Lambda_min - 1);
        v.push_back(samples[1]);
    }
    for (size_t i = 0; i < n; ++i) {
        lambda.push_back(samples[2 * i]);
        v.push_back(samples[2 * i + 1]);
    }
    if (lambda.back() < Lambda_max) {
        lambda.push_back(Lambda_max + 1);
        v.push_back(v.back());
    }
    PiecewiseLinearSpectrum spec(lambda, v);
    // Normalise to the luminance of a constant 1: InnerProduct(spec, ybar) = CIE_Y_integral
    if (normalize) spec.Scale(CIE_Y_integral / InnerProduct(spec, spectra::Y()));
    return spec;
}

std::optional<PiecewiseLinearSpectrum> PiecewiseLinearSpectrum::Read(const std::string& filename,
                                                                     std::string* error) {
    auto fail = [&](const std::string& msg) -> std::optional<PiecewiseLinearSpectrum> {
        if (error) *error = filename + ": " + msg;
        return std::nullopt;
    };
    std::string contents, readError;
    if (!ReadFileBytes(filename, &contents, &readError))
        return fail("cannot read spectrum file: " + readError);
    return Parse(contents, filename, error);
}

std::optional<PiecewiseLinearSpectrum> PiecewiseLinearSpectrum::Parse(const std::string& contents,
                                                                      const std::string& filename,
                                                                      std::string* error) {
    auto fail = [&](const std::string& msg) -> std::optional<PiecewiseLinearSpectrum> {
        if (error) *error = filename + ": " + msg;
        return std::nullopt;
    };
    // '#' comments to end of line, whitespace and commas separate numbers
    std::string numberError;
    std::optional<std::vector<Float>> numbers = ParseNumberText(contents, &numberError);
    if (!numbers) return fail(numberError);
    const std::vector<Float>& vals = *numbers;
    if (vals.empty()) return fail("no values in spectrum file");
    if (vals.size() % 2 != 0) return fail("odd number of values (need lambda value pairs)");

    std::vector<Float> lambda, v;
    for (size_t i = 0; i < vals.size() / 2; ++i) {
        if (i > 0 && !(vals[2 * i] > lambda.back()))
            return fail("wavelengths not increasing at entry " + std::to_string(i + 1));
        lambda.push_back(vals[2 * i]);
        v.push_back(vals[2 * i + 1]);
    }
    return PiecewiseLinearSpectrum(lambda, v);
}

Float PiecewiseLinearSpectrum::operator()(Float lambda) const {
    if (holdEnds && !lambdas.empty() && (lambda < Lambda_min || lambda > Lambda_max))
        lambda = std::clamp(lambda, lambdas.front(), lambdas.back());
    if (lambdas.empty() || !(lambda >= lambdas.front()) || lambda > lambdas.back()) return 0;
    if (lambdas.size() == 1) return values[0];
    size_t o;
    if (!intervalAtNm.empty()) {
        size_t k = std::min(intervalAtNm.size() - 1, size_t(lambda - std::floor(lambdas.front())));
        o = intervalAtNm[k];
        while (o + 2 < lambdas.size() && lambdas[o + 1] <= lambda) ++o;
    } else {
        o = FindInterval(lambdas.size(), [&](size_t i) { return lambdas[i] <= lambda; });
    }
    Float t = (lambda - lambdas[o]) / (lambdas[o + 1] - lambdas[o]);
    return Lerp(t, values[o], values[o + 1]);
}

SampledSpectrum PiecewiseLinearSpectrum::Sample(const SampledWavelengths& lambda) const {
    return SamplePointwise(*this, lambda);
}

Float PiecewiseLinearSpectrum::MaxValue() const {
    if (values.empty()) return 0;
    return *std::max_element(values.begin(), values.end());
}

void PiecewiseLinearSpectrum::Scale(Float s) {
    for (Float& v : values) v *= s;
}

// BlackbodySpectrum
Float BlackbodySpectrum::operator()(Float lambda) const {
    return Float(planck_radiance_normalized(lambda, T));
}

SampledSpectrum BlackbodySpectrum::Sample(const SampledWavelengths& lambda) const {
    return planck_radiance_normalized(lambda, T);
}

// RGB spectra
RGBAlbedoSpectrum::RGBAlbedoSpectrum(const RGBColorSpace& cs, const RGB& rgb)
    : rsp(cs.ToRGBCoeffs(rgb)) {}

SampledSpectrum RGBAlbedoSpectrum::Sample(const SampledWavelengths& lambda) const {
    return SamplePointwise(*this, lambda);
}

namespace {

// An unbounded RGB's shape, rgb / (2 m) for its largest component m: as rgb / m / 2 so that it
// does not overflow for m above half of float's largest value (whose spectrum 2 m times the
// shape is then infinite), and with infinite components as 1 / 2, the others 0.
RGB UnboundedShape(const RGB& rgb, Float m) {
    if (m == 0) return RGB(0, 0, 0);
    if (std::isinf(m)) {
        auto part = [](Float c) { return std::isinf(c) ? Float(0.5) : Float(0); };
        return RGB(part(rgb.r), part(rgb.g), part(rgb.b));
    }
    return rgb / m / 2;
}

}  // namespace

RGBUnboundedSpectrum::RGBUnboundedSpectrum(const RGBColorSpace& cs, const RGB& rgb) {
    Float m = std::max({rgb.r, rgb.g, rgb.b});
    scale = 2 * m;
    rsp = cs.ToRGBCoeffs(UnboundedShape(rgb, m));
}

SampledSpectrum RGBUnboundedSpectrum::Sample(const SampledWavelengths& lambda) const {
    return SamplePointwise(*this, lambda);
}

RGBIlluminantSpectrum::RGBIlluminantSpectrum(const RGBColorSpace& cs, const RGB& rgb)
    : illuminant(&cs.Illuminant()) {
    Float m = std::max({rgb.r, rgb.g, rgb.b});
    scale = 2 * m;
    rsp = cs.ToRGBCoeffs(UnboundedShape(rgb, m));
}

SampledSpectrum RGBIlluminantSpectrum::Sample(const SampledWavelengths& lambda) const {
    return SamplePointwise(*this, lambda);
}

// CIE observer as spectra
namespace spectra {
namespace {
Spectrum MakeCMF(const float* table) {
    return DenselySampledSpectrum::SampleFunction(
        [&](Float l) { return table[int(l) - cie::kCMFLambdaMin]; });
}
}  // namespace
const Spectrum& X() {
    static const Spectrum x = MakeCMF(cie::kX);
    return x;
}
const Spectrum& Y() {
    static const Spectrum y = MakeCMF(cie::kY);
    return y;
}
const Spectrum& Z() {
    static const Spectrum z = MakeCMF(cie::kZ);
    return z;
}
}  // namespace spectra

// Integrals over wavelength
Float InnerProduct(const Spectrum& f, const Spectrum& g) {
    double sum = 0;
    for (int l = int(Lambda_min); l <= int(Lambda_max); ++l)
        sum += double(f(Float(l))) * double(g(Float(l)));
    return Float(sum);
}

Float SpectrumToPhotometric(const Spectrum& s) {
    if (const auto* rgbIllum = s.GetIf<RGBIlluminantSpectrum>()) {
        const DenselySampledSpectrum& illum = rgbIllum->Illuminant();
        double y = 0;
        for (int l = int(Lambda_min); l <= int(Lambda_max); ++l)
            y += double(CIE_Y(Float(l))) * double(illum(Float(l)));
        return Float(y);
    }
    return InnerProduct(spectra::Y(), s);
}

XYZ SpectrumToXYZ(const Spectrum& s) {
    double x = 0, y = 0, z = 0;
    for (int l = int(Lambda_min); l <= int(Lambda_max); ++l) {
        double v = s(Float(l));
        x += CIE_X(Float(l)) * v;
        y += CIE_Y(Float(l)) * v;
        z += CIE_Z(Float(l)) * v;
    }
    return XYZ(Float(x), Float(y), Float(z)) / CIE_Y_integral;
}

}  // namespace kiln
