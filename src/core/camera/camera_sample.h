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

// Importance arriving at a reference point from a point sampled on the camera's lens (pbrt-v4's
// CameraWiSample): Wi the importance We of the ray from pLens towards pRef, wi the unit
// direction from pRef towards pLens, pdf per sr at pRef, pRaster the film position the ray
// reaches.
struct CameraWiSample {
    SampledSpectrum Wi;
    Vector3f wi;
    Float pdf = 0;
    Point2f pRaster;
    Point3f pRef, pLens;
    Normal3f nLens;  // the lens normal (the camera's viewing direction)
};

// Densities of a camera ray (pbrt-v4's Camera::PDF_We): pos per m^2 of lens, dir per sr.
struct CameraPDF {
    Float pos = 0, dir = 0;
};

}  // namespace kiln
