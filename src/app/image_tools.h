// `kiln convert` and `kiln info`: kiln's display transform and metadata for images kiln (or
// anything else) wrote, without rendering.
//
//   kiln convert IN... -o OUT... [--view V] [--exposure EV|auto]
//     IN's R, G, B (several inputs of the same height: side by side, left to right) (linear: an
//     EXR, PFM or HDR render, a merged farm frame, a checkpointed render's output) times 2^EV,
//     written to every OUT: through the display view V for display formats (PNG, JPEG, TIFF, ...;
//     default the view the film asked for, "kiln:view", else Standard), linear for EXR, PFM and
//     HDR. "--exposure auto" puts the 99th percentile of the luminance at 0.9 (as kiln --exposure
//     auto). Outputs are checked before any IN is read.
//   kiln info IMAGE
//     Resolution (and the frame a part belongs to), pixel type, channels grouped by layer
//     (Stokes layers, AOVs), samples per pixel, render time, colour space and every kiln:
//     attribute (seed, exposure, partial, frame, view, options, scene hash).
//
// Both return 0, 1 for a file that cannot be read or written, 2 for a usage error.
#pragma once

#include <string>
#include <vector>

namespace kiln {

int RunConvert(const std::vector<std::string>& args);
int RunInfo(const std::vector<std::string>& args);

}  // namespace kiln
