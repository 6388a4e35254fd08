// The wavelengths a scene renders (nm): the visible 360-830 nm unless the film's sensor covers
// another band (Film "thermal": core/film/thermal_sensor.h). Decided once at load from the
// film; what is tabulated over wavelength (emissivity tables), power estimates for light
// selection and the film's wavelength density all cover it.
#pragma once

#include "spectral/sampled_spectrum.h"

namespace kiln {

struct SpectralRange {
    Float min = Lambda_min, max = Lambda_max;

    bool IsVisible() const { return min == Lambda_min && max == Lambda_max; }
    bool operator==(const SpectralRange&) const = default;
    // Four wavelengths spread over the range (the visible density's at u for the visible
    // range, as pbrt-v4's power estimates take them; evenly spaced otherwise)
    SampledWavelengths Spread(Float u) const {
        return IsVisible() ? SampledWavelengths::SampleVisible(u)
                           : SampledWavelengths::SampleUniform(u, min, max);
    }
};

// Wavelengths kiln renders at all: from 300 nm to 20 um (issue 26's range of sensors).
inline constexpr Float kSpectralRangeMin = 300, kSpectralRangeMax = 20000;

}  // namespace kiln
