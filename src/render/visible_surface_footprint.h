// dp/dx and dp/dy of a camera ray's visible surface, as pbrt-v4 computes them from the ray's
// differentials (SurfaceInteraction::ComputeDifferentials) for its gbuffer film.
#pragma once

#include "core/camera/camera.h"
#include "core/camera/camera_sample.h"
#include "core/film/visible_surface.h"

namespace kiln {

// pbrt-v4's camera ray differentials for `sample` (same lens sample, time and wavelengths;
// perspective and orthographic cameras: the rays one pixel to the right and one down; other
// cameras: finite differences over 0.05 pixel), brought towards `ray` by `scale` (pbrt-v4's
// ScaleDifferentials: origins and unit directions interpolated linearly), are intersected with
// the tangent plane of vs (point vs->p, geometric normal vs->n); vs->dpdx and vs->dpdy are the
// offsets of those hits from vs->p. Where a differential ray is not generated or runs parallel
// to the plane, the camera's estimate (Approximate_dp_dxy with samplesPerPixel) is used
// instead, as pbrt-v4 does for rays without differentials.
// scale: max(1/8, 1/sqrt(samples per pixel)), or 1 without pixel jitter (pbrt-v4).
void SetCameraDifferentials(const Camera& camera, const CameraSample& sample, const Ray& ray,
                            const SampledWavelengths& lambda, Float scale, int samplesPerPixel,
                            VisibleSurface* vs);

}  // namespace kiln
