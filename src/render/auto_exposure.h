// Automatic exposure: brightens or darkens an image so its bright regions (glowing objects,
// typically) land near display white, whatever their absolute radiance.
#pragma once

#include "core/film/film.h"

namespace kiln {

// The exposure change (EV stops) that maps the given luminance percentile of the film's
// pixels (with exposure 0) to `target` luminance: 2^ev Y_p = target. Black pixels are
// ignored; 0 for an all-black film. Percentile in (0, 1], e.g. 0.99.
Float AutoExposureEV(const RGBFilm& film, Float percentile = 0.99f, Float target = 0.9f);
// The same for an image's R, G, B channels in `colorSpace` (kiln convert --exposure auto).
Float AutoExposureEV(const Image& rgb, const RGBColorSpace& colorSpace, Float percentile = 0.99f,
                     Float target = 0.9f);

}  // namespace kiln
