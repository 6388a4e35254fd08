// pbrt-v4's named measured scattering media (its GetMediumScatteringProperties): the
// homogeneous medium's "preset" and the subsurface material's "name".
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "spectral/spectrum.h"

namespace kiln {

// The measured absorption and scattering coefficients (sigma_a, sigma_s) of a named material,
// mm^-1 (RGB-upsampled unbounded spectra); nullopt if unknown. Sources in measured_media.cpp.
std::optional<std::pair<Spectrum, Spectrum>> MeasuredMediumCoefficients(const std::string& name);

}  // namespace kiln
