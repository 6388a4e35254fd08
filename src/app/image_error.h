// pbrt-v4 imgtool's `error` and `falsecolor`, as uses of kiln diff:
//
//   kiln diff error --reference REF [--metric mae|mse|relmse] [--errorfile OUT] PREFIX
//     The error of every image whose path starts with PREFIX (REF left out; all of REF's
//     resolution and channels, and of one sample count when they record it) against REF:
//     prints "<metric> estimate = E" (E the mean over the images of each image's error, the
//     metric's mean over pixels and channels, as kiln diff defines it) and "images N";
//     --errorfile writes the per-pixel mean of that error over the images (channel Y).
//     Several renders with independent seeds estimate a renderer's expected error.
//   kiln diff falsecolor IMAGE -o OUT [--maxvalue V] [--plusminus]
//     The mean of each pixel's channels divided by V (default: the largest magnitude in the
//     image) through OpenImageIO's "inferno" colour map (0 black, 1 yellow-white), or with
//     --plusminus positive values in green and negative in red, as imgtool does.
//
// Both return 0, 1 for unreadable or mismatched images, 2 for usage errors.
#pragma once

#include <string>
#include <vector>

namespace kiln {

// The relative metric's (relmse) epsilon, pbrt-v4's MRSE epsilon: (a - b)^2 / (|b| + eps)^2.
inline constexpr float kRelMSEEpsilon = 0.01f;

int RunImageError(const std::vector<std::string>& args);
int RunFalseColor(const std::vector<std::string>& args);

}  // namespace kiln
