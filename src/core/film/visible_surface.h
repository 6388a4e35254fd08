// The first visible surface of a camera ray, for the film's auxiliary (AOV) layers.
#pragma once

#include "base/vecmath.h"
#include "spectral/sampled_spectrum.h"

namespace kiln {

// p: render-space position; n, ns: geometric and shading normals (unit, render space, on the
// side the ray came from, as pbrt-v4); uv: the surface's (u, v); dpdx, dpdy: the change of p
// from one pixel to the next along x and y of the film, scaled like pbrt-v4's camera ray
// differentials (by max(1/8, 1/sqrt(samples per pixel))); albedo: the BSDF's directional albedo
// estimate (dimensionless, per sampled wavelength). set is false when the ray escaped.
struct VisibleSurface {
    bool set = false;
    Point3f p;
    Normal3f n, ns;
    Point2f uv;
    Vector3f dpdx, dpdy;
    SampledSpectrum albedo;
};

}  // namespace kiln
