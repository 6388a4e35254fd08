// Pictures of the polarisation in a rendered image with Stokes layers (film "stokes": channels
// S0.R ... S3.B, linear, in the film's colour space; film.h).
//
// Each pixel's Stokes vector is reduced to luminance, S_k = Y of the RGB of layer k (a thermal
// film's single channels S0 ... S3 of in-band radiance are taken as they are), and
// normalised, s_k = S_k / S0, giving
//   degree of polarisation           DoP  = sqrt(s1^2 + s2^2 + s3^2),
//   degree of linear polarisation    DoLP = sqrt(s1^2 + s2^2),
//   degree of circular polarisation  DoCP = |s3|,
//   angle of linear polarisation     AoLP = atan2(s2, s1) / 2, from the image's horizontal,
//                                     counter-clockwise in the image, in [0, pi).
// (the degrees clamped to [0, 1]). The pictures, display-encoded sRGB, 8 bits:
//   dolp:      DoLP as grey (black unpolarised, white fully linearly polarised);
//   aolp:      AoLP as hue (0 degrees red, 60 green, 120 blue, back to red at 180), brightness
//              DoLP;
// and the four false-colour visualisations of Wilkie & Weidlich 2010, "A standardised
// polarisation visualisation for images" (SCCG 2010), as Mitsuba 3's polarisation tools draw
// them:
//   dop:       DoP from black (0) to red (1);
//   aop:       orientation of linear polarisation: horizontal (s1 > 0) green, vertical red,
//              +45 degrees (s2 > 0) yellow, -45 degrees blue, added in proportion to |s1|,
//              |s2| (so brightness grows with DoLP);
//   type:      linear (DoLP) cyan, circular (DoCP) yellow, added;
//   chirality: right-handed (s3 > 0) yellow, left-handed blue, in proportion to |s3|, times
//              DoCP.
// Pixels darker than `darkFraction` of the 99th-percentile S0 are black in all of them (their
// polarisation is mostly Monte Carlo noise).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/image/image.h"

namespace kiln {

class RGBColorSpace;

// (name, picture) for dolp, aolp, dop, aop, type, chirality, in that order.
// stokes: an image with the channels S0.R ... S3.B (or S0 ... S3); throws std::runtime_error
// without them.
std::vector<std::pair<std::string, Image>> PolarizationViews(const Image& stokes,
                                                             const RGBColorSpace& colorSpace,
                                                             Float darkFraction = 1e-3f);

}  // namespace kiln
