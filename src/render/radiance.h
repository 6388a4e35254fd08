// What a light path carries: the integrator's radiance type parameter.
//
// Following Mitsuba 3's variants, PathIntegrator<Radiance> and VolPathIntegrator<Radiance> are
// written once against the small interface below, and the scene's needs choose the variant at
// load (renderer.cpp):
//   UnpolarizedRadiance: radiance and throughput are SampledSpectrum; BSDFs return scalar values
//                        per wavelength.
//   PolarizedRadiance:   radiance is a Stokes vector per wavelength and throughput a Mueller
//                        matrix per wavelength, both in the implicit frames of the directions
//                        of travel (spectral/polarization.h); BSDFs return Mueller matrices
//                        rotated into those frames, thermal emission is polarised, other
//                        emitters (media too) are unpolarised and phase functions depolarise.
#pragma once

#include "spectral/polarization.h"
#include "spectral/sampled_spectrum.h"

namespace kiln {

struct UnpolarizedRadiance {
    static constexpr bool Polarized = false;
    // Radiance, W m^-2 sr^-1 nm^-1 at each sampled wavelength.
    using Spectrum = SampledSpectrum;
    // What BSDFs return and path throughput is: it multiplies radiance found further on.
    using Throughput = SampledSpectrum;

    static Throughput One() { return SampledSpectrum(1.f); }
    // Radiance of an unpolarised emitter.
    static Spectrum Unpolarized(const SampledSpectrum& L) { return L; }
    // Throughput applied to radiance.
    static Spectrum Apply(const Throughput& beta, const Spectrum& L) { return beta * L; }
    // What scattering that forgets polarisation (a phase function) does: intensity times a.
    static Throughput Depolarizing(const SampledSpectrum& a) { return a; }
    // The intensity (first Stokes component).
    static const SampledSpectrum& Intensity(const Spectrum& L) { return L; }
    // Magnitude used for Russian roulette: the throughput of intensity.
    static Float RouletteWeight(const Throughput& beta) { return beta.MaxComponentValue(); }
};

struct PolarizedRadiance {
    static constexpr bool Polarized = true;
    using Spectrum = Stokes;
    using Throughput = MuellerMatrix;

    static Throughput One() { return MuellerMatrix::Identity(); }
    static Spectrum Unpolarized(const SampledSpectrum& L) { return Stokes(L); }
    static Spectrum Apply(const Throughput& beta, const Spectrum& L) { return beta * L; }
    // Henyey-Greenstein media have no polarisation model: their scattering depolarises.
    static Throughput Depolarizing(const SampledSpectrum& a) {
        return MuellerMatrix::Depolarizer(a);
    }
    static const SampledSpectrum& Intensity(const Spectrum& L) { return L.Intensity(); }
    // M00: what the throughput does to unpolarised light.
    static Float RouletteWeight(const Throughput& beta) {
        return beta.Intensity().MaxComponentValue();
    }
};

}  // namespace kiln
