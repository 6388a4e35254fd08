// The picture a thermal camera shows: temperature mapped to colour (an "iron" palette: black,
// violet, red, orange, yellow, white from the coldest to the hottest pixel of the frame), with a
// scale bar on the right labelled with both ends in kelvin.
#pragma once

#include <optional>

#include "core/image/image.h"
#include "spectral/color.h"

namespace kiln {

// The palette's colour (sRGB-encoded components in [0, 1]) at t in [0, 1] (clamped).
RGB IronPalette(Float t);

// The temperatures a picture's palette spans, K (lo < hi)
struct TemperatureScale {
    Float lo, hi;
};

// A picture of the temperature channel T (K) of `thermal`: linear RGB (Float) to be written
// in an 8-bit format, the image widened by a scale bar. The palette spans `scale` (pixels
// beyond it take its end colours), or without one the lowest to the highest finite positive
// temperature of the frame (a frame of one temperature gets a 1 K range around it).
Image ThermalPicture(const Image& thermal, int temperatureChannel,
                     std::optional<TemperatureScale> scale = std::nullopt);

}  // namespace kiln
