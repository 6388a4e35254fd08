// What a light path carries: the integrator's radiance type parameter.
//
// Following Mitsuba 3's variants, PathIntegrator<Radiance> is written once against the small
// interface below. UnpolarizedRadiance carries a SampledSpectrum and multiplies throughput by
// scalar BSDF values per wavelength. A polarised variant (Stokes vectors for radiance, Mueller
// matrices for throughput, rotated into each interaction's reference frame) supplies the same
// members, so the integrator does not change and unpolarised scenes pay nothing for it.
#pragma once

#include "materials/bxdfs/bsdf.h"
#include "spectral/sampled_spectrum.h"

namespace kiln {

struct UnpolarizedRadiance {
    // Radiance arriving at the camera, W m^-2 sr^-1 nm^-1 at each sampled wavelength.
    using Spectrum = SampledSpectrum;
    // Path throughput: what multiplies radiance found further along the path.
    using Throughput = SampledSpectrum;

    static Throughput One() { return SampledSpectrum(1.f); }
    // Throughput change of scattering from wi towards wo (f * |cos| / pdf style factors).
    static Throughput Scatter(const SampledSpectrum& f) { return f; }
    // Radiance emitted by a light (unpolarised emitters).
    static Spectrum Emitted(const SampledSpectrum& L) { return L; }
    // Applies throughput to radiance.
    static Spectrum Apply(const Throughput& beta, const Spectrum& L) { return beta * L; }
    // The intensity (first Stokes component) that the film records.
    static const SampledSpectrum& Intensity(const Spectrum& L) { return L; }
    // Magnitude used for Russian roulette.
    static Float MaxComponent(const Throughput& beta) { return beta.MaxComponentValue(); }
};

}  // namespace kiln
