#include "core/film/spectral_buckets.h"

#include <algorithm>
#include <cstdio>

namespace kiln {

SpectralBuckets::SpectralBuckets(size_t nPixels, int nBuckets, Float lambdaMin, Float lambdaMax)
    : nBuckets(nBuckets),
      lambdaMin(lambdaMin),
      lambdaMax(lambdaMax),
      sums(nPixels * size_t(nBuckets), 0.0) {}

std::vector<std::string> SpectralBuckets::ChannelNames() const {
    std::vector<std::string> names;
    for (int b = 0; b < nBuckets; ++b) {
        double centre = lambdaMin + (b + 0.5) * double(lambdaMax - lambdaMin) / nBuckets;
        char text[64];
        std::snprintf(text, sizeof(text), "%.3fnm", centre);
        std::string s(text);
        std::replace(s.begin(), s.end(), '.', ',');  // '.' separates OpenEXR layers
        names.push_back("S0." + s);
    }
    return names;
}

int SpectralBuckets::Bucket(Float lambda) const {
    if (!(lambda >= lambdaMin && lambda <= lambdaMax)) return -1;
    int b = int(double(nBuckets) * (lambda - lambdaMin) / double(lambdaMax - lambdaMin));
    return std::clamp(b, 0, nBuckets - 1);
}

void SpectralBuckets::Add(size_t pixel, const SampledSpectrum& L, const SampledWavelengths& lambda,
                          Float w) {
    SampledSpectrum pdf = lambda.PDF();
    double* row = &sums[pixel * size_t(nBuckets)];
    for (int i = 0; i < NSpectrumSamples; ++i) {
        int b = Bucket(lambda[i]);
        if (b < 0 || pdf[i] == 0) continue;  // terminated secondary wavelengths have pdf 0
        row[b] += double(w) * L[i] / (double(pdf[i]) * NSpectrumSamples);
    }
}

void SpectralBuckets::EnableSplats() {
    if (splats.empty()) splats = std::vector<std::atomic<double>>(sums.size());
}

void SpectralBuckets::AddSplat(size_t pixel, const SampledSpectrum& L,
                               const SampledWavelengths& lambda, Float w) {
    SampledSpectrum pdf = lambda.PDF();
    for (int i = 0; i < NSpectrumSamples; ++i) {
        int b = Bucket(lambda[i]);
        if (b < 0 || pdf[i] == 0) continue;
        double v = double(w) * L[i] / (double(pdf[i]) * NSpectrumSamples);
        std::atomic<double>& a = splats[pixel * size_t(nBuckets) + size_t(b)];
        double old = a.load(std::memory_order_relaxed);
        while (!a.compare_exchange_weak(old, old + v, std::memory_order_relaxed))
            ;
    }
}

Float SpectralBuckets::Value(size_t pixel, int b, double weightSum, double splatFactor) const {
    size_t i = pixel * size_t(nBuckets) + size_t(b);
    double v = weightSum != 0 ? sums[i] / weightSum : 0;
    if (!splats.empty()) v += splatFactor * splats[i].load();
    return Float(v * nBuckets / double(lambdaMax - lambdaMin));
}

std::vector<double> SpectralBuckets::SplatValues() const {
    std::vector<double> v(splats.size());
    for (size_t i = 0; i < splats.size(); ++i) v[i] = splats[i].load();
    return v;
}

void SpectralBuckets::SetSplatValues(const std::vector<double>& values) {
    for (size_t i = 0; i < splats.size() && i < values.size(); ++i) splats[i].store(values[i]);
}

void SpectralBuckets::Clear() {
    std::fill(sums.begin(), sums.end(), 0.0);
    for (std::atomic<double>& s : splats) s.store(0);
}

}  // namespace kiln
