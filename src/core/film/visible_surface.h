// The first visible surface of a camera ray, for the film's auxiliary (AOV) layers.
#pragma once

#include "base/vecmath.h"
#include "spectral/sampled_spectrum.h"

namespace kiln {

// p: render-space position; n, ns: geometric and shading normals (unit); depth: distance from
// the camera along the ray (scene units); albedo: the BSDF's directional albedo estimate
// (dimensionless, per sampled wavelength). set is false when the ray escaped.
struct VisibleSurface {
    bool set = false;
    Point3f p;
    Normal3f n, ns;
    Float depth = 0;
    SampledSpectrum albedo;
};

}  // namespace kiln
