// How the wavelengths of a path are drawn (the hero wavelength and its NSpectrumSamples - 1
// companions, stratified in the distribution's CDF as SampledWavelengths::SampleVisible does).
//
// By default pbrt-v4's visible density (Radziszewski et al. 2009). For scenes with hot matter,
// a mixture: a share of the visible density plus the rest in proportion to the spectrum the
// hot matter radiates times each CIE colour matching function, each normalised to the same
// integral (X, Y and Z of the glow each get a third), so that the steep red end of a glow at
// 1000-2000 K is sampled where its colour comes from and its small Z keeps samples too. The mixture
// is tabulated over 1-nm bins from 360 to 830 nm (piecewise constant, sampled and evaluated
// from the same table, so estimates stay unbiased whatever the spectrum).
//
// Beyond the visible (a film whose sensor covers another band: Film "thermal"), uniform over
// that band, stratified as SampledWavelengths::SampleUniform, or a table over equal bins of it
// (Tabulated: piecewise constant, sampled and evaluated from the same table; scene creation
// makes it from the sensor's response and what the hot matter radiates,
// render/scene_wavelengths.h).
#pragma once

#include <span>
#include <vector>

#include "base/sampling.h"
#include "spectral/sampled_spectrum.h"

namespace kiln {

class WavelengthDistribution {
  public:
    WavelengthDistribution() = default;  // the visible density
    // visibleShare of the visible density plus (1 - visibleShare) of the density proportional
    // to emitted(lambda) (xbar / X + ybar / Y + zbar / Z)(lambda), X, Y, Z the integrals of
    // emitted times each; emitted: non-negative values at the centres of kBins 1-nm bins from
    // Lambda_min. All zero: the visible density.
    WavelengthDistribution(std::span<const Float> emitted, Float visibleShare);
    // Uniform over [lambdaMin, lambdaMax] (nm, lambdaMin < lambdaMax).
    static WavelengthDistribution Band(Float lambdaMin, Float lambdaMax);
    // In proportion to binMeans, the means of a non-negative function over equal bins spanning
    // [lambdaMin, lambdaMax] (some positive).
    static WavelengthDistribution Tabulated(std::span<const Float> binMeans, Float lambdaMin,
                                            Float lambdaMax);
    static constexpr int kBins = int(Lambda_max - Lambda_min);

    // Whether this is the visible density (no table, no band).
    bool IsVisible() const { return table.Size() == 0 && !(bandMax > bandMin); }
    // The wavelengths for a path from one uniform sample.
    SampledWavelengths Sample(Float u) const;
    // The density per nm at lambda.
    Float PDF(Float lambda) const;

  private:
    PiecewiseConstant1D table;
    Float tableMin = Lambda_min, binWidth = 1;  // the table's bins
    Float bandMin = 0, bandMax = 0;             // a band (Band) when bandMax > bandMin
};

}  // namespace kiln
