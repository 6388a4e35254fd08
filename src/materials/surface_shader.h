// SurfaceShader: builds the BSDF at a surface point exactly as the integrator does at a ray hit
// (texture footprint, mix-material choice, shading frame). Emission computed from a material's
// BSDF (thermal_area_light.h) asks it for the BSDF at points that light sampling chose, so that
// a point emits the same radiance however a path finds it.
#pragma once

#include "base/interaction.h"
#include "materials/bxdfs/bsdf.h"
#include "spectral/sampled_spectrum.h"

namespace kiln {

class SurfaceShader {
  public:
    virtual ~SurfaceShader() = default;
    // The BSDF at si (invalid for interface materials or si.material == nullptr). Sets si's
    // texture footprint; si.material becomes the material that built the BSDF (a mix material's
    // component chosen at si). May terminate lambda's secondary wavelengths (dispersion).
    virtual BSDF GetBSDF(SurfaceInteraction& si, SampledWavelengths& lambda) const = 0;
};

}  // namespace kiln
