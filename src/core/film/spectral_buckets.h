// The spectral layer of pbrt-v4's Film "spectral" (SpectralFilm): per pixel, the mean spectral
// radiance over each of nBuckets equal intervals of [lambdaMin, lambdaMax] (nm), in
// W m^-2 sr^-1 nm^-1, written as the channels of Fichet et al.'s OpenEXR spectral layout
// (JCGT 10(3), 2021): "S0.<centre>nm", the bucket's centre with three decimals and a comma for
// the decimal point ("S0.374,688nm"), as pbrt-v4 names them.
//
// Estimator: a path's wavelengths lambda_i (marginal density p_i, n of them) add
// w L_i / (p_i n) to the bucket lambda_i falls in; a bucket's value is that sum over the
// pixel's filter-weight sum, divided by the bucket's width. It is unbiased for any wavelength
// density that covers the bucket, so kiln keeps its own (the visible density, or the glow
// density of scenes with hot matter). pbrt-v4 samples uniformly over [lambdaMin, lambdaMax]
// and averages the radiance of the samples in a bucket, times CIE_Y_integral: the same values
// in expectation, its radiance unit being kiln's divided by CIE_Y_integral. Splats (light
// tracing) add w L_i / (p_i n) too, scaled on output like the film's RGB splats.
#pragma once

#include <atomic>
#include <string>
#include <vector>

#include "spectral/sampled_spectrum.h"

namespace kiln {

class SpectralBuckets {
  public:
    SpectralBuckets() = default;
    // nBuckets >= 1 and Lambda_min <= lambdaMin < lambdaMax <= Lambda_max (checked by the film).
    SpectralBuckets(size_t nPixels, int nBuckets, Float lambdaMin, Float lambdaMax);

    bool Empty() const { return nBuckets == 0; }
    int NBuckets() const { return nBuckets; }
    Float LambdaMin() const { return lambdaMin; }
    Float LambdaMax() const { return lambdaMax; }
    // "S0.374,688nm", ... in bucket order.
    std::vector<std::string> ChannelNames() const;
    // The bucket of a wavelength, or -1 outside [lambdaMin, lambdaMax].
    int Bucket(Float lambda) const;

    // A sample of pixel `pixel` (the film's index) with filter weight w; L finite.
    void Add(size_t pixel, const SampledSpectrum& L, const SampledWavelengths& lambda, Float w);
    void EnableSplats();
    // Thread-safe (atomic adds).
    void AddSplat(size_t pixel, const SampledSpectrum& L, const SampledWavelengths& lambda,
                  Float w);
    // Bucket b of a pixel: its sum over weightSum (0 if no weight), plus splatFactor times
    // its splatted sum, over the bucket's width.
    Float Value(size_t pixel, int b, double weightSum, double splatFactor) const;

    // The sums (nBuckets per pixel) and the splatted sums (empty without EnableSplats), for
    // checkpoints.
    std::vector<double>& Sums() { return sums; }
    const std::vector<double>& Sums() const { return sums; }
    std::vector<double> SplatValues() const;
    void SetSplatValues(const std::vector<double>& values);
    size_t SplatCount() const { return splats.size(); }
    void Clear();

  private:
    int nBuckets = 0;
    Float lambdaMin = 0, lambdaMax = 0;
    std::vector<double> sums;
    std::vector<std::atomic<double>> splats;
};

}  // namespace kiln
