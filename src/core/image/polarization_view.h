// Pictures of the polarisation in a rendered image with Stokes layers (film "stokes": channels
// S0.R ... S3.B, linear, in the film's colour space; film.h).
//
// Each pixel's Stokes vector is reduced to luminance, S_k = Y of the RGB of layer k, and
//   degree of linear polarisation  DoLP = sqrt(S1^2 + S2^2) / S0,
//   degree of circular polarisation DoCP = |S3| / S0,
//   angle of linear polarisation   AoLP = atan2(S2, S1) / 2 (from the image's horizontal,
//                                    counter-clockwise in the image, in [0, pi)).
// Two false-colour images, in the spirit of Wilkie & Weidlich 2010 ("A standardised
// polarisation visualisation for images"; kiln's own colour assignment, described here):
//   degree: red = DoLP, green = DoCP of right-handed (S3 > 0), blue = DoCP of left-handed light;
//           black is unpolarised, full red completely linearly polarised;
//   angle:  hue = AoLP (0 red, 60 degrees green, 120 degrees blue, back to red at 180), value =
//           DoLP, full saturation: unpolarised light is black.
// Pixels darker than `darkFraction` of the 99th-percentile S0 are black in both (their degree
// is mostly Monte Carlo noise). Display-encoded sRGB, 8 bits.
#pragma once

#include "core/image/image.h"

namespace kiln {

class RGBColorSpace;

struct PolarizationPictures {
    Image degree, angle;
};

// stokes: an image with the channels S0.R ... S3.B; throws std::runtime_error without them.
PolarizationPictures PolarizationViews(const Image& stokes, const RGBColorSpace& colorSpace,
                                       Float darkFraction = 1e-3f);

}  // namespace kiln
