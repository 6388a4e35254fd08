// Raw tables behind the named spectra (internal to kiln_spectral and its table generator).
//
// Each table interleaves wavelength (nm) and value: lambda0, v0, lambda1, v1, ... with
// strictly increasing wavelengths. Values are dimensionless (n, k) or relative SPDs.
#pragma once

#include <span>

namespace kiln {

struct NamedSpectrumTable {
    const char* name;
    std::span<const float> interleaved;
    // Illuminants: scaled so that their luminance equals that of a spectrum of constant 1
    // (pbrt-v4's PiecewiseLinearSpectrum::FromInterleaved with normalize = true).
    bool normalize;
};

// pbrt-v4's named spectra (named_spectra_pbrt_data.cpp).
std::span<const NamedSpectrumTable> PbrtNamedSpectrumTables();
// pbrt-v4's camera sensor curves <sensor>_r, _g, _b that kiln has from public measured data
// (named_spectra_camera_data.cpp).
std::span<const NamedSpectrumTable> CameraNamedSpectrumTables();
// kiln's own named spectra of measured optical constants (named_spectra_measured_data.cpp).
std::span<const NamedSpectrumTable> MeasuredNamedSpectrumTables();
// kiln's named glass spectra through the infrared, n and k (named_spectra_glass_data.cpp).
std::span<const NamedSpectrumTable> GlassNamedSpectrumTables();

}  // namespace kiln
