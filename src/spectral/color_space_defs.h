// Definitions of the RGB colour spaces kiln knows: primaries' and white's chromaticities
// (CIE 1931 xy) and the illuminant, by pbrt-v4's names. Shared by RGBColorSpace and the
// build-time RGB-to-spectrum table generator so the two can never disagree.
#pragma once

#include <array>
#include <string_view>

namespace kiln {

struct ColorSpaceDefinition {
    std::string_view name;          // pbrt-v4's name, lower case
    double rx, ry, gx, gy, bx, by;  // primaries, CIE 1931 xy
    std::string_view illuminant;    // a named spectrum (named_spectra.h)
};

// sRGB: IEC 61966-2-1 (Rec. 709 primaries), D65. DCI-P3: SMPTE RP 431-2 primaries with a D65
// white, as pbrt-v4 (i.e. Display P3 gamut). Rec2020: ITU-R BT.2020, D65. ACES2065-1: SMPTE
// ST 2065-1 AP0 primaries, ACES white (D60).
inline constexpr std::array<ColorSpaceDefinition, 4> kColorSpaceDefinitions = {{
    {"srgb", 0.64, 0.33, 0.30, 0.60, 0.15, 0.06, "stdillum-D65"},
    {"dci-p3", 0.680, 0.320, 0.265, 0.690, 0.150, 0.060, "stdillum-D65"},
    {"rec2020", 0.708, 0.292, 0.170, 0.797, 0.131, 0.046, "stdillum-D65"},
    {"aces2065-1", 0.7347, 0.2653, 0.0, 1.0, 0.0001, -0.077, "illum-acesD60"},
}};

}  // namespace kiln
