// The sample values a camera ray is generated from, and the ray it yields (pbrt-v4's
// CameraSample and CameraRay).
#pragma once

#include "base/vecmath.h"
#include "spectral/sampled_spectrum.h"

namespace kiln {

// pFilm: position on the film in raster coordinates (pixels, continuous, (0,0) at the top-left
// corner of the full image); pLens in [0,1)^2; time in [0,1); filterWeight: the pixel filter's
// weight of this sample (see Filter::Sample).
struct CameraSample {
    Point2f pFilm;
    Point2f pLens;
    Float time = 0;
    Float filterWeight = 1;
};

// A render-space ray with unit direction, and its importance weight (1 for pbrt-v4's
// perspective and orthographic cameras).
struct CameraRay {
    Ray ray;
    SampledSpectrum weight = SampledSpectrum(1);
};

}  // namespace kiln
