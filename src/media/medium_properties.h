// What a medium is at one point (pbrt-v4's MediumProperties), in render-space units.
#pragma once

#include "spectral/sampled_spectrum.h"

namespace kiln {

struct MediumProperties {
    // Absorption and scattering coefficients, per unit length.
    SampledSpectrum sigma_a, sigma_s;
    // Henyey-Greenstein asymmetry of the phase function.
    Float g = 0;
    // Radiance emitted per unit length, W m^-2 sr^-1 nm^-1 per unit length: sigma_a Le for
    // pbrt-v4's "Le", sigma_a n^2 B(lambda, T) for a medium at temperature T (medium_emission.h).
    SampledSpectrum emission;
};

}  // namespace kiln
