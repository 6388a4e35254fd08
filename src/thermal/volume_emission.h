// Thermal emission inside matter (Kirchhoff's law in a medium): a medium at temperature T
// (kelvin) inside a body of refractive index n emits, per unit length,
//   kirchhoff (default)  sigma_a n^2 B(lambda, T)          (absolute units, spectral/planck.h)
//   additive             (sigma_a + sigma_s) n^2 B(lambda, T): B added on all extinction
//   diffuse              a blackbody medium: scattering becomes absorption, sigma_t n^2 B
//   none                 nothing.
// n^2 B is the equilibrium radiance inside matter of index n: with it a hot body behind a
// dielectric boundary radiates (1 - R) B through it and a closed cavity stays at B(T).
// A host's medium calls VolumeEmission wherever it evaluates its coefficients (kiln:
// media/medium_emission.h).
#pragma once

#include "spectral/sampled_spectrum.h"
#include "thermal/emission_model.h"

namespace kiln {

// Radiance emitted per unit length (W m^-2 sr^-1 nm^-1 per unit length) by matter at T with
// coefficients sigma_a and sigma_s (per unit length), inside a body of refractive index n
// (nullptr: 1). For the diffuse model sigma_a and sigma_s are changed as that model requires.
// T <= 0 or NaN emits nothing.
SampledSpectrum VolumeEmission(EmissionModel model, Float T, const SampledSpectrum* n,
                               SampledSpectrum& sigma_a, SampledSpectrum& sigma_s,
                               const SampledWavelengths& lambda);

}  // namespace kiln
