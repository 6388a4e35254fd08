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

// Uniform over the scene's wavelengths when they are not the visible ones (Film "thermal").
// The visible density when nothing in the scene glows thermally, or Integrator
// "wavelengthsampling" "visible". Otherwise the mixture of WavelengthDistribution, its hot part
// the sum of blackbody spectra of:
//   thermal lights (hot surfaces), each with its power over 360-830 nm at its power-weighted
//   mean temperature;
//   thermal media (volpath only), at MediumEmission::RepresentativeTemperature, together
//   weighing as much as the thermal lights (1 W each without them).
// The visible share is 0.5, or 0.75 when other lights or non-thermal emissive media exist
// (their light is not in the spectrum, and a hot body's emissivity shapes its spectrum too:
// measured in docs/guide/accuracy-and-speed.md).
// *visibleShare is set to the share used (1: the visible density).
WavelengthDistribution CreateWavelengthDistribution(const Scene& scene, Float* visibleShare);

}  // namespace kiln
