// Display transform: linear scene-referred RGB -> 8-bit sRGB display images, through
// OpenColorIO with the configuration kiln ships (src/core/image/ocio/config.ocio; the
// environment variable KILN_OCIO_CONFIG names another config file to use instead).
//
// Views (display "sRGB" of the config):
//   "Standard"  plain sRGB encoding (IEC 61966-2-1) of linear Rec.709 values in [0, 1];
//   "Filmic"    kiln's filmic tone curve y = x^1.1 / (x^1.1 + k) (mid grey 0.18 -> 0.13,
//               asymptotic to 1, so 1e3 still maps below 1), per channel through a log2 shaper
//               and a generated 1D LUT (ocio/filmic_tone.spi1d, ocio/make_filmic_lut.py), then
//               the sRGB encoding;
//   "ACES"      the ACES 1.0 SDR video output transform (RRT + ODT, OCIO 2.1 built-ins), then
//               the sRGB encoding (clips near 16x mid grey);
//   "Glow"      for thermal scenes whose glow spans many stops: log2 of max(R, G, B) over the
//               24 stops below scene value 1 mapped linearly to [0, 1] (ocio "Glow tone"),
//               applied to the max norm with the colour scaled so chromaticity is kept, then
//               the sRGB encoding. 800 K (21 stops below 1600 K) reads as a dim red glow when
//               1600 K is bright orange;
//   "Raw"       no transform (and no gamut mapping).
//
// Method, in this order, per pixel:
//  1. exposure: rgb *= 2^exposureEV; convert from the image's colour space to linear Rec.709
//     (the config's scene_linear) with a 3x3 matrix.
//  2. gamut mapping, hue preserving (never a per-channel clip of raw values): with luminance
//     Y = 0.2126 R + 0.7152 G + 0.0722 B, a colour with a negative component (out of gamut,
//     common for deep-red glow) is mixed with the grey (Y, Y, Y) of equal luminance,
//     c' = Y + t (c - Y), with the largest t in [0, 1] that makes every component >= 0. This
//     moves along the line of constant hue (in the opponent plane) towards the achromatic axis
//     and keeps Y. Black or negative Y becomes black.
//  3. Standard only: values above 1 are scaled down by the largest component (c / max(c)),
//     which keeps the ratios (hue and saturation) at the cost of luminance. Filmic lets the
//     and ACES let the tone curve compress highlights; its input is the gamut-mapped colour.
//  4. OCIO processor "scene_linear -> display sRGB, view", CPU float path, then quantisation
//     to 8 bits with rounding.
#pragma once

#include <string>
#include <vector>

#include "core/image/image.h"
#include "spectral/color.h"

namespace kiln {

// DisplaySettings Definition
struct DisplaySettings {
    std::string view = "Standard";  // "Standard" | "Filmic" | "ACES" | "Glow" | "Raw"
    Float exposureEV = 0;           // stops; linear values are multiplied by 2^exposureEV
};

// Path of the OCIO config in use (KILN_OCIO_CONFIG if set, else the shipped one).
std::string OCIOConfigPath();
// The views of the config's sRGB display. Throws std::runtime_error if the config is broken.
std::vector<std::string> DisplayViews();
// "unknown display view "V" (the views are Standard, Filmic, ...)"
std::string UnknownViewMessage(const std::string& view);

// Hue-preserving gamut mapping of steps 2 and 3 above, on linear Rec.709 RGB.
// scaleAboveOne: also apply step 3 (the Standard view).
RGB MapToDisplayGamut(RGB rgb, bool scaleAboveOne);

// Tone of scene-linear 1.0 under the Filmic curve (y = x^1.1 / (x^1.1 + k), k = 1.0147888:
// 1 / (1 + k)); the knee of the path to white.
inline constexpr Float kFilmicKnee = 0.49633f;
// Step 3 of the Filmic view on a gamut-mapped colour c, given toned = curve(max(c)) (display
// linear); returns display-linear RGB with max component `toned`.
RGB FilmicHuePreserving(RGB c, Float toned);

// Converts an image whose first three channels are linear RGB in colorSpace to an 8-bit sRGB
// display image (PixelFormat::U256, 3 channels R, G, B, sRGB encoding) through OCIO.
// Throws std::runtime_error for an unknown view or a broken config.
Image ToDisplayImage(const Image& linearRGB, const RGBColorSpace& colorSpace,
                     const DisplaySettings& settings);
// The same before quantisation: display-encoded values (PixelFormat::Float, R, G, B).
Image ToDisplayEncodedFloat(const Image& linearRGB, const RGBColorSpace& colorSpace,
                            const DisplaySettings& settings);

}  // namespace kiln
