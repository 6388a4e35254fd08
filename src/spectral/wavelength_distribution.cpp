#include "spectral/wavelength_distribution.h"

#include <array>
#include <cmath>

#include "spectral/cie.h"

namespace kiln {

WavelengthDistribution::WavelengthDistribution(std::span<const Float> emitted, Float visibleShare) {
    if (emitted.size() != size_t(kBins)) return;
    // emitted times each matching function, each normalised by its integral: every colour
    // channel of the emission gets a third of the hot part (a glow's Z, small as it is, keeps
    // its samples)
    std::array<std::vector<double>, 3> channel;
    std::array<double, 3> channelSum{};
    for (int c = 0; c < 3; ++c) channel[size_t(c)].assign(kBins, 0.0);
    for (int i = 0; i < kBins; ++i) {
        Float lambda = Lambda_min + i + 0.5f;
        Float e = emitted[size_t(i)];
        if (!(e > 0) || !std::isfinite(e)) continue;
        Float cmf[3] = {CIE_X(lambda), CIE_Y(lambda), CIE_Z(lambda)};
        for (int c = 0; c < 3; ++c) {
            channel[size_t(c)][size_t(i)] = double(e) * cmf[c];
            channelSum[size_t(c)] += channel[size_t(c)][size_t(i)];
        }
    }
    std::vector<double> hot(kBins, 0.0);
    double hotSum = 0, visibleSum = 0;
    for (int c = 0; c < 3; ++c) {
        if (!(channelSum[size_t(c)] > 0)) continue;
        for (int i = 0; i < kBins; ++i)
            hot[size_t(i)] += channel[size_t(c)][size_t(i)] / channelSum[size_t(c)];
    }
    for (double h : hot) hotSum += h;
    if (!(hotSum > 0)) return;
    for (int i = 0; i < kBins; ++i)
        visibleSum += SampledWavelengths::VisibleWavelengthPDF(Lambda_min + i + 0.5f);
    std::vector<Float> f(kBins);
    for (int i = 0; i < kBins; ++i)
        f[size_t(i)] =
            Float(visibleShare * SampledWavelengths::VisibleWavelengthPDF(Lambda_min + i + 0.5f) /
                      visibleSum +
                  (1 - visibleShare) * hot[size_t(i)] / hotSum);
    table = PiecewiseConstant1D(f, Lambda_min, Lambda_max);
}

WavelengthDistribution WavelengthDistribution::Band(Float lambdaMin, Float lambdaMax) {
    WavelengthDistribution d;
    d.bandMin = lambdaMin;
    d.bandMax = lambdaMax;
    return d;
}

WavelengthDistribution WavelengthDistribution::Tabulated(std::span<const Float> binMeans,
                                                         Float lambdaMin, Float lambdaMax) {
    WavelengthDistribution d;
    d.table = PiecewiseConstant1D(binMeans, lambdaMin, lambdaMax);
    d.tableMin = lambdaMin;
    d.binWidth = (lambdaMax - lambdaMin) / Float(binMeans.size());
    return d;
}

SampledWavelengths WavelengthDistribution::Sample(Float u) const {
    if (bandMax > bandMin) return SampledWavelengths::SampleUniform(u, bandMin, bandMax);
    if (IsVisible()) return SampledWavelengths::SampleVisible(u);
    std::array<Float, NSpectrumSamples> lambda, pdf;
    for (int i = 0; i < NSpectrumSamples; ++i) {
        Float up = u + Float(i) / NSpectrumSamples;
        if (up >= 1) up -= 1;
        int bin = 0;
        Float l = table.Sample(up, &pdf[size_t(i)], &bin);
        // Inside the bin whose density it carries (rounding may reach the next bin's start)
        Float start = tableMin + Float(bin) * binWidth;
        Float end = tableMin + Float(bin + 1) * binWidth;
        lambda[size_t(i)] = l < start ? start : (l < end ? l : std::nextafter(end, start));
    }
    return SampledWavelengths::FromSamples(lambda, pdf);
}

Float WavelengthDistribution::PDF(Float lambda) const {
    if (bandMax > bandMin)
        return lambda >= bandMin && lambda <= bandMax ? 1 / (bandMax - bandMin) : 0;
    if (IsVisible()) return SampledWavelengths::VisibleWavelengthPDF(lambda);
    if (!(lambda >= tableMin && lambda < tableMin + binWidth * Float(table.Size()))) return 0;
    size_t i = std::min(size_t((lambda - tableMin) / binWidth), table.Size() - 1);
    return table.Func(i) / table.Integral();
}

}  // namespace kiln
