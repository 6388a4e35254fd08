// Measured spectra behind the named camera sensors' colour fit: the 24 ColorChecker Classic
// swatch reflectances and the CIE daylight basis functions (tables in color_checker_data.cpp,
// sources cited there), and CIE daylight spectra of a given temperature built from them.
#pragma once

#include <span>

#include "spectral/spectrum.h"

namespace kiln {

// Swatch i's reflectance (dimensionless, 0-1) interleaved as lambda (nm), value, ...
std::span<const std::span<const float>> ColorCheckerSwatchTables();
// The 24 swatch reflectances as spectra (pbrt-v4's FromInterleaved: first and last values
// extended over 360-830 nm), in the chart's order; built on first use.
std::span<const PiecewiseLinearSpectrum> ColorCheckerSwatches();

// CIE daylight basis S0, S1, S2 (relative), tabulated from lambda0 every step nm.
struct DaylightBasisTables {
    float lambda0, step;
    std::span<const float> S0, S1, S2;
};
DaylightBasisTables GetDaylightBasisTables();

// pbrt-v4's daylight illuminant of white-balance temperature T (K): the correlated colour
// temperature is T * 1.4388 / 1.4380 (the CIE daylight formulas use the old c2 constant);
// below 4000 K a blackbody of that temperature normalised to peak 1, else the CIE daylight
// spectrum (S0 + M1 S1 + M2 S2) / 100 with the CIE 015 chromaticity (x, y) of that temperature
// and M1, M2 unrounded (as pbrt-v4). Relative SPD (S0 is about 100 at 560 nm, so about 1).
Spectrum CIEDaylightSpectrum(Float T);

}  // namespace kiln
