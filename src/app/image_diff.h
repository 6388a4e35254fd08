// `kiln diff`: numerical and perceptual comparison of two images (a test image A and a
// reference B), with a false-colour difference image.
//
// Pixel values are compared as kiln reads them (Image::Read): linear for float/half files,
// 8- and 16-bit files decoded with their transfer function (sRGB unless declared linear).
// Every metric is a mean over all pixels and, except flip-like, all channels; A and B must
// have the same resolution, channel count and channel names (in order).
//
//   mae        mean |A - B|
//   rmse       sqrt(mean (A - B)^2)
//   psnr       20 log10(1 / rmse), dB, peak value 1 (fixed, unlike OIIO's image maximum)
//   relmse     mean (A - B)^2 / (|B| + 0.01)^2               (pbrt-v4's Image::MRSE / imgtool
//                                                             "MRSE": same epsilon 0.01)
//   flip-like  mean CIE76 colour difference deltaE*ab between A and B after the display
//              tone map of an sRGB monitor: RGB (channels R, G, B if present, else the first
//              three, a single channel as grey) is clamped to [0, 1] (the range such a display
//              shows), taken as linear Rec. 709 / sRGB primaries with a D65 white, converted to
//              CIE XYZ (IEC 61966-2-1 matrix) and to CIELAB with the D65 white (CIE 015:2018,
//              eq. 8.1-8.3). deltaE*ab ~ 1 is about a just-noticeable difference; 0 = identical.
//              This is a simple metric defined here, not NVIDIA's FLIP (no spatial filtering,
//              no HDR exposure bracketing: differences above 1.0 in all channels are invisible
//              to it; the other metrics see them).
//
// The difference image shows the per-pixel relative RMS error
//   e = sqrt(mean_c (A - B)^2 / (|B| + 0.01)^2)
// on a log scale, e <= 1e-3 -> 0 and e >= 1 -> 1, through OpenImageIO's perceptually uniform
// "inferno" colour map (black: identical, yellow-white: 100 % error or more; the OpenImageIO
// plugin is loaded for it); NaN/Inf pixels of either image are shown in pure green. It is
// written through Image::Write (atomic).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/vecmath.h"
#include "core/image/image.h"

namespace kiln {

struct ImageDiffMetrics {
    double mae = 0, rmse = 0, psnr = 0, relmse = 0, flipLike = 0;
    double maxError = 0;          // largest |A - B| over pixels and channels
    Point2i maxErrorPixel{0, 0};  // where it is
    int64_t nonFinitePixels = 0;  // pixels with a NaN/Inf value in A or B
};

// Names of the metrics, in the order RunImageDiff prints them: "rmse", "relmse", "mae",
// "psnr", "flip-like".
const std::vector<std::string>& ImageDiffMetricNames();
// Value of a named metric; std::nullopt for an unknown name.
std::optional<double> GetMetric(const ImageDiffMetrics& m, const std::string& name);

// Compares test image `a` with reference `b`. Throws std::invalid_argument if resolutions,
// channel counts or channel names differ. If diffImage is not null it receives the false-colour
// difference image (R, G, B, linear Float, same resolution; see above).
ImageDiffMetrics CompareImages(const Image& a, const Image& b, Image* diffImage = nullptr);

// `kiln diff A B [--metric rmse|relmse|mae|psnr|flip-like] [--threshold X] [--out FILE]`
// (args without "diff"). Prints every metric as "name value" on stdout, one per line (plus
// "maxerror", "nonfinite"). Returns 0, or 1 if --threshold is given and the chosen metric
// (default relmse) is above it (for psnr: below it; NaN always fails), or 2 on usage errors,
// unreadable files or mismatched images (message on stderr naming both files).
int RunImageDiff(const std::vector<std::string>& args);

std::string ImageDiffUsageText();

}  // namespace kiln
