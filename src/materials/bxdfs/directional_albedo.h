// Directional-hemispherical reflectance of a BxDF, for Kirchhoff emission (emissivity =
// 1 - reflectance for opaque bodies).
#pragma once

#include "materials/bxdfs/bxdf.h"

namespace kiln {

// Fraction of power arriving from wo (local frame, unit, wo.z != 0) that is reflected into
// wo's hemisphere, per sampled wavelength, in [0, 1]. Transmission is not counted (for a
// dielectric interface it enters the emitting body). Exact for smooth conductors, smooth
// dielectrics and thin dielectrics (Fresnel equations); otherwise a deterministic estimate from
// a fixed stratified set of sqrtSamples^2 points (cell centres, no jitter), so the result is a
// smooth function of wo for non-stochastic BxDFs (layered BxDFs remain stochastic in wo).
SampledSpectrum DirectionalAlbedo(const BxDF& bxdf, Vector3f wo, int sqrtSamples = 32);

}  // namespace kiln
