// Scene creation step: the wavelengths the film draws (spectral/wavelength_distribution.h),
// chosen from what the scene's hot matter radiates.
#pragma once

#include "core/parser/diagnostics.h"
#include "spectral/spectral_range.h"
#include "spectral/wavelength_distribution.h"

namespace kiln {

class Scene;
struct SceneDescription;

// One warning, at the first of them, when a scene rendered beyond the visible (range) gives
// materials or textures RGB colours or RGB image maps: an RGB says nothing outside 360-830 nm,
// and holds its value at the nearer end there.
void WarnOfColoursBeyondTheVisible(const SceneDescription& desc, const SpectralRange& range,
                                   Diagnostics& diag);

// A thermal film (Film "thermal", its band): over 4096 equal bins of the band, a share of the
// sensor's response (uniform for a flat band) plus the rest in proportion to the response
// times the blackbody spectra of the hot matter below, each weighted by its power over the band
// (share 0.5, 0.75 with other emitters; 1 when nothing glows thermally or with
// "wavelengthsampling" "visible").
// Otherwise the visible density when nothing in the scene glows thermally, or Integrator
// "wavelengthsampling" "visible". Otherwise the mixture of WavelengthDistribution, its hot part
// the sum of blackbody spectra of:
//   thermal lights (hot surfaces), each with its power over the scene's wavelengths at its
//   power-weighted mean temperature;
//   thermal media (volpath only), at MediumEmission::RepresentativeTemperature, together
//   weighing as much as the thermal lights (1 W each without them).
// The visible share is 0.5, or 0.75 when other lights or non-thermal emissive media exist
// (their light is not in the spectrum, and a hot body's emissivity shapes its spectrum too:
// measured in docs/guide/accuracy-and-speed.md).
// *visibleShare is set to the share used (1: the visible density).
WavelengthDistribution CreateWavelengthDistribution(const Scene& scene, Float* visibleShare);

}  // namespace kiln
